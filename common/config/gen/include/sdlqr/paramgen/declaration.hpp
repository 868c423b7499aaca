#pragma once
// A parameter declaration file (<component>/params/<name>.yaml): the rows of one or more
// ParamTable sections as data. sdlqr_paramgen turns each file into a header of functions that add
// the rows, in the file's order, to a table (emitRows); the hand-written declaration() keeps what
// is logic (the t.check rules, rows built in code). The format, one entry per row:
//
//   header: sdlqr/lowlevel/mixer.hpp     # the structs' header (absent: the includer declares them)
//   namespace: sdlqr::lowlevel
//   sections:
//     - struct: MixerParams
//       help: control allocation with sequential desaturation
//       rows:
//         - key: yaw_collective_share   # field: <member> when the member is named otherwise
//           type: number                # number, integer, flag, choice, list, derived_list, section
//           default: 0.15               # written into the C++ as it is spelled here
//           unit: "-"
//           range: "[0.0, 1.0]"         # finite, > a, >= a, [a, b], (a, b), (a, b], [a, b)
//           doc: collective thrust yaw may take (or add)
//           in_flight: kLimits          # optional: the PARAMS group (ParamsUpdate::kLimits)
//         - code: addTrackingRow        # a row built in code: void addTrackingRow(ParamTable<S>&)
//
// choice: `choices:` maps each word to its enumerator, `default:` is a word; list: `size:` and a
// sequence default; derived_list: `size`, `placeholder` and the functions `derive`, `get`, `set`
// (ParamTable::derivedList). A default may name a C++ constant the code shares (kDefaultGravity):
// its range is then checked by a static_assert in the generated code.
// Every error is a DeclarationError, one line naming the file and the key.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sdlqr::paramgen {

struct DeclarationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An accepted interval as written ("(0, 5]") and as numbers, for the default's check.
struct RangeSpec {
  std::string factory = "finite";  // the Range:: factory: finite, above, atLeast, closed, open, ...
  std::string low_text, high_text;  // the bounds as written (empty when absent)
  double low = 0.0, high = 0.0;
  bool has_low = false, has_high = false, low_open = false, high_open = false;
  bool contains(double value) const;
  std::string cpp() const;  // "Range::openClosed(0, 5)"
};
// Throws std::invalid_argument with the reason on text it cannot read.
RangeSpec parseRange(const std::string& text);

struct Row {
  std::string type;  // number, integer, flag, choice, list, derived_list, section, code
  std::string key, field, unit, doc, in_flight;
  std::vector<std::string> defaults;  // one scalar, or a list's elements, as written
  int size = 1;
  RangeSpec range;
  std::vector<std::pair<std::string, std::string>> choices;  // word, enumerator
  std::string placeholder, derive, get, set;  // derived_list
  std::string code;                           // code: the function that adds the row
  const std::string& member() const { return field.empty() ? key : field; }
};

struct Section {
  std::string name;  // the struct
  std::string help;
  std::vector<Row> rows;
};

struct Declaration {
  std::string file;  // as named in errors
  std::string header;
  std::string name_space;
  std::vector<Section> sections;
};

Declaration parseDeclaration(const std::string& yaml_text, const std::string& file);
// The header adding each section's rows: ParamTable<S> <lowerCamel S>Rows() per section.
std::string emitRows(const Declaration& declaration);
std::string rowsFunctionName(const std::string& struct_name);  // MixerParams -> mixerParamsRows

}  // namespace sdlqr::paramgen
