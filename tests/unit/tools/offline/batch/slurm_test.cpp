// The Slurm side of a batch without a cluster: the sbatch script, squeue's lines, and the waiter's
// decisions (requeue once, stop on a second failure, a cancel or a lost task). The real cluster:
// tests/integration/slurm/slurm_batch.sh (label slurm).
#include <gtest/gtest.h>

#include "sdlqr/batch/slurm.hpp"
#include "sdlqr/config/config.hpp"

namespace sdlqr::batch {
namespace {

SlurmJob jobOf(int tasks, int cpus_per_task) {
  SlurmJob job;
  job.batch_binary = "/opt/sdlqr/build/bin/sdlqr-batch";
  job.spec = "bench/hover_jumps_1000.yaml";
  job.out_dir = "/shared/runs/sweep";
  job.work_dir = "/opt/sdlqr";
  job.job_name = "sdlqr-hover_jumps_1000";
  job.options.tasks = tasks;
  job.options.cpus_per_task = cpus_per_task;
  return job;
}

bool holds(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SbatchScript, OneShardPerArrayTaskOnTheCoresSlurmGives) {
  const std::string script = sbatchScript(jobOf(4, 2));
  EXPECT_TRUE(holds(script, "#SBATCH --array=1-4\n"));
  EXPECT_TRUE(holds(script, "#SBATCH --cpus-per-task=2\n"));
  EXPECT_FALSE(holds(script, "--exclusive"));
  EXPECT_FALSE(holds(script, "--partition"));
  EXPECT_TRUE(holds(script, "#SBATCH --requeue\n"));
  EXPECT_TRUE(holds(script, "#SBATCH --output=/shared/runs/sweep/slurm/task-%a.out\n"));
  EXPECT_TRUE(holds(script, "#SBATCH --chdir=/opt/sdlqr\n"));
  EXPECT_TRUE(holds(script, "exec '/opt/sdlqr/build/bin/sdlqr-batch' 'bench/hover_jumps_1000.yaml' --shard \"${SLURM_ARRAY_TASK_ID}/4\""));
  EXPECT_TRUE(holds(script, "--out '/shared/runs/sweep/slurm'\"/shard-${SLURM_ARRAY_TASK_ID}\""));
  EXPECT_TRUE(holds(script, "--jobs \"${SLURM_CPUS_PER_TASK:-$SLURM_CPUS_ON_NODE}\""));
}

TEST(SbatchScript, WholeNodesAreExclusiveAndAPartitionIsNamed) {
  SlurmJob job = jobOf(8, 0);
  job.options.partition = "long";
  const std::string script = sbatchScript(job);
  EXPECT_TRUE(holds(script, "#SBATCH --array=1-8\n"));
  EXPECT_TRUE(holds(script, "#SBATCH --exclusive\n"));
  EXPECT_TRUE(holds(script, "#SBATCH --partition=long\n"));
  EXPECT_FALSE(holds(script, "--cpus-per-task"));
}

TEST(SbatchScript, RefusesNoTasksAndPathsWithSpaces) {
  try {
    sbatchScript(jobOf(0, 1));
    FAIL() << "a job of no task was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "--tasks");
  }
  SlurmJob spaced = jobOf(2, 1);
  spaced.out_dir = "/shared/my runs";
  try {
    sbatchScript(spaced);
    FAIL() << "an #SBATCH path with a space was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "--out");
  }
}

TEST(SbatchScript, QuotesWordsForTheShell) {
  EXPECT_EQ(shellQuoted("plain"), "'plain'");
  EXPECT_EQ(shellQuoted("it's $HOME"), "'it'\\''s $HOME'");
}

TEST(Squeue, ReadsTasksRangesAndStatesOfItsJobOnly) {
  const std::vector<TaskStatus> tasks =
      parseSqueue("17_1|COMPLETED\n17_[3-4,6%2]|PENDING\n18_2|FAILED\n17_2|NODE_FAIL\n17_5|COMPLETING\n", "17");
  ASSERT_EQ(tasks.size(), 6u);
  EXPECT_EQ(tasks[0].task, 1);
  EXPECT_EQ(tasks[0].state, TaskState::kCompleted);
  EXPECT_EQ(tasks[1].task, 3);
  EXPECT_EQ(tasks[2].task, 4);
  EXPECT_EQ(tasks[3].task, 6);
  EXPECT_EQ(tasks[3].state, TaskState::kPending);
  EXPECT_EQ(tasks[4].task, 2);
  EXPECT_EQ(tasks[4].state, TaskState::kFailed);
  EXPECT_EQ(tasks[4].slurm_state, "NODE_FAIL");
  EXPECT_EQ(tasks[5].state, TaskState::kRunning);
  EXPECT_EQ(taskStateOf("CANCELLED"), TaskState::kCancelled);
  EXPECT_EQ(taskStateOf("OUT_OF_MEMORY"), TaskState::kFailed);
  EXPECT_EQ(taskStateOf("TIMEOUT"), TaskState::kFailed);
}

TEST(Squeue, ALineItCannotReadIsAnError) {
  EXPECT_THROW(parseSqueue("17_x|RUNNING\n", "17"), std::runtime_error);
  EXPECT_THROW(parseSqueue("no bar here\n", "17"), std::runtime_error);
  EXPECT_THROW(parseSqueue("17_[2-3|PENDING\n", "17"), std::runtime_error);
}

std::vector<TaskStatus> listed(const std::string& text) { return parseSqueue(text, "9"); }

TEST(ArrayWatch, FinishesWhenEveryShardIsDone) {
  ArrayWatch watch(2);
  ArrayWatch::Decision d = watch.observe({}, {false, false});  // just submitted, not listed yet
  EXPECT_EQ(d.pending, 2);
  EXPECT_FALSE(d.finished);
  d = watch.observe(listed("9_1|RUNNING\n9_2|PENDING\n"), {false, false});
  EXPECT_EQ(d.running, 1);
  EXPECT_EQ(d.pending, 1);
  d = watch.observe(listed("9_1|COMPLETED\n"), {true, false});  // task 2 still unlisted: pending
  EXPECT_EQ(d.done, 1);
  EXPECT_FALSE(d.finished);
  d = watch.observe(listed("9_2|COMPLETED\n"), {true, true});  // task 1's record expired: its files say done
  EXPECT_TRUE(d.finished);
  EXPECT_TRUE(d.failure.empty());
}

TEST(ArrayWatch, RequeuesAFailedTaskOnceAndStopsOnItsSecondFailure) {
  ArrayWatch watch(2);
  ArrayWatch::Decision d = watch.observe(listed("9_1|FAILED\n9_2|RUNNING\n"), {false, false});
  EXPECT_EQ(d.requeue, std::vector<int>{1});
  EXPECT_EQ(d.requeued, 1);
  EXPECT_TRUE(d.failure.empty());
  // Listed as failed until Slurm takes the requeue: still the first failure.
  d = watch.observe(listed("9_1|FAILED\n9_2|RUNNING\n"), {false, false});
  EXPECT_TRUE(d.requeue.empty());
  EXPECT_TRUE(d.failure.empty());
  d = watch.observe(listed("9_1|PENDING\n9_2|COMPLETED\n"), {false, true});
  EXPECT_TRUE(d.failure.empty());
  d = watch.observe(listed("9_1|OUT_OF_MEMORY\n9_2|COMPLETED\n"), {false, true});
  EXPECT_TRUE(d.requeue.empty());
  EXPECT_EQ(d.failure, "task 1 of 2 failed again (OUT_OF_MEMORY) after 1 requeue(s)");
  EXPECT_FALSE(d.finished);
}

TEST(ArrayWatch, ACancelledOrLostTaskEndsTheWait) {
  ArrayWatch cancelled(1);
  EXPECT_EQ(cancelled.observe(listed("9_1|CANCELLED\n"), {false}).failure, "task 1 of 1 was cancelled (CANCELLED)");
  ArrayWatch lost(1);
  EXPECT_TRUE(lost.observe(listed("9_1|RUNNING\n"), {false}).failure.empty());
  EXPECT_EQ(lost.observe({}, {false}).failure, "task 1 of 1 left the queue without finishing its shard");
}

TEST(ArrayWatch, ACompletedTaskWaitsForItsFilesThenFails) {
  ArrayWatch watch(1);
  ArrayWatch::Decision d;
  for (int poll = 0; poll < 30; ++poll) {
    d = watch.observe(listed("9_1|COMPLETED\n"), {false});
    ASSERT_TRUE(d.failure.empty()) << "poll " << poll;
    EXPECT_EQ(d.running, 1);
  }
  d = watch.observe(listed("9_1|COMPLETED\n"), {false});
  EXPECT_EQ(d.failure, "task 1 of 1 completed but its shard holds no flights.csv");
}

}  // namespace
}  // namespace sdlqr::batch
