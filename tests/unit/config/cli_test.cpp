// ArgParser: a number option's range and a required option are declared with the option and
// checked as the command line is parsed, each refusal one line naming the option.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sdlqr/config/cli.hpp"

namespace sdlqr {
namespace {

// Parses `words` (after the program name); returns the error text, empty when it parsed.
std::string parseWords(const ArgParser& parser, std::vector<const char*> words) {
  words.insert(words.begin(), "program");
  bool help = false;
  return parser.parse(static_cast<int>(words.size()), words.data(), &help);
}

struct Numbers {
  double rate = 1.0;
  long long seed = -1;  // -1: not given, outside the range on purpose
  int port = 8080;
};

void addNumbers(ArgParser& parser, Numbers& n) {
  parser.addOption("--rate", &n.rate, "HZ", "messages a second", Range::openClosed(0, 1000));
  parser.addOption("--seed", &n.seed, "N", "noise seed", Range::atLeast(0));
  parser.addOption("--port", &n.port, "N", "TCP port", Range::closed(1, 65535));
}

TEST(ArgParser, ANumberInsideItsRangeIsStored) {
  Numbers n;
  ArgParser parser("program", "test");
  addNumbers(parser, n);
  EXPECT_EQ(parseWords(parser, {"--rate", "1000", "--seed", "0", "--port", "1"}), "");
  EXPECT_EQ(n.rate, 1000.0);
  EXPECT_EQ(n.seed, 0);
  EXPECT_EQ(n.port, 1);
}

TEST(ArgParser, ANumberNotGivenKeepsItsDefaultEvenOutsideTheRange) {
  Numbers n;
  ArgParser parser("program", "test");
  addNumbers(parser, n);
  EXPECT_EQ(parseWords(parser, {}), "");
  EXPECT_EQ(n.seed, -1);
}

TEST(ArgParser, ANumberOutsideItsRangeIsRefusedNamingTheOptionAndTheRange) {
  const std::vector<std::pair<std::vector<const char*>, std::string>> cases = {
      {{"--rate", "0"}, "--rate: must be in (0, 1000], got '0'"},
      {{"--rate", "1000.5"}, "--rate: must be in (0, 1000], got '1000.5'"},
      {{"--seed", "-1"}, "--seed: must be >= 0, got '-1'"},
      {{"--port", "65536"}, "--port: must be in [1, 65535], got '65536'"},
      {{"--port", "0"}, "--port: must be in [1, 65535], got '0'"},
  };
  for (const auto& [words, error] : cases) {
    Numbers n;
    ArgParser parser("program", "test");
    addNumbers(parser, n);
    EXPECT_EQ(parseWords(parser, words), error);
  }
}

TEST(ArgParser, ANonNumberIsRefusedBeforeItsRangeIsAsked) {
  Numbers n;
  ArgParser parser("program", "test");
  addNumbers(parser, n);
  EXPECT_EQ(parseWords(parser, {"--rate", "nan"}), "--rate: expected a finite number, got 'nan'");
  EXPECT_EQ(parseWords(parser, {"--port", "80.5"}), "--port: expected an integer, got '80.5'");
}

TEST(ArgParser, HelpShowsEachRange) {
  Numbers n;
  ArgParser parser("program", "test");
  addNumbers(parser, n);
  const std::string help = parser.usage();
  EXPECT_NE(help.find("messages a second; must be in (0, 1000]"), std::string::npos) << help;
  EXPECT_NE(help.find("noise seed; must be >= 0"), std::string::npos) << help;
  EXPECT_NE(help.find("TCP port; must be in [1, 65535]"), std::string::npos) << help;
}

TEST(ArgParser, ARequiredOptionMissingIsRefusedByName) {
  std::string scenario;
  double airborne = 0.0;
  ArgParser parser("program", "test");
  parser.addOption("--scenario", &scenario, "FILE", "scenario file", Presence::kRequired);
  parser.addOption("--airborne", &airborne, "S", "seconds airborne", Range::above(0), Presence::kRequired);
  EXPECT_EQ(parseWords(parser, {"--airborne", "5"}), "--scenario is required");
  EXPECT_EQ(parseWords(parser, {"--scenario", "a.yaml"}), "--airborne is required");
  EXPECT_EQ(parseWords(parser, {"--scenario", "a.yaml", "--airborne", "5"}), "");
  EXPECT_EQ(scenario, "a.yaml");
  EXPECT_EQ(airborne, 5.0);
}

TEST(ArgParser, HelpIsGivenThoughARequiredOptionIsMissing) {
  std::string scenario;
  ArgParser parser("program", "test");
  parser.addOption("--scenario", &scenario, "FILE", "scenario file", Presence::kRequired);
  std::vector<const char*> words = {"program", "--help"};
  bool help = false;
  EXPECT_EQ(parser.parse(static_cast<int>(words.size()), words.data(), &help), "");
  EXPECT_TRUE(help);
}

}  // namespace
}  // namespace sdlqr
