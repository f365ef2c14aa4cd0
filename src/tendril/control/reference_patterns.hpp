#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace tendril::control {

// The reference paths the limb tracks in bend-angle space (θx, θy in degrees), seed 001 Figs.
// 5.3 and 5.5. The thesis shows the shapes but gives no coordinates; these are tendril's, sized
// to stay inside the task's ±75° goal range and sampled every ≤ 5° (half the waypoint tolerance)
// so that the follower walks along the shape rather than cutting its corners:
//   circle  radius 40° about 0, one turn counter-clockwise from (40, 0)
//   square  corners (±40, ±40), counter-clockwise from (40, −40)
//   spiral  Archimedean, r = 50° · s, angle 4π s, s: 0 → 1 (two turns outward from 0)
//   sml     the letters S, M, L side by side, each 30° wide and 40° tall, centred on x = −50, 0,
//           50, drawn as one stroke (S from its top right, M from its bottom left, L from its top)
Eigen::Matrix2Xd reference_pattern(std::string_view name);
// "circle", "square", "spiral", "sml".
std::vector<std::string> reference_pattern_names();

// `corners` with points inserted so that consecutive points are at most `spacing` apart (the
// corners kept).
Eigen::Matrix2Xd densify(const Eigen::Matrix2Xd& corners, double spacing);

// Distance from `point` to the polyline `path` (its nearest point on any segment).
double distance_to_path(const Eigen::Vector2d& point, const Eigen::Matrix2Xd& path);
// Tracking error of seed 001's Tables 5.4–5.5 as tendril measures it: the root mean square, over
// every control step of the run, of the distance from the limb's angles to the reference path.
double tracking_rmse(const Eigen::Matrix2Xd& trajectory, const Eigen::Matrix2Xd& path);

}  // namespace tendril::control
