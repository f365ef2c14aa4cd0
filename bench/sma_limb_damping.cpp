// How the SMA limb twin's bending rings, and what the sensor's 13–18 Hz sampling makes of it
// (docs/results/learned_dynamics.md, "The twin's damping against the thesis' limb"). For each
// damping rate (SmaLimbSpec::damping_rate, 1/s; the twin's default 15):
//   release: the stiff limb held bent by 0.02 N on its tip (+x) for 1.5 s, then let go: the free
//            response of the first bending mode — its frequency and damping ratio by the
//            logarithmic decrement of the first two maxima, and the undershoot below rest;
//   step:    the calibrated stiff limb at rest, throttle u_x 0 → 10 for 1.5 s (below the 100°
//            cut-off): the overshoot of the bend rate over its smoothed course;
//   staircase: u_x 0, 3, 6, 9, 6, 3, 0, … each held 10 readings (the data sets' holds, the random
//            walk's largest step of 3 levels): the one-step change of the filtered rate, as the
//            data sets' "predict no change" sees it, within 3 readings of a throttle change and
//            under steady throttle.
// The limb is simulated with a noise-free sensor read every millisecond; the thesis' sampler is
// laid over that trace — a reading every 55–75 ms (uniform, whole ms), σ = 0.2° noise within
// 0.5°, 0.1° resolution — and filtered as the data sets are (control::StateFilter, α = 0.8).
//
//   build/bench/sma_limb_damping [--output DIR] [--rates 15,30,45,60,90,200]
//       [--calibration configs/sma_limb/calibration_stiff.yaml]
//
// With --output, writes damping_summary.csv and damping_traces.csv (every 10 ms) there, never
// overwriting. Run from the source directory.
//
//   build/bench/sma_limb_damping --replay data/sma_limb/stiff_exploration.csv FROM TO
//
// instead replays a data set's throttles on SmaLimb/Robot-v0 (stiff, its calibration, reset
// seed 1, as `tendril data collect` made it) and prints, for readings FROM…TO (row numbers of
// the data), the replayed and the recorded readings beside each coil's wire temperature,
// martensite fraction and tension: what the limb did at a sudden jump of the data.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "tendril/control/state_filter.hpp"
#include "tendril/core/config.hpp"
#include "tendril/envs/registry.hpp"
#include "tendril/envs/sma_limb/limb_calibration.hpp"
#include "tendril/physics/twins/sma/sma_limb.hpp"

