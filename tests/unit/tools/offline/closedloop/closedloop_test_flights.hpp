#pragma once
// What several tests record and measure alike on an in-process flight: MOTOR_CMD, the log and its
// report, the truth's mean error against the reference over a window, and every check passing; a header, so the files of one test binary
// (one translation unit) share it.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/closedloop/closed_loop.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::test {

// The rotor saturation criteria count MOTOR_CMD.
inline closedloop::RecordOptions motorCommandsRecorded() {
  closedloop::RecordOptions record;
  record.motor_command = true;
  return record;
}

// An in-process flight's log and the analysis of it.
struct AnalyzedFlight {
  logger::FlightLog log;
  analysis::FlightReport report;
};

// Mean over [from, to] s of `error(truth, reference position)`, at every SIM_TRUTH with a reference.
template <typename Error>
double meanErrorToReference(const logger::FlightLog& log, double from, double to, Error error) {
  double sum = 0.0;
  int n = 0;
  for (const SimTruth& s : log.sim_truth.messages) {
    const double t = 1e-6 * static_cast<double>(s.utime);
    const auto i = log.reference.indexAtOrBefore(s.utime);
    if (t < from || t > to || i < 0) continue;
    sum += error(s, Eigen::Vector3d(position(log.reference[static_cast<size_t>(i)].x)));
    ++n;
  }
  return n ? sum / n : NAN;
}

// Mean height of the truth minus the reference's over [from, to] s.
inline double meanHeightError(const logger::FlightLog& log, double from, double to) {
  return meanErrorToReference(log, from, to,
                              [](const SimTruth& s, const Eigen::Vector3d& reference) { return s.position[2] - reference[2]; });
}

// Mean horizontal distance of the truth to the reference over [from, to] s.
inline double meanHorizontalError(const logger::FlightLog& log, double from, double to) {
  return meanErrorToReference(log, from, to, [](const SimTruth& s, const Eigen::Vector3d& reference) {
    return (s.position - reference).head<2>().norm();
  });
}

inline void expectEveryCheckPasses(const analysis::FlightReport& report, const std::string& what) {
  ASSERT_FALSE(report.checks.empty()) << what;
  for (const analysis::Check& c : report.checks) {
    EXPECT_TRUE(c.pass) << what << ": " << c.name << " = " << c.value << " (limit " << c.limit << ")";
  }
}

}  // namespace sdlqr::test
