// sdlqr-gains --once: its parsing and JSON library, and the built executable itself (found via
// SDLQR_BINARY_DIR): the JSON parses strictly, its K equals the library's K digit for digit, and
// every bad input exits with code 2 and one line on stderr.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/gains/gains_cli.hpp"
#include "test_paths.hpp"

namespace sdlqr {
namespace {

// --- a small strict JSON reader (RFC 8259 values; enough to reject anything malformed) ---
struct Json {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject } kind = Kind::kNull;
  double number = 0.0;
  bool boolean = false;
  std::string text;
  std::vector<Json> items;
  std::map<std::string, Json> fields;

  const Json& operator[](const std::string& key) const {
    const auto it = fields.find(key);
    if (it == fields.end()) throw std::runtime_error("missing key " + key);
    return it->second;
  }
};

class JsonParser {
 public:
  explicit JsonParser(const std::string& text) : s_(text) {}
  Json parseDocument() {
    Json value = parseValue();
    skipSpace();
    if (pos_ != s_.size()) fail("trailing characters");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& why) {
    throw std::runtime_error("JSON error at " + std::to_string(pos_) + ": " + why);
  }
  void skipSpace() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\n' || s_[pos_] == '\r' || s_[pos_] == '\t')) ++pos_;
  }
  char peek() {
    skipSpace();
    if (pos_ >= s_.size()) fail("unexpected end");
    return s_[pos_];
  }
  void expect(char c) {
    if (peek() != c) fail(std::string("expected ") + c);
    ++pos_;
  }
  bool literal(const char* word) {
    const std::string w(word);
    if (s_.compare(pos_, w.size(), w) != 0) return false;
    pos_ += w.size();
    return true;
  }
  std::string parseString() {
    expect('"');
    std::string out;
    while (pos_ < s_.size() && s_[pos_] != '"') {
      if (s_[pos_] == '\\') fail("escapes not expected in this output");
      if (static_cast<unsigned char>(s_[pos_]) < 0x20) fail("control character in string");
      out += s_[pos_++];
    }
    if (pos_ >= s_.size()) fail("unterminated string");
    ++pos_;
    return out;
  }
  double parseNumber() {
    const size_t start = pos_;
    if (s_[pos_] == '-') ++pos_;
    if (pos_ >= s_.size() || !std::isdigit(static_cast<unsigned char>(s_[pos_]))) fail("bad number");
    if (s_[pos_] == '0') {
      ++pos_;
    } else {
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    if (pos_ < s_.size() && s_[pos_] == '.') {
      ++pos_;
      if (pos_ >= s_.size() || !std::isdigit(static_cast<unsigned char>(s_[pos_]))) fail("bad fraction");
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    if (pos_ < s_.size() && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < s_.size() && (s_[pos_] == '+' || s_[pos_] == '-')) ++pos_;
      if (pos_ >= s_.size() || !std::isdigit(static_cast<unsigned char>(s_[pos_]))) fail("bad exponent");
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    return std::strtod(s_.substr(start, pos_ - start).c_str(), nullptr);
  }
  Json parseValue() {
    Json v;
    const char c = peek();
    if (c == '{') {
      v.kind = Json::Kind::kObject;
      ++pos_;
      if (peek() == '}') {
        ++pos_;
        return v;
      }
      while (true) {
        const std::string key = parseString();
        expect(':');
        if (v.fields.count(key)) fail("duplicate key " + key);
        v.fields[key] = parseValue();
        if (peek() == ',') {
          ++pos_;
          continue;
        }
        expect('}');
        return v;
      }
    }
    if (c == '[') {
      v.kind = Json::Kind::kArray;
      ++pos_;
      if (peek() == ']') {
        ++pos_;
        return v;
      }
      while (true) {
        v.items.push_back(parseValue());
        if (peek() == ',') {
          ++pos_;
          continue;
        }
        expect(']');
        return v;
      }
    }
    if (c == '"') {
      v.kind = Json::Kind::kString;
      v.text = parseString();
      return v;
    }
    if (literal("null")) return v;
    if (literal("true") || literal("false")) {
      v.kind = Json::Kind::kBool;
      v.boolean = s_[pos_ - 1] == 'e' && s_[pos_ - 2] == 'u';
      return v;
    }
    v.kind = Json::Kind::kNumber;
    v.number = parseNumber();
    return v;
  }

  const std::string& s_;
  size_t pos_ = 0;
};

Json parseJson(const std::string& text) { return JsonParser(text).parseDocument(); }

TEST(JsonReader, RejectsMalformedDocuments) {
  EXPECT_NO_THROW(parseJson("{\"a\": [1, -2.5e-3, null], \"b\": \"x\"}"));
  for (const char* bad : {"{\"a\": nan}", "{\"a\": 1,}", "{\"a\": 01}", "[1 2]", "{\"a\": inf}", "{a: 1}", "{} x"}) {
    EXPECT_THROW(parseJson(bad), std::runtime_error) << bad;
  }
}

// --- the executable ---
struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

RunResult runGains(const std::string& arguments) {
  const std::string base = sdlqr::test::tempPath("gains");
  const std::string command = std::string(SDLQR_BINARY_DIR) + "/bin/sdlqr-gains " + arguments + " >" + base +
                              ".out 2>" + base + ".err";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = readFile(base + ".out");
  result.err = readFile(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return result;
}

GainMatrix gainOf(const Json& json) {
  const Json& K = json["K"];
  EXPECT_EQ(K.items.size(), 4u);
  GainMatrix gain;
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(K.items[i].items.size(), 10u);
    for (int j = 0; j < 10; ++j) gain(i, j) = K.items[i].items[j].number;
  }
  return gain;
}

const char* kTiltedState = "1,-2,3,0.8660254037844387,0.5,0,0,4,0,-1";
const char* kFastInput = "3,-2,1,15";

TEST(GainsOnce, PrintsOneJsonObjectWhoseKEqualsTheLibraryDigitForDigit) {
  const RunResult run = runGains(std::string("--once --state ") + kTiltedState + " --input " + kFastInput);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << "one line of output";
  const Json json = parseJson(run.out);
  EXPECT_EQ(json["status"].text, "ok");
  EXPECT_EQ(json["method"].text, "tangent");
  EXPECT_EQ(json["dt"].number, 0.01);
  EXPECT_GT(json["iterations"].number, 0.0);
  EXPECT_GT(json["solve_us"].number, 0.0);
  EXPECT_LT(json["residual"].number, 1e-9);
  ASSERT_EQ(json["x_lin"].items.size(), 10u);
  ASSERT_EQ(json["u_lin"].items.size(), 4u);

  const State x = gains::parseStateList(kTiltedState, "--state");
  const Input u = gains::parseInputList(kFastInput, "--input");
  const LqrResult library = solveLqr(x, u, LqrParams());
  ASSERT_EQ(library.status, SolveStatus::kOk);
  const GainMatrix printed = gainOf(json);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 10; ++j) EXPECT_EQ(printed(i, j), library.K(i, j)) << i << "," << j;
  }
  for (int i = 0; i < 10; ++i) EXPECT_EQ(json["x_lin"].items[i].number, x[i]);  // already unit
  std::cout << "solve_us reported by the executable: " << json["solve_us"].number << "\n";
}