namespace {

using tendril::envs::sma_limb::LimbCalibration;
using tendril::physics::SmaLimb;
using tendril::physics::SmaLimbSpec;
namespace fs = std::filesystem;

// The stiff limb with a noise-free sensor read every millisecond and no zero offset.
SmaLimbSpec fine_stiff(double damping_rate) {
  SmaLimbSpec spec = SmaLimbSpec::stiff();
  spec.damping_rate = damping_rate;
  spec.sensor.min_period_ms = 1;
  spec.sensor.max_period_ms = 1;
  spec.sensor.noise_std = 0.0;
  spec.sensor.resolution = 1e-9;
  spec.sensor.zero_offset.setZero();
  return spec;
}

struct Trace {
  std::vector<double> t;      // s, every millisecond
  std::vector<double> theta;  // true θx, deg
  std::vector<int> u;         // throttle u_x in force from this millisecond on
};

// Runs `limb` for `seconds` under throttle `u` (PWM from the table), appending to `trace`.
void run(SmaLimb& limb, const LimbCalibration& table, int u, double seconds, Trace& trace) {
  limb.set_pwm(table.pwm_for(u, 0));
  const double end = limb.time() + seconds - 1e-9;
  while (limb.time() < end) {
    limb.next_reading();
    trace.t.push_back(limb.time());
    trace.theta.push_back(limb.true_angles_deg().x());
    trace.u.push_back(u);
  }
}

struct Release {
  double deflection = 0, frequency = NAN, zeta = NAN, undershoot = 0, settle = NAN;
  double frequency_full = NAN, zeta_full = NAN;
};

// Free response after letting go of a static tip load: maxima and minima about rest (0°).
Release release(double rate, Trace& trace) {
  SmaLimb limb(fine_stiff(rate), 1);
  limb.push(Eigen::Vector3d(0.02, 0.0, 0.0), 1.5);
  while (limb.time() < 1.5 - 1e-9) limb.next_reading();
  Release r;
  r.deflection = limb.true_angles_deg().x();
  while (limb.time() < 3.5 - 1e-9) {
    limb.next_reading();
    trace.t.push_back(limb.time() - 1.5);
    trace.theta.push_back(limb.true_angles_deg().x());
    trace.u.push_back(0);
  }
  // x(t) = A e^{−ζω t}(cos ω_d t + ζω/ω_d sin ω_d t): extrema every half period, the first a
  // minimum below rest. Damping ratio from the half-period decrement A → |x_min|, frequency from
  // the half period; with a maximum after it, from the full-period decrement too.
  const std::vector<double>& x = trace.theta;
  std::size_t minimum = 0, maximum = 0;
  for (std::size_t k = 1; k + 1 < x.size() && maximum == 0; ++k) {
    if (minimum == 0 && x[k] < 0.0 && x[k] < x[k - 1] && x[k] <= x[k + 1]) minimum = k;
    if (minimum != 0 && x[k] > 0.0 && x[k] > x[k - 1] && x[k] >= x[k + 1]) maximum = k;
  }
  // Below 2 % undershoot the decrement drowns in the higher modes: no measured ratio.
  if (minimum != 0 && -x[minimum] >= 0.02 * r.deflection) {
    r.undershoot = -x[minimum] / r.deflection;
    const double decrement = std::log(1.0 / r.undershoot);
    r.zeta = decrement / std::sqrt(M_PI * M_PI + decrement * decrement);
    r.frequency = 0.5 / trace.t[minimum];
  }
  if (minimum != 0) r.undershoot = std::max(0.0, -x[minimum] / r.deflection);
  if (maximum != 0 && !std::isnan(r.zeta)) {
    const double decrement = std::log(r.deflection / x[maximum]);
    r.zeta_full = decrement / std::sqrt(4.0 * M_PI * M_PI + decrement * decrement);
    r.frequency_full = 1.0 / trace.t[maximum];
  }
  for (std::size_t k = x.size(); k-- > 0;) {
    if (std::abs(x[k]) > 0.02 * r.deflection) {
      r.settle = trace.t[k];
      break;
    }
  }
  return r;
}

// The thesis' sampler over a millisecond trace: readings every 55–75 ms from `from` (s),
// noisy, quantised, filtered; returns the filtered rate ω̄x per reading and the throttle each
// reading was followed by.
struct Sampled {
  std::vector<double> t, omega;
  std::vector<int> u;
};
Sampled sample(const Trace& trace, double from, bool noisy, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> period(55, 75);
  std::normal_distribution<double> noise(0.0, 0.2);
  tendril::control::StateFilter filter(0.8);
  Sampled s;
  // trace.t[k] = (k + 1) ms after the start (or after `from`'s origin): index by milliseconds.
  const double origin = trace.t.front() - 1e-3;
  for (long ms = std::lround((from - origin) * 1e3); ms <= static_cast<long>(trace.t.size());
       ms += period(rng)) {
    const std::size_t k = static_cast<std::size_t>(std::max(0L, ms - 1));
    double reading = trace.theta[k];
    if (noisy) reading += std::clamp(noise(rng), -0.5, 0.5);
    reading = std::round(reading * 10.0) / 10.0;
    const double time = origin + 1e-3 * static_cast<double>(ms);
    s.t.push_back(time);
    s.omega.push_back(filter.update(time, Eigen::Vector2d(reading, 0.0))[2]);
    s.u.push_back(trace.u[std::min(k + 1, trace.u.size() - 1)]);
  }
  return s;
}

struct Split {
  double change = 0, steady = 0, all = 0;
};
// Persistence's one-step error of ω̄ (deg/s): at reading t, ω̄_{t+1} − ω̄_t, within 3 readings
// of a throttle change (u_k ≠ u_{k−1} for k = t, t−1, t−2) or not (one axis; the data sets' rows
// pool two axes, of which the other is at rest here).
Split persistence(const Sampled& s) {
  double sums[2] = {0, 0};
  int counts[2] = {0, 0};
  for (std::size_t t = 1; t + 1 < s.omega.size(); ++t) {
    bool changed = false;
    for (std::size_t k = t; k + 3 > t && k >= 1; --k) changed = changed || s.u[k] != s.u[k - 1];
    const double e = s.omega[t + 1] - s.omega[t];
    sums[changed ? 0 : 1] += e * e;
    ++counts[changed ? 0 : 1];
  }
  return {std::sqrt(sums[0] / counts[0]), std::sqrt(sums[1] / counts[1]),
          std::sqrt((sums[0] + sums[1]) / (counts[0] + counts[1]))};
}

// Overshoot of a throttle step's bend rate: the largest excess of the millisecond rate over its
// running mean across one period of the default's first mode (0.2 s), relative to the peak of
// that running mean — the part of the motion that is ringing, not the coils' smooth pull.
double rate_ringing(const Trace& trace) {
  const std::size_t n = trace.theta.size(), half = 100;
  std::vector<double> rate(n, 0.0);
  for (std::size_t k = 1; k < n; ++k) rate[k] = (trace.theta[k] - trace.theta[k - 1]) / 1e-3;
  double ring = 0.0, smooth_peak = 0.0;
  for (std::size_t k = half; k + half < n; ++k) {
    double mean = 0.0;
    for (std::size_t j = k - half; j < k + half; ++j) mean += rate[j];
    mean /= 2.0 * half;
    smooth_peak = std::max(smooth_peak, std::abs(mean));
    ring = std::max(ring, std::abs(rate[k] - mean));
  }
  return ring / smooth_peak;
}

// The data set's rows (time, θx, θy, u_x, u_y, …), header and comments skipped.
std::vector<std::vector<double>> read_rows(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    std::vector<double> row;
    std::size_t begin = 0;
    for (std::size_t comma; (comma = line.find(',', begin)) != std::string::npos;
         begin = comma + 1) {
      row.push_back(std::stod(line.substr(begin, comma - begin)));
    }
    row.push_back(std::stod(line.substr(begin)));
    rows.push_back(row);
  }
  return rows;
}

