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

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/lowlevel/lowlevel_params.hpp"
#include "sdlqr/sim/sim_params.hpp"
#include "sdlqr/trajectory/params.hpp"

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
    config.allowOnly({"vehicle", "lqr", "sim", "estimator", "lowlevel", "controller", "gains", "logger", "mission",
                      "trajectory", "faults"});
    loadSection<VehicleParams>(config, "vehicle");
    loadSection<LqrParams>(config, "lqr");
    loadSection<FaultParams>(config, "faults");
    loadSection<controller::ControllerParams>(config, "controller");
    loadSection<gains::GainsParams>(config, "gains");
    loadSection<lowlevel::LowlevelParams>(config, "lowlevel");
    loadSection<estimator::EstimatorParams>(config, "estimator");
    loadSection<sim::SimParams>(config, "sim");
    loadSection<trajectory::TrajectoryParams>(config, "trajectory");
  } catch (const ConfigError&) {
  }
  return 0;
}
