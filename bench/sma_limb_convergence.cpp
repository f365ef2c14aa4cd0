// The SMA limb twin's rod resolution against a fine reference: how far the tip's true bend
// angles of coarser rods (elements, steps per millisecond, rotary-inertia scale) stray from it
// in three scenes, and what each costs. The twin's default is the second row.
//
//   build-lite/bench/sma_limb_convergence
//
// Scenes (noise-free sensor, the same reading times for every rod):
//   hold:  stiff limb, +x coil at PWM 30 for 2.5 s, then off for 2 s;
//   push:  stiff limb at rest, 0.05 N along x on the tip for 0.1 s, then 1 s free;
//   pair:  soft limb, +x and +y coils at PWM 22 for 3 s.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <vector>

#include "tendril/physics/twins/sma/sma_limb.hpp"

namespace {

using tendril::physics::SmaLimb;
using tendril::physics::SmaLimbSpec;

struct Rod {
  int elements, steps_per_ms;
  double rotary_inertia_scale;
};

struct Trace {
  std::vector<Eigen::Vector2d> angles;
  double robot_s = 0.0, cpu_s = 0.0;
  bool finite = true;
};

Trace scene(const std::string& name, const Rod& rod) {
  SmaLimbSpec spec = name == "pair" ? SmaLimbSpec::soft() : SmaLimbSpec::stiff();
  spec.n_elements = rod.elements;
  spec.steps_per_millisecond = rod.steps_per_ms;
  spec.rotary_inertia_scale = rod.rotary_inertia_scale;
  spec.sensor.noise_std = 0.0;
  SmaLimb limb(spec, 3);
  Trace trace;
  const std::clock_t start = std::clock();
  auto until = [&](double t) {
    while (limb.time() < t) {
      limb.next_reading();
      trace.angles.push_back(limb.true_angles_deg());
    }
  };
  if (name == "hold") {
    limb.set_pwm({30, 0, 0, 0});
    until(2.5);
    limb.set_pwm({0, 0, 0, 0});
    until(4.5);
  } else if (name == "push") {
    limb.push(Eigen::Vector3d(0.05, 0.0, 0.0), 0.1);
    until(1.1);
  } else {
    limb.set_pwm({22, 0, 22, 0});
    until(3.0);
  }
  trace.cpu_s = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  trace.robot_s = limb.time();
  trace.finite = limb.finite();
  return trace;
}

double largest_difference(const Trace& a, const Trace& b) {
  double largest = 0.0;
  for (std::size_t k = 0; k < std::min(a.angles.size(), b.angles.size()); ++k) {
    largest = std::max(largest, (a.angles[k] - b.angles[k]).norm());
  }
  return largest;
}

double peak(const Trace& trace) {
  double largest = 0.0;
  for (const Eigen::Vector2d& angles : trace.angles) largest = std::max(largest, angles.norm());
  return largest;
}

}  // namespace

int main() {
  const Rod reference{40, 40, 1.0};
  // {10, 5, 1}: the default step without the scaled rotary inertia — beyond the rod's stability.
  const std::vector<Rod> rods{{6, 4, 4.0},   {10, 5, 4.0},  {10, 5, 1.0}, {10, 10, 1.0},
                              {20, 10, 4.0}, {20, 20, 1.0}, reference};
  const char* scenes[3] = {"hold", "push", "pair"};
  std::vector<Trace> truth;
  for (const char* name : scenes) truth.push_back(scene(name, reference));
  std::printf(
      "reference: %d elements, %d steps/ms, rotary inertia x%.0f; peak bends %.2f, "
      "%.2f, %.2f deg\n",
      reference.elements, reference.steps_per_ms, reference.rotary_inertia_scale, peak(truth[0]),
      peak(truth[1]), peak(truth[2]));
  std::printf("%8s %8s %8s | %14s %14s %14s | %12s\n", "elements", "steps/ms", "inertia",
              "hold: max err", "push: max err", "pair: max err", "x real time");
  for (const Rod& rod : rods) {
    double robot = 0.0, cpu = 0.0;
    double errors[3];
    bool finite = true;
    for (int s = 0; s < 3; ++s) {
      const Trace trace = scene(scenes[s], rod);
      errors[s] = largest_difference(trace, truth[s]);
      robot += trace.robot_s;
      cpu += trace.cpu_s;
      finite = finite && trace.finite;
    }
    if (!finite) {
      std::printf("%8d %8d %7.0fx | unstable: the rod's state became non-finite\n", rod.elements,
                  rod.steps_per_ms, rod.rotary_inertia_scale);
      continue;
    }
    std::printf("%8d %8d %7.0fx | %11.2f deg %11.2f deg %11.2f deg | %11.0fx\n", rod.elements,
                rod.steps_per_ms, rod.rotary_inertia_scale, errors[0], errors[1], errors[2],
                robot / cpu);
  }
  return 0;
}
