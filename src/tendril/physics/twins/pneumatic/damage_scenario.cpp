#include "tendril/physics/twins/pneumatic/damage_scenario.hpp"

#include "tendril/core/error.hpp"

namespace tendril::physics::pneumatic {

DamageScenario parse_damage_scenario(std::string_view name, std::string_view where) {
  if (name == "S0") return DamageScenario::kS0;
  if (name == "S1") return DamageScenario::kS1;
  if (name == "S2") return DamageScenario::kS2;
  if (name == "S3") return DamageScenario::kS3;
  if (name == "S4") return DamageScenario::kS4;
  std::string what = "unknown damage scenario '";
  what += name;
  what += "' (expected S0, S1, S2, S3 or S4)";
  throw Error(what, std::string(where));
}

std::string to_string(DamageScenario scenario) {
  std::string name = "S";
  name += std::to_string(static_cast<int>(scenario));
  return name;
}

std::array<bool, kChambers> disabled_chambers(DamageScenario scenario, int chamber) {
  require(chamber >= 0 && chamber < kChambersPerModule,
          "the damaged chamber must be 0, 1 or 2, got " + std::to_string(chamber),
          "disabled_chambers");
  std::array<bool, kChambers> disabled{};
  switch (scenario) {
    case DamageScenario::kS0:
      break;
    case DamageScenario::kS1:
      disabled[chamber_index(0, chamber)] = true;
      break;
    case DamageScenario::kS2:
      disabled[chamber_index(1, chamber)] = true;
      break;
    case DamageScenario::kS3:
      disabled[chamber_index(2, chamber)] = true;
      break;
    case DamageScenario::kS4:
      disabled[chamber_index(0, chamber)] = true;
      disabled[chamber_index(1, chamber)] = true;
      break;
  }
  return disabled;
}

}  // namespace tendril::physics::pneumatic
