#include "sdlqr/mavlinkgen/definitions.hpp"

#include <expat.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "sdlqr/mavlink/crc.hpp"

namespace sdlqr::mavlinkgen {

namespace {

std::string attribute(const XML_Char** attributes, const char* name) {
  for (int i = 0; attributes[i] != nullptr; i += 2) {
    if (std::strcmp(attributes[i], name) == 0) return attributes[i + 1];
  }
  return {};
}

// The SAX state of one file: which element the character data belongs to.
struct Reader {
  XML_Parser parser = nullptr;
  std::string file;
  Definitions out;
  std::vector<std::string> path;  // open elements
  bool in_message = false, in_enum = false, in_entry = false, extensions = false;
  std::string text;               // character data of the innermost element

  [[noreturn]] void fail(const std::string& reason) const {
    throw DefinitionError(file + ":" + std::to_string(XML_GetCurrentLineNumber(parser)) + ": " + reason);
  }

  Field field(const XML_Char** attributes) const {
    Field f;
    f.name = attribute(attributes, "name");
    f.units = attribute(attributes, "units");
    f.enum_name = attribute(attributes, "enum");
    f.extension = extensions;
    std::string type = attribute(attributes, "type");
    if (type == "uint8_t_mavlink_version") {
      type = "uint8_t";
      f.mavlink_version = true;
    }
    const size_t bracket = type.find('[');
    if (bracket != std::string::npos) {
      const size_t close = type.find(']', bracket);
      if (close == std::string::npos) fail("field " + f.name + ": type '" + type + "' has no closing ]");
      f.array_length = std::atoi(type.substr(bracket + 1, close - bracket - 1).c_str());
      if (f.array_length <= 0 || f.array_length > 255) fail("field " + f.name + ": bad array length in '" + type + "'");
      type = type.substr(0, bracket);
    }
    f.type = type;
    if (f.name.empty()) fail("a field without a name");
    try {
      typeSize(f.type);
    } catch (const DefinitionError& e) {
      fail("field " + f.name + ": " + e.what());
    }
    return f;
  }

  void start(const std::string& element, const XML_Char** attributes) {
    text.clear();
    const std::string parent = path.empty() ? "" : path.back();
    path.push_back(element);
    if (element == "message") {
      Message m;
      m.name = attribute(attributes, "name");
      const std::string id = attribute(attributes, "id");
      if (m.name.empty() || id.empty()) fail("a message without name or id");
      m.id = static_cast<uint32_t>(std::stoul(id));
      out.messages.push_back(m);
      in_message = true;
      extensions = false;
    } else if (element == "field" && in_message) {
      out.messages.back().fields.push_back(field(attributes));
    } else if (element == "extensions" && in_message) {
      extensions = true;
    } else if (element == "enum" && parent == "enums") {
      Enum e;
      e.name = attribute(attributes, "name");
      e.bitmask = attribute(attributes, "bitmask") == "true";
      if (e.name.empty()) fail("an enum without a name");
      out.enums.push_back(e);
      in_enum = true;
    } else if (element == "entry" && in_enum) {
      EnumEntry entry;
      entry.name = attribute(attributes, "name");
      const std::string value = attribute(attributes, "value");
      if (entry.name.empty() || value.empty()) fail("enum " + out.enums.back().name + ": an entry without name or value");
      entry.value = std::stoull(value, nullptr, 0);
      out.enums.back().entries.push_back(entry);
      in_entry = true;
    }
  }

