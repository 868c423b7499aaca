// libFuzzer harness of the vehicle file as every process reads it: YAML text, the top-level
// mapping check and section allow-list of loadVehicleConfig, then each section's load(). Beyond
// ASan/UBSan findings it checks the contract of the loaders: they either return parameters that
// pass their own valid(), or throw ConfigError / std::invalid_argument (the one-line error and
// exit code 2 of runMain); any other exception would end a process with exit code 1 instead.

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "sdlqr/config/config.hpp"
#include "sdlqr/params/vehicle_file.hpp"

namespace {

using namespace sdlqr;

template <class Params>
void loadSection(const ConfigReader& root, const char* section) {
  try {
    const Params params = Params::load(root.child(section));
    if (!params.valid()) std::abort();  // load() returned parameters its own check refuses
  } catch (const ConfigError&) {
  } catch (const std::invalid_argument&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const YAML::Exception&) {
    return 0;  // loadYamlFile turns these into a ConfigError
  }
  if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  if (!root.IsMap()) return 0;
  try {
    const ConfigReader config(root, "");
    config.allowOnly(vehicleFileSections());
    // Every section of the vehicle file (the one list in params::forEachSection), each on its own.
    params::VehicleFile file;
    params::forEachSection(file, [&](const char* name, auto& section) {
      loadSection<std::decay_t<decltype(section)>>(config, name);
    });
  } catch (const ConfigError&) {
  }
  return 0;
}
