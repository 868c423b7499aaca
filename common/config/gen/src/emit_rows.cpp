// Writes a declaration file's rows as the ParamTable calls a hand-written table used to hold: one
// call per row, numbers spelled as in the file (so every default is the same double), in order.
// The functions live in an anonymous namespace: the header is included by the one .cpp that
// defines its section's declaration().

#include <cctype>
#include <sstream>
#include <string>

#include "sdlqr/paramgen/declaration.hpp"

namespace sdlqr::paramgen {

namespace {

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string memberOf(const Row& row) { return "&P::" + row.member(); }

std::string listDefault(const Row& row) {
  std::string out = "{";
  for (size_t i = 0; i < row.defaults.size(); ++i) out += (i ? ", " : "") + row.defaults[i];
  return out + "}";
}

std::string choices(const Row& row) {
  std::string out = "{";
  for (size_t i = 0; i < row.choices.size(); ++i) {
    out += (i ? ", {" : "{") + quoted(row.choices[i].first) + ", " + row.choices[i].second + "}";
  }
  return out + "}";
}

std::string rowCall(const Row& row) {
  const std::string key = quoted(row.key);
  const std::string tail = quoted(row.unit) + ", " + row.range.cpp() + ", " + quoted(row.doc) + ")";
  std::string call;
  if (row.type == "number" || row.type == "integer") {
    call = "t." + row.type + "(" + key + ", " + memberOf(row) + ", " + row.defaults[0] + ", " + tail;
  } else if (row.type == "list") {
    call = "t.list<" + std::to_string(row.size) + ">(" + key + ", " + memberOf(row) + ", " + listDefault(row) + ", " + tail;
  } else if (row.type == "flag") {
    call = "t.flag(" + key + ", " + memberOf(row) + ", " + row.defaults[0] + ", " + quoted(row.doc) + ")";
  } else if (row.type == "choice") {
    call = "t.choice(" + key + ", " + memberOf(row) + ", " + row.defaults[0] + ", " + choices(row) + ", " + quoted(row.doc) + ")";
  } else if (row.type == "section") {
    call = "t.section(" + key + ", " + memberOf(row) + ")";
  } else if (row.type == "derived_list") {
    call = "t.derivedList<" + std::to_string(row.size) + ">(" + key + ", " + quoted(row.unit) + ", " + row.range.cpp() +
           ", " + quoted(row.doc) + ", " + quoted(row.placeholder) + ", " + row.derive + ", " + row.get + ", " + row.set + ")";
  } else {
    return row.code + "(t);";
  }
  if (!row.in_flight.empty()) call += ".inFlight(ParamsUpdate::" + row.in_flight + ")";
  return call + ";";
}

// A default naming a C++ constant is checked against its range where the constant is known.
std::string constantCheck(const Row& row) {
  const std::string& value = row.defaults.empty() ? std::string() : row.defaults[0];
  if (row.type != "number" && row.type != "integer") return {};
  if (value.size() < 2 || value[0] != 'k' || !std::isupper(static_cast<unsigned char>(value[1]))) return {};
  const RangeSpec& r = row.range;
  std::string test = "true";
  if (r.has_low) test = value + (r.low_open ? " > " : " >= ") + r.low_text;
  if (r.has_high) test += " && " + value + (r.high_open ? " < " : " <= ") + r.high_text;
  return "  static_assert(" + test + ", " + quoted(row.key + ": the default " + value + " is outside its range") + ");\n";
}

void emitPrototypes(std::ostringstream& out, const Section& section) {
  const std::string table = "ParamTable<" + section.name + ">";
  for (const Row& row : section.rows) {
    if (row.type == "code") out << "void " << row.code << "(" << table << "& t);\n";
    if (row.type != "derived_list") continue;
    const std::string list = table + "::List<" + std::to_string(row.size) + ">";
    out << "void " << row.derive << "(" << section.name << "& p);\n"
        << list << " " << row.get << "(const " << section.name << "& p);\n"
        << "void " << row.set << "(" << section.name << "& p, const " << list << "& values);\n";
  }
}

void emitSection(std::ostringstream& out, const Section& section) {
  emitPrototypes(out, section);
  out << "\n// The rows of " << section.name << ", in declaration order.\n"
      << "ParamTable<" << section.name << "> " << rowsFunctionName(section.name) << "() {\n"
      << "  using P = " << section.name << ";\n";
  for (const Row& row : section.rows) out << constantCheck(row);
  out << "  ParamTable<P> t(" << quoted(section.help) << ");\n";
  for (const Row& row : section.rows) out << "  " << rowCall(row) << "\n";
  out << "  return t;\n}\n\n";
}

bool anyInFlight(const Declaration& declaration) {
  for (const Section& section : declaration.sections) {
    for (const Row& row : section.rows) {
      if (!row.in_flight.empty()) return true;
    }
  }
  return false;
}

}  // namespace

std::string rowsFunctionName(const std::string& struct_name) {
  std::string name = struct_name;
  if (!name.empty()) name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
  return name + "Rows";
}

std::string emitRows(const Declaration& declaration) {
  std::ostringstream out;
  out << "#pragma once\n// Generated by sdlqr_paramgen from " << declaration.file << ": edit that file, not this one.\n\n";
  if (!declaration.header.empty()) out << "#include \"" << declaration.header << "\"\n";
  out << "#include \"sdlqr/config/param_table.hpp\"\n";
  if (anyInFlight(declaration)) out << "#include \"sdlqr/messages/messages.hpp\"\n";
  out << "\nnamespace " << declaration.name_space << " {\nnamespace {\n\n";
  for (const Section& section : declaration.sections) emitSection(out, section);
  out << "}  // namespace\n}  // namespace " << declaration.name_space << "\n";
  return out.str();
}

}  // namespace sdlqr::paramgen
