#include "sdlqr/trajectory/trajectory_csv.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>
#include <vector>

#include "text_fields.hpp"

namespace sdlqr::trajectory {

namespace {

const char* const kColumnNames[kCsvColumns] = {"t",  "px", "py", "pz", "qw", "qx", "qy", "qz",
                                               "vx", "vy", "vz", "wx", "wy", "wz", "c"};

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(detail::trimBlanks(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

// "# key: value" comment lines that set a Trajectory flag; other comments are ignored.
void readDirective(const std::string& comment, const std::string& name, int line, Trajectory& out) {
  const std::string body = detail::trimBlanks(comment.substr(1));
  const auto colon = body.find(':');
  if (colon == std::string::npos) return;
  const std::string key = detail::trimBlanks(body.substr(0, colon));
  const std::string value = detail::trimBlanks(body.substr(colon + 1));
  if (key == "closed") {
    if (value == "true") out.closed = true;
    else if (value == "false") out.closed = false;
    else throw TrajectoryFileError(name, line, "closed: expected true or false, got '" + value + "'");
  } else if (key == "tracking") {
    if (value == "spatial") out.tracking = ReferenceMode::kSpatial;
    else if (value == "temporal") out.tracking = ReferenceMode::kTemporal;
    else throw TrajectoryFileError(name, line, "tracking: expected spatial or temporal, got '" + value + "'");
  }
}

double parseNumber(const std::string& field, int column, const std::string& name, int line) {
  const std::string column_name = kColumnNames[column];
  if (field.empty()) throw TrajectoryFileError(name, line, "column " + column_name + ": empty");
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (*end != '\0') {
    throw TrajectoryFileError(name, line, "column " + column_name + ": cannot parse '" + field + "'");
  }
  if (!std::isfinite(value)) throw TrajectoryFileError(name, line, "column " + column_name + ": not finite");
  return value;
}

TrajectorySample sampleFromFields(const std::vector<std::string>& fields, const std::string& name, int line) {
  double v[kCsvColumns];
  for (int c = 0; c < kCsvColumns; ++c) v[c] = parseNumber(fields[c], c, name, line);
  TrajectorySample s;
  s.t = v[0];
  s.x = makeState(Vec3(v[1], v[2], v[3]), Quat(v[4], v[5], v[6], v[7]), Vec3(v[8], v[9], v[10]));
  s.u = makeInput(Vec3(v[11], v[12], v[13]), v[14]);
  return s;
}

}  // namespace

Trajectory parseTrajectoryCsv(std::istream& in, const std::string& name, const SampleChecks& checks) {
  Trajectory out;
  std::string text;
  int line = 0;
  int last_sample_line = 0;
  bool header_allowed = true;
  while (std::getline(in, text)) {
    ++line;
    const std::string trimmed = detail::trimBlanks(text);
    if (trimmed.empty()) continue;
    if (trimmed[0] == '#') {
      readDirective(trimmed, name, line, out);
      continue;
    }
    const std::vector<std::string> fields = splitFields(trimmed);
    if (header_allowed && fields[0] == kColumnNames[0]) {
      bool same = static_cast<int>(fields.size()) == kCsvColumns;
      for (int c = 0; same && c < kCsvColumns; ++c) same = fields[c] == kColumnNames[c];
      if (!same) throw TrajectoryFileError(name, line, std::string("header must be ") + kCsvHeader);
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (static_cast<int>(fields.size()) != kCsvColumns) {
      throw TrajectoryFileError(name, line, "expected " + std::to_string(kCsvColumns) + " columns, got " +
                                                std::to_string(fields.size()));
    }
    const TrajectorySample sample = sampleFromFields(fields, name, line);
    const TrajectorySample* previous = out.samples.empty() ? nullptr : &out.samples.back();
    const std::string why = checkSample(sample, previous, checks);
    if (!why.empty()) throw TrajectoryFileError(name, line, why);
    out.samples.push_back(sample);
    last_sample_line = line;
  }
  if (in.bad()) throw TrajectoryFileError(name, line, "read error");
  const std::string why = checkClosure(out, checks);
  if (!why.empty()) throw TrajectoryFileError(name, last_sample_line > 0 ? last_sample_line : line, why);
  return out;
}

Trajectory readTrajectoryCsv(const std::string& path, const SampleChecks& checks) {
  std::ifstream file(path);
  if (!file) throw TrajectoryFileError(path, 0, "cannot open file");
  return parseTrajectoryCsv(file, path, checks);
}

void writeTrajectoryCsv(std::ostream& out, const Trajectory& trajectory) {
  out << "# sdlqr trajectory: one sample per line\n"
      << "# t [s]; p [m] world; q [-] w,x,y,z body to world; v [m/s] world; w [rad/s] body; c [m/s^2]\n"
      << "# closed: " << (trajectory.closed ? "true" : "false") << "\n"
      << "# tracking: " << (trajectory.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial") << "\n"
      << kCsvHeader << "\n";
  char buffer[32];
  for (const TrajectorySample& s : trajectory.samples) {
    double v[kCsvColumns];
    v[0] = s.t;
    for (int i = 0; i < kStateDim; ++i) v[1 + i] = s.x[i];
    for (int i = 0; i < kInputDim; ++i) v[1 + kStateDim + i] = s.u[i];
    for (int c = 0; c < kCsvColumns; ++c) {
      std::snprintf(buffer, sizeof(buffer), "%.17g", v[c]);
      out << (c > 0 ? "," : "") << buffer;
    }
    out << "\n";
  }
}

void writeTrajectoryCsv(const std::string& path, const Trajectory& trajectory) {
  std::ofstream file(path);
  if (!file) throw TrajectoryFileError(path, 0, "cannot open for writing");
  writeTrajectoryCsv(file, trajectory);
  file.flush();
  if (!file) throw TrajectoryFileError(path, 0, "write failed");
}

}  // namespace sdlqr::trajectory
