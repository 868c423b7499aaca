#include "sdlqr/batch/slurm_submit.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "sdlqr/batch/command.hpp"

#include "file_text.hpp"

namespace sdlqr::batch {

namespace {

// [s] between two looks at the queue: quick enough to requeue a failed task at once, rare enough
// for a cluster's controller (one squeue per batch).
constexpr double kPollSeconds = 2.0;

std::string workingFolder() {
  char buffer[PATH_MAX];
  if (::getcwd(buffer, sizeof buffer) == nullptr) throw std::runtime_error("cannot read the working folder");
  return buffer;
}

std::string thisExecutable() {
  char buffer[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n <= 0) throw std::runtime_error("cannot find this sdlqr-batch's path (/proc/self/exe)");
  return std::string(buffer, static_cast<size_t>(n));
}

std::string commandFailure(const std::vector<std::string>& argv, const CommandResult& r) {
  std::string message = argv[0] + " failed (exit " + std::to_string(r.status) + ")";
  std::string error = r.error.empty() ? r.out : r.error;
  while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
  return error.empty() ? message : message + ": " + error;
}

CommandResult mustRun(const std::vector<std::string>& argv) {
  CommandResult r = runCommand(argv);
  if (!r.ok()) throw std::runtime_error(commandFailure(argv, r));
  return r;
}

// Rows of a shard's journal so far (its header line not counted).
long long journalRows(const std::string& shard_dir) {
  const std::string path = shard_dir + "/flights.partial.csv";
  if (!detail::exists(path)) return 0;
  const std::string text = detail::fileText(path);
  return std::max(0LL, static_cast<long long>(std::count(text.begin(), text.end(), '\n')) - 1);
}

// "slurm job 17: tasks 1 pending, 2 running, 1 done, 1 requeued; flights 23/40"
std::string progressLine(const std::string& job_id, const ArrayWatch::Decision& d, long long flights, long long total) {
  std::string line = "slurm job " + job_id + ": tasks " + std::to_string(d.pending) + " pending, " +
                     std::to_string(d.running) + " running, " + std::to_string(d.done) + " done";
  if (d.requeued > 0) line += ", " + std::to_string(d.requeued) + " requeued";
  return line + "; flights " + std::to_string(flights) + "/" + std::to_string(total);
}

// On a terminal the line is redrawn at every look; in a log file a line is written when the
// tasks change, and otherwise at most every 10 s.
class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool terminal) : terminal_(terminal), last_print_(std::chrono::steady_clock::now()) {}
  void show(const std::string& line) {
    if (terminal_) {
      std::fprintf(stderr, "\r%s\033[K", line.c_str());
      return;
    }
    const auto now = std::chrono::steady_clock::now();
    const bool tasks_changed = line.substr(0, line.find(';')) != last_line_.substr(0, last_line_.find(';'));
    if (line == last_line_ || !(tasks_changed || now - last_print_ > std::chrono::seconds(10))) return;
    std::fprintf(stderr, "%s\n", line.c_str());
    last_line_ = line;
    last_print_ = now;
  }
  void note(const std::string& text) { std::fprintf(stderr, "%s%s\n", terminal_ ? "\n" : "", text.c_str()); }
  void finish() {
    if (terminal_) std::fputc('\n', stderr);
  }

 private:
  bool terminal_;
  std::string last_line_;
  std::chrono::steady_clock::time_point last_print_;
};

void requeue(const std::string& job_id, int task) {
  const std::string id = job_id + "_" + std::to_string(task);
  mustRun({"scontrol", "requeue", id});
  // Slurm holds a requeued job back for a while (its begin time moves ~2 min on): a failed task
  // of ours is due again now.
  mustRun({"scontrol", "update", "JobId=" + id, "StartTime=now"});
}

}  // namespace

SlurmJob slurmJobFor(const BatchContext& context, const std::string& spec_path, const std::string& out_dir,
                     const SlurmOptions& options) {
  SlurmJob job;
  job.work_dir = workingFolder();
  job.batch_binary = thisExecutable();
  job.spec = spec_path;
  job.out_dir = !out_dir.empty() && out_dir.front() == '/' ? out_dir : job.work_dir + "/" + out_dir;
  const std::string name = context.spec.path.substr(context.spec.path.find_last_of('/') + 1);
  job.job_name = "sdlqr-" + name.substr(0, name.rfind(".yaml"));
  job.options = options;
  return job;
}

std::string submitSlurmBatch(const BatchContext& context, const SlurmJob& job) {
  const std::string script = sbatchScript(job);
  const int tasks = job.options.tasks;
  for (int task = 1; task <= tasks; ++task) checkBatchFolder(shardDir(job.out_dir, task), context, Shard{task, tasks});
  if (detail::exists(shardDir(job.out_dir, tasks + 1))) {
    throw std::runtime_error(shardDir(job.out_dir, tasks + 1) + ": this folder holds a split of the batch into more than " +
                             std::to_string(tasks) + " tasks: choose another --out or the same --tasks");
  }
  makeDirectories(slurmDir(job.out_dir));
  const std::string path = slurmDir(job.out_dir) + "/job.sh";
  writeText(path, script);
  const CommandResult r = mustRun({"sbatch", "--parsable", path});
  const std::string id = r.out.substr(0, r.out.find_first_of(";\n"));  // "17" or "17;cluster"
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    throw std::runtime_error("sbatch: cannot read a job id in '" + r.out + "'");
  }
  writeText(slurmDir(job.out_dir) + "/job_id", id + "\n");
  return id;
}

Table waitAndMerge(const BatchContext& context, const SlurmJob& job, const std::string& job_id, bool terminal) {
  const int tasks = job.options.tasks;
  const long long total = static_cast<long long>(context.spec.flights) * static_cast<long long>(context.spec.controllers.size());
  const std::vector<std::string> squeue = {"squeue", "--array", "--noheader", "--states=all", "--jobs=" + job_id,
                                           "--format=%i|%T"};
  ArrayWatch watch(tasks);
  ProgressPrinter printer(terminal);
  for (;;) {
    const CommandResult listed = mustRun(squeue);
    std::vector<bool> finished;
    long long flights = 0;
    for (int task = 1; task <= tasks; ++task) {
      finished.push_back(detail::exists(shardDir(job.out_dir, task) + "/flights.csv"));
      flights += journalRows(shardDir(job.out_dir, task));
    }
    const ArrayWatch::Decision d = watch.observe(parseSqueue(listed.out, job_id), finished);
    for (int task : d.requeue) {
      printer.note("slurm job " + job_id + ": task " + std::to_string(task) +
                   " failed; requeued, it continues its journal (log " + taskLogPath(job.out_dir, task) + ")");
      requeue(job_id, task);
    }
    printer.show(progressLine(job_id, d, flights, total));
    if (!d.failure.empty()) {
      printer.finish();
      throw std::runtime_error("slurm job " + job_id + ": " + d.failure + "; logs in " + slurmDir(job.out_dir) +
                               " (the same command flies what is missing: each shard continues its journal)");
    }
    if (d.finished) break;
    std::this_thread::sleep_for(std::chrono::duration<double>(kPollSeconds));
  }
  printer.finish();
  std::vector<std::string> shards;
  for (int task = 1; task <= tasks; ++task) shards.push_back(shardDir(job.out_dir, task));
  return mergeShards(shards, job.out_dir, context);
}

}  // namespace sdlqr::batch
