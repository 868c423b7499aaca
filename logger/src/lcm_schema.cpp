#include "sdlqr/logger/lcm_schema.hpp"

#include <cctype>
#include <map>
#include <set>
#include <sstream>

#include "sdlqr/math/types.hpp"

namespace sdlqr::logger {

namespace {

const std::set<std::string> kPrimitiveTypes = {"int8_t", "int16_t", "int32_t", "int64_t", "float",
                                               "double", "string", "boolean", "byte"};
const std::set<std::string> kIntegerTypes = {"int8_t", "int16_t", "int32_t", "int64_t"};

struct Token {
  std::string text;
  int line = 0;
};

struct Source {
  std::vector<Token> tokens;
  std::map<int, std::string> line_comments;  // trailing `//` comment of each line
};

std::string trim(const std::string& s) {
  size_t begin = 0;
  size_t end = s.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(s[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(s[end - 1]))) --end;
  return s.substr(begin, end - begin);
}

bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

Source tokenize(const std::string& text, const std::string& file) {
  Source source;
  int line = 1;
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      const size_t end = text.find('\n', i);
      const size_t stop = end == std::string::npos ? text.size() : end;
      source.line_comments[line] = trim(text.substr(i + 2, stop - i - 2));
      i = stop;
    } else if (text.compare(i, 2, "/*") == 0) {
      const size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) throw LcmSchemaError(file + ":" + std::to_string(line) + ": unterminated /* comment");
      for (size_t k = i; k < end; ++k) line += text[k] == '\n' ? 1 : 0;
      i = end + 2;
    } else if (isIdentifierStart(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+') {
      size_t end = i + 1;
      while (end < text.size() && (isIdentifierChar(text[end]) || text[end] == '+' || text[end] == '-')) ++end;
      source.tokens.push_back({text.substr(i, end - i), line});
      i = end;
    } else {
      source.tokens.push_back({std::string(1, c), line});
      ++i;
    }
  }
  return source;
}

class Parser {
 public:
  Parser(Source source, std::string file) : source_(std::move(source)), file_(std::move(file)) {}

  LcmStruct parse() {
    LcmStruct out;
    out.file = file_;
    while (!atEnd()) {
      const Token& t = next();
      if (t.text == "package") {
        out.package = identifier("package name");
        expect(";");
      } else if (t.text == "struct") {
        if (!out.name.empty()) fail(t.line, "more than one struct in one file");
        out.name = identifier("struct name");
        expect("{");
        parseMembers(out);
      } else {
        fail(t.line, "unexpected '" + t.text + "'");
      }
    }
    if (out.name.empty()) fail(0, "no struct found");
    return out;
  }

 private:
  void parseMembers(LcmStruct& out) {
    while (true) {
      if (atEnd()) fail(lastLine(), "missing '}'");
      if (peek().text == "}") {
        next();
        return;
      }
      if (peek().text == "const") {
        while (next().text != ";") {
          if (atEnd()) fail(lastLine(), "missing ';' after const");
        }
        continue;
      }
      const Token type = next();
      if (!kPrimitiveTypes.count(type.text)) {
        fail(type.line, "field type '" + type.text + "' is not an LCM primitive; the CSV export supports primitives only");
      }
      std::vector<LcmField> declared;
      while (true) {
        LcmField field;
        field.type = type.text;
        field.line = peek().line;
        field.name = identifier("field name");
        while (peek().text == "[") {
          next();
          const Token dim = next();
          LcmDimension d;
          if (std::isdigit(static_cast<unsigned char>(dim.text[0]))) {
            d.size = std::stoi(dim.text);
            if (d.size <= 0) fail(dim.line, "array size must be positive");
          } else {
            d.length_field = dim.text;
            checkLengthField(out, dim);
          }
          field.dimensions.push_back(d);
          expect("]");
        }
        if (static_cast<int>(field.dimensions.size()) > kMaxDimensions) {
          fail(field.line, "field '" + field.name + "' has more than " + std::to_string(kMaxDimensions) + " dimensions");
        }
        declared.push_back(field);
        const Token sep = next();
        if (sep.text == ";") {
          attachUnits(declared, sep.line);
          break;
        }
        if (sep.text != ",") fail(sep.line, "expected ';' or ',' after field '" + field.name + "'");
      }
      for (LcmField& f : declared) out.fields.push_back(std::move(f));
    }
  }

