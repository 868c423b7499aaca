// The parameter declaration generator (common/config/gen): what it reads from a declaration file,
// the ParamTable calls it writes, and each refusal by its one-line message naming file and key.

#include <string>

#include <gtest/gtest.h>

#include "sdlqr/paramgen/declaration.hpp"

namespace {

using sdlqr::paramgen::DeclarationError;
using sdlqr::paramgen::emitRows;
using sdlqr::paramgen::parseDeclaration;
using sdlqr::paramgen::parseRange;

// One section with a row of every type, numbers spelled as the C++ would not print them.
const char* const kDeclaration = R"yaml(
header: sdlqr/probe/probe.hpp
namespace: sdlqr::probe
sections:
  - struct: ProbeParams
    help: "a probe section"
    rows:
      - key: rate_hz
        type: number
        default: 100.0
        unit: Hz
        range: "[1.0, 1000.0]"
        doc: "control rate"
        in_flight: kLimits
      - key: noise
        field: noise_density
        type: number
        default: 5e-4
        unit: "rad/s/sqrt(Hz)"
        range: "> 0.0"
        doc: "white noise"
      - key: count
        type: integer
        default: 3
        unit: "-"
        range: ">= 1"
        doc: "a count"
      - key: gravity
        type: number
        default: kDefaultGravity
        unit: "m/s^2"
        range: "(0.0, 100.0)"
        doc: "gravity"
      - code: addTrackingRow
      - key: gain
        type: list
        size: 3
        default: [5.61, 9.10, 29.7]
        unit: "1/s"
        range: "(0, 50]"
        doc: "kp x, y, z"
      - key: mode
        type: choice
        default: scale
        choices: {refuse: Mode::kRefuse, scale: Mode::kScale}
        doc: "refused or scaled"
      - key: enabled
        type: flag
        default: true
        doc: "on or off"
      - key: guard
        type: section
      - key: rotor_xy
        type: derived_list
        size: 2
        unit: m
        range: finite
        doc: "positions"
        placeholder: "[x0, y0]"
        derive: layout
        get: flat
        set: setFlat
)yaml";

