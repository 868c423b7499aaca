#pragma once
// The 100 Hz controller process logic (paper §II-C, §III-B): on each tick of simulation time it
// takes the newest estimate, the reference of the tick and the newest valid K, and computes the
// body-rate and thrust command. K comes from the gain solver at 10 Hz; when it goes stale the last
// valid K is kept and flagged, and after a timeout a hover K computed here takes over.
//
// The law is lqr.law, switched in flight by PARAMS (FIELD_LAW) through a bumpless transfer
// (bumpless_transfer.hpp): sdlqr (the above), hover_lqr (the hover K computed here, always),
// geometric (geometric_control.hpp), sdlqr_integral and sdlqr_actuator (the extensions'
// GAINS with their K_aug on the states kept in extension_states.hpp; until their first K arrives,
// or when it goes past the fallback age, they run as sdlqr), sdlqr_adaptive (sdlqr whose model's
// thrust gain is estimated online, extension_states.hpp: the feed-forward thrust divided by it,
// and REFERENCE thrust_gain gives it to the gain solver's linearization).

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/controller/bumpless_transfer.hpp"
#include "sdlqr/controller/control_law.hpp"
#include "sdlqr/controller/extension_states.hpp"
#include "sdlqr/controller/geometric_control.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/controller/reference_generator.hpp"

namespace sdlqr::controller {

struct ControllerStatus {
  GainsFreshness gains = GainsFreshness::kFallback;
  FlightPhase phase = FlightPhase::kIdle;
  int64_t ticks = 0;
  int64_t predicted_ticks = 0;  // computed from the last estimate before the tick, carried forward
  int64_t fallback_ticks = 0;
  int64_t stale_ticks = 0;
  int64_t saturated_ticks = 0;
  ControlLaw law = ControlLaw::kSdlqr;  // the law of the last tick
  bool extension_active = false;        // the last tick used an extension's K_aug
  bool transferring = false;            // the last tick was part of a bumpless transfer
  int64_t law_switches = 0;             // transfers started
  Input law_output = Input::Zero();     // the last tick's law command before the transfer (limited)
};

class StateDependentLqr {
 public:
  // Solves the fallback hover K once (the reason construction may fail: throws std::runtime_error
  // when the weights admit no stabilizing hover gain).
  StateDependentLqr(const LqrParams& lqr, const ControllerParams& params);

  // A K that passed validation (finite, solved OK); older than the current one is ignored.
  void setGains(const GainSet& gains);
  // A COMMAND with the seq of the one handled last is the mission's re-send and changes nothing.
  void handleCommand(const Command& command);
  // Starts tracking (copies the samples: call on receipt). Empty string when accepted, else why not.
  std::string setTrajectory(const Trajectory& trajectory);
  // Offers a PARAMS update under the rule the gain solver shares (RuntimeLqrParams::apply).
  // Applied weights (for the fallback K) and limits count from the next tick, tracking switches
  // the scheme without losing the place. Weights that admit no stabilizing hover K are kInvalid;
  // anything but kApplied changes nothing.
  ParamsOutcome applyParams(const ParamsUpdate& update);

  struct Tick {
    RateCommand command;
    Reference reference;
  };
  // Returns true when this estimate is the one to compute the next tick from and fills `out`
  // (stamped with the tick's time); false between ticks, before the estimator is initialised, and
  // while idle on the ground.
  bool onStateEstimate(const StateEstimate& estimate, Tick& out);
  // The time of the tick this estimate would be computed into (its own, or the grid point it is
  // carried forward to), -1 if none; changes nothing. Whether a command comes out also depends
  // on the flight phase. For the replay, which asks before it feeds.
  int64_t tickUtimeFor(const StateEstimate& received) const;

  const ControllerStatus& status() const { return status_; }
  const GainMatrix& fallbackGain() const { return fallback_K_; }
  // The rotor drag of the model the gains were solved for (lqr.model_rotor_drag).
  RotorDrag modelRotorDrag() const { return lqr_.params().rotorDrag(); }
  const ReferenceGenerator& references() const { return references_; }
  const Vec3& positionErrorIntegral() const { return integral_.value(); }
  // sdlqr_adaptive's estimate of produced over commanded thrust (kept for every law; 1 on the ground).
  double thrustGain() const { return thrust_gain_.value(); }

 private:
  struct GainSlot {
    GainSet gains;
    bool has = false;
  };
  // What one law computed in a tick.
  struct LawTick {
    ControlOutput control;
    GainsFreshness freshness = GainsFreshness::kFresh;
    int64_t gains_seq = -1;
    bool extension = false;
  };
  const GainMatrix& chooseGain(int64_t now_utime, GainsFreshness& freshness, int64_t& gains_seq);
  GainSlot& slotFor(ControlLaw law);
  LawTick computeLaw(const StateEstimate& estimate, const Reference& reference);
  LawTick lqrTick(const StateEstimate& estimate, const Reference& reference, const Input& u_ref);
  void updateThrustGain(const StateEstimate& received);
  void hoverGain(const Reference& reference, GainMatrix& K, Quat& q_lin) const;
  bool extensionFresh(const GainSlot& slot, int64_t now_utime) const;
  void updateExtensionStates(const StateEstimate& estimate, const Reference& reference, const RateCommand& command,
                             bool headroom_scaled);

  RuntimeLqrParams lqr_;
  ControllerParams params_;
  ReferenceGenerator references_;
  GainMatrix fallback_K_;
  GainSet gains_;
  bool has_gains_ = false;
  GainSlot integral_gains_, actuator_gains_;
  PositionErrorIntegral integral_;
  ThrustLagModel thrust_model_;
  ThrustGainEstimate thrust_gain_;
  Vec3 last_reference_position_ = Vec3::Zero();  // of the last tick (the thrust gain adapts near it)
  BumplessTransfer transfer_;
  ControlLaw tick_law_ = ControlLaw::kSdlqr;  // law and extension of the last tick
  bool tick_extension_ = false;
  bool has_commanded_ = false;
  Input last_command_ = Input::Zero();
  StateEstimate latest_;
  bool has_estimate_ = false;
  int64_t next_tick_utime_ = 0;
  double last_thrust_;  // [m/s^2] for carrying an estimate forward to the tick
  int64_t command_seq_ = 0;
  int64_t reference_seq_ = 0;
  // Inputs named in each REFERENCE, so a replay can check it fed the tick the same ones.
  int64_t command_seq_handled_ = -1;
  ControllerStatus status_;
};

}  // namespace sdlqr::controller