  void checkLengthField(const LcmStruct& out, const Token& dim) {
    for (const LcmField& f : out.fields) {
      if (f.name == dim.text) {
        if (!kIntegerTypes.count(f.type) || !f.dimensions.empty()) {
          fail(dim.line, "array length '" + dim.text + "' must be an integer scalar field");
        }
        return;
      }
    }
    fail(dim.line, "array length '" + dim.text + "' is not a field declared before");
  }

  void attachUnits(std::vector<LcmField>& fields, int line) {
    const auto it = source_.line_comments.find(line);
    const std::string comment = it == source_.line_comments.end() ? std::string() : it->second;
    const size_t close = comment.find(']');
    if (comment.empty() || comment[0] != '[' || close == std::string::npos) {
      fail(line, "field '" + fields.front().name + "' needs a trailing comment starting with its [unit]");
    }
    const std::string unit = trim(comment.substr(1, close - 1));
    if (unit.empty()) fail(line, "field '" + fields.front().name + "' has an empty [unit]; use [-] for none");
    for (LcmField& f : fields) f.unit = unit;
  }

  std::string identifier(const std::string& what) {
    if (atEnd()) fail(lastLine(), "expected " + what);
    const Token t = next();
    if (!isIdentifierStart(t.text[0])) fail(t.line, "expected " + what + ", got '" + t.text + "'");
    return t.text;
  }
  void expect(const std::string& text) {
    if (atEnd()) fail(lastLine(), "expected '" + text + "'");
    const Token t = next();
    if (t.text != text) fail(t.line, "expected '" + text + "', got '" + t.text + "'");
  }
  bool atEnd() const { return pos_ >= source_.tokens.size(); }
  const Token& peek() const {
    if (atEnd()) fail(lastLine(), "unexpected end of file");
    return source_.tokens[pos_];
  }
  const Token& next() {
    const Token& t = peek();
    ++pos_;
    return t;
  }
  int lastLine() const { return source_.tokens.empty() ? 0 : source_.tokens.back().line; }
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw LcmSchemaError(file_ + ":" + std::to_string(line) + ": " + what);
  }

  Source source_;
  std::string file_;
  size_t pos_ = 0;
};

// ---- emitting ----------------------------------------------------------------------------

std::string cppString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out + "\"";
}

std::string descriptorName(const LcmStruct& type) {
  std::string out = "k";
  bool upper = true;
  for (char c : type.name) {
    if (c == '_') {
      upper = true;
      continue;
    }
    out.push_back(upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c);
    upper = false;
  }
  return out;
}

std::string cppClass(const LcmStruct& type) {
  std::string ns;
  for (char c : type.package) {
    if (c == '.') ns += "::";
    else ns.push_back(c);
  }
  return "::" + (ns.empty() ? std::string() : ns + "::") + type.name;
}

std::string includePath(const LcmStruct& type) {
  std::string dir;
  for (char c : type.package) dir.push_back(c == '.' ? '/' : c);
  return (dir.empty() ? std::string() : dir + "/") + type.name + ".hpp";
}

// LCM booleans are int8_t in C++ and may hold any byte, so they are printed as integers.
std::string cellWriter(const std::string& lcm_type, const std::string& value) {
  if (lcm_type == "double") return "w.real(" + value + ");";
  if (lcm_type == "float") return "w.real32(" + value + ");";
  if (lcm_type == "string") return "w.text(" + value + ");";
  return "w.integer(static_cast<int64_t>(" + value + "));";
}

std::string bound(const LcmDimension& d) {
  return d.variable() ? "static_cast<int>(m." + d.length_field + ")" : std::to_string(d.size);
}

std::string indexSuffix(size_t depth) {
  std::string out;
  for (size_t k = 0; k < depth; ++k) out += "[i" + std::to_string(k) + "]";
  return out;
}

void emitWriteField(std::ostringstream& out, const LcmField& f) {
  const std::string indent = "  ";
  if (f.dimensions.empty()) {
    out << indent << cellWriter(f.type, "m." + f.name) << "\n";
    return;
  }
  const bool json = f.hasVariableDimension();
  std::string pad = indent;
  if (json) out << pad << "w.beginArray();\n";
  for (size_t k = 0; k < f.dimensions.size(); ++k) {
    const std::string i = "i" + std::to_string(k);
    out << pad << "for (int " << i << " = 0; " << i << " < " << bound(f.dimensions[k]) << "; ++" << i << ") {\n";
    pad += "  ";
    if (json && k + 1 < f.dimensions.size()) out << pad << "w.beginArray();\n";
  }
  out << pad << cellWriter(f.type, "m." + f.name + indexSuffix(f.dimensions.size())) << "\n";
  for (size_t k = f.dimensions.size(); k-- > 0;) {
    pad.resize(pad.size() - 2);
    if (json && k + 1 < f.dimensions.size()) out << pad << "  w.endArray();\n";
    out << pad << "}\n";
  }
  if (json) out << pad << "w.endArray();\n";
}

