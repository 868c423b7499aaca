#include "sdlqr/foxglove/lcm_json.hpp"

#include "sdlqr/bus/decode.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"

namespace sdlqr::foxglove {

std::string dumpJson(const Json& json) { return json.dump(-1, ' ', false, Json::error_handler_t::replace); }

bool lcmBytesToJson(std::string_view lcm_type, const void* data, std::size_t size, std::string* out) {
  bool decoded = false;
  lcmtypes::visitLcmType(lcm_type, [&](auto tag) {
    using LcmType = typename decltype(tag)::type;
    LcmType message;
    if (size > UINT32_MAX || bus::decode(data, static_cast<uint32_t>(size), message) != RejectReason::kNone) return;
    *out = dumpJson(toJson(message));
    decoded = true;
  });
  return decoded;
}

const lcmtypes::JsonSchemaText* jsonSchemaOf(std::string_view lcm_type) { return lcmtypes::findJsonSchema(lcm_type); }

}  // namespace sdlqr::foxglove
