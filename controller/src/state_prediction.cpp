#include "sdlqr/controller/state_prediction.hpp"

#include "sdlqr/math/model.hpp"

namespace sdlqr::controller {

StateEstimate predictEstimate(const StateEstimate& estimate, double thrust, int64_t to_utime, double gravity) {
  StateEstimate predicted = estimate;
  predicted.utime = to_utime;
  const double h = 1e-6 * static_cast<double>(to_utime - estimate.utime);
  if (!(h > 0.0)) return predicted;
  const Input u = makeInput(estimate.body_rate, thrust);
  const State x0 = estimate.state();
  const State k1 = dynamics(x0, u, gravity);
  const State k2 = dynamics(x0 + 0.5 * h * k1, u, gravity);
  const State k3 = dynamics(x0 + 0.5 * h * k2, u, gravity);
  const State k4 = dynamics(x0 + h * k3, u, gravity);
  const State x = x0 + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  predicted.position = position(x);
  predicted.orientation = orientation(x).normalized();
  predicted.velocity = velocity(x);
  return predicted;
}

}  // namespace sdlqr::controller