int replay(const std::string& file, const std::string& calibration, std::size_t from,
           std::size_t to) {
  const auto rows = read_rows(file);
  if (to >= rows.size() || from > to) throw std::runtime_error("rows out of range");
  auto env = tendril::envs::make(
      "SmaLimb/Robot-v0",
      tendril::Config::parse("limb: stiff\ncalibration: " + calibration + "\n"));
  env->reset(1);
  std::printf("%9s | %15s | %15s | %6s | coil: wire °C, martensite ξ, tension N\n", "time_s",
              "replayed θx θy", "recorded θx θy", "u");
  for (std::size_t k = 0; k < to; ++k) {
    tendril::Action action(2);
    action << static_cast<float>(rows[k][3]), static_cast<float>(rows[k][4]);
    const tendril::Observation reading = env->step(action).observation;
    if (k + 1 < from) continue;
    tendril::Scene scene;
    env->describe_scene(scene);
    std::printf("%9.3f | %7.2f %7.2f | %7.2f %7.2f | %2.0f %2.0f |", rows[k + 1][0], reading[0],
                reading[1], rows[k + 1][1], rows[k + 1][2], rows[k][3], rows[k][4]);
    for (const char* coil : {"+x", "-x", "+y", "-y"}) {
      double wire = 0, martensite = 0, tension = 0;
      for (const auto& [name, value] : scene.values) {
        const std::string prefix = std::string("coil ") + coil + " ";
        if (name == prefix + "wire_temperature_C") wire = value;
        if (name == prefix + "martensite") martensite = value;
        if (name == prefix + "tension_N") tension = value;
      }
      std::printf(" %s %5.1f %4.2f %4.2f", coil, wire, martensite, tension);
    }
    std::printf("\n");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string table_file = "configs/sma_limb/calibration_stiff.yaml";
  fs::path out;
  std::vector<double> rates{15, 30, 45, 60, 90, 200};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--calibration" && has_value) {
      table_file = argv[++i];
    } else if (arg == "--output" && has_value) {
      out = argv[++i];
    } else if (arg == "--rates" && has_value) {
      rates.clear();
      std::string list = argv[++i];
      for (std::size_t begin = 0, comma = 0; comma != std::string::npos; begin = comma + 1) {
        comma = list.find(',', begin);
        rates.push_back(std::stod(list.substr(begin, comma - begin)));
      }
    } else if (arg == "--replay" && i + 3 < argc) {
      return replay(argv[i + 1], table_file, std::stoul(argv[i + 2]), std::stoul(argv[i + 3]));
    } else {
      std::fprintf(stderr, "unknown or incomplete argument %s (see the file's header)\n",
                   arg.c_str());
      return 2;
    }
  }
  const LimbCalibration table = LimbCalibration::load(table_file);
  if (!out.empty()) {
    for (const char* name : {"damping_summary.csv", "damping_traces.csv"}) {
      if (fs::exists(out / name)) {
        std::fprintf(stderr, "%s: exists; nothing is overwritten\n", (out / name).c_str());
        return 1;
      }
    }
  }
  std::string summary =
      "damping_rate_per_s,release_deflection_deg,release_frequency_hz,release_zeta,"
      "release_frequency_full_hz,release_zeta_full,zeta_rayleigh,release_undershoot,"
      "release_settle_2pct_s,step_rate_ringing,step_peak_rate_deg_s,"
      "step_sampled_largest_domega_deg_s,staircase_persistence_change_deg_s,"
      "staircase_persistence_steady_deg_s,staircase_persistence_all_deg_s,"
      "staircase_noise_free_change_deg_s,staircase_noise_free_steady_deg_s\n";
  std::string traces = "damping_rate_per_s,scene,time_s,theta_x_deg,u_x\n";
  std::printf("%6s | %8s %7s %6s %6s %6s %9s %8s | %8s %9s %7s | %28s | %20s\n", "rate", "release",
              "f [Hz]", "zeta", "zeta2", "r/2w", "undershoot", "settle", "ringing", "peak rate",
              "max dw", "persistence change/steady/all", "noise-free chg/std");
  // The first mode's natural frequency from the default's free response: with every rate
  // decaying at r (damping r M, Rayleigh's mass-proportional form) a linear rod's modes have
  // ω_d² = ω_n² − r²/4 and ζ = r / (2 ω_n) — the estimate beside each measured ratio.
  Trace default_trace;
  const double default_rate = SmaLimbSpec::stiff().damping_rate;
  const double omega_d = 2.0 * M_PI * release(default_rate, default_trace).frequency;
  const double omega_n = std::sqrt(omega_d * omega_d + 0.25 * default_rate * default_rate);
  std::printf("first bending mode: %.2f Hz damped at %g/s, %.2f Hz undamped\n",
              omega_d / (2.0 * M_PI), default_rate, omega_n / (2.0 * M_PI));
  for (double rate : rates) {
    const double zeta_rayleigh = rate / (2.0 * omega_n);
    Trace free;
    const Release r = release(rate, free);

    Trace step;
    {
      SmaLimb limb(fine_stiff(rate), 2);
      run(limb, table, 0, 0.5, step);
      run(limb, table, 10, 1.5, step);
    }
    double peak_rate = 0.0;
    for (std::size_t k = 1; k < step.theta.size(); ++k) {
      peak_rate = std::max(peak_rate, (step.theta[k] - step.theta[k - 1]) / 1e-3);
    }
    const double ringing = rate_ringing(step);
    // The largest one-step change of the filtered rate the sampler sees (noise-free) over the step.
    const Sampled step_view = sample(step, step.t.front(), false, 5);
    double step_jump = 0.0;
    for (std::size_t k = 1; k < step_view.omega.size(); ++k) {
      step_jump = std::max(step_jump, std::abs(step_view.omega[k] - step_view.omega[k - 1]));
    }

    Trace stairs;
    {
      SmaLimb limb(fine_stiff(rate), 3);
      const int levels[] = {0, 3, 6, 9, 6, 3, 0, -3, -6, -9, -6, -3};
      run(limb, table, 0, 1.0, stairs);
      for (int cycle = 0; cycle < 4; ++cycle) {
        for (int u : levels) run(limb, table, u, 0.65, stairs);
      }
      run(limb, table, 0, 0.65, stairs);
    }
    const Split noisy = persistence(sample(stairs, 1.0, true, 7));
    const Split clean = persistence(sample(stairs, 1.0, false, 7));

    std::printf(
        "%6.0f | %7.2f° %7.2f %6.3f %6.3f %6.3f %8.1f%% %7.3fs | %7.1f%% %7.0f°/s %7.1f | %8.1f "
        "%8.1f %8.1f | %9.1f %9.1f\n",
        rate, r.deflection, r.frequency, r.zeta, r.zeta_full, zeta_rayleigh, 100 * r.undershoot,
        r.settle, 100 * ringing, peak_rate, step_jump, noisy.change, noisy.steady, noisy.all,
        clean.change, clean.steady);
    char line[512];
    std::snprintf(
        line, sizeof line,
        "%g,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.4f,%.1f,%.1f,%.2f,%.2f,%.2f,%.2f,%.2f\n",
        rate, r.deflection, r.frequency, r.zeta, r.frequency_full, r.zeta_full, zeta_rayleigh,
        r.undershoot, r.settle, ringing, peak_rate, step_jump, noisy.change, noisy.steady,
        noisy.all, clean.change, clean.steady);
    summary += line;
    // Traces every 10 ms: the release (from the moment of letting go) and the step (from rest).
    const std::pair<const char*, const Trace*> scenes[] = {{"release", &free}, {"step", &step}};
    for (const auto& [name, trace] : scenes) {
      for (std::size_t k = 9; k < trace->t.size(); k += 10) {
        std::snprintf(line, sizeof line, "%g,%s,%.3f,%.4f,%d\n", rate, name, trace->t[k],
                      trace->theta[k], trace->u[k]);
        traces += line;
      }
    }
  }
  if (!out.empty()) {
    std::ofstream(out / "damping_summary.csv") << summary;
    std::ofstream(out / "damping_traces.csv") << traces;
    std::printf("wrote %s and %s\n", (out / "damping_summary.csv").c_str(),
                (out / "damping_traces.csv").c_str());
  }
  return 0;
}
