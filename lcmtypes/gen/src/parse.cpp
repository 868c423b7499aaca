#include <cctype>
#include <set>
#include <sstream>

#include "sdlqr/lcmgen/schema.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::lcmgen {

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
  std::map<int, std::string> line_comments;  // `//` comment of each line
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

// Splits "[m] position @as Vec3 @default 1" into the text before the first '@' and the
// annotations {"as": "Vec3", "default": "1"}.
std::string splitAnnotations(const std::string& comment, Annotations& out) {
  const size_t first = comment.find('@');
  if (first == std::string::npos) return comment;
  size_t at = first;
  while (at != std::string::npos) {
    const size_t next = comment.find('@', at + 1);
    const std::string item = trim(comment.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
    const size_t space = item.find_first_of(" \t");
    out.emplace(item.substr(0, space), space == std::string::npos ? std::string() : trim(item.substr(space)));
    at = next;
  }
  return trim(comment.substr(0, first));
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
        package_line_ = t.line;
      } else if (t.text == "struct") {
        if (!out.name.empty()) fail(t.line, "more than one struct in one file");
        out.name = identifier("struct name");
        structComment(out, t.line);
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
  // Every comment line after the package statement and before `struct` describes the struct.
  void structComment(LcmStruct& out, int struct_line) {
    std::string text;
    for (auto it = source_.line_comments.upper_bound(package_line_); it != source_.line_comments.end() && it->first < struct_line; ++it) {
      const std::string part = splitAnnotations(it->second, out.annotations);
      if (!part.empty()) text += (text.empty() ? "" : " ") + part;
    }
    out.comment = text;
  }

  void parseMembers(LcmStruct& out) {
    while (true) {
      if (atEnd()) fail(lastLine(), "missing '}'");
      if (peek().text == "}") {
        next();
        return;
      }
      if (peek().text == "const") {
        next();
        parseConstants(out);
        continue;
      }
      const Token type = next();
      if (!kPrimitiveTypes.count(type.text)) {
        fail(type.line, "field type '" + type.text + "' is not an LCM primitive; the generator supports primitives only");
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
          attachComment(declared, sep.line);
          break;
        }
        if (sep.text != ",") fail(sep.line, "expected ';' or ',' after field '" + field.name + "'");
      }
      for (LcmField& f : declared) out.fields.push_back(std::move(f));
    }
  }

  void parseConstants(LcmStruct& out) {
    const Token type = next();
    while (true) {
      LcmConst c;
      c.type = type.text;
      c.line = peek().line;
      c.name = identifier("constant name");
      expect("=");
      c.value = next().text;
      const Token sep = next();
      const auto comment = source_.line_comments.find(sep.line);
      if (comment != source_.line_comments.end()) c.comment = comment->second;
      out.constants.push_back(c);
      if (sep.text == ";") return;
      if (sep.text != ",") fail(sep.line, "expected ';' or ',' after constant '" + c.name + "'");
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

  void attachComment(std::vector<LcmField>& fields, int line) {
    const auto it = source_.line_comments.find(line);
    Annotations annotations;
    const std::string comment = it == source_.line_comments.end() ? std::string() : splitAnnotations(it->second, annotations);
    const size_t close = comment.find(']');
    if (comment.empty() || comment[0] != '[' || close == std::string::npos) {
      fail(line, "field '" + fields.front().name + "' needs a trailing comment starting with its [unit]");
    }
    const std::string unit = trim(comment.substr(1, close - 1));
    if (unit.empty()) fail(line, "field '" + fields.front().name + "' has an empty [unit]; use [-] for none");
    for (LcmField& f : fields) {
      f.unit = unit;
      f.comment = comment;
      f.annotations = annotations;
    }
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
  int package_line_ = 0;
};

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

std::string LcmField::annotation(const std::string& name) const {
  const auto it = annotations.find(name);
  return it == annotations.end() ? std::string() : it->second;
}

bool LcmStruct::hasUtimeAndSeq() const {
  return fields.size() >= 2 && fields[0].name == "utime" && fields[0].type == "int64_t" &&
         fields[0].dimensions.empty() && fields[1].name == "seq" && fields[1].type == "int64_t" &&
         fields[1].dimensions.empty();
}

const LcmField* LcmStruct::field(const std::string& name) const {
  for (const LcmField& f : fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
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

}  // namespace sdlqr::lcmgen