void emitReadField(std::ostringstream& out, const LcmField& f) {
  const std::string indent = "  ";
  if (f.dimensions.empty()) {
    out << indent << "if (!readCell(cells, column++, m." << f.name << ", error)) return false;\n";
    return;
  }
  if (!f.hasVariableDimension()) {
    std::string pad = indent;
    for (size_t k = 0; k < f.dimensions.size(); ++k) {
      const std::string i = "i" + std::to_string(k);
      out << pad << "for (int " << i << " = 0; " << i << " < " << f.dimensions[k].size << "; ++" << i << ") {\n";
      pad += "  ";
    }
    out << pad << "if (!readCell(cells, column++, m." << f.name << indexSuffix(f.dimensions.size())
        << ", error)) return false;\n";
    for (size_t k = f.dimensions.size(); k-- > 0;) {
      pad.resize(pad.size() - 2);
      out << pad << "}\n";
    }
    return;
  }
  out << indent << "{\n";
  out << indent << "  JsonValue a0;\n";
  out << indent << "  if (!readJsonCell(cells, column++, a0, error)) return false;\n";
  std::string pad = indent + "  ";
  for (size_t k = 0; k < f.dimensions.size(); ++k) {
    const std::string a = "a" + std::to_string(k);
    const std::string i = "i" + std::to_string(k);
    out << pad << "if (!checkArray(" << a << ", " << bound(f.dimensions[k]) << ", " << cppString(f.name)
        << ", error)) return false;\n";
    out << pad << "ensureSize(m." << f.name << indexSuffix(k) << ", " << a << ".items.size());\n";
    out << pad << "for (int " << i << " = 0; " << i << " < " << bound(f.dimensions[k]) << "; ++" << i << ") {\n";
    pad += "  ";
    const std::string element = a + ".items[static_cast<size_t>(" + i + ")]";
    if (k + 1 < f.dimensions.size()) {
      out << pad << "const JsonValue& a" << (k + 1) << " = " << element << ";\n";
    } else {
      out << pad << "if (!readJsonElement(" << element << ", m." << f.name << indexSuffix(f.dimensions.size()) << ", "
          << cppString(f.name) << ", error)) return false;\n";
    }
  }
  for (size_t k = f.dimensions.size(); k-- > 0;) {
    pad.resize(pad.size() - 2);
    out << pad << "}\n";
  }
  out << indent << "}\n";
}

int primitiveBytes(const std::string& type) {
  if (type == "int8_t" || type == "boolean" || type == "byte") return 1;
  if (type == "int16_t") return 2;
  if (type == "int32_t" || type == "float") return 4;
  if (type == "int64_t" || type == "double") return 8;
  return 0;  // string: variable
}

// Walks the encoding field by field (see wire_check.hpp): fixed-size runs are skipped, length
// fields read, strings skipped one by one, variable arrays checked against the bytes left.
void emitEncodingFits(std::ostringstream& out, const LcmStruct& t) {
  std::set<std::string> length_fields;
  for (const LcmField& f : t.fields) {
    for (const LcmDimension& d : f.dimensions) {
      if (d.variable()) length_fields.insert(d.length_field);
    }
  }
  out << "inline bool encodingFits(const " << cppClass(t) << "*, const uint8_t* data, int64_t size) {\n";
  out << "  wire::Cursor c{data, size, 0};\n";
  out << "  if (!c.skip(8)) return false;  // fingerprint\n";
  for (const std::string& name : length_fields) out << "  int64_t n_" << name << " = 0;\n";
  for (const LcmField& f : t.fields) {
    const int bytes = primitiveBytes(f.type);
    if (length_fields.count(f.name)) {  // a scalar integer (the parser checks)
      out << "  if (!c.readInteger(" << bytes << ", &n_" << f.name << ") || n_" << f.name << " < 0) return false;\n";
      continue;
    }
    out << "  {  // " << f.name << "\n";
    out << "    int64_t count = 1;\n";
    for (const LcmDimension& d : f.dimensions) {
      const std::string factor = d.variable() ? "n_" + d.length_field : std::to_string(d.size);
      out << "    if (!wire::elementCount(count, " << factor << ", size, &count)) return false;\n";
    }
    if (bytes > 0) {
      out << "    if (!c.fits(count, " << bytes << ") || !c.skip(count * " << bytes << ")) return false;\n";
    } else {
      out << "    if (!c.fits(count, 5)) return false;\n";
      out << "    for (int64_t i = 0; i < count; ++i) {\n      if (!c.skipString()) return false;\n    }\n";
    }
    out << "  }\n";
  }
  out << "  return c.pos == c.size;\n}\n\n";
}

