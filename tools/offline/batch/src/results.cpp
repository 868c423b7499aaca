#include "sdlqr/batch/results.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "sdlqr/tables/csv.hpp"

#include "file_text.hpp"

namespace sdlqr::batch {

void makeDirectories(const std::string& dir) {
  for (size_t slash = dir.find('/', 1);; slash = dir.find('/', slash + 1)) {
    const std::string prefix = dir.substr(0, slash);
    if (::mkdir(prefix.c_str(), 0755) != 0 && errno != EEXIST) {
      throw std::runtime_error(prefix + ": cannot create folder: " + std::strerror(errno));
    }
    if (slash == std::string::npos) return;
  }
}

namespace {

std::string headerLine(const std::vector<std::string>& header) {
  std::ostringstream text;
  tables::CsvWriter csv(text);
  for (const std::string& h : header) csv.name(h);
  csv.endRow();
  return text.str();
}

std::string rowLine(const std::vector<std::string>& cells) { return headerLine(cells); }

std::vector<std::vector<std::string>> records(const std::string& text, const std::string& path, bool drop_cut_tail) {
  std::istringstream in(text);
  std::vector<std::vector<std::string>> out;
  std::vector<std::string> cells;
  std::string error;
  while (tables::readCsvRecord(in, &cells, &error)) out.push_back(cells);
  if (!error.empty() && !drop_cut_tail) throw std::runtime_error(path + ": " + error);
  return out;
}

// "key: value" lines of batch.yaml.
std::map<std::string, std::string> batchInfo(const std::string& dir) {
  const YAML::Node node = loadYamlFile(dir + "/batch.yaml");
  std::map<std::string, std::string> out;
  for (const auto& item : node) out[item.first.Scalar()] = item.second.Scalar();
  return out;
}

std::string batchInfoText(const BatchContext& context, const Shard& shard) {
  std::ostringstream text;
  text << "# sdlqr-batch folder: what was flown here (a run continues only the same batch)\n"
       << "fingerprint: \"" << context.spec.fingerprint << "\"  # of the batch file, scenario and vehicle file texts\n"
       << "spec: \"" << context.spec.path << "\"\n"
       << "scenario: \"" << context.scenario.name << "\"\n"
       << "flights: " << context.spec.flights << "\n"
       << "controllers: \"";
  for (size_t i = 0; i < context.spec.controllers.size(); ++i) text << (i ? "," : "") << context.spec.controllers[i];
  text << "\"\nshard: \"" << shard.text() << "\"\n";
  return text.str();
}

}  // namespace

void writeText(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw std::runtime_error(temporary + ": cannot write");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) throw std::runtime_error(path + ": cannot replace");
}

Shard Shard::parse(const std::string& text) {
  Shard s;
  char slash = 0;
  std::istringstream in(text);
  if (!(in >> s.index >> slash >> s.count) || slash != '/' || !in.eof() || s.count < 1 || s.index < 1 ||
      s.index > s.count) {
    throw ConfigError("--shard", "expected I/N with 1 <= I <= N, got '" + text + "'");
  }
  return s;
}

int Table::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

void sortRows(Table& table, const std::vector<std::string>& controllers) {
  auto order = [&](const std::vector<std::string>& r) {
    const long long flight = std::stoll(r.at(0));
    const auto c = std::find(controllers.begin(), controllers.end(), r.at(1));
    return std::make_pair(flight, c - controllers.begin());
  };
  std::stable_sort(table.rows.begin(), table.rows.end(), [&](const auto& a, const auto& b) { return order(a) < order(b); });
}

void writeTable(const Table& table, const std::string& path) {
  std::string text = headerLine(table.header);
  for (const auto& r : table.rows) text += rowLine(r);
  writeText(path, text);
}

Table readTable(const std::string& path) {
  if (!detail::exists(path)) throw std::runtime_error(path + ": no such file");
  auto rows = records(detail::fileText(path), path, false);
  if (rows.empty()) throw std::runtime_error(path + ": empty (no header)");
  Table t;
  t.header = rows.front();
  t.rows.assign(rows.begin() + 1, rows.end());
  return t;
}

void checkBatchFolder(const std::string& dir, const BatchContext& context, const Shard& shard) {
  if (!detail::exists(dir + "/batch.yaml")) return;
  const auto info = batchInfo(dir);
  if (info.count("fingerprint") == 0 || info.at("fingerprint") != context.spec.fingerprint) {
    throw std::runtime_error(dir + ": holds another batch (another batch file, scenario or vehicle file): choose another --out");
  }
  if (info.count("shard") == 0 || info.at("shard") != shard.text()) {
    throw std::runtime_error(dir + ": holds shard " + (info.count("shard") ? info.at("shard") : "?") +
                             " of this batch, not " + shard.text() + ": choose another --out");
  }
}

