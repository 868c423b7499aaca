#include "sdlqr/mavlink/message_info.hpp"

#include <algorithm>
#include <iterator>

#include "sdlqr/mavlink/messages.hpp"

namespace sdlqr::mavlink {

const MessageInfo* findMessage(uint32_t id) {
  const auto* end = std::end(kMessageTable);
  const auto* found = std::lower_bound(std::begin(kMessageTable), end, id,
                                       [](const MessageInfo& info, uint32_t key) { return info.id < key; });
  return found != end && found->id == id ? found : nullptr;
}

}  // namespace sdlqr::mavlink