std::string banner(const std::string& source_note) {
  return "// Generated by sdlqr_lcm_fields_gen from " + source_note + ". Do not edit: change the .lcm file.\n";
}

}  // namespace

bool LcmField::hasVariableDimension() const {
  for (const LcmDimension& d : dimensions) {
    if (d.variable()) return true;
  }
  return false;
}

int LcmField::fixedElementCount() const {
  int count = 1;
  for (const LcmDimension& d : dimensions) count *= d.variable() ? 1 : d.size;
  return count;
}

bool LcmStruct::hasUtimeAndSeq() const {
  return fields.size() >= 2 && fields[0].name == "utime" && fields[0].type == "int64_t" &&
         fields[0].dimensions.empty() && fields[1].name == "seq" && fields[1].type == "int64_t" &&
         fields[1].dimensions.empty();
}

LcmStruct parseLcmStruct(const std::string& text, const std::string& file_name) {
  return Parser(tokenize(text, file_name), file_name).parse();
}

std::vector<std::string> elementUnits(const LcmField& field) {
  const int count = field.fixedElementCount();
  std::vector<std::string> parts;
  std::stringstream stream(field.unit);
  std::string part;
  while (std::getline(stream, part, ',')) parts.push_back(trim(part));

  std::vector<std::string> units(static_cast<size_t>(count), field.unit);
  if (field.dimensions.size() != 1 || field.hasVariableDimension()) return units;
  // Segment starts of the documented layouts (x = [p, q, v], u = [omega, c]).
  std::vector<int> starts;
  if (count == kStateDim && parts.size() == 3) starts = {kPos, kQuat, kVel, kStateDim};
  if (count == kInputDim && parts.size() == 2) starts = {kRate, kThrust, kInputDim};
  if (starts.empty()) return units;
  for (size_t segment = 0; segment + 1 < starts.size(); ++segment) {
    for (int i = starts[segment]; i < starts[segment + 1]; ++i) units[static_cast<size_t>(i)] = parts[segment];
  }
  return units;
}

std::vector<std::string> csvColumns(const LcmStruct& type) {
  std::vector<std::string> columns;
  for (const LcmField& f : type.fields) {
    if (f.dimensions.empty()) {
      columns.push_back(f.name + " [" + f.unit + "]");
    } else if (f.hasVariableDimension()) {
      std::string name = f.name;
      for (const LcmDimension& d : f.dimensions) name += "[" + (d.variable() ? d.length_field : std::to_string(d.size)) + "]";
      columns.push_back(name + " [" + f.unit + "]");
    } else {
      const std::vector<std::string> units = elementUnits(f);
      const int inner = f.dimensions.size() == 2 ? f.dimensions[1].size : 1;
      for (int flat = 0; flat < f.fixedElementCount(); ++flat) {
        std::string name = f.name + "[" + std::to_string(flat / inner) + "]";
        if (f.dimensions.size() == 2) name += "[" + std::to_string(flat % inner) + "]";
        columns.push_back(name + " [" + units[static_cast<size_t>(flat)] + "]");
      }
    }
  }
  return columns;
}

