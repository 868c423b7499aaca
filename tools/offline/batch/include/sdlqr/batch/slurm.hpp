#pragma once
// A batch on a Slurm cluster (docs/batches.md): one job array, one shard of the batch per array
// task. Task I of N runs `sdlqr-batch SPEC --shard I/N --out OUT/slurm/shard-I` on the cores
// Slurm gives it (a shard folder resumes from its journal like any batch folder); the submitting
// process waits, showing tasks and flights, requeues a task that failed once (it continues its
// journal), and merges the shards into OUT: the files a single machine writes, bit for bit.
//
// Every node must see the same paths (the shared file system Slurm clusters have) and the same
// build of sdlqr-batch. This header is the pure part — the script, squeue's lines, the waiter's
// decisions — so it is tested without a cluster; slurm_submit.hpp talks to Slurm.

#include <string>
#include <vector>

namespace sdlqr::batch {

struct SlurmOptions {
  int tasks = 0;          // array tasks = shards
  int cpus_per_task = 0;  // 0: each task a whole node of its own (--exclusive), every core of it
  std::string partition;  // empty: the cluster's default partition
};

// What one submission flies, with the paths every node uses.
struct SlurmJob {
  std::string batch_binary;  // absolute path of sdlqr-batch
  std::string spec;          // the batch file as the user named it (relative to work_dir)
  std::string out_dir;       // the merged batch folder; the shards and task logs under OUT/slurm
  std::string work_dir;      // each task's working folder (sbatch --chdir)
  std::string job_name;
  SlurmOptions options;
};

std::string slurmDir(const std::string& out_dir);                // OUT/slurm
std::string shardDir(const std::string& out_dir, int task);      // OUT/slurm/shard-I
std::string taskLogPath(const std::string& out_dir, int task);   // OUT/slurm/task-I.out

// The batch script `sbatch` is given. Throws ConfigError naming the option when the options
// make no job (no task, a negative core count).
std::string sbatchScript(const SlurmJob& job);

// A word of the shell that stays one word whatever it holds: 'it''s' quoted for /bin/bash.
std::string shellQuoted(const std::string& text);

enum class TaskState {
  kPending,    // PENDING, REQUEUED, ...: waits for a node
  kRunning,    // RUNNING, COMPLETING, CONFIGURING, SUSPENDED, ...
  kCompleted,  // exit code 0
  kFailed,     // FAILED, NODE_FAIL, BOOT_FAIL, OUT_OF_MEMORY, TIMEOUT, PREEMPTED, DEADLINE: requeued once
  kCancelled,  // CANCELLED by someone: not requeued
};

struct TaskStatus {
  int task = 0;             // the array index, 1-based
  TaskState state = TaskState::kPending;
  std::string slurm_state;  // as squeue printed it
};

// Task states of `job_id` from `squeue --array --noheader --states=all --format=%i|%T` (lines
// "17_3|RUNNING"; a pending range "17_[2-4]|PENDING" gives one entry per task). Lines of other
// jobs are skipped; a line it cannot read throws std::runtime_error quoting it.
std::vector<TaskStatus> parseSqueue(const std::string& text, const std::string& job_id);
TaskState taskStateOf(const std::string& slurm_state);

// What the waiter does next, decided from what squeue lists and which shard folders are finished
// (they hold flights.csv). A task is done when its shard is finished and Slurm lists it completed
// (or no more: a finished task's record expires). A failed task is requeued once; a second
// failure, a cancelled task or one that left the queue unfinished ends the wait with the reason.
class ArrayWatch {
 public:
  explicit ArrayWatch(int tasks, int requeues_per_task = 1);

  struct Decision {
    std::vector<int> requeue;  // tasks to requeue now
    int pending = 0, running = 0, done = 0, requeued = 0;
    bool finished = false;     // every task done: merge
    std::string failure;       // non-empty: stop waiting, this is why
  };
  // `shard_finished[i]`: task i + 1's shard folder holds its flights.csv.
  Decision observe(const std::vector<TaskStatus>& listed, const std::vector<bool>& shard_finished);

 private:
  int tasks_;
  int requeues_per_task_;
  // Per task:
  std::vector<int> requeues_;
  std::vector<bool> seen_;        // listed by squeue at least once
  std::vector<bool> restarting_;  // requeued, its failure may still be listed until Slurm shows it pending
  std::vector<int> completed_without_files_;  // polls listed COMPLETED before flights.csv appeared
};

}  // namespace sdlqr::batch
