#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace tendril::envs::sma_limb {

// Which calibration a controller made from the limb's data is deployed with (seed 001 Ch. 5–6:
// policies and safety critics trained inside a learned model, then run on the limb). The model
// was fitted on data collected with one calibration; deployed on another limb table or without
// the zero offsets removed, the controller sees readings shifted by up to 12° and throttles that
// drive other PWM — a different system from the one it learned.

// The calibration file the learned model in `model_directory` was fitted with: the model's run
// (`config.yaml`, key data.file) names its data set, whose header names the calibration it was
// collected with ("# calibration: FILE"); "none" when it was collected uncalibrated. nullopt when
// any link of that chain is missing (a model from elsewhere, a moved data set).
std::optional<std::string> model_calibration(const std::filesystem::path& model_directory);

// The calibration a deployment on `limb` (stiff | soft) runs on. `given` is what the command line
// named ("" for nothing; a file or "none"), `trained` the model's (model_calibration). With a
// known, calibrated `trained` of the same limb, nothing given means `trained`, and a given
// calibration must hold the same PWM table and zero offsets (its file may be another copy). On
// another limb (a transfer test: the stiff limb's policy on the soft limb) that limb's own
// calibration file must be given. A calibrated model's controller is never deployed with
// `none`, nor an uncalibrated model's on a calibration. Without a known `trained` the command
// line must name one. Error names `where` and the files.
std::string deployment_calibration(const std::string& given,
                                   const std::optional<std::string>& trained,
                                   const std::string& limb, const std::string& where);

}  // namespace tendril::envs::sma_limb