  void end(const std::string& element) {
    const std::string parent = path.size() >= 2 ? path[path.size() - 2] : "";
    if (element == "field" && in_message) {
      out.messages.back().fields.back().description = text;
    } else if (element == "description" && parent == "message" && in_message) {
      out.messages.back().description = text;
    } else if (element == "description" && parent == "entry" && in_entry) {
      out.enums.back().entries.back().description = text;
    } else if (element == "description" && parent == "enum" && in_enum) {
      out.enums.back().description = text;
    } else if (element == "version" && parent == "mavlink") {
      out.version = std::atoi(text.c_str());
    } else if (element == "message") {
      in_message = false;
    } else if (element == "enum") {
      in_enum = false;
    } else if (element == "entry") {
      in_entry = false;
    }
    path.pop_back();
    text.clear();
  }
};

void XMLCALL onStart(void* data, const XML_Char* name, const XML_Char** attributes) {
  static_cast<Reader*>(data)->start(name, attributes);
}
void XMLCALL onEnd(void* data, const XML_Char* name) { static_cast<Reader*>(data)->end(name); }
void XMLCALL onText(void* data, const XML_Char* s, int length) { static_cast<Reader*>(data)->text.append(s, length); }

}  // namespace

Definitions parseDefinitions(const std::string& xml, const std::string& file_name) {
  std::unique_ptr<XML_ParserStruct, void (*)(XML_Parser)> parser(XML_ParserCreate(nullptr), XML_ParserFree);
  Reader reader;
  reader.parser = parser.get();
  reader.file = file_name;
  XML_SetUserData(parser.get(), &reader);
  XML_SetElementHandler(parser.get(), onStart, onEnd);
  XML_SetCharacterDataHandler(parser.get(), onText);
  if (XML_Parse(parser.get(), xml.data(), static_cast<int>(xml.size()), XML_TRUE) == XML_STATUS_ERROR) {
    reader.fail(XML_ErrorString(XML_GetErrorCode(parser.get())));
  }
  return reader.out;
}

void merge(Definitions& into, const Definitions& from) {
  if (from.version != 0) {
    if (into.version != 0 && into.version != from.version) throw DefinitionError("files of different <version>");
    into.version = from.version;
  }
  for (const Message& m : from.messages) {
    for (const Message& existing : into.messages) {
      if (existing.id == m.id || existing.name == m.name) {
        throw DefinitionError("message " + m.name + " (" + std::to_string(m.id) + ") defined twice");
      }
    }
    into.messages.push_back(m);
  }
  for (const Enum& e : from.enums) {
    auto same = std::find_if(into.enums.begin(), into.enums.end(), [&](const Enum& x) { return x.name == e.name; });
    if (same == into.enums.end()) {
      into.enums.push_back(e);
    } else {
      same->entries.insert(same->entries.end(), e.entries.begin(), e.entries.end());
    }
  }
}

int typeSize(const std::string& type) {
  if (type == "char" || type == "uint8_t" || type == "int8_t") return 1;
  if (type == "uint16_t" || type == "int16_t") return 2;
  if (type == "uint32_t" || type == "int32_t" || type == "float") return 4;
  if (type == "uint64_t" || type == "int64_t" || type == "double") return 8;
  throw DefinitionError("unknown field type '" + type + "'");
}

std::vector<Field> wireOrder(const Message& message) {
  std::vector<Field> base, extensions;
  for (const Field& f : message.fields) (f.extension ? extensions : base).push_back(f);
  std::stable_sort(base.begin(), base.end(),
                   [](const Field& a, const Field& b) { return typeSize(a.type) > typeSize(b.type); });
  base.insert(base.end(), extensions.begin(), extensions.end());
  return base;
}

namespace {
int bytesOf(const Field& f) { return typeSize(f.type) * std::max(1, f.array_length); }
}  // namespace

int minLength(const Message& message) {
  int length = 0;
  for (const Field& f : message.fields) length += f.extension ? 0 : bytesOf(f);
  return length;
}

int maxLength(const Message& message) {
  int length = 0;
  for (const Field& f : message.fields) length += bytesOf(f);
  return length;
}

uint8_t crcExtra(const Message& message) {
  uint16_t crc = mavlink::kCrcInit;
  const auto add = [&crc](const std::string& s) {
    crc = mavlink::crcAccumulate(reinterpret_cast<const uint8_t*>(s.data()), s.size(), crc);
  };
  add(message.name + " ");
  for (const Field& f : wireOrder(message)) {
    if (f.extension) break;
    add(f.type + " " + f.name + " ");
    if (f.array_length > 0) crc = mavlink::crcAccumulate(static_cast<uint8_t>(f.array_length), crc);
  }
  return static_cast<uint8_t>((crc & 0xFF) ^ (crc >> 8));
}

}  // namespace sdlqr::mavlinkgen
