#include "sdlqr/gains/gains_params.hpp"

#include "gains_params_rows.hpp"

namespace sdlqr::gains {

GainsParams::GainsParams() { declaration().setDefaults(*this); }

const ParamTable<GainsParams>& GainsParams::declaration() {
  static const ParamTable<GainsParams> table = gainsParamsRows();
  return table;
}

}  // namespace sdlqr::gains