TEST(GainsOnce, IterativeMethodAndConfigWeightsAreUsed) {
  const std::string config = sdlqr::test::tempPath("gains_test_config.yaml");
  {
    std::ofstream out(config);
    out << "lqr:\n  r_diag: [2, 4, 4, 0.2]\n  dt: 0.02\n  tolerance: 1.0e-11\n";
  }
  const RunResult run = runGains(std::string("--once --state 0,0,1,1,0,0,0,0,0,0 --input 0,0,0,9.81 --config ") +
                                 config + " --method iterative");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json json = parseJson(run.out);
  EXPECT_EQ(json["method"].text, "iterative");
  EXPECT_EQ(json["dt"].number, 0.02);
  LqrParams params;
  params.r_diag << 2, 4, 4, 0.2;
  params.dt = 0.02;
  params.tolerance = 1e-11;
  params.method = LqrMethod::kIterative;
  const LqrResult library = solveLqr(gains::parseStateList("0,0,1,1,0,0,0,0,0,0", "s"),
                                     gains::parseInputList("0,0,0,9.81", "u"), params);
  ASSERT_EQ(library.status, SolveStatus::kOk);
  EXPECT_EQ(gainOf(json), library.K);
  EXPECT_EQ(json["iterations"].number, library.iterations);
  std::remove(config.c_str());
}

TEST(GainsOnce, NonUnitQuaternionIsReportedNormalized) {
  const RunResult run = runGains("--once --state 0,0,0,2,0,0,0,0,0,0 --input 0,0,0,9.81");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json json = parseJson(run.out);
  EXPECT_EQ(json["x_lin"].items[3].number, 1.0);
}

