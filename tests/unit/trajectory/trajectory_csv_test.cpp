#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <random>
#include <sstream>

#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"

#include "config_errors.hpp"

namespace sdlqr::trajectory {
namespace {

bool bitEqual(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expectIdentical(const Trajectory& a, const Trajectory& b) {
  ASSERT_EQ(a.samples.size(), b.samples.size());
  EXPECT_EQ(a.closed, b.closed);
  EXPECT_EQ(a.tracking, b.tracking);
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    EXPECT_TRUE(bitEqual(a.samples[k].t, b.samples[k].t)) << k;
    for (int i = 0; i < kStateDim; ++i) EXPECT_TRUE(bitEqual(a.samples[k].x[i], b.samples[k].x[i])) << k << " x" << i;
    for (int i = 0; i < kInputDim; ++i) EXPECT_TRUE(bitEqual(a.samples[k].u[i], b.samples[k].u[i])) << k << " u" << i;
  }
}

Trajectory roundTrip(const Trajectory& trajectory) {
  std::stringstream text;
  writeTrajectoryCsv(text, trajectory);
  return parseTrajectoryCsv(text, "round.csv");
}

TEST(TrajectoryCsv, WriteThenReadIsExact) {
  Trajectory fast = sampleTrajectory(paperMinSnapFast(TrajectoryParams{}), 0.1, 9.81);
  fast.tracking = ReferenceMode::kTemporal;
  expectIdentical(fast, roundTrip(fast));
  const Trajectory ellipse = paperEllipse(TrajectoryParams{}, 9.81);
  expectIdentical(ellipse, roundTrip(ellipse));
}

// A valid file whose line `line` (1-based) is replaced by `replacement`.
std::string fileWithLine(int line, const std::string& replacement) {
  std::vector<std::string> lines = {
      "# test trajectory",                                   // 1
      "t,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,c",          // 2
      "0, 0,0,1, 1,0,0,0, 0,0,0, 0,0,0, 9.81",               // 3
      "",                                                    // 4
      "0.1, 0.1,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81",           // 5
      "# a comment between samples",                         // 6
      "0.2, 0.2,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81",           // 7
      "0.3, 0.3,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81",           // 8
  };
  lines[line - 1] = replacement;
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  return text;
}

std::string errorOf(const std::string& text) {
  return testing::messageThrownBy<TrajectoryFileError>([&] {
    std::istringstream in(text);
    parseTrajectoryCsv(in, "file.csv");
  });
}

TEST(TrajectoryCsv, ReadsCommentsBlankLinesAndOptionalHeader) {
  std::istringstream with_header(fileWithLine(6, "# still a comment"));
  const Trajectory a = parseTrajectoryCsv(with_header, "a.csv");
  EXPECT_EQ(a.samples.size(), 4u);
  EXPECT_DOUBLE_EQ(a.samples[2].t, 0.2);
  EXPECT_DOUBLE_EQ(a.samples[2].x[kPos], 0.2);
  EXPECT_DOUBLE_EQ(a.samples[1].x[kVel], 1.0);
  EXPECT_DOUBLE_EQ(a.samples[3].u[kThrust], 9.81);
  EXPECT_FALSE(a.closed);
  EXPECT_EQ(a.tracking, ReferenceMode::kSpatial);
  std::istringstream without_header(fileWithLine(2, "# closed: false"));
  EXPECT_EQ(parseTrajectoryCsv(without_header, "b.csv").samples.size(), 4u);
}

TEST(TrajectoryCsv, EveryInvalidLineIsNamed) {
  EXPECT_EQ(errorOf(fileWithLine(7, "0.1, 0.2,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81")), "file.csv:7: time not increasing");
  EXPECT_EQ(errorOf(fileWithLine(7, "0.05, 0.2,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81")), "file.csv:7: time not increasing");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, nan,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81")), "file.csv:5: column px: not finite");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, 0.1,0,1, 1,0,0,0, 1,0,0, 0,0,inf, 9.81")), "file.csv:5: column wz: not finite");
  EXPECT_EQ(errorOf(fileWithLine(8, "0.3, 0.3,0,1, 1,0,0,0, 1,0,0, 0,0,0")), "file.csv:8: expected 15 columns, got 14");
  EXPECT_EQ(errorOf(fileWithLine(8, "0.3, 0.3,0,1, 1,0,0,0, 1,0,0, 0,0,0,9.81,1")), "file.csv:8: expected 15 columns, got 16");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, 0.1,0,1, 1,0,0,0, 1,0,abc, 0,0,0, 9.81")), "file.csv:5: column vz: cannot parse 'abc'");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, 0.1,0,1, 1,0,0,0, 1,0,1.5.2, 0,0,0, 9.81")),
            "file.csv:5: column vz: cannot parse '1.5.2'");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, 0.1,0,1, 1,0,0,0, 1,0,, 0,0,0, 9.81")), "file.csv:5: column vz: empty");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, 0.1,0,1, 0.9,0,0,0, 1,0,0, 0,0,0, 9.81")),
            "file.csv:5: quaternion norm 0.9 is not 1");
  EXPECT_EQ(errorOf(fileWithLine(7, "0.2, 2.2,0,1, 1,0,0,0, 1,0,0, 0,0,0, 9.81")),
            "file.csv:7: position jump 2.1 m exceeds 1 m");
  EXPECT_EQ(errorOf(fileWithLine(5, "0.1, 0.1,0,1, 1,0,0,0, 1,0,0, 0,0,0, -1")), "file.csv:5: thrust negative");
  EXPECT_EQ(errorOf(fileWithLine(2, "t,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,c")),
            "file.csv:2: header must be t,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,c");
  EXPECT_EQ(errorOf(fileWithLine(1, "# closed: maybe")), "file.csv:1: closed: expected true or false, got 'maybe'");
  EXPECT_EQ(errorOf(fileWithLine(1, "# tracking: sideways")),
            "file.csv:1: tracking: expected spatial or temporal, got 'sideways'");
  // The closed flag promises a full lap: the last sample must be back at the first position.
  EXPECT_EQ(errorOf(fileWithLine(1, "# closed: true")),
            "file.csv:8: closed trajectory must end at its first position (0.3 m away)");
}

