#pragma once
// What a receiver needs to know of a message id before it can check a frame: its CRC extra and
// its payload lengths (a MAVLink 2 payload may be shorter than the minimum: trailing zero bytes
// are cut; never longer than the maximum). The table is generated (messages.hpp kMessageTable).

#include <cstdint>
#include <string_view>

namespace sdlqr::mavlink {

struct MessageInfo {
  uint32_t id;
  uint8_t crc_extra;
  uint8_t min_length;  // [bytes] the fields before <extensions/>
  uint8_t max_length;  // [bytes] every field
  std::string_view name;
};

// The message of `id` among those generated, or nullptr (an id this stack does not use).
const MessageInfo* findMessage(uint32_t id);

}  // namespace sdlqr::mavlink
