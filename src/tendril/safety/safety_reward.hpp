#pragma once

#include <cstdint>

namespace tendril::safety {

// The safety agent's reward of seed 001 §6.2 (eqs. 6.3–6.4), with discount γ ∈ (0, 1):
//
//   r_safe(x, u, x') =  l(x)                  x ∉ X_unsafe, x' ∉ X_unsafe
//                       −1 / (γ^t (1 − γ))    x ∉ X_unsafe, x' ∈ X_unsafe
//                       −1                    x ∈ X_unsafe
//
// with l(x) = d(x) / max_{x ∉ X_unsafe} d(x) ∈ (0, 1] and d the signed distance to X_unsafe
// (d ≤ 0 counts as unsafe). t is the time step of x within its episode: discounted back to the
// episode's start, entering the unsafe set is worth −1/(1 − γ) whenever it happens, so the sign
// of V separates safe from irrecoverable states (the bounds of §6.2.2 below).
class SafetyReward {
 public:
  explicit SafetyReward(double gamma);

  double gamma() const { return gamma_; }

  // l(x) of eq. (6.4) from d(x) and its maximum over the safe set.
  static double level(double margin, double max_margin);
  // r_safe of eq. (6.3); `level_x` is l(x), `time_step` t of x.
  double reward(double level_x, int64_t time_step, bool unsafe, bool next_unsafe) const;

  // §6.2.2 for episodes of at most T steps: 0 < V*(x) ≤ (1 − γ^{T+1})/(1 − γ) on X_safe,
  // −(1 + γ)/(1 − γ) ≤ V*(x) < 0 on X_irrec, V*(x) = −(1 − γ^{T+1})/(1 − γ) on X_unsafe.
  double safe_value_bound(int64_t horizon) const;
  double irrecoverable_value_bound() const;
  double unsafe_value(int64_t horizon) const;
  // The target of the supervised unsafe loss (eq. 6.6): −1/(1 − γ).
  double unsafe_target() const { return -1.0 / (1.0 - gamma_); }

 private:
  double gamma_;
};

}  // namespace tendril::safety
