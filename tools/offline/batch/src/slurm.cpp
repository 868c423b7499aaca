#include "sdlqr/batch/slurm.hpp"

#include <sstream>
#include <stdexcept>

#include "sdlqr/config/config.hpp"

namespace sdlqr::batch {

namespace {

// Polls a task may stay COMPLETED without its shard's flights.csv in sight (a shared file
// system shows another node's files late) before the wait gives up on it.
constexpr int kCompletedWithoutFilesPolls = 30;

int parseIndex(const std::string& text, const std::string& line) {
  size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || value < 1) throw std::runtime_error("squeue: cannot read task '" + text + "' in '" + line + "'");
  return value;
}

// "3", "[2-4]", "[2-4%2]" or "[1,3-4]" after "JOB_".
std::vector<int> taskIndices(std::string text, const std::string& line) {
  if (text.empty() || text.front() != '[') return {parseIndex(text, line)};
  if (text.back() != ']') throw std::runtime_error("squeue: cannot read tasks in '" + line + "'");
  text = text.substr(1, text.size() - 2);
  text = text.substr(0, text.find('%'));  // a limit of tasks at once
  std::vector<int> out;
  std::istringstream ranges(text);
  for (std::string range; std::getline(ranges, range, ',');) {
    const size_t dash = range.find('-');
    const int first = parseIndex(range.substr(0, dash), line);
    const int last = dash == std::string::npos ? first : parseIndex(range.substr(dash + 1), line);
    for (int i = first; i <= last; ++i) out.push_back(i);
  }
  return out;
}

}  // namespace

std::string slurmDir(const std::string& out_dir) { return out_dir + "/slurm"; }
std::string shardDir(const std::string& out_dir, int task) { return slurmDir(out_dir) + "/shard-" + std::to_string(task); }
std::string taskLogPath(const std::string& out_dir, int task) {
  return slurmDir(out_dir) + "/task-" + std::to_string(task) + ".out";
}

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string sbatchScript(const SlurmJob& job) {
  const SlurmOptions& o = job.options;
  if (o.tasks < 1) throw ConfigError("--tasks", "a Slurm batch needs at least one array task (--tasks N or --nodes N)");
  if (o.cpus_per_task < 0) throw ConfigError("--cpus-per-task", "must be >= 1");
  // #SBATCH lines are not shell words: a path there cannot be quoted.
  const auto unquotable = [](const std::string& key, const std::string& path) {
    if (path.find_first_of(" \t\n") == std::string::npos) return;
    throw ConfigError(key, "'" + path + "': a Slurm batch's folders may not hold spaces (#SBATCH lines)");
  };
  unquotable("--out", job.out_dir);
  unquotable("working folder", job.work_dir);
  const std::string tasks = std::to_string(o.tasks);
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by sdlqr-batch --slurm: batch " << job.spec << ", one shard per array task (docs/batches.md).\n"
    << "#SBATCH --job-name=" << job.job_name << "\n"
    << "#SBATCH --array=1-" << tasks << "\n"
    << "#SBATCH --nodes=1\n"
    << "#SBATCH --ntasks=1\n";
  if (o.cpus_per_task > 0) {
    s << "#SBATCH --cpus-per-task=" << o.cpus_per_task << "\n";
  } else {
    s << "#SBATCH --exclusive\n";
  }
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << "\n";
  // Requeued (by Slurm on a lost node, by the waiter on a failure), a task continues its journal;
  // its log keeps every attempt.
  s << "#SBATCH --requeue\n"
    << "#SBATCH --open-mode=append\n"
    << "#SBATCH --output=" << slurmDir(job.out_dir) << "/task-%a.out\n"
    << "#SBATCH --chdir=" << job.work_dir << "\n"
    << "set -eu\n"
    << "echo \"sdlqr-batch shard ${SLURM_ARRAY_TASK_ID}/" << tasks
    << " on $(hostname), attempt $((${SLURM_RESTART_COUNT:-0} + 1))\"\n"
    << "exec " << shellQuoted(job.batch_binary) << " " << shellQuoted(job.spec) << " --shard \"${SLURM_ARRAY_TASK_ID}/"
    << tasks << "\" \\\n"
    << "  --out " << shellQuoted(slurmDir(job.out_dir)) << "\"/shard-${SLURM_ARRAY_TASK_ID}\""
    << " --jobs \"${SLURM_CPUS_PER_TASK:-$SLURM_CPUS_ON_NODE}\" --no-progress\n";
  return s.str();
}

