#pragma once

#include <string_view>

#include "tendril/core/config.hpp"

namespace tendril {

// Every YAML file tendril reads says what it is in its first key, `kind:` — so that a file given
// to the wrong command is refused with a message that names the command that reads it, and a
// reader of the file knows what it is without guessing from its keys:
//   experiment     an RL training (tendril train, and the config.yaml of its run directory)
//   sweep          a grid of overrides of one experiment (tendril sweep …)
//   model_fit      a learned dynamics model's fit (tendril model fit, and its run's config.yaml)
//   adaptation     online adaptation of trained policies (tendril adapt)
//   data_protocol  a robot's data protocol (tendril data collect|calibrate|replay|…)
//   calibration    a robot's calibration (SmaLimb/Robot-v0's `calibration:`)
//   simulation     a rod simulation (tendril simulate)
namespace file_kind {
inline constexpr std::string_view kExperiment = "experiment";
inline constexpr std::string_view kSweep = "sweep";
inline constexpr std::string_view kModelFit = "model_fit";
inline constexpr std::string_view kAdaptation = "adaptation";
inline constexpr std::string_view kDataProtocol = "data_protocol";
inline constexpr std::string_view kCalibration = "calibration";
inline constexpr std::string_view kSimulation = "simulation";
}  // namespace file_kind

// Reads the `kind:` of the document `file` views. A file without one is taken as `expected`
// (files older than the key read on, and the value is recorded as used, so a run's resolved
// config.yaml names its kind). Raises Error naming the file, its kind and what reads that kind
// when it is another, or listing the kinds when it is none of them.
void expect_kind(const Config& file, std::string_view expected);

}  // namespace tendril
