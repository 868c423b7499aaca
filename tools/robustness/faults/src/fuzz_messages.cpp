#include "sdlqr/faults/fuzz_messages.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace sdlqr::faults {

namespace {

int primitiveSize(std::string_view type) {
  if (type == "int8_t" || type == "byte" || type == "boolean") return 1;
  if (type == "int16_t") return 2;
  if (type == "int32_t" || type == "float") return 4;
  if (type == "int64_t" || type == "double") return 8;
  return 0;  // string or a nested type: not walked
}

int64_t readBigEndian(const uint8_t* p, int bytes) {
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value = (value << 8) | p[i];
  const int shift = 64 - 8 * bytes;
  return shift > 0 ? static_cast<int64_t>(value << shift) >> shift : static_cast<int64_t>(value);
}

void writeDouble(uint8_t* p, double value) {
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 8; ++i) p[i] = static_cast<uint8_t>(bits >> (56 - 8 * i));
}

}  // namespace

const char* toString(FuzzKind kind) {
  switch (kind) {
    case FuzzKind::kRandomBytes: return "random_bytes";
    case FuzzKind::kTruncated: return "truncated";
    case FuzzKind::kOversized: return "oversized";
    case FuzzKind::kWrongFingerprint: return "wrong_fingerprint";
    case FuzzKind::kNonFinite: return "nonfinite";
    case FuzzKind::kHuge: return "huge";
    case FuzzKind::kReplayed: return "replayed";
  }
  return "unknown";
}

std::vector<int64_t> doubleOffsets(const lcmtypes::TypeDescriptor& type, const uint8_t* data, int64_t size) {
  std::vector<int64_t> offsets;
  std::vector<std::pair<std::string_view, int64_t>> integers;  // scalar integer fields: array lengths
  int64_t pos = 8;
  for (std::size_t f = 0; f < type.num_fields; ++f) {
    const lcmtypes::FieldDescriptor& field = type.fields[f];
    const int element = primitiveSize(field.type);
    if (element == 0) return {};
    int64_t count = 1;
    for (int d = 0; d < field.num_dimensions; ++d) {
      const lcmtypes::ArrayDimension& dim = field.dimensions[d];
      int64_t length = dim.size;
      if (length == 0) {
        length = -1;
        for (const auto& [name, value] : integers) {
          if (name == dim.length_field) length = value;
        }
      }
      if (length < 0 || length > size) return {};
      count *= length;
    }
    if (count > (size - pos) / element) return {};
    if (field.num_dimensions == 0 && field.type != "double" && field.type != "float") {
      integers.emplace_back(field.name, readBigEndian(data + pos, element));
    }
    if (field.type == "double") {
      for (int64_t i = 0; i < count; ++i) offsets.push_back(pos + 8 * i);
    }
    pos += count * element;
  }
  if (pos != size) return {};
  return offsets;
}

bool FuzzGenerator::make(FuzzKind kind, const lcmtypes::TypeDescriptor& type, const std::vector<uint8_t>& valid,
                         std::vector<uint8_t>& out) {
  const int64_t size = static_cast<int64_t>(valid.size());
  switch (kind) {
    case FuzzKind::kRandomBytes: {
      const int64_t length = 1 + static_cast<int64_t>(next() % static_cast<uint64_t>(2 * size + 1));
      out.resize(static_cast<size_t>(length));
      for (uint8_t& b : out) b = static_cast<uint8_t>(next());
      return true;
    }
    case FuzzKind::kTruncated: {
      if (size < 2) return false;
      out.assign(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(1 + next() % static_cast<uint64_t>(size - 1)));
      return true;
    }
    case FuzzKind::kOversized: {
      out = valid;
      const int64_t extra = 1 + static_cast<int64_t>(next() % 64);
      for (int64_t i = 0; i < extra; ++i) out.push_back(static_cast<uint8_t>(next()));
      return true;
    }
    case FuzzKind::kWrongFingerprint: {
      if (size < 8) return false;
      out = valid;
      out[static_cast<size_t>(next() % 8)] ^= static_cast<uint8_t>(1 + next() % 255);
      return true;
    }
    case FuzzKind::kNonFinite:
    case FuzzKind::kHuge: {
      const std::vector<int64_t> offsets = doubleOffsets(type, valid.data(), size);
      if (offsets.empty()) return false;
      out = valid;
      const int64_t offset = offsets[next() % offsets.size()];
      static constexpr double kNonFiniteValues[] = {std::numeric_limits<double>::quiet_NaN(),
                                                    std::numeric_limits<double>::infinity(),
                                                    -std::numeric_limits<double>::infinity()};
      static constexpr double kHugeValues[] = {1e300, -1e300, 1e12, -1e12};
      const double value = kind == FuzzKind::kNonFinite ? kNonFiniteValues[next() % 3] : kHugeValues[next() % 4];
      writeDouble(out.data() + offset, value);
      return true;
    }
    case FuzzKind::kReplayed:
      if (valid.empty()) return false;
      out = valid;
      return true;
  }
  return false;
}

}  // namespace sdlqr::faults
