#include "sdlqr/bus/realtime.hpp"

#include <sys/mman.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace sdlqr::bus {

std::string lockMemoryWhenAsked() {
  const char* asked = std::getenv("SDLQR_REALTIME");
  if (asked == nullptr || std::strcmp(asked, "1") != 0) return "";
  if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) return "";
  return std::string("--realtime: mlockall failed (") + std::strerror(errno) +
         "): memory stays pageable (needs CAP_IPC_LOCK or a larger RLIMIT_MEMLOCK)";
}

}  // namespace sdlqr::bus
