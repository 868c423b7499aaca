#include "sdlqr/lowlevel/mixer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/QR>

#include "mixer_rows.hpp"


namespace sdlqr::lowlevel {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kScaleTolerance = 1e-9;

// std::clamp for an interval that round-off may have closed (low a hair above high).
double clampToInterval(double value, double low, double high) {
  if (low > high) return 0.5 * (low + high);
  return std::clamp(value, low, high);
}
}  // namespace

MixerParams::MixerParams() { declaration().setDefaults(*this); }

const ParamTable<MixerParams>& MixerParams::declaration() {
  static const ParamTable<MixerParams> table = mixerParamsRows();
  return table;
}

Mixer::Mixer(const Mat44& effectiveness, double min_thrust, double max_thrust, const MixerParams& params)
    : effectiveness_(effectiveness), params_(params) {
  if (!effectiveness.allFinite()) throw std::invalid_argument("mixer: effectiveness matrix is not finite");
  allocation_ = Eigen::CompleteOrthogonalDecomposition<Mat44>(effectiveness).pseudoInverse();
  collective_column_ = allocation_.col(0);
  // Shifting the collective is the desaturation tool; it only works if every rotor takes part.
  if (!(collective_column_.minCoeff() > 1e-6)) {
    throw std::invalid_argument("mixer: a rotor does not contribute to the collective thrust");
  }
  for (int rotor = 0; rotor < 4; ++rotor) inverse_collective_column_[rotor] = 1.0 / collective_column_[rotor];
  setThrustLimits(min_thrust, max_thrust);
}

void Mixer::setThrustLimits(double min_thrust, double max_thrust) {
  if (!(std::isfinite(min_thrust) && std::isfinite(max_thrust) && min_thrust < max_thrust)) {
    throw std::invalid_argument("mixer: rotor thrust limits must be finite with min < max");
  }
  min_thrust_ = min_thrust;
  max_thrust_ = max_thrust;
}

void Mixer::collectiveInterval(const Vec4& base, double* low, double* high) const {
  // The eight divisions as four vector ones (the same quotients): most of a mix's time was them.
  const Vec4 lows = (Vec4::Constant(min_thrust_) - base).cwiseQuotient(collective_column_);
  const Vec4 highs = (Vec4::Constant(max_thrust_) - base).cwiseQuotient(collective_column_);
  *low = -kInfinity;
  *high = kInfinity;
  for (int rotor = 0; rotor < 4; ++rotor) {
    *low = std::max(*low, lows[rotor]);
    *high = std::min(*high, highs[rotor]);
  }
}

double Mixer::largestFeasibleScale(const Vec4& base, const Vec4& direction, double collective_low,
                                   double collective_high) const {
  // Every bound on F is a line offset + slope * k. A feasible F exists while each lower bound
  // stays below each upper bound; each pair limits k from above when their gap closes with k.
  double lower_offset[5], lower_slope[5], upper_offset[5], upper_slope[5];
  for (int rotor = 0; rotor < 4; ++rotor) {
    const double inverse_share = inverse_collective_column_[rotor];
    lower_offset[rotor] = (min_thrust_ - base[rotor]) * inverse_share;
    upper_offset[rotor] = (max_thrust_ - base[rotor]) * inverse_share;
    lower_slope[rotor] = upper_slope[rotor] = -direction[rotor] * inverse_share;
  }
  lower_offset[4] = collective_low;
  upper_offset[4] = collective_high;
  lower_slope[4] = upper_slope[4] = 0.0;

  double scale = 1.0;
  for (int l = 0; l < 5; ++l) {
    if (!std::isfinite(lower_offset[l])) continue;
    for (int u = 0; u < 5; ++u) {
      if (!std::isfinite(upper_offset[u])) continue;
      const double gap = upper_offset[u] - lower_offset[l];  // must stay >= 0
      const double closing = lower_slope[l] - upper_slope[u];
      // scale <= 1: a gap of at least `closing` (gap / closing >= 1) cannot lower it, and the
      // division it spares is most of a mix (the test is exact: the quotient rounds monotonically).
      if (closing > 0.0) {
        if (gap < closing) scale = std::min(scale, gap / closing);
      } else if (gap < 0.0) {
        scale = 0.0;  // infeasible whatever k: give the axis up entirely
      }
    }
  }
  return std::clamp(scale, 0.0, 1.0);
}

MixerResult Mixer::mix(double collective, const Vec3& torque) const {
  MixerResult result;
  if (!std::isfinite(collective) || !torque.allFinite()) {
    // Nothing sensible can be allocated from a non-finite demand; never pass it to the rotors.
    result.thrust.setConstant(min_thrust_);
    result.collective_limited = true;
    result.saturated_positive.setConstant(true);
    result.saturated_negative.setConstant(true);
    const Vec4 wrench = effectiveness_ * result.thrust;
    result.collective = wrench[0];
    result.torque = wrench.tail<3>();
    return result;
  }

  const Vec4 roll_pitch = allocation_.col(1) * torque[0] + allocation_.col(2) * torque[1];
  result.roll_pitch_scale = largestFeasibleScale(Vec4::Zero(), roll_pitch, -kInfinity, kInfinity);
  Vec4 differential = result.roll_pitch_scale * roll_pitch;

  double low = 0.0, high = 0.0;
  collectiveInterval(differential, &low, &high);
  const double collective_for_roll_pitch = clampToInterval(collective, low, high);

  // Yaw may move the collective by `window` beyond both the demand and what roll/pitch needed.
  const Vec4 yaw = allocation_.col(3) * torque[2];
  const double window = params_.yaw_collective_share * std::abs(collective);
  const double window_low = std::min(collective, collective_for_roll_pitch) - window;
  const double window_high = std::max(collective, collective_for_roll_pitch) + window;
  result.yaw_scale = largestFeasibleScale(differential, yaw, window_low, window_high);
  differential += result.yaw_scale * yaw;

  // Back as close to the demanded collective as the rotors and the yaw window allow.
  collectiveInterval(differential, &low, &high);
  const double delivered_collective = clampToInterval(collective, std::max(low, window_low), std::min(high, window_high));
  // The clamp only removes round-off: the steps above already keep every rotor in range.
  result.thrust = (differential + collective_column_ * delivered_collective).cwiseMax(min_thrust_).cwiseMin(max_thrust_);

  const Vec4 wrench = effectiveness_ * result.thrust;
  result.collective = wrench[0];
  result.torque = wrench.tail<3>();
  result.collective_limited = std::abs(delivered_collective - collective) > kScaleTolerance * (1.0 + std::abs(collective));
  const bool roll_pitch_limited = result.roll_pitch_scale < 1.0 - kScaleTolerance;
  const bool yaw_limited = result.yaw_scale < 1.0 - kScaleTolerance;
  for (int axis = 0; axis < 3; ++axis) {
    const bool limited = axis < 2 ? roll_pitch_limited : yaw_limited;
    result.saturated_positive[axis] = limited && torque[axis] > 0.0;
    result.saturated_negative[axis] = limited && torque[axis] < 0.0;
  }
  return result;
}

}  // namespace sdlqr::lowlevel
