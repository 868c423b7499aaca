#pragma once
// The bus without a bus: every message a core publishes goes to each core whose declared input
// ports take its type (ports.hpp), in the order the cores are given, within the call that
// published it (as on the bus, minus the transport). The in-process closed loop and the tests
// that step the cores together route through this one class; the order of the cores is theirs
// to choose and say why.
//
//   InProcessWiring<Recorder, LowlevelCore, EstimatorCore> wiring(recorder, lowlevel, estimator);
//   sim.step(wiring.outbox());        // a publisher that is not routed to (the simulator)
//
// `observer(m)` sees every message first (a recorder; NoObserver: nothing). Each core publishes
// through an Outbox that refuses a type missing from its Outputs (ports::UndeclaredOutput).

#include <tuple>
#include <utility>

#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"

namespace sdlqr {

struct NoObserver {
  template <class Msg>
  void operator()(const Msg&) const {}
};

template <class Observer, class... Cores>
class InProcessWiring {
 public:
  explicit InProcessWiring(Observer& observer, Cores&... cores)
      : observer_(observer), cores_(cores...), outboxes_(ports::CoreOutbox<Cores, Route>(Route{this})...), any_(Route{this}) {}
  InProcessWiring(const InProcessWiring&) = delete;
  InProcessWiring& operator=(const InProcessWiring&) = delete;

  // Shows `m` to the observer, then hands it to every core whose ports take it.
  template <class Msg>
  void publish(const Msg& m) {
    observer_(m);
    std::apply([&](auto&... core) { (deliverTo(core, m), ...); }, cores_);
  }
  // The Outbox of one of the cores (it publishes only its Outputs).
  template <class Core>
  Outbox& outboxOf() {
    return std::get<ports::CoreOutbox<Core, Route>>(outboxes_);
  }
  // An Outbox for a publisher outside the wiring (a foreign message, a test): anything goes.
  Outbox& outbox() { return any_; }
  // Every core's onWallTime, where it has one.
  void feedWallTime(double now_s) {
    std::apply([&](auto&... core) { (ports::feedWallTime(core, now_s), ...); }, cores_);
  }

 private:
  struct Route {
    InProcessWiring* wiring;
    template <class Msg>
    void operator()(const Msg& m) const {
      wiring->publish(m);
    }
  };
  template <class Core, class Msg>
  void deliverTo(Core& core, const Msg& m) {
    ports::deliver(core, m, outboxOf<Core>());
  }

  Observer& observer_;
  std::tuple<Cores&...> cores_;
  std::tuple<ports::CoreOutbox<Cores, Route>...> outboxes_;
  OutboxTo<Route> any_;
};

}  // namespace sdlqr