// kDeclaration with the first `from` replaced by `to` (the faults below are in the gain row).
std::string replacedOnce(const std::string& from, const std::string& to) {
  std::string text = kDeclaration;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string declarationError(const std::string& text) {
  try {
    parseDeclaration(text, "probe/params/probe.yaml");
  } catch (const DeclarationError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(ParamGen, ReadsEveryTypeKeepingNumbersAsWritten) {
  const auto declaration = parseDeclaration(kDeclaration, "probe.yaml");
  ASSERT_EQ(declaration.sections.size(), 1u);
  const auto& rows = declaration.sections[0].rows;
  ASSERT_EQ(rows.size(), 10u);
  EXPECT_EQ(rows[0].defaults[0], "100.0");
  EXPECT_EQ(rows[1].defaults[0], "5e-4");
  EXPECT_EQ(rows[1].member(), "noise_density");
  EXPECT_EQ(rows[4].type, "code");
  EXPECT_EQ(rows[5].defaults, (std::vector<std::string>{"5.61", "9.10", "29.7"}));
  EXPECT_EQ(rows[6].defaults[0], "Mode::kScale");
}

TEST(ParamGen, EmitsOneCallPerRowInOrder) {
  const std::string text = emitRows(parseDeclaration(kDeclaration, "probe/params/probe.yaml"));
  const char* const calls[] = {
      "#include \"sdlqr/probe/probe.hpp\"",
      "void addTrackingRow(ParamTable<ProbeParams>& t);",
      "ParamTable<ProbeParams> probeParamsRows() {",
      "static_assert(kDefaultGravity > 0.0 && kDefaultGravity < 100.0,",
      "ParamTable<P> t(\"a probe section\");",
      "t.number(\"rate_hz\", &P::rate_hz, 100.0, \"Hz\", Range::closed(1.0, 1000.0), \"control rate\")"
      ".inFlight(ParamsUpdate::kLimits);",
      "t.number(\"noise\", &P::noise_density, 5e-4, \"rad/s/sqrt(Hz)\", Range::above(0.0), \"white noise\");",
      "t.integer(\"count\", &P::count, 3, \"-\", Range::atLeast(1), \"a count\");",
      "t.number(\"gravity\", &P::gravity, kDefaultGravity, \"m/s^2\", Range::open(0.0, 100.0), \"gravity\");",
      "addTrackingRow(t);",
      "t.list<3>(\"gain\", &P::gain, {5.61, 9.10, 29.7}, \"1/s\", Range::openClosed(0, 50), \"kp x, y, z\");",
      "t.choice(\"mode\", &P::mode, Mode::kScale, {{\"refuse\", Mode::kRefuse}, {\"scale\", Mode::kScale}}, "
      "\"refused or scaled\");",
      "t.flag(\"enabled\", &P::enabled, true, \"on or off\");",
      "t.section(\"guard\", &P::guard);",
      "t.derivedList<2>(\"rotor_xy\", \"m\", Range::finite(), \"positions\", \"[x0, y0]\", layout, flat, setFlat);",
  };
  size_t at = 0;
  for (const char* call : calls) {
    const size_t found = text.find(call, at);
    ASSERT_NE(found, std::string::npos) << "missing or out of order: " << call << "\n" << text;
    at = found;
  }
  EXPECT_NE(text.find("ParamTable<ProbeParams>::List<2> flat(const ProbeParams& p);"), std::string::npos);
}

TEST(ParamGen, RangeSyntaxMapsOntoTheRangeFactories) {
  const std::pair<const char*, const char*> written_and_cpp[] = {
      {"finite", "Range::finite()"},           {"> 0.0", "Range::above(0.0)"},
      {">= 0", "Range::atLeast(0)"},           {"[1, 255]", "Range::closed(1, 255)"},
      {"(0, 1)", "Range::open(0, 1)"},         {"(0.0, 5.0]", "Range::openClosed(0.0, 5.0)"},
      {"[0.0, 1.0)", "Range::closedOpen(0.0, 1.0)"},
  };
  for (const auto& [written, cpp] : written_and_cpp) EXPECT_EQ(parseRange(written).cpp(), cpp) << written;
  EXPECT_TRUE(parseRange("(0, 5]").contains(5.0));
  EXPECT_FALSE(parseRange("(0, 5]").contains(0.0));
}

TEST(ParamGen, RefusesEachFaultWithOneLineNamingFileAndKey) {
  const std::string file = "probe/params/probe.yaml: ProbeParams.";
  EXPECT_EQ(declarationError(replacedOnce("type: list", "type: lsit")), file + "gain: unknown type 'lsit'");
  EXPECT_EQ(declarationError(replacedOnce("        unit: \"1/s\"\n", "")), file + "gain: missing unit");
  EXPECT_EQ(declarationError(replacedOnce("        doc: \"kp x, y, z\"\n", "")), file + "gain: missing doc");
  EXPECT_EQ(declarationError(replacedOnce("        default: [5.61, 9.10, 29.7]\n", "")), file + "gain: missing default");
  EXPECT_EQ(declarationError(replacedOnce("range: \"(0, 50]\"", "range: \"(0, 50\"")),
            file + "gain: bad range \"(0, 50\": expected finite, > a, >= a or an interval like (a, b]");
  EXPECT_EQ(declarationError(replacedOnce("range: \"(0, 50]\"", "range: \"> zero\"")),
            file + "gain: bad range \"> zero\": 'zero' is not a finite number");
  EXPECT_EQ(declarationError(replacedOnce("key: gain", "key: count")), file + "count: duplicate key");
  EXPECT_EQ(declarationError(replacedOnce("[5.61, 9.10, 29.7]", "[5.61, 90.1, 29.7]")),
            file + "gain: default 90.1 outside (0, 50]");
  EXPECT_EQ(declarationError(replacedOnce("        size: 3\n", "        size: 3\n        colour: red\n")),
            file + "gain: unknown field 'colour'");
}

TEST(ParamGen, RefusesDefaultsTheTableCouldNotHold) {
  const std::string file = "probe/params/probe.yaml: ProbeParams.";
  std::string text = kDeclaration;
  EXPECT_EQ(declarationError(text.replace(text.find("default: 3"), 10, "default: 0")), file + "count: default 0 outside >= 1");
  text = kDeclaration;
  EXPECT_EQ(declarationError(text.replace(text.find("default: 3"), 10, "default: 2.5")),
            file + "count: default '2.5' is not a whole number");
  text = kDeclaration;
  EXPECT_EQ(declarationError(text.replace(text.find("default: scale"), 14, "default: clamp")),
            file + "mode: default 'clamp' is not one of the choices");
  EXPECT_EQ(declarationError(replacedOnce("[5.61, 9.10, 29.7]", "[5.61, 9.10]")),
            file + "gain: default must be a list of 3 numbers");
}

}  // namespace
