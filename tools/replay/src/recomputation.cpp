#include "sdlqr/replay/recomputation.hpp"

#include <algorithm>
#include <stdexcept>

namespace sdlqr::replay {

int64_t RecordedFlight::utimeAt(const LogPosition& p) const {
  const auto i = static_cast<std::size_t>(p.index);
  switch (p.kind) {
    case InputKind::kImu: return imu[i].utime;
    case InputKind::kVioPose: return vio_pose[i].utime;
    case InputKind::kStateEstimate: return state_estimate[i].utime;
    case InputKind::kCommand: return command[i].utime;
    case InputKind::kTrajectory: return trajectory[i].utime;
    case InputKind::kParams: return params[i].utime;
  }
  return 0;
}

namespace {

template <class T>
std::map<int64_t, std::size_t> indexBySeq(const std::vector<T>& series) {
  std::map<int64_t, std::size_t> index;
  for (std::size_t i = 0; i < series.size(); ++i) index.emplace(series[i].seq, i);
  return index;
}

const estimator::EstimatorParams& checked(const ReplayParams& p) {
  if (!p.lqr.valid()) throw std::invalid_argument("lqr: " + p.lqr.invalidReason());
  if (!p.controller.valid()) throw std::invalid_argument("controller: " + p.controller.invalidReason());
  if (!p.gains.valid()) throw std::invalid_argument("gains: " + p.gains.invalidReason());
  return p.estimator;
}

}  // namespace

Recomputation::Recomputation(const ReplayParams& params, const RecordedFlight& flight)
    : flight_(flight),
      estimator_(checked(params)),
      scheduler_(params.lqr, params.gains.rate_hz),
      solve_period_us_(static_cast<int64_t>(1e6 / params.gains.rate_hz + 0.5)),
      controller_(params.lqr, params.controller),
      tick_period_us_(static_cast<int64_t>(1e6 / params.controller.rate_hz + 0.5)),
      limits_(params.validation),
      recorded_gains_(indexBySeq(flight.gains)),
      recorded_reference_(indexBySeq(flight.reference)),
      recorded_estimate_(indexBySeq(flight.state_estimate)) {}

void Recomputation::step() {
  const LogPosition p = flight_.order[next_++];
  const auto i = static_cast<std::size_t>(p.index);
  switch (p.kind) {
    case InputKind::kImu: onImu(flight_.imu[i]); break;
    case InputKind::kVioPose: estimator_.onVio(flight_.vio_pose[i]); break;
    case InputKind::kStateEstimate: onRecordedEstimate(flight_.state_estimate[i].seq); break;
    case InputKind::kCommand: heard_commands_.push_back(i); break;
    case InputKind::kTrajectory: onTrajectory(flight_.trajectory[i]); break;
    case InputKind::kParams: onParams(flight_.params[i]); break;
  }
}

void Recomputation::finish() {
  for (const auto& [seq, estimate] : waiting_) handOver(estimate);
  waiting_.clear();
  for (std::size_t i : heard_commands_) applyCommand(flight_.command[i]);
  heard_commands_.clear();
}

bool Recomputation::rejected(RejectReason reason) {
  if (reason == RejectReason::kNone) return false;
  ++pairing_.rejected;
  return true;
}

// sdlqr-estimator: every IMU sample, the estimate published unless non-finite.
void Recomputation::onImu(const ImuSample& sample) {
  const std::optional<StateEstimate> estimate = estimator_.onImu(sample);
  if (!estimate || !estimate->state().allFinite() || !estimate->body_rate.allFinite()) return;
  outputs_.state_estimate.push_back(*estimate);
  if (estimate->seq <= handed_over_up_to_) {
    ++pairing_.estimates_without_record;  // its place in the log has passed (or never was)
    handOver(*estimate);
  } else {
    waiting_.emplace(estimate->seq, *estimate);
  }
}

// The recorded STATE_EST marks where the controller and the solver received this seq.
void Recomputation::onRecordedEstimate(int64_t seq) {
  handed_over_up_to_ = std::max(handed_over_up_to_, seq);
  while (!waiting_.empty() && waiting_.begin()->first <= seq) {
    const StateEstimate estimate = waiting_.begin()->second;
    waiting_.erase(waiting_.begin());
    handOver(estimate);
  }
}

// The solver first: a solve at this estimate can only use references of earlier ticks (the
// REFERENCE of this estimate's tick is sent after the estimate), while this estimate's tick may
// name the GAINS solved at it (when the solver was quicker than the controller).
void Recomputation::handOver(const StateEstimate& estimate) {
  gainsOnEstimate(estimate);
  controllerOnEstimate(estimate);
}

// The GAINS a recorded tick names, recomputed if the replay has it, else as recorded.
void Recomputation::feedNamedGains(int64_t gains_seq) {
  if (gains_seq < 0 || gains_seq == fed_gains_seq_) return;
  if (auto it = replayed_gains_.find(gains_seq); it != replayed_gains_.end()) {
    controller_.setGains(outputs_.gains[it->second]);
    ++pairing_.gains_from_replay;
  } else if (auto rec = recorded_gains_.find(gains_seq); rec != recorded_gains_.end()) {
    controller_.setGains(flight_.gains[rec->second]);
    ++pairing_.gains_from_record;
  } else {
    return;
  }
  fed_gains_seq_ = gains_seq;
}

// True when the recorded tick shows the controller cannot have received `estimate` (a tick is
// computed from the last estimate before a grid point, carried forward, or on the first one at
// or after it):
//  - feeding it would tick earlier in the same grid slot than the recording did, or
//  - the recorded tick is carried forward from the next estimate over a longer interval than
//    the one from this estimate: the controller's previous estimate was older than this one.
bool Recomputation::missedByController(const StateEstimate& estimate, const RateCommand& recorded) const {
  const int64_t tick_utime = controller_.tickUtimeFor(estimate);
  if (tick_utime >= 0) {
    const int64_t next_grid = (tick_utime / tick_period_us_ + 1) * tick_period_us_;
    return recorded.utime > tick_utime && recorded.utime < next_grid && recorded.state_seq > estimate.seq;
  }
  if (recorded.state_seq != estimate.seq + 1) return false;
  const auto next = recorded_estimate_.find(estimate.seq + 1);
  if (next == recorded_estimate_.end()) return false;
  const int64_t next_utime = flight_.state_estimate[next->second].utime;
  const bool carried_forward = recorded.utime > next_utime;
  return carried_forward && next_utime + (next_utime - estimate.utime) <= recorded.utime;
}

// sdlqr-controller's STATE_EST handler, with the GAINS of the next recorded tick fed first.
void Recomputation::controllerOnEstimate(const StateEstimate& estimate) {
  deliverCommandsBefore(estimate);
  RejectReason reason = validate(estimate, limits_);
  if (reason == RejectReason::kNone) reason = controller_state_time_.check(estimate.utime, -1);
  if (rejected(reason)) return;
  controller_state_time_.accept(estimate.utime);

  const std::vector<RateCommand>& ticks_ = flight_.rate_command;
  // A tick is computed from estimate state_seq, carried forward, on the arrival of the next one.
  while (next_tick_ < ticks_.size() && ticks_[next_tick_].state_seq < estimate.seq - 1) ++next_tick_;
  if (next_tick_ < ticks_.size() && ticks_[next_tick_].state_seq <= estimate.seq) {
    feedNamedGains(ticks_[next_tick_].gains_seq);
  }
  // The controller's STATE_EST queue holds one message: a busy controller misses estimates, and
  // a tick then comes later than the grid point (on the next estimate it did receive). An
  // estimate that would make a tick earlier than the recorded one was not received: skip it.
  if (next_tick_ < ticks_.size() && missedByController(estimate, ticks_[next_tick_])) {
    ++pairing_.estimates_missed_by_controller;
    return;
  }
  controller::StateDependentLqr::Tick tick;
  if (!controller_.onStateEstimate(estimate, tick)) return;
  replayed_reference_[tick.reference.seq] = outputs_.reference.size();
  outputs_.rate_command.push_back(tick.command);
  outputs_.reference.push_back(tick.reference);
  while (next_tick_ < ticks_.size() && ticks_[next_tick_].seq <= tick.command.seq) ++next_tick_;
}

// sdlqr-gains' STATE_EST handler, with the REFERENCE the recorded solve names.
void Recomputation::gainsOnEstimate(const StateEstimate& estimate) {
  RejectReason reason = validate(estimate, limits_);
  if (reason == RejectReason::kNone) reason = gains_state_time_.check(estimate.utime, -1);
  if (rejected(reason)) return;
  gains_state_time_.accept(estimate.utime);
  if (estimate.status == EstimatorStatus::kInitializing) return;
  const std::vector<GainSet>& solves = flight_.gains;
  while (next_solve_ < solves.size() && solves[next_solve_].state_seq < estimate.seq) ++next_solve_;
  // The solver solves on the first estimate it receives at or after each grid point; when the
  // recorded solve names a later one, this estimate was lost in its one-message queue.
  if (next_solve_ < solves.size() && solves[next_solve_].state_seq > estimate.seq &&
      scheduler_.isDue(estimate) && solves[next_solve_].utime < (estimate.utime / solve_period_us_ + 1) * solve_period_us_) {
    ++pairing_.estimates_missed_by_solver;
    return;
  }
  if (!scheduler_.due(estimate)) return;
  if (next_solve_ < solves.size() && solves[next_solve_].state_seq == estimate.seq) {
    const int64_t reference_seq = solves[next_solve_].reference_seq;
    if (auto it = replayed_reference_.find(reference_seq); it != replayed_reference_.end()) {
      scheduler_.setReference(outputs_.reference[it->second]);
      ++pairing_.references_from_replay;
    } else if (auto rec = recorded_reference_.find(reference_seq); rec != recorded_reference_.end()) {
      scheduler_.setReference(flight_.reference[rec->second]);
      ++pairing_.references_from_record;
    }
  } else {
    ++pairing_.solves_unpaired;
  }
  GainSet gains;
  if (scheduler_.solve(estimate, gains) != SolveStatus::kOk) {
    ++pairing_.solve_failures;
    return;
  }
  // solve_us is the solver's wall time, measured by the process: not recomputed.
  replayed_gains_[gains.seq] = outputs_.gains.size();
  outputs_.gains.push_back(gains);
}

// COMMAND and STATE_EST race on the bus like GAINS do: the REFERENCE of the tick computed from
// this estimate names the last COMMAND the controller had handled.
void Recomputation::deliverCommandsBefore(const StateEstimate& estimate) {
  const std::vector<RateCommand>& ticks = flight_.rate_command;
  std::size_t t = next_tick_;
  while (t < ticks.size() && ticks[t].state_seq < estimate.seq) ++t;
  const auto reference = t < ticks.size() && ticks[t].state_seq == estimate.seq
                             ? recorded_reference_.find(ticks[t].reference_seq)
                             : recorded_reference_.end();
  if (reference == recorded_reference_.end()) {  // no tick to say otherwise: the recorder's order
    for (std::size_t i : heard_commands_) applyCommand(flight_.command[i]);
    heard_commands_.clear();
    return;
  }
  const int64_t named = flight_.reference[reference->second].command_seq;
  for (const Command& command : flight_.command) {  // in log order, also those heard later
    if (command.seq > applied_command_seq_ && command.seq <= named) applyCommand(command);
  }
  heard_commands_.erase(std::remove_if(heard_commands_.begin(), heard_commands_.end(),
                                       [&](std::size_t i) { return flight_.command[i].seq <= applied_command_seq_; }),
                        heard_commands_.end());
}

// sdlqr-controller's COMMAND handler; a re-sent command (same seq) is handled once.
void Recomputation::applyCommand(const Command& command) {
  if (command.seq <= applied_command_seq_) return;
  applied_command_seq_ = command.seq;
  if (rejected(validate(command, limits_))) return;
  controller_.handleCommand(command);
}

void Recomputation::onTrajectory(const Trajectory& trajectory) {
  if (rejected(validate(trajectory, limits_))) return;
  if (!controller_.setTrajectory(trajectory).empty()) ++pairing_.rejected;
}

void Recomputation::onParams(const ParamsUpdate& update) {
  if (rejected(validate(update, limits_))) return;
  controller_.applyParams(update);
  if (scheduler_.applyParams(update) != ParamsOutcome::kApplied) ++pairing_.rejected;
}

}  // namespace sdlqr::replay
