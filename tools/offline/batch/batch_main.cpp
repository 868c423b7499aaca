// sdlqr-batch: Monte Carlo batches of whole flights on the in-process closed loop (docs/batches.md, Batches).
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "sdlqr/batch/runner.hpp"
#include "sdlqr/batch/slurm_submit.hpp"
#include "sdlqr/batch/summary.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/tables/csv.hpp"

namespace sdlqr::batch {
namespace {

constexpr const char* kProgram = "sdlqr-batch";

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out.flush()) throw std::runtime_error(path + ": cannot write");
}

int listParameters() {
  const closedloop::StackConfig nominal;
  std::cout << "# perturbable parameters (the simulator's plant and the scenario's disturbances): key [unit] range, nominal\n";
  for (const PlantParameter& p : listPlantParameters()) {
    std::cout << p.key << (p.info.kind == ParamKind::kList ? "[i]" : "") << "  [" << p.info.unit << "]  "
              << p.info.range.rule(p.info.unit) << ", nominal " << p.info.default_text << "  " << p.info.help << "\n";
  }
  std::cout << "# batch file keys\n";
  for (const KeyHelp& k : specKeys()) std::cout << k.key << ": " << k.help << "\n";
  std::cout << "# distributions\n";
  for (const KeyHelp& k : distributionKeys()) std::cout << k.key << ": " << k.help << "\n";
  return 0;
}

// Writes the flight's files, flies them in-process and compares the row with the batch's.
int refly(const BatchContext& context, int flight, const std::string& controller, const std::string& out_dir,
          const std::string& batch_dir) {
  if (flight < 0 || flight >= context.spec.flights) {
    throw ConfigError("--refly", "flight " + std::to_string(flight) + " not in 0.." + std::to_string(context.spec.flights - 1));
  }
  makeDirectories(out_dir);
  const FlightDraw draw = drawFlight(context.spec, context.config, context.scenario.sim, flight);
  writeFlightFiles(context, draw, controller, out_dir);
  const FlownFlight flown = fly(context, loadFlightFiles(out_dir), controller);
  const std::string line = row(context, draw, controller, flown.report);
  writeFile(out_dir + "/row.csv", line);
  std::ofstream report(out_dir + "/report.txt");
  analysis::writeSummary(flown.report, report);
  std::ofstream truth(out_dir + "/truth.csv");
  truth << "t,x,y,z\n";
  for (const SimTruth& s : flown.log.sim_truth.messages) {
    truth << 1e-6 * static_cast<double>(s.utime) << "," << s.position.x() << "," << s.position.y() << ","
          << s.position.z() << "\n";
  }
  std::cout << "flight " << flight << " (" << controller << ", seed " << draw.seed << "): "
            << (flown.report.passed() ? "passed" : "FAILED") << "; files in " << out_dir
            << " (scenario.yaml, plant.yaml, report.txt, truth.csv, row.csv)\n"
            << "over the bus with a log: ./sdlqr run " << out_dir << "/scenario.yaml --plant-config " << out_dir
            << "/plant.yaml\n";
  if (batch_dir.empty()) return 0;
  const Table batch = readTable(batch_dir + "/flights.csv");
  for (const auto& r : batch.rows) {
    if (r[0] != std::to_string(flight) || r[1] != controller) continue;
    std::string batch_line;
    {
      std::ostringstream text;
      tables::CsvWriter csv(text);
      for (const std::string& cell : r) csv.name(cell);
      csv.endRow();
      batch_line = text.str();
    }
    const bool same = batch_line == line;
    std::cout << (same ? "the same row as in " : "DIFFERS from the row in ") << batch_dir << "/flights.csv\n";
    return same ? 0 : 1;
  }
  throw std::runtime_error(batch_dir + "/flights.csv: no row of flight " + std::to_string(flight) + " " + controller);
}

struct SlurmChoice {
  bool slurm = false, no_wait = false, dry_run = false;
  int tasks = 0, nodes = 0, cpus_per_task = 0;
  std::string partition;
};

SlurmOptions slurmOptionsOf(const SlurmChoice& c) {
  if (c.tasks > 0 && c.nodes > 0) throw ConfigError("--nodes", "give --nodes N (whole nodes) or --tasks N, not both");
  if (c.tasks <= 0 && c.nodes <= 0) throw ConfigError("--tasks", "--slurm needs --tasks N or --nodes N");
  if (c.nodes > 0 && c.cpus_per_task > 0) throw ConfigError("--cpus-per-task", "a task of --nodes has every core of its node");
  SlurmOptions o;
  o.tasks = c.nodes > 0 ? c.nodes : c.tasks;
  o.cpus_per_task = c.nodes > 0 ? 0 : std::max(1, c.cpus_per_task);
  o.partition = c.partition;
  return o;
}

// Submits the batch as a job array; waits and merges unless told not to. Returns the merged
// table, or nothing when it only printed the script or submitted.
std::optional<Table> runOnSlurm(const BatchContext& context, const std::string& spec_path, const std::string& out_dir,
                                const SlurmChoice& choice) {
  const SlurmJob job = slurmJobFor(context, spec_path, out_dir, slurmOptionsOf(choice));
  if (choice.dry_run) {
    std::cout << sbatchScript(job);
    return std::nullopt;
  }
  const std::string id = submitSlurmBatch(context, job);
  std::string collect = "./sdlqr batch-merge " + spec_path + " --out " + out_dir;
  for (int task = 1; task <= job.options.tasks; ++task) collect += " " + shardDir(out_dir, task);
  std::cerr << "slurm job " << id << ": " << job.options.tasks << " array tasks, script " << slurmDir(job.out_dir)
            << "/job.sh, task logs " << slurmDir(job.out_dir) << "/task-I.out\n";
  if (choice.no_wait) {
    std::cout << id << "\n";
    std::cerr << "when every task is done, collect with: " << collect << "\n";
    return std::nullopt;
  }
  std::cerr << "waiting (interrupted, the job runs on; collect then with: " << collect << ")\n";
  Table table = waitAndMerge(context, job, id, ::isatty(STDERR_FILENO) != 0);
  std::cerr << "batch-merge: " << job.options.tasks << " shards, " << table.rows.size() << " rows -> " << out_dir
            << "/flights.csv\n";
  return table;
}

