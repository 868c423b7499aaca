#pragma once
// Where a process core puts the messages it publishes: one overload per message type (one type
// per channel, channels.hpp). The bus implements it by publishing on the channel of the type
// (common/bus core_binding.hpp); the in-process loop routes each message to the cores that
// consume it; the replay keeps what it recomputes. Cores never see which.

#include <utility>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr {

class Outbox {
 public:
  virtual ~Outbox() = default;
  virtual void publish(const ImuSample& m) = 0;
  virtual void publish(const VioPose& m) = 0;
  virtual void publish(const SimTruth& m) = 0;
  virtual void publish(const StateEstimate& m) = 0;
  virtual void publish(const GainSet& m) = 0;
  virtual void publish(const RateCommand& m) = 0;
  virtual void publish(const Reference& m) = 0;
  virtual void publish(const MotorCommand& m) = 0;
  virtual void publish(const Command& m) = 0;
  virtual void publish(const Disturbance& m) = 0;
  virtual void publish(const ParamsUpdate& m) = 0;
  virtual void publish(const Trajectory& m) = 0;
  virtual void publish(const SimClockTick& m) = 0;
};

// An Outbox that hands every message to one generic callable, sink(const T&).
template <class Sink>
class OutboxTo : public Outbox {
 public:
  explicit OutboxTo(Sink sink) : sink_(std::move(sink)) {}
  void publish(const ImuSample& m) override { sink_(m); }
  void publish(const VioPose& m) override { sink_(m); }
  void publish(const SimTruth& m) override { sink_(m); }
  void publish(const StateEstimate& m) override { sink_(m); }
  void publish(const GainSet& m) override { sink_(m); }
  void publish(const RateCommand& m) override { sink_(m); }
  void publish(const Reference& m) override { sink_(m); }
  void publish(const MotorCommand& m) override { sink_(m); }
  void publish(const Command& m) override { sink_(m); }
  void publish(const Disturbance& m) override { sink_(m); }
  void publish(const ParamsUpdate& m) override { sink_(m); }
  void publish(const Trajectory& m) override { sink_(m); }
  void publish(const SimClockTick& m) override { sink_(m); }

 private:
  Sink sink_;
};

}  // namespace sdlqr
