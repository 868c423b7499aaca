#pragma once
// What a soak needs from its flight log: whether the log is whole, the airborne span on the
// wall clock (the /proc samples' clock) and the bus latency at each instant.

#include <string>
#include <vector>

#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/soak/soak_check.hpp"

namespace sdlqr::soak {

struct LogWholeness {
  bool file_complete = false;     // no corrupt bytes, no torn tail
  int64_t seq_lost = 0;           // forward seq gaps over every vehicle channel but HEARTBEAT
  std::string worst_channel;      // the channel with the most, empty when none
  double airborne_start = 0.0;    // [s] wall clock (epoch) of the first airborne truth sample
  double airborne_end = 0.0;      // [s] ... of the last
  double airborne_sim_s = 0.0;    // [s] simulation time airborne
  bool crashed = false;
  bool passed(double expected_airborne_s) const;  // complete, no gap, no crash, long enough
};

LogWholeness checkLogWhole(const logger::FlightLog& log);

// STATE_EST -> RATE_CMD computed from it, on the recorder's receive clock, at the command's
// receive time [s, epoch].
std::vector<LatencySample> commandLatencyOverTime(const logger::FlightLog& log);

}  // namespace sdlqr::soak
