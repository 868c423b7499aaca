#pragma once
// Whether a flight's message loss was the kernel's (scripts/packet_loss: an nftables rule on the
// input hook drops a share of the datagrams, each for every socket at once, the recorder's too).
// Judged from the rule's own counter and the log, never from the subscribers' counts alone (those
// also count their own queues' drops, so they are not zero on a flight that lost nothing):
//   - the rule dropped datagrams (its counter > 0);
//   - the log's seq gaps on the channels with one publisher are those drops: at most the counter
//     plus what the recorder lost on its own, and at least the counter's share of such datagrams
//     (the log's share of HEARTBEAT datagrams, whose seq is per process, taken out) less three
//     standard deviations of a binomial draw;
//   - every subscriber counted at least the log's gaps on each channel it listens to, up to its
//     last heartbeat, over what its own queue dropped (lost - queue_drop), less what the recorder
//     lost on its own.
// Pure: a decoded FlightLog, its liveness (each process's own last heartbeat) and the counter in.

#include <cstdint>
#include <vector>

#include "sdlqr/faults/finding.hpp"
#include "sdlqr/faults/liveness.hpp"
#include "sdlqr/logger/flight_log.hpp"

namespace sdlqr::faults {

std::vector<Finding> judgeKernelLoss(const logger::FlightLog& log, const Liveness& liveness, int64_t kernel_dropped);

}  // namespace sdlqr::faults
