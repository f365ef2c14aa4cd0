#pragma once

#include <filesystem>
#include <string>

#include "tendril/rl/export/policy_network.hpp"

namespace tendril::rl {

// A policy as one dependency-free C header (C89, <math.h> only): its weights as float arrays
// and a function
//
//   static void <name>_act(const float *observation, float *action);
//
// that computes the policy's deterministic action from a raw observation — the observation
// normalization, the layers and the action's squash and scaling of PolicyNetwork — as tendril's
// Policy::act(…, deterministic = true) does (a discrete action is written as its index). On AVR
// (avr-gcc defines __AVR__) the arrays live in flash (PROGMEM) and are read with
// pgm_read_float, so a microcontroller's RAM holds only two layers' activations.
// `name` prefixes every identifier (upper case for the macros <NAME>_OBSERVATION_SIZE,
// <NAME>_ACTION_SIZE, <NAME>_PARAMETER_COUNT); it must be a C identifier, or Error.
std::string c_header(const PolicyNetwork& network, const std::string& name,
                     const std::string& description);

// Writes c_header(policy_network(policy), …) to `file` atomically; `description` (e.g. the
// policy file) goes into the header's opening comment.
void write_c_header(const Policy& policy, const std::filesystem::path& file,
                    const std::string& name, const std::string& description);

}  // namespace tendril::rl