TEST(GainsOnce, BadInputExitsWithCodeTwoAndOneLine) {
  const std::string config = sdlqr::test::tempPath("gains_bad_r.yaml");
  {
    std::ofstream out(config);
    out << "lqr:\n  r_diag: [1, 5, 0, 0.1]\n";
  }
  const std::string good_input = " --input 0,0,0,9.81";
  const std::string good_state = " --state 0,0,0,1,0,0,0,0,0,0";
  const std::vector<std::string> cases = {
      "--once --state 0,0,0,1,0,0,0,0,0" + good_input,          // 9 numbers
      "--once --state 0,0,0,1,0,0,0,0,0,0,0" + good_input,      // 11 numbers
      "--once --state 0,0,0,1,0,nan,0,0,0,0" + good_input,      // NaN
      "--once --state 0,0,0,1,0,inf,0,0,0,0" + good_input,      // Inf
      "--once --state 0,0,0,1,0,abc,0,0,0,0" + good_input,      // not a number
      "--once --state 0,0,0,1,,0,0,0,0,0" + good_input,         // empty item
      "--once --state 0,0,0,0,0,0,0,0,0,0" + good_input,        // zero quaternion
      "--once" + good_state + " --input 0,0,9.81",              // 3 inputs
      "--once" + good_state + " --input 0,0,0,1e999",           // overflow
      "--once" + good_state + good_input + " --config " + config,  // R not positive definite
      "--once" + good_state + good_input + " --config /nonexistent/quad.yaml",
      "--once" + good_state + good_input + " --method newton",  // unknown method
      "--once" + good_state,                                    // no input
      "--once" + good_state + good_input + " --bogus",          // unknown option
      good_state.substr(1) + good_input,                        // a point without --once
  };
  for (const std::string& arguments : cases) {
    const RunResult run = runGains(arguments);
    EXPECT_EQ(run.exit_code, 2) << arguments << "\nstdout: " << run.out << "\nstderr: " << run.err;
    EXPECT_EQ(run.out, "") << arguments;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << arguments << ": " << run.err;
    EXPECT_EQ(run.err.rfind("sdlqr-gains: ", 0), 0u) << run.err;
  }
  std::remove(config.c_str());
}

TEST(GainsOnce, HelpExitsZero) {
  const RunResult run = runGains("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("--once"), std::string::npos);
}

// --- the library behind it ---
TEST(GainsCli, ParsesListsAndRejectsBadOnes) {
  const State x = gains::parseStateList("1,2,3,1,0,0,0,-4,5e-1,6", "--state");
  EXPECT_EQ(x[0], 1.0);
  EXPECT_EQ(x[8], 0.5);
  EXPECT_THROW(gains::parseStateList("1,2,3", "--state"), std::invalid_argument);
  EXPECT_THROW(gains::parseStateList("0,0,0,0,0,0,0,0,0,0", "--state"), std::invalid_argument);
  EXPECT_THROW(gains::parseInputList("1,2,3,x", "--input"), std::invalid_argument);
  EXPECT_THROW(gains::parseInputList("1,2,3,4 ", "--input"), std::invalid_argument);
  try {
    gains::parseInputList("1,2", "--input");
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--input: ", 0), 0u) << e.what();
  }
}

TEST(GainsCli, JsonOfAFailedSolveUsesNullForNonFiniteAndNamesTheReason) {
  LqrResult failed;
  failed.status = SolveStatus::kNotConverged;
  failed.reason = "did not converge";
  failed.residual = std::numeric_limits<double>::quiet_NaN();
  const std::string text = gains::formatGainsJson(State::Zero(), Input::Zero(), LqrParams(), failed, 1.5);
  const Json json = parseJson(text);
  EXPECT_EQ(json["status"].text, "not_converged");
  EXPECT_EQ(json["reason"].text, "did not converge");
  EXPECT_EQ(json["residual"].kind, Json::Kind::kNull);
}

TEST(GainsCli, SeventeenDigitsRoundTrip) {
  LqrResult result;
  result.status = SolveStatus::kOk;
  result.K(2, 7) = 0.1 + 0.2;  // 0.30000000000000004
  result.K(0, 0) = -1.0 / 3.0;
  const Json json = parseJson(gains::formatGainsJson(State::Zero(), Input::Zero(), LqrParams(), result, 0.0));
  EXPECT_EQ(gainOf(json), result.K);
}

}  // namespace
}  // namespace sdlqr
