// Accuracy of the implicit rod integrators against each robot's explicit reference: the tip's
// deviation over an episode under the seeds' own actuation signals, and the speed, for a range
// of implicit steps. Writes one CSV row per (robot, integrator, step); the largest step within
// each robot's tolerance is read from it (docs/results/implicit_rods.md).
//
// Every robot also runs position Verlet at half the reference's step against the reference: the
// reference's own discretisation error, the floor below which a tolerance means nothing. Each
// row states the largest deviation twice: of the read-outs as sampled, and of their moving
// averages over a window of the robot's (`smoothing`), the part of the deviation that is not
// fast oscillation.
//
//   build/bench/implicit_accuracy [out.csv [robot]]
//
// (default docs/results/implicit_rods/accuracy.csv, every robot; naming one runs only it, e.g.
// to profile its implicit steps).
//
// Robots and signals:
//   case1      the Elastica arm of Tracking3D-v0 (20 elements, Verlet 0.2 ms), a random policy's
//              12 control points drawn afresh every RL step (1.4 ms), 10 s; tip in mm.
//   case3      the arm of StructuredObstacles-v0 (50 elements, Verlet 0.1 ms, eight cylinders
//              with soft-wall contact), a random policy's two control points every 1.4 ms
//              (rate-limited), 5 s; tip in mm.
//   sma        the stiff SMA limb (10 elements, Verlet 0.2 ms), count-based exploration's PWM
//              (seed 001, ten readings per hold) recorded on the reference and replayed, 120 s;
//              the bend sensor's true angles in degrees at every reading.
//   sma_continuous  the same limb and protocol with the coils' phase continuous on a re-entered
//              branch (PhaseReentry::kContinuous), which removes the twin's jumps of the bend
//              angle when a branch is re-entered; reference and implicit runs on that twin.
//   pneumatic  the pneumatic arm (18 elements, Verlet 0.5 ms, stochastic effects of the data
//              protocol on), the saturating pressure signal at 10 Hz (seed 002), 60 s; module
//              3's tip in mm at every motion-capture sample (100 Hz).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "tendril/core/rng.hpp"
#include "tendril/envs/pneumatic/saturating_signal.hpp"
#include "tendril/envs/sma_limb/limb_calibration.hpp"
#include "tendril/envs/sma_limb/throttle_sources.hpp"
#include "tendril/physics/arms/elastica_arm.hpp"
#include "tendril/physics/twins/pneumatic/pneumatic_arm.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

