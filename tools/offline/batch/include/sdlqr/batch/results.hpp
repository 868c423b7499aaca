#pragma once
// What a batch folder holds, and how a run continues and shards join:
//
//   batch.yaml           what was flown: the spec's fingerprint, flights, controllers, shard
//   flights.partial.csv  the journal: the header, then each flight's row as soon as it landed
//                        (flushed; a row cut short by a kill is dropped when the run resumes)
//   flights.csv          every row, sorted by flight then controller; written once all are flown
//   summary.txt          success rates with Wilson intervals, the worst flights and how to re-fly them
//
// A run in a folder that holds the same batch continues it (no finished flight is flown again); a
// folder that holds another batch (another fingerprint or shard) is refused.

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sdlqr/batch/flight.hpp"

namespace sdlqr::batch {

struct Shard {
  int index = 1;  // 1-based
  int count = 1;
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
  // "I/N" with 1 <= I <= N; throws ConfigError naming --shard.
  static Shard parse(const std::string& text);
};

// mkdir -p; throws std::runtime_error naming the folder.
void makeDirectories(const std::string& dir);
// Writes a file atomically (a temporary file renamed over it); throws std::runtime_error naming it.
void writeText(const std::string& path, const std::string& text);

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const;  // -1 when absent
};

// Rows sorted by flight (numerically), then by the controllers' order in `controllers`.
void sortRows(Table& table, const std::vector<std::string>& controllers);
void writeTable(const Table& table, const std::string& path);  // atomically (temporary file + rename)
Table readTable(const std::string& path);                      // throws std::runtime_error naming the file

// Refuses (std::runtime_error naming the folder) a folder that holds another batch, or another
// shard of this one; a folder without batch.yaml passes.
void checkBatchFolder(const std::string& dir, const BatchContext& context, const Shard& shard);

// The journal of a folder: opens (creating the folder) or continues it.
class Journal {
 public:
  Journal(const std::string& dir, const BatchContext& context, const Shard& shard);
  // Flight/controller pairs already flown.
  bool done(int flight, const std::string& controller) const;
  size_t doneCount() const { return done_.size(); }
  void append(const std::string& row);  // one CSV row, '\n' included; flushed
  // The journal as a table (every row flown so far).
  Table table() const;

 private:
  std::string path_;
  std::set<std::pair<int, std::string>> done_;
  std::vector<std::string> header_;
  std::string text_;  // the rows, in landing order
  int fd_ = -1;
};

void writeBatchInfo(const std::string& dir, const BatchContext& context, const Shard& shard);

// Joins complete shard folders of one batch into `out_dir` (flights.csv, batch.yaml; the
// summary is the caller's). Throws std::runtime_error naming the folder and what is wrong: another
// batch, a shard missing or given twice, an unfinished shard.
Table mergeShards(const std::vector<std::string>& shard_dirs, const std::string& out_dir, const BatchContext& context);

}  // namespace sdlqr::batch
