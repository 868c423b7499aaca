#pragma once
// Shared by the logger tests: a scratch folder, writing an LCM event log without a bus (LCM's
// event-log API), and random CSV cells for any generated type descriptor.

#include <lcm/lcm-cpp.hpp>
#include <unistd.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sdlqr/lcmtypes/field_descriptor.hpp"

namespace sdlqr::logger::test {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("sdlqr_logger_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

struct RawEvent {
  std::string channel;
  std::vector<uint8_t> bytes;
  int64_t receive_utime = 0;
};

inline void writeLog(const std::filesystem::path& path, const std::vector<RawEvent>& events) {
  lcm::LogFile log(path.string(), "w");
  if (!log.good()) throw std::runtime_error("cannot write " + path.string());
  for (const RawEvent& e : events) {
    lcm::LogEvent event;
    event.timestamp = e.receive_utime;
    event.channel = e.channel;
    event.datalen = static_cast<int32_t>(e.bytes.size());
    event.data = const_cast<uint8_t*>(e.bytes.data());
    if (log.writeEvent(&event) != 0) throw std::runtime_error("writeEvent failed");
  }
}

template <class LcmType>
std::vector<uint8_t> encode(const LcmType& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  if (message.encode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size())) {
    throw std::runtime_error("encode failed");
  }
  return bytes;
}

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Random values as text a reader of the export must accept, written independently of the
// library's formatter: doubles in C99 hex-float notation, strings JSON-escaped with \u only.
class RandomCells {
 public:
  explicit RandomCells(uint64_t seed) : rng_(seed) {}

  std::vector<std::string> make(const lcmtypes::TypeDescriptor& type) {
    std::set<std::string_view> length_fields;
    for (size_t f = 0; f < type.num_fields; ++f) {
      for (int d = 0; d < type.fields[f].num_dimensions; ++d) {
        if (!type.fields[f].dimensions[d].length_field.empty()) length_fields.insert(type.fields[f].dimensions[d].length_field);
      }
    }
    std::map<std::string_view, int64_t> lengths;
    std::vector<std::string> cells;
    for (size_t f = 0; f < type.num_fields; ++f) {
      const lcmtypes::FieldDescriptor& field = type.fields[f];
      bool variable = false;
      int fixed = 1;
      for (int d = 0; d < field.num_dimensions; ++d) {
        if (!field.dimensions[d].length_field.empty()) variable = true;
        else fixed *= field.dimensions[d].size;
      }
      if (length_fields.count(field.name)) {
        lengths[field.name] = static_cast<int64_t>(rng_() % 5);
        cells.push_back(std::to_string(lengths[field.name]));
      } else if (!variable) {
        for (int i = 0; i < fixed; ++i) cells.push_back(scalar(field.type, false));
      } else {
        cells.push_back(jsonArray(field, 0, lengths));
      }
    }
    return cells;
  }

  std::string scalar(std::string_view type, bool json) {
    if (type == "double" || type == "float") return real(json);
    if (type == "string") return json ? jsonString(text()) : text();
    if (type == "int8_t" || type == "boolean") return std::to_string(static_cast<int8_t>(rng_()));
    if (type == "byte") return std::to_string(static_cast<uint8_t>(rng_()));
    if (type == "int16_t") return std::to_string(static_cast<int16_t>(rng_()));
    if (type == "int32_t") return std::to_string(static_cast<int32_t>(rng_()));
    return std::to_string(static_cast<int64_t>(rng_()));
  }

  std::string text() {
    static const std::vector<std::string> pieces = {"a", "Z", "0", " ", ",", "\"", "'", "\n", "\r", "\t", "\\",
                                                    ";", "{", "]", "\xC3\xA9", "\x7f", "reject.nan"};
    std::string out;
    const size_t n = rng_() % 12;
    for (size_t i = 0; i < n; ++i) out += pieces[rng_() % pieces.size()];
    return out;
  }

 private:
  std::string real(bool json) {
    double value = 0.0;
    switch (rng_() % 10) {
      case 0: return json ? "Infinity" : "inf";
      case 1: return json ? "-Infinity" : "-inf";
      case 2: return json ? "NaN" : "nan";
      case 3: value = -0.0; break;
      case 4: value = std::ldexp(static_cast<double>(rng_() % 1000 + 1), -1074); break;  // subnormal
      default: {
        uint64_t bits = rng_();
        std::memcpy(&value, &bits, sizeof value);
        if (!std::isfinite(value)) value = static_cast<double>(bits % 1000003) / 7.0;
      }
    }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, json ? "%.17g" : "%a", value);  // JSON has no hex floats
    return buffer;
  }

  static std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
      if (std::isalnum(c) || c >= 0x80) {
        out.push_back(static_cast<char>(c));
      } else {
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04x", c);
        out += escape;
      }
    }
    return out + "\"";
  }

  std::string jsonArray(const lcmtypes::FieldDescriptor& field, int depth, const std::map<std::string_view, int64_t>& lengths) {
    if (depth < 0 || depth >= static_cast<int>(std::size(field.dimensions))) throw std::logic_error("bad depth");
    const lcmtypes::ArrayDimension& d = field.dimensions[depth];
    const int64_t n = d.length_field.empty() ? d.size : lengths.at(d.length_field);
    std::string out = "[";
    for (int64_t i = 0; i < n; ++i) {
      if (i) out += ", ";
      out += depth + 1 < field.num_dimensions ? jsonArray(field, depth + 1, lengths) : scalar(field.type, true);
    }
    return out + "]";
  }

  std::mt19937_64 rng_;
};

}  // namespace sdlqr::logger::test
