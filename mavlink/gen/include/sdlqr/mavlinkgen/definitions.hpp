#pragma once
// MAVLink message definitions as the official XML gives them (mavlink/definitions/), and the
// rules of the wire format that follow from them (mavlink.io/en/guide/serialization.html):
//   wire order   the fields before <extensions/> sorted by the size of their type, largest
//                first (a stable sort: equal sizes keep their XML order); then the extension
//                fields in XML order
//   lengths      min: the bytes of the fields before <extensions/>; max: of every field
//   CRC extra    X.25 over "NAME " and, per field before <extensions/> in wire order, "type name "
//                plus the array length as one byte for an array; the low byte XOR the high byte
// Pure: text in, model out; the generator (gen_main.cpp) and its unit tests use it.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sdlqr::mavlinkgen {

class DefinitionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Field {
  std::string type;         // base type: "uint8_t", "int32_t", "float", "char", ...
  std::string name;
  int array_length = 0;     // 0: a scalar
  bool extension = false;   // after <extensions/>
  bool mavlink_version = false;  // uint8_t_mavlink_version: the protocol fills it in
  std::string units;
  std::string enum_name;
  std::string description;
};

struct Message {
  uint32_t id = 0;
  std::string name;         // "SET_ATTITUDE_TARGET"
  std::string description;
  std::vector<Field> fields;  // XML order
};

struct EnumEntry {
  std::string name;         // "MAV_RESULT_ACCEPTED"
  uint64_t value = 0;
  std::string description;
};

struct Enum {
  std::string name;         // "MAV_RESULT"
  bool bitmask = false;
  std::string description;
  std::vector<EnumEntry> entries;
};

struct Definitions {
  int version = 0;  // <version>: the value of a uint8_t_mavlink_version field (0: not given)
  std::vector<Message> messages;
  std::vector<Enum> enums;
};

// One XML file (its <include> elements are not followed: the generator is given every file).
// Throws DefinitionError "FILE:LINE: reason" on malformed XML, an unknown field type, a message
// without id or name.
Definitions parseDefinitions(const std::string& xml, const std::string& file_name);
// Appends `from`; an enum defined in both (MAV_CMD in several dialects) gets the entries of both.
// Throws DefinitionError on a message id or name defined twice.
void merge(Definitions& into, const Definitions& from);

int typeSize(const std::string& type);  // [bytes] of one element; throws DefinitionError
std::vector<Field> wireOrder(const Message& message);
int minLength(const Message& message);  // [bytes]
int maxLength(const Message& message);  // [bytes]
uint8_t crcExtra(const Message& message);  // X.25 of sdlqr/mavlink/crc.hpp, the frames' own

}  // namespace sdlqr::mavlinkgen
