#include "sdlqr/lcmgen/plain_model.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

namespace sdlqr::lcmgen {

namespace {

const std::vector<EigenType>& eigenTypes() {
  static const std::vector<EigenType> types = {
      {"Vec3", 3, 1, "Vec3::Zero()"},   {"Vec4", 4, 1, "Vec4::Zero()"},   {"Quat", 4, 1, "identityQuat()"},
      {"State", 10, 1, "State::Zero()"}, {"Input", 4, 1, "Input::Zero()"}, {"GainMatrix", 40, 10, "GainMatrix::Zero()"},
      {"Mat4", 16, 4, "Mat4::Zero()"},
  };
  return types;
}

const EigenType* findEigen(const std::string& name) {
  for (const EigenType& t : eigenTypes()) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

// A double array of this length without @as.
const EigenType* defaultEigen(int elements) {
  if (elements == 3) return findEigen("Vec3");
  if (elements == 4) return findEigen("Vec4");
  if (elements == 10) return findEigen("State");
  return nullptr;
}

std::string cppScalar(const std::string& lcm_type) {
  if (lcm_type == "string") return "std::string";
  if (lcm_type == "boolean") return "int8_t";
  if (lcm_type == "byte") return "uint8_t";
  return lcm_type;
}

std::string zeroOf(const std::string& lcm_type) {
  if (lcm_type == "string") return "";
  if (lcm_type == "double") return "0.0";
  if (lcm_type == "float") return "0.0f";
  return "0";
}

[[noreturn]] void fail(const LcmStruct& s, int line, const std::string& what) {
  throw LcmSchemaError(s.file + ":" + std::to_string(line) + ": " + what);
}

class Builder {
 public:
  explicit Builder(const std::vector<LcmStruct>& types) : types_(types) {}

  PlainModel build() {
    if (!types_.empty()) model_.package = types_.front().package;
    for (const LcmStruct& s : types_) {
      if (s.package != model_.package) fail(s, 1, "package '" + s.package + "' differs from '" + model_.package + "'");
      declareEnums(s);
    }
    for (const LcmStruct& s : types_) model_.structs.push_back(buildStruct(s));
    return model_;
  }

 private:
  // `@enum Name PREFIX_` on a field declares the enum from the constants PREFIX_*.
  void declareEnums(const LcmStruct& s) {
    for (const LcmField& f : s.fields) {
      const std::string spec = f.annotation("enum");
      const size_t space = spec.find(' ');
      if (spec.empty() || space == std::string::npos) continue;
      PlainEnum e;
      e.name = spec.substr(0, space);
      const std::string prefix = stripStar(spec.substr(space + 1));
      e.underlying = cppScalar(f.type);
      e.defined_in = s.name + "." + f.name + " " + prefix + "*";
      for (const LcmConst& c : s.constants) {
        if (c.name.rfind(prefix, 0) != 0) continue;
        if (c.type != f.type) fail(s, c.line, "constant " + c.name + " is " + c.type + ", enum field '" + f.name + "' is " + f.type);
        e.values.push_back({constantName(c.name.substr(prefix.size())), c.type, c.value, c.comment});
        enum_constants_[e.name][c.name] = e.values.back().name;
      }
      if (e.values.empty()) fail(s, f.line, "@enum " + e.name + ": no constant starts with " + prefix);
      for (const PlainEnum& other : model_.enums) {
        if (other.name == e.name) fail(s, f.line, "enum " + e.name + " is declared twice");
      }
      model_.enums.push_back(e);
    }
  }

  static std::string stripStar(std::string prefix) {
    if (!prefix.empty() && prefix.back() == '*') prefix.pop_back();
    return prefix;
  }

  const PlainEnum* findEnum(const std::string& name) const {
    for (const PlainEnum& e : model_.enums) {
      if (e.name == name) return &e;
    }
    return nullptr;
  }

  PlainStruct buildStruct(const LcmStruct& s) {
    PlainStruct out;
    out.lcm = &s;
    out.comment = s.comment;
    const auto plain = s.annotations.find("plain");
    if (plain == s.annotations.end() || plain->second.empty()) fail(s, 1, "struct " + s.name + " needs @plain <Name> in its comment");
    out.name = plain->second;
    for (auto [it, end] = s.annotations.equal_range("method"); it != end; ++it) out.methods.push_back(it->second);
    out.channel = channelOf(s);

    std::map<std::string, std::vector<const LcmField*>> sized_by;  // length field -> arrays
    for (const LcmField& f : s.fields) {
      for (size_t k = 0; k < f.dimensions.size(); ++k) {
        if (!f.dimensions[k].variable()) continue;
        if (k != 0) fail(s, f.line, "field '" + f.name + "': only the first dimension may be variable");
        sized_by[f.dimensions[k].length_field].push_back(&f);
      }
    }
    for (const LcmField& f : s.fields) {
      if (f.has("flags")) addFlags(s, f, out);
      const auto arrays = sized_by.find(f.name);
      if (arrays != sized_by.end()) {
        addLengthField(s, f, arrays->second, out);
      } else if (!f.hasVariableDimension() || !inRowGroup(s, f)) {
        out.members.push_back(member(s, f));
      }
    }
    return out;
  }

  // `@channel STATE_EST [StateEstimate]`: the identifier defaults to the type's name without _t.
  static PlainChannel channelOf(const LcmStruct& s) {
    PlainChannel out;
    const auto channel = s.annotations.find("channel");
    if (channel == s.annotations.end()) {
      if (s.annotations.count("split_port")) fail(s, 1, "@split_port without @channel");
      return out;
    }
    std::istringstream words(channel->second);
    words >> out.name >> out.id;
    const bool upper_snake = !out.name.empty() && std::all_of(out.name.begin(), out.name.end(), [](char c) {
      return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
    });
    if (!upper_snake) fail(s, 1, "@channel needs an UPPER_SNAKE name, got '" + channel->second + "'");
    if (out.id.empty()) {
      std::string stem = s.name.size() > 2 && s.name.compare(s.name.size() - 2, 2, "_t") == 0
                             ? s.name.substr(0, s.name.size() - 2) : s.name;
      for (char& c : stem) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      out.id = constantName(stem).substr(1);
    }
    const auto port = s.annotations.find("split_port");
    if (port != s.annotations.end()) {
      const std::string& text = port->second;
      const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
      if (!digits || text.size() > 3 || std::stoi(text) < 1) fail(s, 1, "@split_port needs a port offset from 1 to 999, got '" + text + "'");
      out.split_port = std::stoi(text);
    }
    return out;
  }

  // An array sized by a length field with @rows is a member of the rows, not of the struct.
  static bool inRowGroup(const LcmStruct& s, const LcmField& f) {
    return s.field(f.dimensions[0].length_field)->has("rows");
  }

  void addFlags(const LcmStruct& s, const LcmField& f, PlainStruct& out) {
    const std::string prefix = stripStar(f.annotation("flags"));
    for (const LcmConst& c : s.constants) {
      if (c.name.rfind(prefix, 0) == 0) {
        out.constants.push_back({constantName(c.name.substr(prefix.size())), cppScalar(c.type), c.value, c.comment});
      }
    }
    if (out.constants.empty()) fail(s, f.line, "@flags: no constant starts with " + prefix);
  }

  // A length field is not a plain member: the plain side holds a std::vector (one array) or a
  // std::vector of rows (@rows, several arrays), and its size is the count.
  void addLengthField(const LcmStruct& s, const LcmField& length, const std::vector<const LcmField*>& arrays,
                      PlainStruct& out) {
    const std::string rows = length.annotation("rows");
    if (rows.empty()) {
      if (arrays.size() > 1) fail(s, length.line, "'" + length.name + "' sizes several arrays: add @rows <member> <RowType>");
      return;  // the one array becomes a std::vector member where it is declared
    }
    const size_t space = rows.find(' ');
    if (space == std::string::npos) fail(s, length.line, "@rows needs <member> <RowType>");
    PlainMember group;
    group.name = rows.substr(0, space);
    group.row_type = rows.substr(space + 1);
    group.length_field = &length;
    group.comment = length.name + " rows of";
    for (const LcmField* f : arrays) group.comment += (f == arrays.front() ? " " : ", ") + f->name;
    group.comment += "; " + length.comment;
    PlainStruct row;
    row.name = group.row_type;
    row.comment = "One row of " + out.name + "::" + group.name + " (" + s.name + " arrays sized by " + length.name + ").";
    for (const LcmField* f : arrays) {
      PlainMember m = member(s, *f, /*row_element=*/true);
      const std::string renamed = f->annotation("row");
      if (!renamed.empty()) m.name = renamed;
      row.members.push_back(m);
    }
    model_.rows.push_back(row);
    group.shape.kind = Shape::Kind::kVector;
    group.shape.cpp_type = "std::vector<" + group.row_type + ">";
    out.members.push_back(group);
  }

  // The member mirroring `f`; a row element takes the shape below the leading dimension.
  PlainMember member(const LcmStruct& s, const LcmField& f, bool row_element = false) {
    PlainMember m;
    m.name = f.name;
    m.comment = f.comment;
    m.field = &f;
    m.wall_time = f.has("wall_time");
    m.shape = shape(s, f, row_element ? 1 : 0);
    const std::string value = f.annotation("default");
    if (!value.empty()) {
      if (m.shape.kind == Shape::Kind::kEnum) {
        const auto& names = enum_constants_[m.shape.cpp_type];
        const auto it = names.find(value);
        if (it == names.end()) fail(s, f.line, "@default " + value + " is not a constant of enum " + m.shape.cpp_type);
        m.shape.init = m.shape.cpp_type + "::" + it->second;
      } else {
        m.shape.init = value;
      }
    }
    return m;
  }

  // The shape of dimensions [k, end) of `f`.
  Shape shape(const LcmStruct& s, const LcmField& f, size_t k) {
    Shape out;
    out.lcm_scalar = cppScalar(f.type);
    if (k == f.dimensions.size()) return leaf(s, f);
    int elements = 1;
    for (size_t j = k; j < f.dimensions.size(); ++j) elements *= f.dimensions[j].variable() ? 0 : f.dimensions[j].size;
    // @as names the type of the last, fixed dimension.
    const std::string as = f.annotation("as");
    if (!as.empty() && f.type != "double") {
      fail(s, f.line, "@as " + as + " on '" + f.name + "': only double arrays and int8_t scalars take @as");
    }
    if (elements > 0 && f.type == "double" && f.dimensions.size() - k == 1) {
      const EigenType* eigen = as.empty() ? defaultEigen(elements) : findEigen(as);
      if (!as.empty() && !eigen) fail(s, f.line, "@as " + as + ": not one of Vec3 Vec4 Quat State Input GainMatrix Mat4");
      if (eigen) {
        if (eigen->elements != elements) {
          fail(s, f.line, "@as " + as + " holds " + std::to_string(eigen->elements) + " numbers, '" + f.name + "' " +
                              std::to_string(elements));
        }
        out.kind = Shape::Kind::kEigen;
        out.cpp_type = eigen->name;
        out.init = eigen->init;
        out.size = elements;
        out.eigen_cols = eigen->cols;
        return out;
      }
    }
    out.inner.push_back(shape(s, f, k + 1));
    const Shape& element = out.inner.front();
    if (f.dimensions[k].variable()) {
      out.kind = Shape::Kind::kVector;
      out.cpp_type = "std::vector<" + element.cpp_type + ">";
    } else {
      out.kind = Shape::Kind::kArray;
      out.size = f.dimensions[k].size;
      out.cpp_type = "std::array<" + element.cpp_type + ", " + std::to_string(out.size) + ">";
      out.init = "{}";
    }
    return out;
  }

  Shape leaf(const LcmStruct& s, const LcmField& f) {
    Shape out;
    out.lcm_scalar = cppScalar(f.type);
    out.cpp_type = out.lcm_scalar;
    out.init = zeroOf(f.type);
    const std::string as = f.annotation("as");
    const std::string enum_spec = f.annotation("enum");
    if (as == "bool") {
      if (f.type != "int8_t" && f.type != "boolean") fail(s, f.line, "@as bool needs an int8_t field");
      out.kind = Shape::Kind::kBool;
      out.cpp_type = "bool";
      out.init = "false";
    } else if (!as.empty() && f.dimensions.empty()) {
      fail(s, f.line, "@as " + as + " on a scalar: only @as bool");
    } else if (!enum_spec.empty()) {
      const std::string name = enum_spec.substr(0, enum_spec.find(' '));
      const PlainEnum* e = findEnum(name);
      if (!e) fail(s, f.line, "@enum " + name + " is declared by no field (write @enum " + name + " PREFIX_ where its constants are)");
      if (e->underlying != out.lcm_scalar) fail(s, f.line, "@enum " + name + " is " + e->underlying + ", '" + f.name + "' is " + f.type);
      out.kind = Shape::Kind::kEnum;
      out.cpp_type = name;
      out.init = name + "::" + e->values.front().name;
    }
    return out;
  }

  const std::vector<LcmStruct>& types_;
  PlainModel model_;
  std::map<std::string, std::map<std::string, std::string>> enum_constants_;  // enum -> LCM name -> kName
};

}  // namespace

std::string constantName(const std::string& upper_snake) {
  std::string out = "k";
  bool upper = true;
  for (char c : upper_snake) {
    if (c == '_') {
      upper = true;
      continue;
    }
    out.push_back(upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c)))
                        : static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    upper = false;
  }
  return out;
}

PlainModel buildPlainModel(const std::vector<LcmStruct>& types) { return Builder(types).build(); }

}  // namespace sdlqr::lcmgen