namespace tendril {
namespace {

using physics::RodIntegrator;
using Clock = std::chrono::steady_clock;

// A trajectory of read-outs (mm or degrees), one per sample, and what it cost.
struct Trajectory {
  std::vector<Eigen::VectorXd> samples;
  double wall_seconds = 0.0;
  double simulated_seconds = 0.0;
  physics::NewtonStatistics newton;
  bool failed = false;
  std::string failure;
};

struct Robot {
  std::string name;
  std::string unit;           // of the deviation
  double tolerance;           // the robot's sensor noise, in `unit`
  double reference_step;      // s, the paper's position-Verlet step
  std::vector<double> steps;  // implicit steps to try, s
  int smoothing;              // samples in the moving average of the smoothed deviation
  // A run with the integrator at the step (position Verlet too: the reference and its half).
  std::function<Trajectory(RodIntegrator, double)> run;
};

// The largest and the mean distance of a run's samples from the reference's.
struct Deviation {
  double largest = 0.0, mean = 0.0;
};

Deviation deviation(const std::vector<Eigen::VectorXd>& run,
                    const std::vector<Eigen::VectorXd>& reference) {
  Deviation d;
  for (std::size_t k = 0; k < run.size(); ++k) {
    const double distance = (run[k] - reference[k]).norm();
    d.largest = std::max(d.largest, distance);
    d.mean += distance / static_cast<double>(run.size());
  }
  return d;
}

// Centred moving averages over `window` samples (shortened at the ends).
std::vector<Eigen::VectorXd> smoothed(const std::vector<Eigen::VectorXd>& samples, int window) {
  const int n = static_cast<int>(samples.size()), half = window / 2;
  std::vector<Eigen::VectorXd> out;
  out.reserve(samples.size());
  for (int k = 0; k < n; ++k) {
    const int first = std::max(0, k - half), last = std::min(n - 1, k + half);
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(samples[k].size());
    for (int j = first; j <= last; ++j) sum += samples[j];
    out.push_back(sum / static_cast<double>(last - first + 1));
  }
  return out;
}

template <typename Body>
Trajectory timed(Body&& body) {
  Trajectory trajectory;
  const auto start = Clock::now();
  try {
    body(trajectory);
  } catch (const Error& e) {
    trajectory.failed = true;
    trajectory.failure = e.what();
  }
  trajectory.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return trajectory;
}

// The Elastica arm under a random policy: new control points every 1.4 ms.
Trajectory run_arm(physics::ElasticaArmSpec spec, double duration, RodIntegrator integrator,
                   double step) {
  spec.integrator = integrator;
  if (integrator == RodIntegrator::kPositionVerlet) {
    // The muscles' rate limit is per step: kept per second at another Verlet step.
    spec.actuation.max_change_per_step *= step / spec.time_step;
    spec.time_step = step;
  } else {
    spec.implicit_step = step;
  }
  return timed([&](Trajectory& out) {
    physics::ElasticaArm arm = physics::build_elastica_arm(spec);
    const double action_period = 1.4e-3;
    const int substeps = static_cast<int>(std::lround(action_period / arm.rod.time_step()));
    Rng rng(11);
    Eigen::VectorXd targets(arm.muscles->spec().action_size());
    const int actions = static_cast<int>(std::lround(duration / action_period));
    for (int a = 0; a < actions; ++a) {
      for (Eigen::Index k = 0; k < targets.size(); ++k) targets[k] = rng.uniform(-1.0, 1.0);
      arm.muscles->set_targets(targets);
      if (!arm.rod.advance(substeps)) throw Error("the arm's state became non-finite");
      out.samples.push_back(1e3 * arm.rod.tip_position());
    }
    out.simulated_seconds = arm.rod.time();
    out.newton = arm.rod.newton_statistics();
  });
}

// The PWM of count-based exploration on the explicit twin, one entry per reading.
std::vector<std::array<int, 4>> exploration_pwm(const physics::SmaLimbSpec& spec, int readings) {
  physics::SmaLimb limb(spec, 3);
  const envs::sma_limb::LimbCalibration calibration =
      envs::sma_limb::LimbCalibration::nominal(spec.name);
  envs::sma_limb::CountBasedExploration exploration;
  Rng rng(5);
  std::vector<std::array<int, 4>> schedule;
  std::array<int, 4> pwm{0, 0, 0, 0};
  for (int r = 0; r < readings; ++r) {
    const Eigen::Vector2d angles = limb.true_angles_deg();
    exploration.observe(angles);
    if (r % 10 == 0) {  // a hold: ten readings under the same throttles
      const Eigen::Vector2i throttles = exploration.next(angles, rng);
      pwm = calibration.pwm_for(throttles.x(), throttles.y());
    }
    schedule.push_back(pwm);
    limb.set_pwm(pwm);
    (void)limb.next_reading();
  }
  return schedule;
}

Trajectory run_sma(physics::SmaLimbSpec spec, const std::vector<std::array<int, 4>>& schedule,
                   RodIntegrator integrator, double step) {
  spec.integrator = integrator;
  if (integrator == RodIntegrator::kPositionVerlet) {
    spec.steps_per_millisecond = static_cast<int>(std::lround(1e-3 / step));
  } else {
    spec.implicit_step = step;
  }
  return timed([&](Trajectory& out) {
    physics::SmaLimb limb(spec, 3);
    for (const std::array<int, 4>& pwm : schedule) {
      limb.set_pwm(pwm);
      (void)limb.next_reading();
      if (!limb.finite()) throw Error("the limb's state became non-finite");
      out.samples.push_back(limb.true_angles_deg());
    }
    out.simulated_seconds = limb.time();
    out.newton = limb.rod().newton_statistics();
  });
}

Trajectory run_pneumatic(RodIntegrator integrator, double step) {
  physics::pneumatic::PneumaticArmSpec spec;
  spec.effects.drift = spec.effects.hysteresis = spec.effects.imbalance = true;
  spec.effects.elasticity = true;
  spec.integrator = integrator;
  spec.time_step = step;
  return timed([&](Trajectory& out) {
    physics::pneumatic::PneumaticArm arm(spec);
    if (!arm.begin_trial(0)) throw Error("the arm did not settle");
    envs::pneumatic::SaturatingSignal signal(envs::pneumatic::SaturatingSignalSpec{}, Rng(0));
    for (int k = 0; k < 600; ++k) {  // 60 s at 10 Hz
      arm.set_commands(signal.next(0.1));
      for (int s = 0; s < 10; ++s) {
        if (!arm.advance_samples(1)) throw Error("the arm's state became non-finite");
        out.samples.push_back(1e3 * arm.true_tip_positions().col(2));
      }
    }
    out.simulated_seconds = arm.time();
    out.newton = arm.rod().newton_statistics();
  });
}

}  // namespace
}  // namespace tendril

