#include "sdlqr/params/vehicle_file.hpp"

#include <sstream>
#include <type_traits>

namespace sdlqr::params {

VehicleFile VehicleFile::load(const std::string& path) {
  const ConfigReader root = loadVehicleConfig(path);
  VehicleFile file;
  forEachSection(file, [&](const char* name, auto& section) {
    section = std::decay_t<decltype(section)>::load(root.child(name));
  });
  file.lqr.vehicle_rotor_drag = file.vehicle.rotor_drag;
  throwIfInvalid(root.child("lqr"), lqrLimitsInvalidReason(file.lqr, file.validation));
  const ConfigReader lowlevel = root.child("lowlevel");
  throwIfInvalid(lowlevel, file.lowlevel.invalidReasonFor(file.vehicle, file.lqr.gravity));
  throwIfInvalid(lowlevel, file.lowlevel.invalidReasonFor(file.validation));
  return file;
}

std::vector<PrintedSection> VehicleFile::sections() const {
  std::vector<PrintedSection> out;
  forEachSection(*this, [&](const char* name, const auto& section) { out.push_back(printedSection(name, section)); });
  return out;
}

std::vector<std::pair<std::string, const ParamSection*>> declarations() {
  VehicleFile file;
  std::vector<std::pair<std::string, const ParamSection*>> out;
  forEachSection(file, [&](const char* name, auto& section) {
    out.emplace_back(name, &std::decay_t<decltype(section)>::declaration());
  });
  return out;
}

std::string defaultVehicleFileText() {
  static const VehicleFile defaults;
  std::ostringstream out;
  printSections(out,
                {"sdlqr vehicle file: the paper's 255 g, 250 mm quadrotor (§III-A) and the settings of every process.",
                 "Printed from the parameter declarations by `sdlqr-params --defaults`: every value is the built-in",
                 "default, so change a default in its declaration (the struct's declaration() in its .cpp), not",
                 "here. For another vehicle copy this file and edit the copy; every key is optional. Each process",
                 "reads the sections it needs (`<process> --print-config` shows them); an unknown key or a bad",
                 "value stops it with a one-line error naming the key (exit code 2).",
                 "Each key: value  # [unit] meaning. A key printed commented out follows from others unless given."},
                defaults.sections());
  return out.str();
}

std::string firstDifference(const std::string& expected, const std::string& actual) {
  std::istringstream a(expected), b(actual);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a && !more_b) return {};
    if (more_a != more_b || line_a != line_b) {
      return "line " + std::to_string(line) + ": expected " + (more_a ? "'" + line_a + "'" : "the end") + ", found " +
             (more_b ? "'" + line_b + "'" : "the end");
    }
  }
}

}  // namespace sdlqr::params
