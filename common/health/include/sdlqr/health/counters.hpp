#pragma once
// Named counters reported in HEARTBEAT; registered once at start so counting never allocates.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sdlqr {

class Counters {
 public:
  using Id = int;
  // Registers `name` (or finds it when registered already).
  Id add(const std::string& name);
  void increment(Id id, int64_t by = 1) { values_[static_cast<size_t>(id)] += by; }
  // For gauges (a watchdog's age, an expired flag).
  void set(Id id, int64_t value) { values_[static_cast<size_t>(id)] = value; }
  int64_t value(Id id) const { return values_[static_cast<size_t>(id)]; }
  // -1 when no counter has that name.
  Id find(std::string_view name) const;
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<int64_t>& values() const { return values_; }

 private:
  std::vector<std::string> names_;
  std::vector<int64_t> values_;
};

}  // namespace sdlqr
