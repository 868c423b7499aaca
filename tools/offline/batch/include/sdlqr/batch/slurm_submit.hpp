#pragma once
// The side of a Slurm batch that talks to the cluster (slurm.hpp: what it says): sbatch submits
// the job array, squeue shows its tasks, scontrol requeues a failed one. The commands come from
// PATH and read the cluster's configuration as they always do (SLURM_CONF, /etc/slurm);
// site options such as an account or a time limit pass through sbatch's own environment
// variables (SBATCH_ACCOUNT, SBATCH_TIMELIMIT, ...).

#include <string>

#include "sdlqr/batch/results.hpp"
#include "sdlqr/batch/slurm.hpp"

namespace sdlqr::batch {

// The job for `spec_path` (as the user named it) into `out_dir`, run from this process's working
// folder by this very sdlqr-batch.
SlurmJob slurmJobFor(const BatchContext& context, const std::string& spec_path, const std::string& out_dir,
                     const SlurmOptions& options);

// Checks the shard folders a previous submission left hold this batch split the same way, writes
// OUT/slurm/job.sh and submits it. Returns the job id; throws std::runtime_error with sbatch's
// message when it refuses.
std::string submitSlurmBatch(const BatchContext& context, const SlurmJob& job);

// Waits for the job's tasks with a progress line on stderr (redrawn on a terminal), requeues a
// failed task once, and merges the shards into job.out_dir (flights.csv, batch.yaml; the summary
// is the caller's). Throws std::runtime_error naming the task and its log when the batch cannot
// finish.
Table waitAndMerge(const BatchContext& context, const SlurmJob& job, const std::string& job_id, bool terminal);

}  // namespace sdlqr::batch