Journal::Journal(const std::string& dir, const BatchContext& context, const Shard& shard)
    : path_(dir + "/flights.partial.csv"), header_(header(context)) {
  makeDirectories(dir);
  checkBatchFolder(dir, context, shard);
  writeBatchInfo(dir, context, shard);
  // Rows that landed whole; a row a kill cut short (no line end, or fewer cells) is dropped.
  const std::string old = detail::exists(path_) ? detail::fileText(path_) : std::string();
  std::string kept = headerLine(header_);
  if (!old.empty()) {
    const size_t end = old.rfind('\n');
    const auto rows = records(end == std::string::npos ? std::string() : old.substr(0, end + 1), path_, true);
    if (!rows.empty() && rows.front() != header_) {
      throw std::runtime_error(path_ + ": columns differ from this batch's: choose another --out");
    }
    for (size_t i = 1; i < rows.size(); ++i) {
      if (rows[i].size() != header_.size()) continue;
      if (!done_.insert({std::stoi(rows[i][0]), rows[i][1]}).second) continue;
      text_ += rowLine(rows[i]);
    }
  }
  writeText(path_, kept + text_);
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND);
  if (fd_ < 0) throw std::runtime_error(path_ + ": cannot open: " + std::strerror(errno));
}

bool Journal::done(int flight, const std::string& controller) const { return done_.count({flight, controller}) > 0; }

void Journal::append(const std::string& row) {
  // One write per row: a kill leaves whole rows and at most one cut short.
  for (size_t written = 0; written < row.size();) {
    const ssize_t n = ::write(fd_, row.data() + written, row.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(path_ + ": cannot write: " + std::strerror(errno));
    written += static_cast<size_t>(n);
  }
  text_ += row;
}

Table Journal::table() const {
  Table t;
  t.header = header_;
  t.rows = records(text_, path_, false);
  return t;
}

void writeBatchInfo(const std::string& dir, const BatchContext& context, const Shard& shard) {
  writeText(dir + "/batch.yaml", batchInfoText(context, shard));
}

Table mergeShards(const std::vector<std::string>& shard_dirs, const std::string& out_dir, const BatchContext& context) {
  if (shard_dirs.empty()) throw std::runtime_error("batch-merge: no shard folders given");
  Table merged;
  merged.header = header(context);
  std::set<int> indices;
  int count = 0;
  for (const std::string& dir : shard_dirs) {
    if (!detail::exists(dir + "/batch.yaml")) throw std::runtime_error(dir + ": not a batch folder (no batch.yaml)");
    const auto info = batchInfo(dir);
    if (info.count("fingerprint") == 0 || info.at("fingerprint") != context.spec.fingerprint) {
      throw std::runtime_error(dir + ": another batch (its fingerprint differs from " + context.spec.path + ")");
    }
    const Shard shard = Shard::parse(info.count("shard") ? info.at("shard") : "");
    if (count != 0 && shard.count != count) throw std::runtime_error(dir + ": shard " + shard.text() + " of another split");
    count = shard.count;
    if (!indices.insert(shard.index).second) throw std::runtime_error(dir + ": shard " + shard.text() + " given twice");
    if (!detail::exists(dir + "/flights.csv")) throw std::runtime_error(dir + ": shard " + shard.text() + " unfinished (no flights.csv; run it again to finish)");
    const Table t = readTable(dir + "/flights.csv");
    if (t.header != merged.header) throw std::runtime_error(dir + "/flights.csv: columns differ from this batch's");
    merged.rows.insert(merged.rows.end(), t.rows.begin(), t.rows.end());
  }
  for (int i = 1; i <= count; ++i) {
    if (!indices.count(i)) throw std::runtime_error("batch-merge: shard " + std::to_string(i) + "/" + std::to_string(count) + " missing");
  }
  sortRows(merged, context.spec.controllers);
  const size_t expected = static_cast<size_t>(context.spec.flights) * context.spec.controllers.size();
  if (merged.rows.size() != expected) {
    throw std::runtime_error("batch-merge: " + std::to_string(merged.rows.size()) + " rows, expected " + std::to_string(expected));
  }
  makeDirectories(out_dir);
  writeBatchInfo(out_dir, context, Shard{});
  writeTable(merged, out_dir + "/flights.csv");
  return merged;
}

}  // namespace sdlqr::batch
