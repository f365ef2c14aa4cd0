#pragma once

#include <algorithm>

#include "tendril/core/error.hpp"
#include "tendril/core/snapshot.hpp"
#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::physics::pneumatic {

// Material hysteresis of each chamber (seed 002 §III-B names it among the causes of the arm's
// stochastic behaviour, without a model): a play (backlash) operator of width w from the chamber
// pressure p to the pressure that strains the material, y ← clamp(y, p − w/2, p + w/2). The
// output stays put while the input reverses within the band, so loading and unloading paths
// differ by w, and after venting a residual of up to w/2 remains (the arm does not quite return
// to where it was). Width 0 gives y = p. [A] choice of the operator: play (Krasnosel'skii–
// Pokrovskii's elementary hysteron), because it has one state per chamber and is exact to
// snapshot.
class PlayHysteresis {
 public:
  explicit PlayHysteresis(double width_bar = 0.0) : half_width_(0.5 * width_bar) {
    require(width_bar >= 0.0 && width_bar < 1e3, "hysteresis width must be in [0, 1000) bar",
            "PlayHysteresis");
  }

  const ChamberVector& update(const ChamberVector& input) {
    for (int k = 0; k < kChambers; ++k) {
      output_[k] = std::clamp(output_[k], input[k] - half_width_, input[k] + half_width_);
    }
    return output_;
  }
  const ChamberVector& output() const { return output_; }
  void reset() { output_.setZero(); }
  double width() const { return 2.0 * half_width_; }

  void save_state(SnapshotWriter& out) const {
    out.section("PlayHysteresis");
    out.put_matrix(output_);
  }
  void load_state(SnapshotReader& in) {
    in.section("PlayHysteresis");
    ChamberVector output;
    in.get_matrix(output);
    output_ = output;
  }

 private:
  double half_width_;
  ChamberVector output_ = ChamberVector::Zero();
};

}  // namespace tendril::physics::pneumatic
