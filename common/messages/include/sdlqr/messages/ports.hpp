#pragma once
// A process core's ports: the messages it takes and the ones it publishes, declared once in the
// core (as a Drake system declares its input and output ports). Everything that drives a core
// routes by these declarations:
//   - the process: bus::CoreBinding subscribes each input port on the channel of its type
//     (common/bus/core_binding.hpp), with the port's queue and deadline;
//   - the in-process closed loop: each published message reaches every core whose input port
//     takes its type (tools/offline/closedloop);
//   - the replay: what it feeds the recomputed cores and which core counts a refused input
//     (tools/examine/replay).
// A core declares, in its class:
//
//   static constexpr auto inputs() {
//     return std::tuple{
//         ports::Input{&ControllerCore::onStateEstimate, 1, std::chrono::microseconds(4000)},
//         ports::Input{&ControllerCore::onGains, 4},
//     };
//   }
//   using Outputs = ports::Publishes<RateCommand, Reference>;
//
// An input method is `R onX(const Msg&)` or `R onX(const Msg&, Outbox&)` (one that publishes);
// the channel follows from Msg (one type per channel, the .lcm file's @channel). A core publishes
// only its Outputs: the drivers refuse any other type (PublishChecked below).

#include <chrono>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/messages/outbox.hpp"

namespace sdlqr::ports {

template <class Method>
struct MethodTraits;
template <class R, class C, class M>
struct MethodTraits<R (C::*)(const M&, Outbox&)> {
  using Core = C;
  using Msg = M;
  static constexpr bool kPublishes = true;
};
template <class R, class C, class M>
struct MethodTraits<R (C::*)(const M&)> {
  using Core = C;
  using Msg = M;
  static constexpr bool kPublishes = false;
};

// One input: the core's method for a message type and how the bus queues it.
template <class Method>
struct Input {
  using Core = typename MethodTraits<Method>::Core;
  using Msg = typename MethodTraits<Method>::Msg;
  using Predicate = bool (Core::*)() const;

  // queue: messages the bus holds for the method (of those waiting, the first are delivered);
  // budget: a call that takes longer is a missed deadline (zero: not timed).
  constexpr Input(Method method, int queue = 1, std::chrono::microseconds budget = std::chrono::microseconds::zero())
      : method_(method), queue_(queue), budget_(budget) {}
  // The port exists only while the core says so (read once, when the process binds its ports).
  constexpr Input onlyWhen(Predicate predicate) const {
    Input copy = *this;
    copy.only_when_ = predicate;
    return copy;
  }

  Method method() const { return method_; }
  int queue() const { return queue_; }
  std::chrono::microseconds budget() const { return budget_; }
  bool active(const Core& core) const { return only_when_ == nullptr || (core.*only_when_)(); }
  void deliver(Core& core, const Msg& m, Outbox& out) const {
    if constexpr (MethodTraits<Method>::kPublishes) {
      (core.*method_)(m, out);
    } else {
      (void)out;
      (core.*method_)(m);
    }
  }

 private:
  Method method_;
  int queue_;
  std::chrono::microseconds budget_;
  Predicate only_when_ = nullptr;
};

// The message types a core publishes.
template <class... Msg>
struct Publishes {
  template <class T>
  static constexpr bool kHas = (std::is_same_v<T, Msg> || ...);
};

// f(port) for every input port of Core, in declaration order.
template <class Core, class F>
void forEachInput(F&& f) {
  std::apply([&](const auto&... port) { (f(port), ...); }, Core::inputs());
}

// Whether Core has an input port of type Msg.
template <class Core, class Msg>
constexpr bool takes() {
  return std::apply([](const auto&... port) { return (std::is_same_v<typename std::decay_t<decltype(port)>::Msg, Msg> || ...); },
                    Core::inputs());
}

// Whether Core has an input port on the channel of `stream`.
template <class Core>
bool takesStream(Stream stream) {
  bool found = false;
  forEachInput<Core>([&](const auto& port) {
    found = found || streamOf<typename std::decay_t<decltype(port)>::Msg>() == stream;
  });
  return found;
}

// Hands `m` to every active input port of `core` that takes its type, in declaration order.
template <class Core, class Msg>
void deliver(Core& core, const Msg& m, Outbox& out) {
  if constexpr (takes<Core, Msg>()) {
    forEachInput<Core>([&](const auto& port) {
      if constexpr (std::is_same_v<typename std::decay_t<decltype(port)>::Msg, Msg>) {
        if (port.active(core)) port.deliver(core, m, out);
      }
    });
  }
}

// The core's watchdogs take wall time through onWallTime(now_s), if it has one.
template <class Core, class = void>
struct HasWallTime : std::false_type {};
template <class Core>
struct HasWallTime<Core, std::void_t<decltype(std::declval<Core&>().onWallTime(0.0))>> : std::true_type {};
template <class Core>
void feedWallTime(Core& core, double now_s) {
  if constexpr (HasWallTime<Core>::value) core.onWallTime(now_s);
}

class UndeclaredOutput : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// A sink that passes on what Core declares it publishes and refuses anything else: a core that
// publishes a type missing from its Outputs is a wiring error, not a message.
template <class Core, class Sink>
struct PublishChecked {
  Sink sink;
  template <class Msg>
  void operator()(const Msg& m) const {
    if constexpr (Core::Outputs::template kHas<Msg>) {
      sink(m);
    } else {
      throw UndeclaredOutput("a core publishes " + std::string(channelOf<Msg>()) + " without declaring it in its Outputs");
    }
  }
};

// The Outbox a driver hands Core: every declared output goes to `sink`.
template <class Core, class Sink>
class CoreOutbox final : public OutboxTo<PublishChecked<Core, Sink>> {
 public:
  explicit CoreOutbox(Sink sink) : OutboxTo<PublishChecked<Core, Sink>>(PublishChecked<Core, Sink>{std::move(sink)}) {}
};

}  // namespace sdlqr::ports
