// The loader replays inputs in the order the recorder received them (each event's time), not in
// the order it wrote them: after a stall the recorder writes one socket's backlog before
// another's (a solve heard before the IMU samples that led to it).

#include <gtest/gtest.h>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/replay/flight_loader.hpp"
#include "test_support.hpp"

namespace sdlqr::replay {
namespace {

using logger::test::RawEvent;
using logger::test::ScratchDir;

template <class Plain>
RawEvent event(const std::string& channel, const Plain& message, int64_t receive_utime) {
  const auto lcm_message = bus::toLcm(message);
  std::vector<uint8_t> bytes(static_cast<size_t>(lcm_message.getEncodedSize()));
  lcm_message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return {channel, std::move(bytes), receive_utime};
}

ImuSample imu(int64_t seq) {
  ImuSample s;
  s.utime = 1000 * seq;
  s.seq = seq;
  return s;
}

StateEstimate estimate(int64_t seq) {
  StateEstimate e;
  e.utime = 4000 * seq;
  e.seq = seq;
  return e;
}

TEST(FlightLoader, InputsTakeTheOrderOfTheirReceiveTimes) {
  ScratchDir dir("flight_loader");
  // Written: IMU 1, then the backlog of the STATE_EST socket (received between IMU 2 and 3),
  // then IMU 2 and 3; one STATE_EST and IMU at the same time keep the written order.
  logger::test::writeLog(dir / "f.lcmlog", {event("IMU", imu(1), 100), event("STATE_EST", estimate(7), 250),
                                            event("IMU", imu(2), 200), event("IMU", imu(3), 300),
                                            event("STATE_EST", estimate(8), 300)});
  LoadStats stats;
  const RecordedFlight flight = loadRecordedFlight((dir / "f.lcmlog").string(), "", &stats);
  ASSERT_EQ(flight.order.size(), 5u);
  const std::vector<std::pair<InputKind, int32_t>> expected = {{InputKind::kImu, 0},
                                                               {InputKind::kImu, 1},
                                                               {InputKind::kStateEstimate, 0},
                                                               {InputKind::kImu, 2},
                                                               {InputKind::kStateEstimate, 1}};
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(flight.order[i].kind, expected[i].first) << "position " << i;
    EXPECT_EQ(flight.order[i].index, expected[i].second) << "position " << i;
  }
  // Each series stays in log order.
  EXPECT_EQ(flight.imu[1].seq, 2);
  EXPECT_EQ(flight.state_estimate[0].seq, 7);
}

}  // namespace
}  // namespace sdlqr::replay
