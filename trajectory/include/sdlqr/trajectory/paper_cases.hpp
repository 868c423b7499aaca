#pragma once
// The reference trajectories of the paper's experiments (§III-C), lifted by height_offset so the
// vehicle flies them clear of the floor (the paper's own frame starts at z = 0).
//
//  minsnap fast  §III-C.2: min-snap through p0 = (0,-1.2,0), p1 = (1.5,0,0.5), p2 = (0,1.5,0),
//                p3 = (-1.5,0,0.5), v_max 3.0 m/s. The path closes on p0; by default it starts
//                at rest on p0, flies `laps` laps and stops on p0 ("close to an ellipse except for
//                the start and end phase"); with `periodic` it is one C^4 lap that repeats.
//  minsnap slow  §III-C.4: the same at v_max 1.0 m/s (the disturbance experiment).
//  ellipse       §III-C.3: p(a) = (1.5 sin a, -1.2 cos a, 0.5 sin a), d a = 2 pi / 36, deliberately
//                infeasible: velocity 2.0 m/s pointing to the next sample, level attitude at the
//                fixed yaw, hover thrust c = g, zero body rates; times from segment length / speed.
//                Closed: 36 samples per lap plus the closing sample (= sample 0).

#include <vector>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/min_snap.hpp"
#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::trajectory {

// p0..p3 of §III-C.2 raised by height_offset.
std::vector<Waypoint> paperWaypoints(double height_offset);
// The waypoint list generateMinSnap gets: p0, then laps x (p1, p2, p3, p0); or p0..p3 when periodic.
std::vector<Waypoint> paperPathWaypoints(const TrajectoryParams& params);

MinSnapTrajectory paperMinSnap(double v_max, const TrajectoryParams& params);
MinSnapTrajectory paperMinSnapFast(const TrajectoryParams& params);
MinSnapTrajectory paperMinSnapSlow(const TrajectoryParams& params);

// Position on the paper's ellipse at angle alpha [rad], raised by height_offset.
Vec3 paperEllipsePoint(double alpha, double height_offset);
Trajectory paperEllipse(const TrajectoryParams& params, double gravity);

}  // namespace sdlqr::trajectory
