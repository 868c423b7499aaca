// encodingFits<T> for every bus type: the size walk generated from lcmtypes/*.lcm (one
// definition of the wire layout, regenerated when a .lcm file changes).

#include "sdlqr/bus/node.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/lcmtypes/generated/wire_fits.hpp"

namespace sdlqr::bus {

#define SDLQR_ENCODING_FITS(TYPE)                                                        \
  template <>                                                                            \
  bool encodingFits<TYPE>(const uint8_t* data, int64_t size) {                           \
    return lcmtypes::encodingFits(static_cast<const TYPE*>(nullptr), data, size);        \
  }

SDLQR_LCMTYPES_SDLQR_EACH(SDLQR_ENCODING_FITS)

#undef SDLQR_ENCODING_FITS

}  // namespace sdlqr::bus
