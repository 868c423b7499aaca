#pragma once
// The vehicle-file sections sdlqr-px4-emulator reads, loaded and checked as the processes whose
// cores it runs check them (sdlqr-sim, sdlqr-estimator, sdlqr-lowlevel), and printed by
// --print-config.

#include <vector>

#include "sdlqr/config/print_config.hpp"
#include "sdlqr/px4emu/emulator_core.hpp"

namespace sdlqr::px4emu {

// Throws ConfigError naming the key.
EmulatorConfig loadEmulatorConfig(const ConfigReader& root);
std::vector<PrintedSection> printedSections(const EmulatorConfig& config);

}  // namespace sdlqr::px4emu
