// sdlqr-compare's command line: --help, and every bad option or benchmark file refused with exit
// code 2 and one line naming the key.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

const std::string kBinary = SDLQR_BINARY_DIR "/bin/sdlqr-compare";
const std::string kBenchmark = SDLQR_SOURCE_DIR "/tests/unit/tools/offline/compare/small_benchmark.yaml";
const std::string kCliWork = SDLQR_BINARY_DIR "/compare_cli_test/" + std::to_string(::getpid());

struct Outcome {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

Outcome run(const std::string& arguments) {
  Outcome o;
  FILE* pipe = ::popen((kBinary + " " + arguments + " 2>&1").c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer{};
  for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) o.output.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

void expectOneLineErrorNaming(const std::string& arguments, const std::string& key) {
  const Outcome o = run(arguments);
  EXPECT_EQ(o.exit_code, 2) << arguments << "\n" << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << arguments << "\n" << o.output;
  EXPECT_NE(o.output.find(key + ":"), std::string::npos) << arguments << "\n" << o.output;
}

TEST(CompareCli, HelpNamesEveryOption) {
  const Outcome o = run("--help");
  EXPECT_EQ(o.exit_code, 0);
  for (const char* option : {"--out", "--controllers", "--scenarios", "--seed", "--jobs", "--quiet"}) {
    EXPECT_NE(o.output.find(option), std::string::npos) << option;
  }
}

TEST(CompareCli, BadOptionsAndFilesFailWithOneLineNamingTheKey) {
  const std::string out = " --out " + kCliWork + "/out";
  expectOneLineErrorNaming(kBenchmark + out + " --controllers sdlqr,pid", "--controllers[1]");
  expectOneLineErrorNaming(kBenchmark + out + " --scenarios hover", "--scenarios[0]");
  expectOneLineErrorNaming(kBenchmark + " --controllers sdlqr", "--out");
  expectOneLineErrorNaming(kBenchmark + out + " --jobs 0", "--jobs");
  expectOneLineErrorNaming(out.substr(1), "BENCHMARK");
  ASSERT_EQ(std::system(("mkdir -p " + kCliWork).c_str()), 0);
  const std::string bad = kCliWork + "/bad.yaml";
  std::ofstream(bad) << "controllers: [sdlqr, lqg]\nexperiments: [hover_jumps]\n";
  expectOneLineErrorNaming(bad + out, "controllers[1]");
  std::ofstream(bad) << "experiments: [hover_jumps]\nspeed_sweeps: {}\n";
  expectOneLineErrorNaming(bad + out, "speed_sweeps");
  EXPECT_EQ(std::system(("rm -rf " + kCliWork).c_str()), 0);
}

TEST(CompareCli, WritesTheReportOfTheSelectedFlights) {
  const std::string dir = kCliWork + "/selected";
  const Outcome o = run(kBenchmark + " --out " + dir + " --controllers geometric --scenarios short_hover --jobs 1");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("compare: [1/1] short_hover geometric:"), std::string::npos) << o.output;
  std::ifstream report(dir + "/report.md");
  std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("| `geometric` |"), std::string::npos);
  EXPECT_EQ(text.find("`sdlqr` |"), std::string::npos) << "not selected";
  EXPECT_EQ(text.find("speed_sweep"), std::string::npos) << "not selected";
  EXPECT_EQ(std::system(("rm -rf " + kCliWork).c_str()), 0);
}

}  // namespace
