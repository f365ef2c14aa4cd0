#pragma once

#include <array>
#include <string>
#include <string_view>

#include "tendril/physics/twins/pneumatic/chambers.hpp"

namespace tendril::physics::pneumatic {

// The evaluation scenarios of seed 002 §V-A: S0 the intact arm; S1, S2, S3 one chamber's
// supply disrupted in module 1, 2, 3 (the paper's counting: module 1 is at the base); S4 one
// chamber disrupted in module 1 and one in module 2. The paper does not say which chamber of a
// module; `chamber` (0, 1 or 2, default 0) chooses it for every disrupted module.
enum class DamageScenario { kS0, kS1, kS2, kS3, kS4 };

// "S0" … "S4"; raises tendril::Error naming `where` for anything else.
DamageScenario parse_damage_scenario(std::string_view name, std::string_view where = {});
std::string to_string(DamageScenario scenario);

// The disabled chambers of `scenario`, by flat index.
std::array<bool, kChambers> disabled_chambers(DamageScenario scenario, int chamber = 0);

}  // namespace tendril::physics::pneumatic
