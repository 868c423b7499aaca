#pragma once
// The adapter between the bus and a process core (the core's library holds every gate, counter
// and algorithm; see e.g. controller/controller_core.hpp). The core declares its ports once
// (sdlqr/messages/ports.hpp); binding subscribes every input port on the channel of its type,
// with the port's queue and deadline, and publishes what the core puts in its Outbox:
//
//   controller::ControllerCore core(...);
//   bus::Node node("sdlqr-controller", options, core.health());   // HEARTBEAT from the core
//   bus::CoreBinding<controller::ControllerCore> bus(node, core);  // every port of inputs()
//   bus.serve(spin_ms);                                           // spin, feed wall time
//
// The byte-level stage (size walk, decode) is the Node's; the wall time is fed to the core's
// onWallTime(now) before every message and after every spin, so a stream's watchdog is fed with
// the time of its message.

#include <chrono>
#include <string_view>
#include <type_traits>
#include <utility>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/decode.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/wall_clock.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"

namespace sdlqr::bus {

using ::sdlqr::channelOf;

// Publishes each message on the channel of its type.
struct PublishOnItsChannel {
  Node* node;
  template <class Msg>
  void operator()(const Msg& m) const {
    node->publish(channelOf<Msg>(), toLcm(m));
  }
};
// Publishes any message on its channel (a process that is no core, e.g. a test peer).
class NodeOutbox final : public OutboxTo<PublishOnItsChannel> {
 public:
  explicit NodeOutbox(Node& node) : OutboxTo<PublishOnItsChannel>(PublishOnItsChannel{&node}) {}
};

template <class Core>
class CoreBinding {
 public:
  // Subscribes every input port of Core::inputs() that is active for `core`.
  CoreBinding(Node& node, Core& core) : node_(node), core_(core), outbox_(PublishOnItsChannel{&node}) {
    ports::forEachInput<Core>([this](const auto& port) {
      if (port.active(core_)) bind(port);
    });
  }

  // Spins until SIGINT/SIGTERM, feeding wall time after every spin; then the last heartbeat.
  void serve(int spin_ms) {
    while (node_.spin(spin_ms)) feedWallTime();
    node_.shutdown();
  }

  Outbox& outbox() { return outbox_; }
  Node& node() { return node_; }

 private:
  template <class Port>
  void bind(const Port& port) {
    using Msg = typename Port::Msg;
    node_.subscribe<LcmOf<Msg>>(channelOf<Msg>(), [this, port](const LcmOf<Msg>& m) {
      feedWallTime();
      port.deliver(core_, fromLcm(m), outbox_);
    }, port.queue(), port.budget());
  }

  void feedWallTime() { ports::feedWallTime(core_, monotonicSeconds()); }

  Node& node_;
  Core& core_;
  ports::CoreOutbox<Core, PublishOnItsChannel> outbox_;
};

}  // namespace sdlqr::bus
