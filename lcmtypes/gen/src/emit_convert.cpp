#include <sstream>

#include "emit_text.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {

namespace {

using Kind = Shape::Kind;

// Copies between a plain expression and an lcm-gen expression of one shape. `lcm_vector`: the
// field has a variable dimension, so lcm-gen holds every dimension as a std::vector.
class CopyEmitter {
 public:
  CopyEmitter(std::ostringstream& out, bool to_lcm) : out_(out), to_lcm_(to_lcm) {}

  // `count`: the length field of a variable-length array.
  void copy(const Shape& shape, const std::string& plain, const std::string& lcm, bool lcm_vector,
            const std::string& pad, int depth, const std::string& count = "") {
    switch (shape.kind) {
      case Kind::kScalar: line(pad, plain, lcm, lcm, plain); break;
      case Kind::kBool: line(pad, plain, lcm + " != 0", lcm, plain + " ? 1 : 0"); break;
      case Kind::kEnum:
        line(pad, plain, "static_cast<" + shape.cpp_type + ">(" + lcm + ")", lcm,
             "static_cast<" + shape.lcm_scalar + ">(" + plain + ")");
        break;
      case Kind::kEigen: eigen(shape, plain, lcm, lcm_vector, pad, depth); break;
      case Kind::kArray: {
        const std::string i = index(depth);
        if (to_lcm_ && lcm_vector) out_ << pad << lcm << ".resize(" << shape.size << ");\n";
        out_ << pad << "for (int " << i << " = 0; " << i << " < " << shape.size << "; ++" << i << ") {\n";
        copy(shape.inner.front(), plain + "[" + i + "]", lcm + "[" + i + "]", lcm_vector, pad + "  ", depth + 1);
        out_ << pad << "}\n";
        break;
      }
      case Kind::kVector: {
        const std::string i = index(depth);
        const std::string n = plain + ".size()";
        if (to_lcm_) {
          out_ << pad << lcm << ".resize(" << n << ");\n";
        } else {
          out_ << pad << plain << ".resize(::sdlqr::lcmtypes::rowCount(" << count << ", " << lcm << ".size()));\n";
        }
        out_ << pad << "for (size_t " << i << " = 0; " << i << " < " << n << "; ++" << i << ") {\n";
        copy(shape.inner.front(), plain + "[" + i + "]", lcm + "[" + i + "]", lcm_vector, pad + "  ", depth + 1);
        out_ << pad << "}\n";
        break;
      }
    }
  }

 private:
  static std::string index(int depth) { return "i" + std::to_string(depth); }

  void line(const std::string& pad, const std::string& plain, const std::string& from_lcm, const std::string& lcm,
            const std::string& from_plain) {
    if (to_lcm_) out_ << pad << lcm << " = " << from_plain << ";\n";
    else out_ << pad << plain << " = " << from_lcm << ";\n";
  }

  // A fixed-size Eigen type over a 1-D array (row-major into a matrix).
  void eigen(const Shape& shape, const std::string& plain, const std::string& lcm, bool lcm_vector,
             const std::string& pad, int depth) {
    const std::string i = index(depth);
    const std::string element = shape.eigen_cols > 1
                                    ? plain + "(" + i + " / " + std::to_string(shape.eigen_cols) + ", " + i + " % " +
                                          std::to_string(shape.eigen_cols) + ")"
                                    : plain + "[" + i + "]";
    if (to_lcm_ && lcm_vector) out_ << pad << lcm << ".resize(" << shape.size << ");\n";
    out_ << pad << "for (int " << i << " = 0; " << i << " < " << shape.size << "; ++" << i << ") ";
    if (to_lcm_) out_ << lcm << "[" << i << "] = " << element << ";\n";
    else out_ << element << " = " << lcm << "[" << i << "];\n";
  }

  std::ostringstream& out_;
  bool to_lcm_;
};

// A @rows member: the arrays sized by one length field, row by row.
void copyRows(std::ostringstream& out, const PlainModel& model, const PlainMember& group, bool to_lcm) {
  const PlainStruct* row = nullptr;
  for (const PlainStruct& r : model.rows) {
    if (r.name == group.row_type) row = &r;
  }
  const std::string rows = "s." + group.name;
  const std::string length = "m." + group.length_field->name;
  out << "  {\n";
  if (to_lcm) {
    out << "    " << length << " = static_cast<" << group.length_field->type << ">(" << rows << ".size());\n";
    for (const PlainMember& c : row->members) out << "    m." << c.field->name << ".resize(" << rows << ".size());\n";
  } else {
    out << "    " << rows << ".resize(::sdlqr::lcmtypes::rowCount(" << length;
    for (const PlainMember& c : row->members) out << ", m." << c.field->name << ".size()";
    out << "));\n";
  }
  out << "    for (size_t i0 = 0; i0 < " << rows << ".size(); ++i0) {\n";
  out << "      " << (to_lcm ? "const " : "") << row->name << "& row = " << rows << "[i0];\n";
  CopyEmitter copy(out, to_lcm);
  for (const PlainMember& c : row->members) {
    copy.copy(c.shape, "row." + c.name, "m." + c.field->name + "[i0]", true, "      ", 1);
  }
  out << "    }\n  }\n";
}

void copyMembers(std::ostringstream& out, const PlainModel& model, const PlainStruct& s, bool to_lcm) {
  CopyEmitter copy(out, to_lcm);
  for (const PlainMember& m : s.members) {
    if (!m.row_type.empty()) {
      copyRows(out, model, m, to_lcm);
      continue;
    }
    const LcmField& f = *m.field;
    if (to_lcm && f.hasVariableDimension()) {
      const LcmField* length = s.lcm->field(f.dimensions[0].length_field);
      out << "  m." << length->name << " = static_cast<" << length->type << ">(s." << m.name << ".size());\n";
    }
    const std::string count = f.hasVariableDimension() ? "m." + f.dimensions[0].length_field : std::string();
    copy.copy(m.shape, "s." + m.name, "m." + f.name, f.hasVariableDimension(), "  ", 0, count);
  }
}

}  // namespace

std::string emitConvertHeader(const PlainModel& model, const std::string& source_note) {
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// fromLcm / toLcm: field-for-field copies between the lcm-gen classes and the plain structs.\n"
                             "// Converting copies only; validation lives in the libraries. Types without a variable-length\n"
                             "// array or a string convert without allocating. An array count larger than its arrays (a\n"
                             "// message decode cannot produce) is cut to them.\n\n");
  out << "#include <cstddef>\n\n";
  out << "#include \"" << generatedInclude(model.package, "plain.hpp") << "\"\n";
  out << "#include \"sdlqr/lcmtypes/fields.hpp\"\n";
  for (const PlainStruct& s : model.structs) out << "#include \"" << text::lcmInclude(*s.lcm) << "\"\n";
  const std::string ns = text::packageNamespace(model.package);
  out << "\nnamespace " << ns << " {\n\n";
  for (const PlainStruct& s : model.structs) {
    const std::string lcm = text::lcmClass(*s.lcm);
    out << "inline " << s.name << " fromLcm(const " << lcm << "& m) {\n  " << s.name << " s;\n";
    copyMembers(out, model, s, false);
    out << "  return s;\n}\n\n";
    out << "inline " << lcm << " toLcm(const " << s.name << "& s) {\n  " << lcm << " m{};\n";
    copyMembers(out, model, s, true);
    out << "  return m;\n}\n\n";
  }
  out << "}  // namespace " << ns << "\n";
  return out.str();
}

}  // namespace sdlqr::lcmgen
