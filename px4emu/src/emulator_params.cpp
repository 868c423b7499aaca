#include "sdlqr/px4emu/emulator_params.hpp"

#include "emulator_params_rows.hpp"

namespace sdlqr::px4emu {

EmulatorParams::EmulatorParams() { declaration().setDefaults(*this); }

const ParamTable<EmulatorParams>& EmulatorParams::declaration() {
  static const ParamTable<EmulatorParams> table = emulatorParamsRows();
  return table;
}

}  // namespace sdlqr::px4emu