std::string emitDescriptorsHeader(const std::vector<LcmStruct>& types, const std::string& source_note) {
  std::ostringstream out;
  out << "#pragma once\n" << banner(source_note) << "\n";
  out << "#include <cstddef>\n#include <string_view>\n\n#include \"sdlqr/logger/field_descriptor.hpp\"\n\n";
  out << "namespace sdlqr::logger::generated {\n\n";
  for (const LcmStruct& t : types) {
    const std::string id = descriptorName(t);
    out << "// " << t.package << "." << t.name << " (" << t.file << ")\n";
    out << "inline constexpr FieldDescriptor " << id << "Fields[] = {\n";
    for (const LcmField& f : t.fields) {
      out << "    {" << cppString(f.name) << ", " << cppString(f.type) << ", " << cppString(f.unit) << ", "
          << f.dimensions.size() << ", {";
      for (size_t k = 0; k < static_cast<size_t>(kMaxDimensions); ++k) {
        const LcmDimension d = k < f.dimensions.size() ? f.dimensions[k] : LcmDimension{};
        out << (k ? ", " : "") << "{" << d.size << ", " << cppString(d.length_field) << "}";
      }
      out << "}},\n";
    }
    out << "};\n";
    out << "inline constexpr std::string_view " << id << "Columns[] = {\n";
    for (const std::string& c : csvColumns(t)) out << "    " << cppString(c) << ",\n";
    out << "};\n";
    out << "inline constexpr TypeDescriptor " << id << "{" << cppString(t.name) << ", " << id << "Fields, "
        << t.fields.size() << ", " << id << "Columns, " << csvColumns(t).size() << "};\n\n";
  }
  out << "inline constexpr const TypeDescriptor* kAllTypes[] = {\n";
  for (const LcmStruct& t : types) out << "    &" << descriptorName(t) << ",\n";
  out << "};\n\n";
  out << "inline const TypeDescriptor* findType(std::string_view name) {\n";
  out << "  for (const TypeDescriptor* t : kAllTypes) {\n    if (t->name == name) return t;\n  }\n  return nullptr;\n}\n\n";
  out << "}  // namespace sdlqr::logger::generated\n";
  return out.str();
}

std::string emitCsvRowsHeader(const std::vector<LcmStruct>& types, const std::string& source_note) {
  std::ostringstream out;
  out << "#pragma once\n" << banner(source_note);
  out << "// Per LCM type: writeCsvRow (one decoded message as one CSV row, in the column order of the\n"
         "// descriptor), readCsvRow (the inverse, exact), encodingFits (the bytes hold a complete\n"
         "// encoding, checked without allocating), utimeAndSeq, and visitLcmType (type name -> the\n"
         "// lcm-gen class).\n\n";
  out << "#include <cstdint>\n#include <string>\n#include <string_view>\n#include <vector>\n\n";
  out << "#include \"sdlqr/logger/csv.hpp\"\n#include \"sdlqr/logger/generated/lcm_type_descriptors.hpp\"\n"
         "#include \"sdlqr/logger/wire_check.hpp\"\n";
  for (const LcmStruct& t : types) out << "#include \"" << includePath(t) << "\"\n";
  out << "\nnamespace sdlqr::logger::generated {\n\n";
  out << "template <class T>\nstruct TypeTag {\n  using type = T;\n};\n\n";
  out << "template <class T>\nconst TypeDescriptor& descriptorOf();\n\n";
  for (const LcmStruct& t : types) {
    const std::string cls = cppClass(t);
    const std::string id = descriptorName(t);
    out << "// ---- " << t.name << "\n";
    out << "template <>\ninline const TypeDescriptor& descriptorOf<" << cls << ">() { return " << id << "; }\n\n";
    out << "inline void writeCsvRow(CsvWriter& w, const " << cls << "& m) {\n";
    for (const LcmField& f : t.fields) emitWriteField(out, f);
    out << "  w.endRow();\n}\n\n";
    out << "inline bool readCsvRow(const std::vector<std::string>& cells, " << cls << "& m, std::string* error) {\n";
    out << "  if (!checkCellCount(cells, " << id << ".num_columns, error)) return false;\n";
    out << "  size_t column = 0;\n";
    for (const LcmField& f : t.fields) emitReadField(out, f);
    out << "  return true;\n}\n\n";
    emitEncodingFits(out, t);
    out << "inline bool utimeAndSeq(const " << cls << "& " << (t.hasUtimeAndSeq() ? "m" : "")
        << ", int64_t* utime, int64_t* seq) {\n";
    if (t.hasUtimeAndSeq()) {
      out << "  *utime = m.utime;\n  *seq = m.seq;\n  return true;\n}\n\n";
    } else {
      out << "  *utime = 0;\n  *seq = 0;\n  return false;\n}\n\n";
    }
  }
  out << "// Calls visit(TypeTag<T>{}, descriptor) for the lcm-gen class named `name`; false if unknown.\n";
  out << "template <class Visitor>\nbool visitLcmType(std::string_view name, Visitor&& visit) {\n";
  for (const LcmStruct& t : types) {
    out << "  if (name == " << cppString(t.name) << ") {\n    visit(TypeTag<" << cppClass(t) << ">{}, "
        << descriptorName(t) << ");\n    return true;\n  }\n";
  }
  out << "  return false;\n}\n\n";
  out << "}  // namespace sdlqr::logger::generated\n";
  return out.str();
}

}  // namespace sdlqr::logger
