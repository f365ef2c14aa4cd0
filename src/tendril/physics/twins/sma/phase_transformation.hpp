#pragma once

namespace tendril::physics {

// The four transformation temperatures of a shape-memory alloy, °C. On heating, martensite
// turns into austenite between austenite_start (As) and austenite_finish (Af); on cooling,
// austenite turns back between martensite_start (Ms) and martensite_finish (Mf).
//
// The defaults are the coils' effective temperatures under the limb's load. The thesis gives its
// Dynalloy Nitinol an actuation range of 60–110 °C (seed 001, Ch. 3); a coil in the limb
// contracts gradually from As = 60 °C, and finishes higher, at Af = 125 °C, since the stress it
// works against grows with the bend and raises the transformation temperatures
// (Clausius–Clapeyron). With these the twin's calibrated input bounds land at the thesis' (see
// docs/results/sma_limb.md). Ms and Mf are our choice, ≈ 35 °C of hysteresis between the
// mid-points of the two branches, typical of NiTi.
struct TransformationTemperatures {
  double austenite_start = 60.0;
  double austenite_finish = 125.0;
  double martensite_start = 80.0;
  double martensite_finish = 35.0;

  // Raises tendril::Error unless all are finite, As < Af and Mf < Ms.
  void validate() const;
};

// The martensite fraction ξ ∈ [0, 1] of a coil (1: fully martensite, cold, long; 0: fully
// austenite, hot, contracted) with thermal hysteresis, after Liang & Rogers (1990, J. Intell.
// Mater. Syst. Struct. 1(2)) cosine kinetics:
//   heating, As ≤ T ≤ Af:  H(T) = (1 + cos(π (T − As) / (Af − As))) / 2,   ξ = ξ_h H(T) / H(T_h)
//   cooling, Mf ≤ T ≤ Ms:  C(T) = (1 − cos(π (Ms − T) / (Ms − Mf))) / 2,
//                          ξ = ξ_c + (1 − ξ_c) (C(T) − C(T_c)) / (1 − C(T_c))
// (H = 1 below As and 0 above Af; C = 0 above Ms and 1 below Mf). Each branch runs from its
// anchor (T_h, ξ_h) or (T_c, ξ_c) continuously to its end (ξ = 0 at Af, ξ = 1 at Mf). Turning
// round moves the new branch's anchor to the turning point — unless ξ has not changed since that
// branch was last followed, in which case the branch resumes where it left off (a small cooling
// above Ms changes nothing, so heating on continues the same curve). Partial cycles thus trace
// minor loops inside the major one.
struct PhaseState {
  struct Anchor {
    double temperature = 22.0;  // °C
    double martensite = 1.0;
    double left_at = 1.0;  // ξ when the branch was last left
  };
  double martensite = 1.0;    // ξ
  double temperature = 22.0;  // the last temperature seen, °C
  bool heating = true;        // the branch it is on
  Anchor heating_anchor, cooling_anchor;

  // A coil resting at `temperature`, fully martensite.
  static PhaseState rested(double temperature);
};

// How a branch re-entered with ξ unchanged continues. kResume (the twin's default, with which
// its data sets were made) evaluates the branch from its old anchor at the new temperature; when
// the coil re-enters it at another temperature — heated again after cooling above Ms, cooled
// again after heating below As — ξ jumps to the branch's value there, against the temperature's
// direction (heating raising ξ by up to ≈ 0.6 in one step; docs/results/learned_dynamics.md).
// kContinuous keeps ξ where it is until the branch's curve passes it: heating never raises ξ and
// cooling never lowers it, and the fraction is continuous in time.
enum class PhaseReentry { kResume, kContinuous };

// Moves `state` to the new temperature `temperature` (°C) along its branch, turning round first
// if the temperature moved the other way.
void update_phase(const TransformationTemperatures& temperatures, PhaseState& state,
                  double temperature, PhaseReentry reentry = PhaseReentry::kResume);

}  // namespace tendril::physics
