#pragma once

#include <Eigen/Core>

#include "tendril/core/snapshot.hpp"

namespace tendril::envs::sma_limb {

// The four coils' heat as the policy of seed 001 sees it (thesis §5.1.1, eqs. 5.1–5.4,
// Algorithm 2): Joule heating by Ohm's law, P = V²/R with the throttle as V (eq. 5.1), and Newton
// cooling towards an ambient of 0, T_{t+1} = T_t − kΔt·T_t (eq. 5.3). Each step every coil cools,
// then the coil of each axis that the throttle drives (+ for u > 0, − otherwise) gains u²/R · Δt.
// Eq. 5.4 prints a minus before the cooling term; Algorithm 2 adds, as here.
// Order of the four values: [+x, −x, +y, −y] (thesis: p = [+p^x, −p^x, +p^y, −p^y]).
// Driven constantly at |u| = 10 a coil settles at u²/(R k) = 166.7.
class PowerProxy {
 public:
  struct Params {
    double cooling_rate = 0.2;  // k, 1/s: cool to ambient in ~30 s (Fig. A.4)
    double period = 0.075;      // Δt, s
    double resistance = 3.0;    // R
  };

  PowerProxy() = default;
  // Raises Error unless k, Δt, R > 0 and kΔt < 1.
  explicit PowerProxy(Params params);

  const Params& params() const { return params_; }
  const Eigen::Vector4d& power() const { return power_; }
  // The largest value a coil reaches from 0 under throttles of magnitude ≤ `max_throttle`.
  double bound(double max_throttle) const;

  // Algorithm 2 for the throttles (u_x, u_y) applied this step.
  void update(double throttle_x, double throttle_y);
  void reset() { power_.setZero(); }

  void save_state(SnapshotWriter& out) const;
  void load_state(SnapshotReader& in);

 private:
  Params params_;
  Eigen::Vector4d power_ = Eigen::Vector4d::Zero();
};

}  // namespace tendril::envs::sma_limb
