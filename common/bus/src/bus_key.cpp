#include "sdlqr/bus/bus_key.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace sdlqr::bus {

namespace {

constexpr size_t kHexDigits = 2 * sizeof(BusKey::bytes);

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::invalid_argument keyError(const std::string& path, const std::string& what) {
  return std::invalid_argument("bus key " + path + ": " + what);
}

std::string octalMode(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
  return text;
}

// Reads the whole (small) file; more than the key and a line end is no key file.
size_t readAll(int fd, char* buffer, size_t capacity) {
  size_t used = 0;
  while (used < capacity) {
    const ssize_t n = read(fd, buffer + used, capacity - used);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    used += static_cast<size_t>(n);
  }
  return used;
}

}  // namespace

BusKey::~BusKey() { explicit_bzero(bytes.data(), bytes.size()); }

BusKey loadBusKey(const std::string& path) {
  // The mode is read from the descriptor that is read: no window between the check and the read.
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) throw keyError(path, std::strerror(errno));
  struct stat status {};
  if (fstat(fd, &status) != 0 || !S_ISREG(status.st_mode)) {
    close(fd);
    throw keyError(path, "not a regular file");
  }
  if ((status.st_mode & 07777) != 0600) {
    close(fd);
    throw keyError(path, "mode " + octalMode(status.st_mode) + ", must be 0600 (chmod 600 " + path + ")");
  }
  char text[kHexDigits + 3] = {};
  size_t size = readAll(fd, text, sizeof text);
  close(fd);
  while (size > 0 && (text[size - 1] == '\n' || text[size - 1] == '\r')) --size;
  BusKey key;
  bool valid = size == kHexDigits;
  for (size_t i = 0; valid && i < sizeof key.bytes; ++i) {
    const int high = hexValue(text[2 * i]), low = hexValue(text[2 * i + 1]);
    valid = high >= 0 && low >= 0;
    key.bytes[i] = static_cast<uint8_t>(valid ? (high << 4) | low : 0);
  }
  explicit_bzero(text, sizeof text);
  if (!valid) throw keyError(path, "expected one line of 64 hexadecimal digits (32 bytes)");
  return key;
}

std::optional<BusKey> busKeyFromEnvironment() {
  const char* path = std::getenv(kBusKeyVariable);
  if (path == nullptr || path[0] == '\0') return std::nullopt;
  return loadBusKey(path);
}

}  // namespace sdlqr::bus
