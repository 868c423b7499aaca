#pragma once
// Waypoints for generateMinSnap from a file.
//
// YAML:
//   waypoints:          # [m] x, y, z, and optionally yaw [rad] as a 4th value (on all or none)
//     - [0.0, -1.2, 1.0]
//     - [1.5, 0.0, 1.5]
//   periodic: false     # [-] true: one closed C^4 lap (do not repeat the first waypoint)
//   v_max: 2.0          # [m/s] optional
// CSV: one waypoint per line, "x,y,z" or "x,y,z,yaw"; '#' comments, blank lines skipped, an
// optional header row starting with "x".
// Errors name the key ("waypoints[2]: expected 3 or 4 numbers") or the line ("w.csv:4: ...").

#include <iosfwd>
#include <string>
#include <vector>

#include "sdlqr/config/config.hpp"
#include "sdlqr/trajectory/min_snap.hpp"

namespace sdlqr::trajectory {

struct WaypointSpec {
  std::vector<Waypoint> waypoints;
  bool periodic = false;
  double v_max = 0.0;  // [m/s] 0: not given
};

// Throws ConfigError.
WaypointSpec loadWaypointSpec(const ConfigReader& root, const YAML::Node& node);
WaypointSpec loadWaypointYaml(const std::string& path);
// Throws TrajectoryFileError.
std::vector<Waypoint> parseWaypointCsv(std::istream& in, const std::string& name);
std::vector<Waypoint> readWaypointCsv(const std::string& path);

}  // namespace sdlqr::trajectory
