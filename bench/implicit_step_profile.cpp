// A load of implicit rod steps and nothing else, to profile them:
//
//   perf record -F 4000 build/bench/implicit_step_profile case3
//   perf report --no-children --sort symbol
//
// case1 | case3: the Elastica arm of Tracking3D-v0 | StructuredObstacles-v0, BDF2 at 1.4 ms (one
// step per RL action), a random policy's control points every step; pneumatic: the pneumatic
// arm, BDF2 at 10 ms, random pressure commands every 0.1 s; sma: the stiff SMA limb with
// continuous phase re-entry, BDF2 at 2 ms, random PWM on one coil of each pair every ten
// readings. Prints the steps and Newton iterations taken.
#include <array>
#include <cstdio>
#include <string>

#include "tendril/core/rng.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

int main(int argc, char** argv) {
  using namespace tendril;
  using namespace tendril::physics;
  const std::string robot = argc > 1 ? argv[1] : "case1";
  NewtonStatistics statistics;
  Rng rng(11);
  if (robot == "case1" || robot == "case3") {
    ElasticaArmSpec spec =
        robot == "case1" ? ElasticaArmSpec::tracking() : ElasticaArmSpec::structured_obstacles();
    spec.integrator = RodIntegrator::kBdf2;
    spec.implicit_step = 1.4e-3;
    ElasticaArm arm = build_elastica_arm(spec);
    Eigen::VectorXd targets(arm.muscles->spec().action_size());
    for (int a = 0; a < (robot == "case1" ? 40000 : 15000); ++a) {
      for (Eigen::Index k = 0; k < targets.size(); ++k) targets[k] = rng.uniform(-1.0, 1.0);
      arm.muscles->set_targets(targets);
      if (!arm.rod.advance(1)) return 1;
    }
    statistics = arm.rod.newton_statistics();
  } else if (robot == "pneumatic") {
    pneumatic::PneumaticArmSpec spec;
    spec.integrator = RodIntegrator::kBdf2;
    spec.time_step = 1e-2;
    pneumatic::PneumaticArm arm(spec);
    if (!arm.begin_trial(0)) return 1;
    for (int k = 0; k < 3000; ++k) {
      pneumatic::ChamberVector commands;
      for (Eigen::Index i = 0; i < commands.size(); ++i) commands[i] = rng.uniform(0.0, 1.5);
      arm.set_commands(commands);
      if (!arm.advance_samples(10)) return 1;
    }
    statistics = arm.rod().newton_statistics();
  } else if (robot == "sma") {
    SmaLimbSpec spec = SmaLimbSpec::stiff();
    spec.actuator.coil.phase_reentry = PhaseReentry::kContinuous;
    spec.integrator = RodIntegrator::kBdf2;
    spec.implicit_step = 2e-3;
    SmaLimb limb(spec, 3);
    std::array<int, 4> pwm{0, 0, 0, 0};
    for (int r = 0; r < 6000; ++r) {
      if (r % 10 == 0) {
        pwm = {0, 0, 0, 0};
        pwm[rng.uniform(0.0, 1.0) < 0.5 ? 0 : 1] = static_cast<int>(rng.uniform(0.0, 120.0));
        pwm[rng.uniform(0.0, 1.0) < 0.5 ? 2 : 3] = static_cast<int>(rng.uniform(0.0, 120.0));
      }
      limb.set_pwm(pwm);
      (void)limb.next_reading();
      if (!limb.finite()) return 1;
    }
    statistics = limb.rod().newton_statistics();
  } else {
    std::fprintf(stderr, "robot must be case1, case3, pneumatic or sma, got %s\n", robot.c_str());
    return 1;
  }
  std::printf("%s: %lld implicit steps, %lld Newton iterations, %lld factorizations\n",
              robot.c_str(), static_cast<long long>(statistics.steps),
              static_cast<long long>(statistics.iterations),
              static_cast<long long>(statistics.factorizations));
  return 0;
}
