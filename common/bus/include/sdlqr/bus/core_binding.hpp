#pragma once
// The adapter between the bus and a process core (the core's library holds every gate, counter
// and algorithm; see e.g. controller/controller_core.hpp). One line per channel:
//
//   controller::ControllerCore core(...);
//   bus::Node node("sdlqr-controller", options, core.health());   // HEARTBEAT from the core
//   bus::CoreBinding<controller::ControllerCore> bus(node, core);
//   bus.bind(&ControllerCore::onStateEstimate, 1, kTickBudget);    // STATE_EST -> method
//   bus.bind(&ControllerCore::onGains, 4);
//   bus.serve(spin_ms);                                           // spin, feed wall time
//
// The channel follows from the message type (one type per channel); the byte-level stage (size
// walk, decode) is the Node's; the wall time is fed to the core's onWallTime(now) before every
// message and after every spin, so a stream's watchdog is fed with the time of its message.

#include <chrono>
#include <string_view>
#include <type_traits>
#include <utility>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/decode.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/wall_clock.hpp"
#include "sdlqr/messages/outbox.hpp"

namespace sdlqr::bus {

// The channel of each plain message type.
constexpr std::string_view channelOf(const ImuSample*) { return channel::kImu; }
constexpr std::string_view channelOf(const VioPose*) { return channel::kVioPose; }
constexpr std::string_view channelOf(const SimTruth*) { return channel::kSimTruth; }
constexpr std::string_view channelOf(const StateEstimate*) { return channel::kStateEstimate; }
constexpr std::string_view channelOf(const GainSet*) { return channel::kGains; }
constexpr std::string_view channelOf(const RateCommand*) { return channel::kRateCommand; }
constexpr std::string_view channelOf(const Reference*) { return channel::kReference; }
constexpr std::string_view channelOf(const MotorCommand*) { return channel::kMotorCommand; }
constexpr std::string_view channelOf(const Command*) { return channel::kCommand; }
constexpr std::string_view channelOf(const Disturbance*) { return channel::kDisturbance; }
constexpr std::string_view channelOf(const ParamsUpdate*) { return channel::kParams; }
constexpr std::string_view channelOf(const Trajectory*) { return channel::kTrajectory; }
constexpr std::string_view channelOf(const SimClockTick*) { return channel::kSimClock; }
template <class Msg>
constexpr std::string_view channelOf() {
  return channelOf(static_cast<const Msg*>(nullptr));
}

// Publishes each message on the channel of its type.
struct PublishOnItsChannel {
  Node* node;
  template <class Msg>
  void operator()(const Msg& m) const {
    node->publish(channelOf<Msg>(), toLcm(m));
  }
};
class NodeOutbox final : public OutboxTo<PublishOnItsChannel> {
 public:
  explicit NodeOutbox(Node& node) : OutboxTo<PublishOnItsChannel>(PublishOnItsChannel{&node}) {}
};

template <class Core>
class CoreBinding {
 public:
  CoreBinding(Node& node, Core& core) : node_(node), core_(core), outbox_(node) {}

  // A method that publishes: RejectReason Core::onX(const Msg&, Outbox&).
  template <class R, class Msg>
  void bind(R (Core::*method)(const Msg&, Outbox&), int queue_capacity = 1,
            std::chrono::microseconds budget = std::chrono::microseconds::zero()) {
    node_.subscribe<LcmOf<Msg>>(channelOf<Msg>(), [this, method](const LcmOf<Msg>& m) {
      feedWallTime();
      (core_.*method)(fromLcm(m), outbox_);
    }, queue_capacity, budget);
  }
  // A method that only takes input: RejectReason Core::onX(const Msg&).
  template <class R, class Msg>
  void bind(R (Core::*method)(const Msg&), int queue_capacity = 1,
            std::chrono::microseconds budget = std::chrono::microseconds::zero()) {
    node_.subscribe<LcmOf<Msg>>(channelOf<Msg>(), [this, method](const LcmOf<Msg>& m) {
      feedWallTime();
      (core_.*method)(fromLcm(m));
    }, queue_capacity, budget);
  }

  // Spins until SIGINT/SIGTERM, feeding wall time after every spin; then the last heartbeat.
  void serve(int spin_ms) {
    while (node_.spin(spin_ms)) feedWallTime();
    node_.shutdown();
  }

  Outbox& outbox() { return outbox_; }
  Node& node() { return node_; }

 private:
  template <class C, class = void>
  struct HasWallTime : std::false_type {};
  template <class C>
  struct HasWallTime<C, std::void_t<decltype(std::declval<C&>().onWallTime(0.0))>> : std::true_type {};

  void feedWallTime() {
    if constexpr (HasWallTime<Core>::value) core_.onWallTime(monotonicSeconds());
  }

  Node& node_;
  Core& core_;
  NodeOutbox outbox_;
};

}  // namespace sdlqr::bus
