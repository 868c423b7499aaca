// Test helper of the node-mavlink check (node_mavlink_check.mjs): our side of the byte-for-byte
// comparison with an implementation nobody here wrote.
//   mavlink_vectors frames             one JSON line per frame we write: message, address, sequence,
//                                      signing (key, link, timestamp), every field, the frame in hex
//   mavlink_vectors decode [KEY_HEX]   one hex frame per line on stdin -> one JSON line per line:
//                                      the fields our parser decoded, or {"error": ...}
// uint64 fields are JSON strings (JavaScript numbers hold 53 bits); floats are printed exactly.

#include <cinttypes>
#include <cstdio>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

#include "sdlqr/mavlink/dispatch.hpp"

using namespace sdlqr::mavlink;

namespace {

template <class T>
std::string number(T v) {
  char text[64];
  if constexpr (std::is_floating_point_v<T>) {
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
  } else if constexpr (std::is_same_v<T, uint64_t>) {
    std::snprintf(text, sizeof text, "\"%" PRIu64 "\"", v);
  } else if constexpr (std::is_same_v<T, int64_t>) {
    std::snprintf(text, sizeof text, "\"%" PRId64 "\"", v);
  } else {
    std::snprintf(text, sizeof text, "%lld", static_cast<long long>(v));
  }
  return text;
}

template <class Message>
std::string fieldsJson(const Message& m) {
  std::string out = "{";
  m.visitFields([&](const char* name, const auto& field) {
    if (out.size() > 1) out += ",";
    out += std::string("\"") + name + "\":";
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(field)>>) {
      out += number(field);
    } else {
      out += "[";
      for (size_t i = 0; i < field.size(); ++i) out += (i ? "," : "") + number(field[i]);
      out += "]";
    }
  });
  return out + "}";
}

std::string hex(const uint8_t* data, size_t size) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (size_t i = 0; i < size; ++i) {
    out += digits[data[i] >> 4];
    out += digits[data[i] & 15];
  }
  return out;
}

// Every field a distinct value (no zero that truncation could hide), varied by `salt`.
template <class Message>
Message sample(int salt) {
  Message m;
  int k = salt;
  m.visitFields([&k](const char*, auto& field) {
    auto set = [&k](auto& v) {
      using V = std::decay_t<decltype(v)>;
      ++k;
      if constexpr (std::is_floating_point_v<V>) v = static_cast<V>(k * 0.37 - 3.1);
      else if constexpr (std::is_signed_v<V>) v = static_cast<V>(-(k % 100));
      else if constexpr (sizeof(V) == 8) v = static_cast<V>(1700000000000000ULL + static_cast<uint64_t>(k));
      else v = static_cast<V>(k % 200 + 1);
    };
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(field)>>) set(field);
    else for (auto& e : field) set(e);
  });
  return m;
}

constexpr uint64_t kSigningTime = 372000000000ULL;  // a multiple of 100: node-mavlink signs at ms resolution

SigningKey testKey() {
  SigningKey key;
  for (size_t i = 0; i < key.bytes.size(); ++i) key.bytes[i] = static_cast<uint8_t>(0xA0 + i);
  return key;
}

// `signing_time` a multiple of 100 and later than the previous frame's: the timestamp written.
template <class Message>
void printFrame(FrameWriter& writer, const Message& m, uint8_t seq_before, bool signed_frame, uint8_t link_id,
                uint64_t signing_time = kSigningTime) {
  uint8_t buffer[kMaxFrameSize];
  const size_t size = writer.write(m, signing_time, buffer);
  std::cout << "{\"name\":\"" << Message::kName << "\",\"msgid\":" << Message::kId << ",\"sysid\":"
            << static_cast<int>(writer.address().system) << ",\"compid\":" << static_cast<int>(writer.address().component)
            << ",\"seq\":" << static_cast<int>(seq_before) << ",\"signed\":" << (signed_frame ? "true" : "false");
  if (signed_frame) {
    const SigningKey key = testKey();
    std::cout << ",\"key\":\"" << hex(key.bytes.data(), key.bytes.size()) << "\",\"link_id\":"
              << static_cast<int>(link_id) << ",\"timestamp\":" << signing_time;
  }
  std::cout << ",\"fields\":" << fieldsJson(m) << ",\"hex\":\"" << hex(buffer, size) << "\"}\n";
}

int frames() {
  FrameWriter plain(Address{1, 191});
  int seq = 0;
  int salt = 0;
  std::apply([&](auto... messages) {
    ((printFrame(plain, sample<decltype(messages)>(salt += 7), static_cast<uint8_t>(seq++), false, 0)), ...);
  }, AllMessages{});
  // Zero trailing fields, truncated away (ODOMETRY's quality, SET_ATTITUDE_TARGET's thrust_body).
  Odometry odometry = sample<Odometry>(3);
  odometry.quality = 0;
  odometry.estimator_type = 0;
  printFrame(plain, odometry, static_cast<uint8_t>(seq++), false, 0);
  SetAttitudeTarget setpoint = sample<SetAttitudeTarget>(5);
  setpoint.thrust_body = {0, 0, 0};
  printFrame(plain, setpoint, static_cast<uint8_t>(seq++), false, 0);
  // Signed, as the bridge and the emulator sign with a key.
  FrameWriter signer(Address{1, 1});
  signer.enableSigning(testKey(), 3);
  printFrame(signer, setpoint, 0, true, 3, kSigningTime);
  printFrame(signer, odometry, 1, true, 3, kSigningTime + 100);
  return 0;
}

std::vector<uint8_t> bytesOf(const std::string& text) {
  std::vector<uint8_t> out;
  for (size_t i = 0; i + 1 < text.size(); i += 2) out.push_back(static_cast<uint8_t>(std::stoi(text.substr(i, 2), nullptr, 16)));
  return out;
}

int decode(const std::string& key_hex) {
  std::string line;
  uint64_t now = kSigningTime;
  while (std::getline(std::cin, line)) {
    Parser parser;
    if (!key_hex.empty()) {
      SigningKey key;
      const auto bytes = bytesOf(key_hex);
      std::copy(bytes.begin(), bytes.end(), key.bytes.begin());
      parser.requireSigning(key);
    }
    const auto bytes = bytesOf(line);
    std::string out;
    parser.feed(bytes.data(), bytes.size(), now, [&](const Frame& f) {
      dispatch(f, [&](const auto& m) {
        out = "{\"msgid\":" + std::to_string(f.id) + ",\"seq\":" + std::to_string(f.seq) + ",\"sysid\":" +
              std::to_string(f.source.system) + ",\"signed\":" + (f.is_signed ? "true" : "false") +
              ",\"fields\":" + fieldsJson(m) + "}";
      });
    });
    parser.endDatagram();
    if (out.empty()) {
      out = "{\"error\":\"no frame: frames " + std::to_string(parser.counts().frames) + ", dropped";
      for (size_t i = 0; i < kFrameDropCount; ++i) {
        if (parser.counts().dropped[i]) out += std::string(" ") + dropName(static_cast<FrameDrop>(i));
      }
      out += "\"}";
    }
    std::cout << out << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "frames") return frames();
  if (mode == "decode") return decode(argc > 2 ? argv[2] : "");
  std::cerr << "usage: mavlink_vectors frames | decode [KEY_HEX]\n";
  return mode == "--help" ? 0 : 2;
}
