#include "tendril/envs/pneumatic/arm_params.hpp"

#include <cmath>
#include <numbers>

#include "tendril/core/error.hpp"

namespace tendril::envs::pneumatic {

namespace {

using physics::pneumatic::PneumaticArmSpec;

double non_negative(const Config& config, const std::string& key, double fallback) {
  const double value = config.get_or<double>(key, fallback);
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw Error("must be finite and non-negative, got " + std::to_string(value),
                key_where(config, key));
  }
  return value;
}

double positive(const Config& config, const std::string& key, double fallback) {
  const double value = config.get_or<double>(key, fallback);
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error("must be finite and positive, got " + std::to_string(value),
                key_where(config, key));
  }
  return value;
}

}  // namespace

std::string key_where(const Config& config, const std::string& key) {
  const std::string path = config.path().empty() ? key : config.path() + "." + key;
  return config.source() + ": " + path;
}

PneumaticArmSpec arm_spec_from(const Config& params) {
  PneumaticArmSpec spec;
  spec.scenario = physics::pneumatic::parse_damage_scenario(
      params.get_or<std::string>("scenario", "S0"), key_where(params, "scenario"));
  spec.damaged_chamber = params.get_or<int>("damaged_chamber", 0);
  if (spec.damaged_chamber < 0 || spec.damaged_chamber > 2) {
    throw Error("must be 0, 1 or 2, got " + std::to_string(spec.damaged_chamber),
                key_where(params, "damaged_chamber"));
  }
  // The knob's residual supply: the fraction of its command a disrupted chamber still reaches.
  spec.regulators.disabled_fraction = params.get_or<double>("damaged_fraction", 0.0);
  if (!(spec.regulators.disabled_fraction >= 0.0 && spec.regulators.disabled_fraction < 1.0)) {
    throw Error("must lie in [0, 1), got " + std::to_string(spec.regulators.disabled_fraction),
                key_where(params, "damaged_fraction"));
  }
  spec.instance_seed = params.get_or<uint64_t>("instance_seed", 0);

  const bool stochastic = params.get_or<bool>("stochastic", true);
  auto& effects = spec.effects;
  const Config drift = params.child("drift");
  effects.drift = drift.get_or<bool>("enabled", stochastic);
  effects.drift_step = 1e-3 * non_negative(drift, "step_mm", 1e3 * effects.drift_step);
  effects.drift_cap = 1e-3 * non_negative(drift, "cap_mm", 1e3 * effects.drift_cap);
  const Config hysteresis = params.child("hysteresis");
  effects.hysteresis = hysteresis.get_or<bool>("enabled", stochastic);
  effects.hysteresis_width = non_negative(hysteresis, "width_bar", effects.hysteresis_width);
  const Config imbalance = params.child("imbalance");
  effects.imbalance = imbalance.get_or<bool>("enabled", stochastic);
  effects.gain_spread = non_negative(imbalance, "gain_spread", effects.gain_spread);
  if (effects.gain_spread >= 1.0) {
    throw Error("must be below 1", key_where(imbalance, "gain_spread"));
  }
  effects.eccentricity =
      1e-3 * non_negative(imbalance, "eccentricity_mm", 1e3 * effects.eccentricity);
  const Config noise = params.child("sensor_noise");
  effects.sensor_noise = noise.get_or<bool>("enabled", stochastic);
  effects.marker_noise = 1e-3 * non_negative(noise, "marker_sigma_mm", 1e3 * effects.marker_noise);
  const Config elasticity = params.child("elasticity");
  effects.elasticity = elasticity.get_or<bool>("enabled", stochastic);
  effects.elasticity_sigma = non_negative(elasticity, "sigma", effects.elasticity_sigma);
  spec.sensor.latency = non_negative(params, "sensor_latency_s", spec.sensor.latency);
  // One knob for calibrating the twin's stochasticity against the paper's gap.
  const double scale = non_negative(params, "magnitude_scale", 1.0);
  effects.drift_step *= scale;
  effects.drift_cap *= scale;
  effects.hysteresis_width *= scale;
  effects.gain_spread *= scale;
  effects.eccentricity *= scale;
  effects.marker_noise *= scale;
  effects.elasticity_sigma *= scale;
  if (effects.gain_spread >= 1.0) {
    throw Error("makes the chamber gain spread reach 1 or more",
                key_where(params, "magnitude_scale"));
  }
  if (effects.elasticity_sigma >= 0.5) {
    throw Error(
        "makes the elasticity sigma reach 0.5 or more (a module could lose all response)",
        key_where(params, elasticity.has("sigma") ? "elasticity.sigma" : "magnitude_scale"));
  }

  const Config twin = params.child("twin");
  spec.elements_per_module = twin.get_or<int>("elements_per_module", spec.elements_per_module);
  if (spec.elements_per_module < 1) {
    throw Error("must be at least 1", key_where(twin, "elements_per_module"));
  }
  spec.time_step = positive(twin, "time_step_s", spec.time_step);
  if (twin.has("integrator")) {
    try {
      spec.integrator = physics::parse_integrator(twin.get<std::string>("integrator"));
    } catch (const Error& e) {
      throw Error(e.what_wrong(), key_where(twin, "integrator"));
    }
  }
  spec.bend_per_bar =
      std::numbers::pi / 180.0 *
      non_negative(twin, "bend_deg_per_bar", spec.bend_per_bar * 180.0 / std::numbers::pi);
  spec.extension_per_bar = non_negative(twin, "extension_per_bar", spec.extension_per_bar);
  spec.regulators.inflate_time = positive(twin, "inflate_time_s", spec.regulators.inflate_time);
  spec.regulators.deflate_time = positive(twin, "deflate_time_s", spec.regulators.deflate_time);
  spec.regulators.ceiling_bar = positive(twin, "ceiling_bar", spec.regulators.ceiling_bar);
  spec.settle_time = non_negative(twin, "settle_time_s", spec.settle_time);

  try {
    spec.validate();
  } catch (const Error& e) {
    throw Error(e.what_wrong(), params.source() + ": " + params.path());
  }
  return spec;
}

