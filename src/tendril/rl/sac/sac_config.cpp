#include "tendril/rl/sac/sac_config.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril::rl {

SacConfig SacConfig::sb3() { return SacConfig{}; }

SacConfig SacConfig::sb2() {
  SacConfig config;
  config.common.buffer_size = 50'000;
  config.common.batch_size = 64;
  config.common.net_arch = {64, 64};
  return config;
}

SacConfig SacConfig::from_config(const Config& algo) {
  SacConfig config = read_preset(algo, {"sb3", "sb2"}, "SAC") == "sb2" ? sb2() : sb3();
  config.common.read(algo);

  if (algo.has("ent_coef")) {
    const std::string text = algo.get<std::string>("ent_coef");
    if (text.rfind("auto", 0) == 0) {
      config.auto_entropy = true;
      if (text.size() > 5 && text[4] == '_') {
        try {
          config.ent_coef = std::stod(text.substr(5));
        } catch (const std::exception&) {
          throw Error("expected auto, auto_<initial value> or a number, got '" + text + "'",
                      algo.where("ent_coef"));
        }
      } else if (text != "auto") {
        throw Error("expected auto, auto_<initial value> or a number, got '" + text + "'",
                    algo.where("ent_coef"));
      }
    } else {
      config.auto_entropy = false;
      config.ent_coef = algo.get<double>("ent_coef");
    }
  }
  config.target_entropy = algo.get_optional("target_entropy", config.target_entropy, "auto");
  config.target_update_interval =
      algo.get_or<int64_t>("target_update_interval", config.target_update_interval);
  config.policy_delay = algo.get_or<int64_t>("policy_delay", config.policy_delay);
  config.compensate_policy_delay =
      algo.get_or<bool>("compensate_policy_delay", config.compensate_policy_delay);
  config.max_grad_norm = algo.get_optional("max_grad_norm", config.max_grad_norm);
  config.q_clip = algo.get_optional("q_clip", config.q_clip);
  config.use_sde = algo.get_or<bool>("use_sde", config.use_sde);
  config.sde_sample_freq = algo.get_or<int64_t>("sde_sample_freq", config.sde_sample_freq);
  config.log_std_init = algo.get_or<double>("log_std_init", config.log_std_init);
  if (algo.has("head")) config.head = nn::FeatureHeadSpec::from_config(algo.child("head"));
  algo.reject_unknown();
  config.validate();
  return config;
}

void SacConfig::validate() const {
  const std::string where = "SAC config";
  common.validate(where);
  require(ent_coef > 0.0, "ent_coef must be positive", where);
  require(target_update_interval >= 1, "target_update_interval must be at least 1", where);
  require(policy_delay >= 1, "policy_delay must be at least 1", where);
  require(!max_grad_norm || *max_grad_norm > 0.0, "max_grad_norm must be positive", where);
  require(!q_clip || *q_clip > 0.0, "q_clip must be positive", where);
  require(sde_sample_freq == -1 || sde_sample_freq >= 1, "sde_sample_freq must be -1 or positive",
          where);
}

}  // namespace tendril::rl
