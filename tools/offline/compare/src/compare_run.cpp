#include "sdlqr/compare/compare_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace sdlqr::compare {

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

std::string checksText(const analysis::FlightReport& r) {
  int passed = 0;
  for (const analysis::Check& c : r.checks) passed += c.pass ? 1 : 0;
  return std::to_string(passed) + "/" + std::to_string(r.checks.size()) + " checks";
}

// Runs tasks[i] for every i on `jobs` threads; the first exception is rethrown after all stop.
void runTasks(const std::vector<std::function<void()>>& tasks, int jobs) {
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (size_t i = next++; i < tasks.size() && !failed; i = next++) {
      try {
        tasks[i]();
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace

CompareResult runCompare(const Benchmark& benchmark, const CompareOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CompareResult result;
  std::vector<batch::BatchContext> contexts;
  for (const Experiment& e : benchmark.experiments) {
    contexts.push_back(scenarioContext(e.scenario_path, benchmark.controllers, benchmark.seed));
    const mission::Scenario& s = contexts.back().scenario;
    result.experiments.push_back({s.name, s.description, e.scenario_path, s.seed});
    if (result.vehicle_path.empty()) result.vehicle_path = s.vehicle_path;
  }
  const size_t controllers = benchmark.controllers.size();
  result.flights.resize(contexts.size() * controllers);

  std::mutex print_mutex;
  int landed = 0;
  const size_t total = result.flights.size();
  auto say = [&](const std::string& line, int flights, double simulated_s) {
    const std::lock_guard<std::mutex> lock(print_mutex);
    result.flown += flights;
    result.simulated_s += simulated_s;
    if (options.progress) std::fprintf(options.progress, "compare: %s\n", line.c_str());
  };

  std::vector<std::function<void()>> tasks;
  batch::BatchContext sweep_context;
  if (benchmark.has_sweep) {
    sweep_context = scenarioContext(benchmark.sweep.scenario_path, benchmark.controllers, benchmark.seed);
    const mission::Scenario& s = sweep_context.scenario;
    result.sweep = {s.name, s.description, benchmark.sweep.scenario_path, s.seed};
    result.vehicle_path = s.vehicle_path;
    for (const std::string& key : benchmark.sweep.fail_on) result.sweep_limits.push_back(s.criteria.at(key));
    result.refusals = sweepRefusals(sweep_context, benchmark.sweep.speeds);
    result.sweep_seeds = sweepSeeds(benchmark, s);
    result.sweeps.resize(controllers);
    // The sweeps first: each is several flights in a row, the longest tasks.
    for (size_t c = 0; c < controllers; ++c) {
      tasks.push_back([&, c] {
        const std::string& controller = benchmark.controllers[c];
        result.sweeps[c] = flySweep(sweep_context, benchmark.sweep, result.sweep_seeds, result.refusals, controller,
                                    [&](const SweepFlight& f) {
          const std::string what = !f.feasible ? "beyond the vehicle, not flown"
                                   : (f.pass ? "pass" : "FAIL") + std::string(" (path error RMS ") +
                                         number(f.path_error_rms) + " m, max " + number(f.path_error_max) + " m)";
          say(std::string(kSweepName) + " " + controller + " at " + number(f.speed) + " m/s: " + what, f.flights,
              f.simulated_s);
        });
      });
    }
  }
  for (size_t e = 0; e < contexts.size(); ++e) {
    for (size_t c = 0; c < controllers; ++c) {
      tasks.push_back([&, e, c] {
        ExperimentFlight& slot = result.flights[e * controllers + c];
        slot = flyExperiment(contexts[e], benchmark.controllers[c]);
        int number_landed = 0;
        {
          const std::lock_guard<std::mutex> lock(print_mutex);
          number_landed = ++landed;
        }
        say("[" + std::to_string(number_landed) + "/" + std::to_string(total) + "] " + slot.experiment + " " +
                slot.controller + ": " + (slot.report.passed() ? "pass" : "FAIL") + ", " + checksText(slot.report),
            1, slot.simulated_s);
      });
    }
  }
  runTasks(tasks, std::max(1, options.jobs));
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace sdlqr::compare