std::vector<EnvDescription::Parameter> arm_parameters(const std::string& prefix) {
  std::vector<EnvDescription::Parameter> parameters = {
      {"scenario", "", "damage scenario S0–S4 (seed 002 §V-A)"},
      {"damaged_chamber", "", "which chamber of a damaged module (0, 1, 2)"},
      {"damaged_fraction", "1", "of its command a disrupted chamber still reaches, [0, 1)"},
      {"instance_seed", "", "the manufactured robot: draws the chambers' imbalance"},
      {"stochastic", "", "default of every effect's `enabled`"},
      {"drift.enabled", "", "slow drift of the rest pose"},
      {"drift.step_mm", "mm", "standard deviation of the rest pose's drift per trial and axis"},
      {"drift.cap_mm", "mm", "the drift is scaled back beyond this"},
      {"hysteresis.enabled", "", "pressure hysteresis of the regulators"},
      {"hysteresis.width_bar", "bar", "hysteresis band"},
      {"imbalance.enabled", "", "chamber-to-chamber differences"},
      {"imbalance.gain_spread", "1", "relative spread of the chambers' gains, < 1"},
      {"imbalance.eccentricity_mm", "mm", "offset of the chambers from the axis"},
      {"sensor_noise.enabled", "", "motion-capture noise"},
      {"sensor_noise.marker_sigma_mm", "mm", "standard deviation per coordinate"},
      {"elasticity.enabled", "", "per-trial factor 1 + σξ on each module's response"},
      {"elasticity.sigma", "1", "σ of that factor, < 0.5"},
      {"sensor_latency_s", "s", "age of the sample a step returns (multiples of 10 ms)"},
      {"magnitude_scale", "1", "multiplies every magnitude above (the calibration knob)"},
      {"twin.elements_per_module", "", "rod elements per module"},
      {"twin.time_step_s", "s", "physics time step"},
      {"twin.integrator", "",
       "the rods' integrator (physics::parse_integrator); default the "
       "twin's own",
       true},
      {"twin.bend_deg_per_bar", "°/bar", "bend per bar of pressure difference"},
      {"twin.extension_per_bar", "1/bar", "relative extension per bar"},
      {"twin.inflate_time_s", "s", "regulators' inflation time constant"},
      {"twin.deflate_time_s", "s", "regulators' deflation time constant"},
      {"twin.ceiling_bar", "bar", "safety ceiling of every chamber's pressure"},
      {"twin.settle_time_s", "s", "settling at zero pressure before a trial"}};
  for (EnvDescription::Parameter& parameter : parameters) parameter.key = prefix + parameter.key;
  return parameters;
}

}  // namespace tendril::envs::pneumatic