int run(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string out_dir, shard_text = "1/1", controller, batch_dir;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int refly_flight = -1;
  bool no_progress = false, list = false;
  ArgParser parser(kProgram, "Monte Carlo batches of whole flights on the in-process closed loop.");
  parser.allowPositional(&positional, "SPEC.yaml | merge SPEC.yaml SHARD_DIR...");
  parser.addOption("--out", &out_dir, "DIR", "batch folder (continued when it holds part of the same batch)");
  parser.addOption("--jobs", &jobs, "N", "flights flown at once (default: every core)", Range::atLeast(1));
  parser.addOption("--shard", &shard_text, "I/N", "fly only flights k with k mod N = I - 1 (join with merge)");
  parser.addFlag("--no-progress", &no_progress, "no progress line");
  parser.addOption("--refly", &refly_flight, "K", "write flight K's files into --out and fly it alone");
  parser.addOption("--controller", &controller, "NAME", "with --refly: the controller (default: the first)");
  parser.addOption("--batch", &batch_dir, "DIR", "with --refly: check the row equals this batch's");
  parser.addFlag("--list-parameters", &list, "the keys a batch file may perturb, and its own keys");
  SlurmChoice slurm;
  parser.addFlag("--slurm", &slurm.slurm, "submit as a Slurm job array (one shard per task), wait, requeue, merge");
  parser.addOption("--tasks", &slurm.tasks, "N", "with --slurm: N array tasks of --cpus-per-task cores each",
                   Range::atLeast(1));
  parser.addOption("--cpus-per-task", &slurm.cpus_per_task, "C", "with --tasks: cores per task (default 1)",
                   Range::atLeast(1));
  parser.addOption("--nodes", &slurm.nodes, "N", "with --slurm: N array tasks, each a whole node (every core)",
                   Range::atLeast(1));
  parser.addOption("--partition", &slurm.partition, "P", "with --slurm: the partition (default: the cluster's)");
  parser.addFlag("--no-wait", &slurm.no_wait, "with --slurm: print the job id and return (collect with merge)");
  parser.addFlag("--dry-run", &slurm.dry_run, "with --slurm: print the sbatch script, submit nothing");
  parser.setEpilog(
      "Files: DIR/flights.csv (one row per flight), DIR/summary.txt, DIR/batch.yaml, DIR/flights.partial.csv\n"
      "(the journal a resumed run continues); with --slurm also DIR/slurm/ (job.sh, job_id, shard-I/, task-I.out).\n"
      "Exit codes: 0 done, 2 bad batch file or option, 1 other errors (a task that failed twice).");
  parser.parseOrExit(argc, argv);
  if (list) return listParameters();
  const bool merge = !positional.empty() && positional[0] == "merge";
  if (merge) positional.erase(positional.begin());
  if (positional.empty()) throw ConfigError("SPEC", "name a batch file (see --help)");
  if (out_dir.empty()) throw ConfigError("--out", "name the batch folder");
  if (!merge && positional.size() != 1) throw ConfigError("SPEC", "one batch file, got " + std::to_string(positional.size()));
  const BatchContext context = BatchContext::load(positional[0]);

  if (refly_flight >= 0) return refly(context, refly_flight, controller.empty() ? context.spec.controllers[0] : controller, out_dir, batch_dir);
  if ((slurm.no_wait || slurm.dry_run || slurm.tasks || slurm.nodes) && !slurm.slurm) {
    throw ConfigError("--slurm", "--tasks, --nodes, --no-wait and --dry-run go with --slurm");
  }
  Table table;
  if (slurm.slurm) {
    if (merge || shard_text != "1/1") throw ConfigError("--slurm", "makes its own shards: no --shard, no merge");
    std::optional<Table> merged = runOnSlurm(context, positional[0], out_dir, slurm);
    if (!merged) return 0;
    table = std::move(*merged);
  } else if (merge) {
    table = mergeShards({positional.begin() + 1, positional.end()}, out_dir, context);
    std::cerr << "batch-merge: " << positional.size() - 1 << " shards, " << table.rows.size() << " rows -> " << out_dir << "/flights.csv\n";
  } else {
    RunOptions options;
    options.out_dir = out_dir;
    options.jobs = jobs;
    options.shard = Shard::parse(shard_text);
    options.terminal = ::isatty(STDERR_FILENO) != 0;
    options.progress = !no_progress;
    const RunResult result = runBatch(context, options);
    table = result.table;
    std::cerr << "batch: flew " << result.flown << ", resumed " << result.resumed << " from the journal; "
              << result.simulated_s << " s simulated in " << result.wall_s << " s on " << jobs << " jobs ("
              << (result.wall_s > 0 ? result.simulated_s / result.wall_s : 0.0) << " simulated s per wall s)\n";
  }
  const std::string summary = summaryText(context, table);
  writeFile(out_dir + "/summary.txt", summary);
  std::cout << summary;
  return 0;
}

}  // namespace
}  // namespace sdlqr::batch

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-batch", [&] { return sdlqr::batch::run(argc, argv); });
}
