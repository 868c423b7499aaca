#include "sdlqr/batch/runner.hpp"

#include <atomic>
#include <exception>
#include <fstream>
#include <mutex>
#include <thread>

#include "sdlqr/batch/heap.hpp"
#include "sdlqr/batch/progress.hpp"
#include "sdlqr/batch/summary.hpp"

namespace sdlqr::batch {

namespace {

struct Job {
  int flight;
  std::string controller;
};

}  // namespace

RunResult runBatch(const BatchContext& context, const RunOptions& options) {
  keepFreedHeapMemory();
  Journal journal(options.out_dir, context, options.shard);
  std::vector<Job> jobs;
  long long shard_total = 0;
  for (int k = 0; k < context.spec.flights; ++k) {
    if (!inShard(k, options.shard.index, options.shard.count)) continue;
    for (const std::string& c : context.spec.controllers) {
      ++shard_total;
      if (!journal.done(k, c)) jobs.push_back({k, c});
    }
  }
  RunResult result;
  result.resumed = static_cast<long long>(journal.doneCount());
  long long failed = 0;
  {
    const Table landed = journal.table();
    for (const auto& r : landed.rows) failed += r[landed.column("pass")] == "1" ? 0 : 1;
  }
  Progress progress(shard_total, result.resumed, options.terminal);

  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // the journal, the counters, the progress line
  std::exception_ptr error;
  auto worker = [&] {
    logger::FlightLog spare;  // the last flight's log: the next one records into its memory
    for (size_t i = next++; i < jobs.size() && !stop; i = next++) {
      try {
        const FlightDraw draw = drawFlight(context.spec, context.config, context.scenario.sim, jobs[i].flight);
        FlownFlight flown = fly(context, worldOf(context, draw), jobs[i].controller, false, std::move(spare));
        const std::string line = row(context, draw, jobs[i].controller, flown.report);
        std::lock_guard<std::mutex> lock(mutex);
        journal.append(line);
        ++result.flown;
        result.simulated_s += 1e-6 * static_cast<double>(flown.log.sim_truth.messages.empty()
                                                              ? 0
                                                              : flown.log.sim_truth.messages.back().utime);
        failed += flown.report.passed() ? 0 : 1;
        if (options.progress) progress.update(result.resumed + result.flown, failed);
        spare = std::move(flown.log);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
    }
  };
  std::vector<std::thread> threads;
  const int count = std::max(1, std::min<int>(options.jobs, static_cast<int>(jobs.size())));
  for (int t = 0; t < count; ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  if (options.progress) progress.finish(result.resumed + result.flown, failed);
  result.wall_s = progress.elapsedSeconds();

  result.table = journal.table();
  sortRows(result.table, context.spec.controllers);
  writeTable(result.table, options.out_dir + "/flights.csv");
  return result;
}

}  // namespace sdlqr::batch
