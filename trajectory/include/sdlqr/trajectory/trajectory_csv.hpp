#pragma once
// Sampled trajectories as CSV text.
//
// One sample per line, 15 comma-separated numbers:
//   t [s] from the start, strictly increasing
//   px, py, pz [m] world position
//   qw, qx, qy, qz [-] Hamilton quaternion body to world, unit
//   vx, vy, vz [m/s] world velocity
//   wx, wy, wz [rad/s] feed-forward body rates
//   c [m/s^2] feed-forward mass-normalized collective thrust, >= 0
// Lines starting with '#' are comments; blank lines are skipped. An optional header row
// "t,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,c" may precede the first sample. Two comment lines
// carry the Trajectory flags: "# closed: true|false" (closed: one lap, the last sample back at the
// first position) and "# tracking: spatial|temporal".
//
// Reading never crashes on bad text: a wrong column count, an unparsable or non-finite number, a
// time not increasing, a quaternion far from unit, a position jump beyond the limit, a negative
// thrust or fewer than 2 samples throws TrajectoryFileError "file.csv:17: time not increasing".
// The writer prints every double with 17 significant digits, so write then read is exact.

#include <iosfwd>
#include <stdexcept>
#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/validation.hpp"

namespace sdlqr::trajectory {

inline constexpr const char* kCsvHeader = "t,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,c";
inline constexpr int kCsvColumns = 15;

// A std::invalid_argument, so runMain turns it into one line and exit code 2.
class TrajectoryFileError : public std::invalid_argument {
 public:
  // line 0: the file as a whole (cannot open it).
  TrajectoryFileError(const std::string& name, int line, const std::string& reason)
      : std::invalid_argument(name + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + reason),
        line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

// `name` only labels the errors.
Trajectory parseTrajectoryCsv(std::istream& in, const std::string& name, const SampleChecks& checks = {});
Trajectory readTrajectoryCsv(const std::string& path, const SampleChecks& checks = {});

void writeTrajectoryCsv(std::ostream& out, const Trajectory& trajectory);
// Throws TrajectoryFileError when the file cannot be written.
void writeTrajectoryCsv(const std::string& path, const Trajectory& trajectory);

}  // namespace sdlqr::trajectory