TaskState taskStateOf(const std::string& s) {
  if (s == "COMPLETED") return TaskState::kCompleted;
  if (s == "CANCELLED") return TaskState::kCancelled;
  if (s == "FAILED" || s == "NODE_FAIL" || s == "BOOT_FAIL" || s == "OUT_OF_MEMORY" || s == "TIMEOUT" ||
      s == "PREEMPTED" || s == "DEADLINE") {
    return TaskState::kFailed;
  }
  if (s == "PENDING" || s == "REQUEUED" || s == "REQUEUE_HOLD" || s == "REQUEUE_FED" || s == "RESV_DEL_HOLD") {
    return TaskState::kPending;
  }
  return TaskState::kRunning;  // RUNNING, COMPLETING, CONFIGURING, SUSPENDED, STOPPED, RESIZING, ...
}

std::vector<TaskStatus> parseSqueue(const std::string& text, const std::string& job_id) {
  std::vector<TaskStatus> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    const size_t bar = line.find('|');
    const size_t underscore = line.find('_');
    if (bar == std::string::npos || underscore == std::string::npos || underscore > bar) {
      throw std::runtime_error("squeue: cannot read '" + line + "' (expected JOB_TASK|STATE)");
    }
    if (line.substr(0, underscore) != job_id) continue;
    const std::string state = line.substr(bar + 1);
    for (int task : taskIndices(line.substr(underscore + 1, bar - underscore - 1), line)) {
      out.push_back({task, taskStateOf(state), state});
    }
  }
  return out;
}

ArrayWatch::ArrayWatch(int tasks, int requeues_per_task)
    : tasks_(tasks),
      requeues_per_task_(requeues_per_task),
      requeues_(static_cast<size_t>(tasks), 0),
      seen_(static_cast<size_t>(tasks), false),
      restarting_(static_cast<size_t>(tasks), false),
      completed_without_files_(static_cast<size_t>(tasks), 0) {}

ArrayWatch::Decision ArrayWatch::observe(const std::vector<TaskStatus>& listed, const std::vector<bool>& shard_finished) {
  Decision d;
  std::vector<const TaskStatus*> status(static_cast<size_t>(tasks_), nullptr);
  for (const TaskStatus& s : listed) {
    if (s.task >= 1 && s.task <= tasks_) status[static_cast<size_t>(s.task - 1)] = &s;
  }
  for (int task = 1; task <= tasks_; ++task) {
    const size_t i = static_cast<size_t>(task - 1);
    const bool finished = i < shard_finished.size() && shard_finished[i];
    const std::string name = "task " + std::to_string(task) + " of " + std::to_string(tasks_);
    d.requeued += requeues_[i];
    if (status[i] == nullptr) {
      // Never listed yet: just submitted. Listed before and gone: its record expired.
      if (finished) {
        ++d.done;
      } else if (seen_[i]) {
        d.failure = name + " left the queue without finishing its shard";
      } else {
        ++d.pending;
      }
      continue;
    }
    seen_[i] = true;
    const TaskState state = status[i]->state;
    if (state == TaskState::kPending || state == TaskState::kRunning) restarting_[i] = false;
    if (restarting_[i]) {  // requeued, not yet listed as such
      ++d.pending;
      continue;
    }
    switch (state) {
      case TaskState::kPending: ++d.pending; break;
      case TaskState::kRunning: ++d.running; break;
      case TaskState::kCompleted:
        if (finished) {
          ++d.done;
        } else if (++completed_without_files_[i] > kCompletedWithoutFilesPolls) {
          d.failure = name + " completed but its shard holds no flights.csv";
        } else {
          ++d.running;
        }
        break;
      case TaskState::kCancelled: d.failure = name + " was cancelled (" + status[i]->slurm_state + ")"; break;
      case TaskState::kFailed:
        if (requeues_[i] >= requeues_per_task_) {
          d.failure = name + " failed again (" + status[i]->slurm_state + ") after " + std::to_string(requeues_[i]) +
                      " requeue(s)";
          break;
        }
        ++requeues_[i];
        ++d.requeued;
        restarting_[i] = true;
        d.requeue.push_back(task);
        ++d.pending;
        break;
    }
  }
  d.finished = d.failure.empty() && d.done == tasks_;
  return d;
}

}  // namespace sdlqr::batch