int main(int argc, char** argv) {
  using namespace tendril;
  const std::string path = argc > 1 ? argv[1] : "docs/results/implicit_rods/accuracy.csv";
  const physics::SmaLimbSpec sma = physics::SmaLimbSpec::stiff();
  physics::SmaLimbSpec sma_continuous = sma;
  sma_continuous.actuator.coil.phase_reentry = physics::PhaseReentry::kContinuous;
  const std::vector<std::array<int, 4>> schedule = exploration_pwm(sma, 1800);  // ≈ 120 s
  const std::vector<std::array<int, 4>> continuous_schedule = exploration_pwm(sma_continuous, 1800);

  std::vector<Robot> robots = {
      {"case1",
       "mm",
       1.0,
       2.0e-4,
       {2.0e-4, 3.5e-4, 7.0e-4, 1.4e-3},
       72,  // 0.1 s of 1.4 ms actions
       [](RodIntegrator i, double h) {
         return run_arm(physics::ElasticaArmSpec::tracking(), 10.0, i, h);
       }},
      {"case3",
       "mm",
       1.0,
       1.0e-4,
       {1.0e-4, 2.0e-4, 3.5e-4, 7.0e-4, 1.4e-3},
       72,
       [](RodIntegrator i, double h) {
         return run_arm(physics::ElasticaArmSpec::structured_obstacles(), 5.0, i, h);
       }},
      {"sma",
       "deg",
       0.2,
       sma.time_step(),
       {1e-3, 2e-3, 5e-3, 1e-2, 2e-2},
       10,  // one hold of the exploration, ≈ 0.67 s
       [&](RodIntegrator i, double h) { return run_sma(sma, schedule, i, h); }},
      {"sma_continuous",
       "deg",
       0.2,
       sma.time_step(),
       {1e-3, 2e-3, 5e-3, 1e-2, 2e-2},
       10,
       [&](RodIntegrator i, double h) {
         return run_sma(sma_continuous, continuous_schedule, i, h);
       }},
      {"pneumatic",
       "mm",
       0.2,
       5.0e-4,
       {1e-3, 2e-3, 2.5e-3, 5e-3, 1e-2},
       10,  // 0.1 s of 100 Hz samples, one pressure command
       [](RodIntegrator i, double h) { return run_pneumatic(i, h); }},
  };

  const std::string only = argc > 2 ? argv[2] : "";
  std::erase_if(robots, [&](const Robot& robot) { return !only.empty() && robot.name != only; });
  if (robots.empty()) {
    std::fprintf(stderr, "no robot named %s\n", only.c_str());
    return 1;
  }
  std::ofstream csv(path);
  if (!csv) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    return 1;
  }
  csv << "robot,integrator,step_ms,tolerance,unit,max_deviation,mean_deviation,"
         "max_deviation_smoothed,simulated_s_per_wall_s,speed_vs_reference,us_per_step,"
         "step_cost_vs_reference,newton_iterations_per_step,factorizations_per_step,halvings,"
         "within_tolerance\n";
  for (const Robot& robot : robots) {
    const Trajectory reference = robot.run(RodIntegrator::kPositionVerlet, robot.reference_step);
    if (reference.failed) {
      std::fprintf(stderr, "%s: the reference failed: %s\n", robot.name.c_str(),
                   reference.failure.c_str());
      return 1;
    }
    const double reference_speed = reference.simulated_seconds / reference.wall_seconds;
    // Wall time per step: position Verlet takes simulated time / step steps; an implicit rod
    // counts its steps, the halves of failed ones included.
    const auto us_per_step = [](const Trajectory& run, double step) {
      const double steps = run.newton.steps > 0 ? static_cast<double>(run.newton.steps)
                                                : run.simulated_seconds / step;
      return 1e6 * run.wall_seconds / steps;
    };
    const double reference_us = us_per_step(reference, robot.reference_step);
    const std::vector<Eigen::VectorXd> reference_smoothed =
        smoothed(reference.samples, robot.smoothing);
    std::printf("%s: reference (position Verlet, %.2f ms) %.0f simulated s per wall s\n",
                robot.name.c_str(), 1e3 * robot.reference_step, reference_speed);
    csv << robot.name << ",verlet," << 1e3 * robot.reference_step << "," << robot.tolerance << ","
        << robot.unit << ",0,0,0," << reference_speed << ",1," << reference_us << ",1,0,0,0,1\n";

    // One row: the run at `step` against the reference.
    auto report = [&](RodIntegrator integrator, double step, const Trajectory& run) {
      Deviation raw, smooth;
      if (!run.failed) {
        raw = deviation(run.samples, reference.samples);
        smooth = deviation(smoothed(run.samples, robot.smoothing), reference_smoothed);
      }
      const double speed = run.failed ? 0.0 : run.simulated_seconds / run.wall_seconds;
      const double us = run.failed ? 0.0 : us_per_step(run, step);
      const double steps = std::max<double>(1.0, static_cast<double>(run.newton.steps));
      const bool within = !run.failed && raw.largest <= robot.tolerance;
      std::printf(
          "  %-16s %6.2f ms: max %8.4f %s (smoothed %8.4f), mean %8.4f, %6.0f sim s/s (%5.2fx), "
          "%.2f us/step (%.1fx the reference's), %.2f it, %.2f fact/step, %lld halvings%s%s\n",
          physics::integrator_name(integrator), 1e3 * step, raw.largest, robot.unit.c_str(),
          smooth.largest, raw.mean, speed, speed / reference_speed, us, us / reference_us,
          run.newton.iterations / steps, run.newton.factorizations / steps,
          static_cast<long long>(run.newton.halvings), within ? "  within" : "",
          run.failed ? ("  FAILED: " + run.failure).c_str() : "");
      std::fflush(stdout);
      const auto value = [&](double x) {
        return run.failed ? std::string("nan") : std::to_string(x);
      };
      csv << robot.name << "," << physics::integrator_name(integrator) << "," << 1e3 * step << ","
          << robot.tolerance << "," << robot.unit << "," << value(raw.largest) << ","
          << value(raw.mean) << "," << value(smooth.largest) << "," << speed << ","
          << speed / reference_speed << "," << us << "," << us / reference_us << ","
          << run.newton.iterations / steps << "," << run.newton.factorizations / steps << ","
          << run.newton.halvings << "," << (within ? 1 : 0) << "\n";
    };
    // The reference's own discretisation error.
    const double half = 0.5 * robot.reference_step;
    report(RodIntegrator::kPositionVerlet, half, robot.run(RodIntegrator::kPositionVerlet, half));
    for (RodIntegrator integrator : {RodIntegrator::kBackwardEuler, RodIntegrator::kBdf2}) {
      for (double step : robot.steps) report(integrator, step, robot.run(integrator, step));
    }
  }
  std::printf("wrote %s\n", path.c_str());
  return 0;
}
