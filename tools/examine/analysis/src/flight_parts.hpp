#pragma once
// Internal to tools/examine/analysis: the parts analyzeFlight assembles a report from, one idea each.

#include <algorithm>

#include "sdlqr/analysis/flight_report.hpp"

namespace sdlqr::analysis::detail {

inline double seconds(int64_t utime) { return static_cast<double>(utime) * 1e-6; }

// Visits the truth samples with start <= t <= end.
template <class Visit>
void forTruthIn(const logger::FlightLog& log, double start, double end, Visit visit) {
  const auto& truth = log.sim_truth.messages;
  auto it = std::lower_bound(truth.begin(), truth.end(), start,
                             [](const SimTruth& s, double t) { return seconds(s.utime) < t; });
  for (; it != truth.end() && seconds(it->utime) <= end; ++it) visit(*it);
}

// Airborne span, tilt, touchdown speed and crash, from the truth.
void summarizeTruth(const logger::FlightLog& log, FlightReport& report);
// Setpoint windows after take-off and each jump, and the pulls while holding a setpoint, of the
// scenario's events in report.events (those not in the log: windows with `missing` set).
void analyzeWindows(const logger::FlightLog& log, const AnalysisOptions& options, FlightReport& report,
                    const mission::Scenario& scenario);
// The touchdown after each LAND of the scenario.
void analyzeLandings(const logger::FlightLog& log, FlightReport& report);
// Estimate against the truth at the same instant.
EstimatorAccuracy estimatorAccuracy(const logger::FlightLog& log);
// Message rates over the airborne span, solver and controller timing, bus latency, NaN count.
void measureTiming(const logger::FlightLog& log, const AnalysisOptions& options, FlightReport& report);
// CPU and counters per process from the HEARTBEATs sent while airborne, and the figures relative
// to the machine's calibration when one is given.
void measureLoad(const logger::FlightLog& log, FlightReport& report);
// A RATE_CMD whose thrust demand (before the controller's clip) lay outside [c_min, c_max], or
// one with a non-finite command: the one definition of a thrust limit violation.
bool thrustDemandOutside(const RateCommand& command, double c_min, double c_max);
// Thrust demand and rotor limits over simulation time [start, end].
Saturation measureSaturation(const logger::FlightLog& log, const AnalysisOptions& options, double start, double end);
// Lost messages per subscriber and channel (FlightReport::message_loss).
std::vector<ChannelLoss> measureMessageLoss(const logger::FlightLog& log);

}  // namespace sdlqr::analysis::detail
