#include "sdlqr/px4/bridge_params.hpp"

#include "bridge_params_rows.hpp"

namespace sdlqr::px4 {

BridgeParams::BridgeParams() { declaration().setDefaults(*this); }

const ParamTable<BridgeParams>& BridgeParams::declaration() {
  static const ParamTable<BridgeParams> table = bridgeParamsRows();
  return table;
}

}  // namespace sdlqr::px4
