#include "tendril/envs/sma_limb/deployment_calibration.hpp"

#include <fstream>

#include "tendril/core/config.hpp"
#include "tendril/core/error.hpp"
#include "tendril/envs/sma_limb/limb_calibration.hpp"
#include "tendril/envs/sma_limb/sma_limb_env.hpp"

namespace tendril::envs::sma_limb {

namespace fs = std::filesystem;

namespace {

// The value of "# <key>: <value>" in a data file's commented header, or nullopt.
std::optional<std::string> header_value(const fs::path& file, const std::string& key) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  const std::string prefix = "# " + key + ": ";
  std::string line;
  while (std::getline(in, line) && line.rfind('#', 0) == 0) {
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  }
  return std::nullopt;
}

// What the limb runs on: the PWM table and the offsets (the noise floor only documents how the
// table was found).
bool same_limb_table(const LimbCalibration& a, const LimbCalibration& b) {
  return a.limb == b.limb && a.lower_pwm == b.lower_pwm && a.upper_pwm == b.upper_pwm &&
         a.zero_offset_deg == b.zero_offset_deg;
}

}  // namespace

std::optional<std::string> model_calibration(const fs::path& model_directory) {
  const fs::path run_config = model_directory / "config.yaml";
  if (!fs::exists(run_config)) return std::nullopt;
  const Config config = Config::load_file(run_config);
  if (!config.child("data").has("file")) return std::nullopt;
  return header_value(config.child("data").get<std::string>("file"), "calibration");
}

std::string deployment_calibration(const std::string& given,
                                   const std::optional<std::string>& trained,
                                   const std::string& limb, const std::string& where) {
  const std::string uncalibrated = SmaLimbEnv::kUncalibrated;
  if (!trained) {
    require(!given.empty(),
            "name the limb's calibration (--calibration FILE, written by `tendril data "
            "calibrate`; or --calibration none for the nominal table and raw readings): no "
            "learned model of the controller names the calibration of its data",
            where);
    return given;
  }
  if (given.empty() || given == *trained) {
    if (*trained != uncalibrated) {
      const LimbCalibration made_on = LimbCalibration::load(*trained);
      require(made_on.limb == limb || !given.empty(),
              "the controller's model was fitted on the " + made_on.limb + " limb (calibration '" +
                  *trained + "'); on the " + limb +
                  " limb name that limb's own calibration (--calibration FILE)",
              where);
    }
    return *trained;
  }
  const std::string refused =
      "the controller's model was fitted on data collected with calibration '" + *trained +
      "'; deploying it with '" + given + "' ";
  require(given != uncalibrated && *trained != uncalibrated,
          refused + "mixes a calibrated and an uncalibrated limb", where);
  const LimbCalibration made_on = LimbCalibration::load(*trained);
  const LimbCalibration deployed_on = LimbCalibration::load(given);
  // Another limb brings its own calibration (the env checks it is that limb's).
  if (made_on.limb != limb) return given;
  require(same_limb_table(made_on, deployed_on),
          refused +
              "puts it on another PWM table or other zero offsets; leave --calibration "
              "out to use the model's",
          where);
  return given;
}

}  // namespace tendril::envs::sma_limb