TEST(TrajectoryCsv, TooFewSamples) {
  EXPECT_EQ(errorOf("# nothing here\n\n"), "file.csv:2: fewer than 2 samples");
  EXPECT_EQ(errorOf("t,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,c\n0,0,0,1,1,0,0,0,0,0,0,0,0,0,9.81\n"),
            "file.csv:2: fewer than 2 samples");
}

TEST(TrajectoryCsv, JumpLimitIsConfigurable) {
  SampleChecks strict;
  strict.max_position_jump = 0.05;
  std::istringstream in(fileWithLine(1, "#"));
  try {
    parseTrajectoryCsv(in, "strict.csv", strict);
    FAIL() << "accepted a 0.1 m step with a 0.05 m limit";
  } catch (const TrajectoryFileError& e) {
    EXPECT_EQ(std::string(e.what()), "strict.csv:5: position jump 0.1 m exceeds 0.05 m");
    EXPECT_EQ(e.line(), 5);
  }
}

TEST(TrajectoryCsv, GarbageNeverCrashes) {
  // Mutate a valid file at random (bytes replaced, cut, duplicated): it either parses into a valid
  // trajectory or throws TrajectoryFileError; nothing else.
  std::stringstream valid;
  writeTrajectoryCsv(valid, paperEllipse(TrajectoryParams{}, 9.81));
  const std::string original = valid.str();
  std::mt19937 rng(11);
  const std::string alphabet = "0123456789.,-+eE#\n naif:tx";
  int rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = original;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0: text[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: text.erase(at, rng() % 40); break;
        default: text.insert(at, text.substr(rng() % text.size(), rng() % 40)); break;
      }
      if (text.empty()) text = "#";
    }
    std::istringstream in(text);
    try {
      const Trajectory parsed = parseTrajectoryCsv(in, "fuzz.csv");
      EXPECT_EQ(validateTrajectory(parsed, SampleChecks{}), "") << text;
    } catch (const TrajectoryFileError&) {
      ++rejected;
    }
  }
  std::cout << "  3000 mutated files: " << rejected << " rejected with a line number, the rest valid\n";
  EXPECT_GT(rejected, 0);
}

TEST(TrajectoryCsv, MissingFileIsAnError) {
  EXPECT_THROW(readTrajectoryCsv("/nonexistent/dir/trajectory.csv"), TrajectoryFileError);
}

}  // namespace
}  // namespace sdlqr::trajectory
