#pragma once
// A path asked for at a speed the vehicle may not manage: its feasibility at that speed, and, by
// bisection on the speed (the inputs grow with it: thrust with speed^2 / radius, body rates with
// speed / radius), the highest speed at which it is feasible. Used when a trajectory is loaded:
// refused with the report, or flown time-scaled to the limits when the scenario asks for it.

#include <functional>
#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/feasibility.hpp"

namespace sdlqr::trajectory {

struct SpeedFit {
  double requested_speed = 0.0;  // [m/s]
  FeasibilityReport requested;   // at the requested speed
  double feasible_speed = 0.0;   // [m/s] highest feasible speed <= requested (0: none above min_speed)
  Trajectory trajectory;         // at feasible_speed (empty when none)
};

// `generate(speed)` builds the path at a peak speed; it may throw std::invalid_argument.
SpeedFit fitSpeed(const std::function<Trajectory(double)>& generate, double requested_speed,
                  const FeasibilityLimits& limits, double gravity, double min_speed = 0.05);

// The same path flown `factor` times as fast (0 < factor): times divided by it, each sample's
// velocity, acceleration and jerk (from its own inputs, transition.hpp flatStateOf) multiplied by
// factor, factor^2, factor^3, and its state and inputs made again by the flat map. Exact for a
// trajectory whose samples are a flat map's (generated, or a CSV written from one); a hand-made
// one (the paper's ellipse) keeps its attitudes, which never matched its motion.
Trajectory timeScaled(const Trajectory& trajectory, double factor, double gravity);

// The highest speed of a trajectory's samples [m/s].
double peakSpeed(const Trajectory& trajectory);

// A path given as samples (a CSV file, an uploaded TRAJECTORY, the paper's paths) as a generator for
// fitSpeed: at its own peak speed it is returned as given, at another time-scaled (timeScaled).
std::function<Trajectory(double)> givenPathAtSpeed(Trajectory as_given, double gravity);

// One line: "at 3 m/s the path is beyond the vehicle: max |omega| 2.61 > 2 rad/s; feasible up to 2.41 m/s".
std::string describeFit(const SpeedFit& fit, const FeasibilityLimits& limits);

}  // namespace sdlqr::trajectory
