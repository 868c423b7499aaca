#include <cctype>
#include <set>
#include <sstream>

#include "emit_text.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {

namespace {

int primitiveBytes(const std::string& type) {
  if (type == "int8_t" || type == "boolean" || type == "byte") return 1;
  if (type == "int16_t") return 2;
  if (type == "int32_t" || type == "float") return 4;
  if (type == "int64_t" || type == "double") return 8;
  return 0;  // string: variable
}

// Walks the encoding field by field (see sdlqr/lcmtypes/wire_cursor.hpp): fixed-size runs are
// skipped, length fields read, strings skipped one by one, variable arrays checked against the
// bytes left.
void emitEncodingFits(std::ostringstream& out, const LcmStruct& t) {
  std::set<std::string> length_fields;
  for (const LcmField& f : t.fields) {
    for (const LcmDimension& d : f.dimensions) {
      if (d.variable()) length_fields.insert(d.length_field);
    }
  }
  out << "inline bool encodingFits(const " << text::lcmClass(t) << "*, const uint8_t* data, int64_t size) {\n";
  out << "  ::sdlqr::lcmtypes::wire::Cursor c{data, size, 0};\n";
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
      out << "    if (!::sdlqr::lcmtypes::wire::elementCount(count, " << factor << ", size, &count)) return false;\n";
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

std::string typeListMacro(const std::vector<LcmStruct>& types) {
  std::string name = "SDLQR_LCMTYPES_";
  for (char c : types.empty() ? std::string() : types.front().package) {
    name.push_back(c == '.' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return name + "_EACH";
}

std::string packageOf(const std::vector<LcmStruct>& types) { return types.empty() ? std::string() : types.front().package; }

}  // namespace

std::string emitDescriptorsHeader(const std::vector<LcmStruct>& types, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// Field descriptors and CSV columns of every LCM type (no LCM include).\n\n");
  out << "#include <cstddef>\n#include <string_view>\n\n#include \"sdlqr/lcmtypes/field_descriptor.hpp\"\n\n";
  const std::string ns = text::packageNamespace(packageOf(types)) + "::lcmtypes";
  out << "namespace " << ns << " {\n\n";
  out << "using ::sdlqr::lcmtypes::FieldDescriptor;\nusing ::sdlqr::lcmtypes::TypeDescriptor;\n\n";
  for (const LcmStruct& t : types) {
    const std::string id = text::descriptorName(t);
    out << "// " << t.package << "." << t.name << " (" << t.file << ")\n";
    out << "inline constexpr FieldDescriptor " << id << "Fields[] = {\n";
    for (const LcmField& f : t.fields) {
      out << "    {" << text::quoted(f.name) << ", " << text::quoted(f.type) << ", " << text::quoted(f.unit) << ", "
          << f.dimensions.size() << ", {";
      for (size_t k = 0; k < static_cast<size_t>(kMaxDimensions); ++k) {
        const LcmDimension d = k < f.dimensions.size() ? f.dimensions[k] : LcmDimension{};
        out << (k ? ", " : "") << "{" << d.size << ", " << text::quoted(d.length_field) << "}";
      }
      out << "}},\n";
    }
    out << "};\n";
    out << "inline constexpr std::string_view " << id << "Columns[] = {\n";
    for (const std::string& c : csvColumns(t)) out << "    " << text::quoted(c) << ",\n";
    out << "};\n";
    out << "inline constexpr TypeDescriptor " << id << "{" << text::quoted(t.name) << ", " << id << "Fields, "
        << t.fields.size() << ", " << id << "Columns, " << csvColumns(t).size() << "};\n\n";
  }
  out << "inline constexpr const TypeDescriptor* kAllTypes[] = {\n";
  for (const LcmStruct& t : types) out << "    &" << text::descriptorName(t) << ",\n";
  out << "};\n\n";
  out << "inline const TypeDescriptor* findType(std::string_view name) {\n";
  out << "  for (const TypeDescriptor* t : kAllTypes) {\n    if (t->name == name) return t;\n  }\n  return nullptr;\n}\n\n";
  out << "}  // namespace " << ns << "\n";
  return out.str();
}

std::string emitLcmFieldsHeader(const std::vector<LcmStruct>& types, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// LcmFields<T>::visit(v, m...) calls v(FieldDescriptor, m.field...) for every field of the\n"
                             "// lcm-gen class T in wire order; LcmFields<T>::type is its descriptor. visitLcmType maps a\n"
                             "// type name to its class; " + typeListMacro(types) + "(X) calls X(class) for every type.\n\n");
  out << "#include <string_view>\n\n";
  out << "#include \"" << generatedInclude(packageOf(types), "descriptors.hpp") << "\"\n";
  out << "#include \"sdlqr/lcmtypes/fields.hpp\"\n";
  for (const LcmStruct& t : types) out << "#include \"" << text::lcmInclude(t) << "\"\n";
  const std::string ns = text::packageNamespace(packageOf(types)) + "::lcmtypes";
  out << "\nnamespace sdlqr::lcmtypes {\n\n";
  for (const LcmStruct& t : types) {
    const std::string id = "::" + ns + "::" + text::descriptorName(t);
    out << "template <>\nstruct LcmFields<" << text::lcmClass(t) << "> {\n";
    out << "  static constexpr const TypeDescriptor& type = " << id << ";\n";
    out << "  template <class Visitor, class... Messages>\n";
    out << "  static void visit(Visitor&& v, Messages&&... m) {\n";
    for (size_t i = 0; i < t.fields.size(); ++i) {
      out << "    v(" << id << "Fields[" << i << "], m." << t.fields[i].name << "...);\n";
    }
    out << "  }\n};\n\n";
  }
  out << "}  // namespace sdlqr::lcmtypes\n\n";
  out << "namespace " << ns << " {\n\n";
  out << "// Calls visit(TypeTag<T>{}) for the lcm-gen class named `name`; false if unknown.\n";
  out << "template <class Visitor>\nbool visitLcmType(std::string_view name, Visitor&& visit) {\n";
  for (const LcmStruct& t : types) {
    out << "  if (name == " << text::quoted(t.name) << ") {\n    visit(::sdlqr::lcmtypes::TypeTag<" << text::lcmClass(t)
        << ">{});\n    return true;\n  }\n";
  }
  out << "  return false;\n}\n\n";
  out << "}  // namespace " << ns << "\n\n";
  out << "#define " << typeListMacro(types) << "(X)";
  for (const LcmStruct& t : types) out << " \\\n  X(" << text::lcmClass(t) << ")";
  out << "\n";
  return out.str();
}

std::string emitWireFitsHeader(const std::vector<LcmStruct>& types, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// encodingFits(static_cast<const T*>(nullptr), data, size): the bytes hold exactly one\n"
                             "// complete encoding of T, checked before an lcm-gen decoder runs and without allocating\n"
                             "// (see sdlqr/lcmtypes/wire_cursor.hpp).\n\n");
  out << "#include <cstdint>\n\n#include \"sdlqr/lcmtypes/wire_cursor.hpp\"\n";
  for (const LcmStruct& t : types) out << "#include \"" << text::lcmInclude(t) << "\"\n";
  const std::string ns = text::packageNamespace(packageOf(types)) + "::lcmtypes";
  out << "\nnamespace " << ns << " {\n\n";
  for (const LcmStruct& t : types) emitEncodingFits(out, t);
  out << "}  // namespace " << ns << "\n";
  return out.str();
}

}  // namespace sdlqr::lcmgen
