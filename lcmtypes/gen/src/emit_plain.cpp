#include <sstream>

#include "emit_text.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {

namespace {

void emitComment(std::ostringstream& out, const std::string& comment) {
  if (!comment.empty()) out << "  // " << comment;
  out << "\n";
}

void emitEnum(std::ostringstream& out, const PlainEnum& e) {
  out << "// " << e.defined_in << "\n";
  out << "enum class " << e.name << " : " << e.underlying << " {\n";
  for (const PlainConstant& v : e.values) {
    out << "  " << v.name << " = " << v.value << ",";
    emitComment(out, v.comment);
  }
  out << "};\n\n";
}

void emitStruct(std::ostringstream& out, const PlainStruct& s) {
  const std::string origin = s.lcm ? s.lcm->name + ": " : std::string();
  if (!s.comment.empty() || s.lcm) out << "// " << origin << s.comment << "\n";
  out << "struct " << s.name << " {\n";
  for (const PlainConstant& c : s.constants) {
    out << "  static constexpr " << c.type << " " << c.name << " = " << c.value << ";";
    emitComment(out, c.comment);
  }
  if (!s.constants.empty()) out << "\n";
  for (const PlainMember& m : s.members) {
    out << "  " << m.shape.cpp_type << " " << m.name;
    if (!m.shape.init.empty()) out << " = " << m.shape.init;
    out << ";";
    emitComment(out, m.comment);
  }
  if (!s.methods.empty()) out << "\n  // Defined by hand beside this header (the .lcm file's @method).\n";
  for (const std::string& method : s.methods) out << "  " << method << ";\n";
  out << "};\n\n";
}

// Eigen aliases of common/math/types.hpp that another package's structs name.
void emitAliases(std::ostringstream& out, const PlainModel& model) {
  if (model.package == "sdlqr") return;
  for (const char* name : {"Vec3", "Vec4", "Quat", "State", "Input", "GainMatrix", "Mat4", "identityQuat"}) {
    out << "using ::sdlqr::" << name << ";\n";
  }
  out << "\n";
}

std::string fieldInfo(const PlainMember& m) {
  const std::string unit = m.field ? m.field->unit : std::string();
  return "::sdlqr::lcmtypes::PlainField{" + text::quoted(m.name) + ", " + text::quoted(unit) + ", " +
         (m.wall_time ? "true" : "false") + "}";
}

void emitFields(std::ostringstream& out, const std::string& ns, const PlainStruct& s) {
  out << "template <>\ninline constexpr bool kIsPlainStruct<::" << ns << "::" << s.name << "> = true;\n";
  out << "template <>\nstruct PlainFields<::" << ns << "::" << s.name << "> {\n";
  out << "  static constexpr std::string_view kName = " << text::quoted(s.name) << ";\n";
  out << "  template <class Visitor, class... Structs>\n";
  out << "  static void visit(Visitor&& v, Structs&&... s) {\n";
  for (const PlainMember& m : s.members) out << "    v(" << fieldInfo(m) << ", s." << m.name << "...);\n";
  out << "  }\n};\n\n";
}

}  // namespace

std::string emitPlainHeader(const PlainModel& model, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// Plain message structs: what the libraries exchange, one per LCM type, field for field\n"
                             "// (units and frames as in the .lcm files). convert.hpp converts to and from the lcm-gen\n"
                             "// classes, so those never reach algorithm code and the in-process loop needs no bus.\n\n");
  out << "#include <array>\n#include <cstdint>\n#include <string>\n#include <vector>\n\n";
  out << "#include \"sdlqr/math/types.hpp\"\n\n";
  out << "namespace " << text::packageNamespace(model.package) << " {\n\n";
  emitAliases(out, model);
  for (const PlainEnum& e : model.enums) emitEnum(out, e);
  for (const PlainStruct& row : model.rows) emitStruct(out, row);
  for (const PlainStruct& s : model.structs) emitStruct(out, s);
  out << "}  // namespace " << text::packageNamespace(model.package) << "\n";
  return out.str();
}

std::string emitPlainFieldsHeader(const PlainModel& model, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// PlainFields<T>::visit(v, s...) calls v(PlainField, s.member...) for every member of the\n"
                             "// plain struct T in declaration order (see sdlqr/lcmtypes/fields.hpp).\n\n");
  out << "#include <string_view>\n\n";
  out << "#include \"" << generatedInclude(model.package, "plain.hpp") << "\"\n";
  out << "#include \"sdlqr/lcmtypes/fields.hpp\"\n\n";
  out << "namespace sdlqr::lcmtypes {\n\n";
  const std::string ns = text::packageNamespace(model.package);
  for (const PlainStruct& row : model.rows) emitFields(out, ns, row);
  for (const PlainStruct& s : model.structs) emitFields(out, ns, s);
  out << "}  // namespace sdlqr::lcmtypes\n";
  return out.str();
}

}  // namespace sdlqr::lcmgen
