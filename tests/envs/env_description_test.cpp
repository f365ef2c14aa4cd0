#include "tendril/envs/env_description.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/registry.hpp"

namespace tendril::envs {
namespace {

// Whether one of `problems` contains `text`.
bool mentions(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& problem : problems) {
    if (problem.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string joined(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& problem : problems) text += "\n  " + problem;
  return text;
}

// Every registered environment describes itself as it is: its entries cover its spaces with a
// unit each, it says how it rewards and ends, and the parameters it lists are those its factory
// reads with a default (Config records the defaults a factory used, so this cannot drift).
TEST(EnvDescription, EveryRegisteredEnvironmentDescribesItsSpacesRewardAndParameters) {
  const Registry& registry = builtin_registry();
  ASSERT_GE(registry.ids().size(), 22u);  // the 22 of this writing, and any added since
  for (const std::string& id : registry.ids()) {
    const std::vector<std::string> problems = description_mismatches(registry, id);
    EXPECT_TRUE(problems.empty()) << id << ":" << joined(problems);
  }
}

TEST(EnvDescription, UnitsOfDimensionlessEntriesAreWrittenOne) {
  // One spelling for dimensionless entries across the reference ("1", not "—" or "-").
  for (const std::string& id : builtin_registry().ids()) {
    const EnvDescription described = builtin_registry().spec(id).description();
    for (const auto* entries : {&described.observation, &described.action}) {
      for (const EnvDescription::Entries& run : *entries) {
        EXPECT_NE(run.unit, "—") << id << ": " << run.name;
        EXPECT_NE(run.unit, "-") << id << ": " << run.name;
      }
    }
  }
}

TEST(EnvDescription, PendulumReadsGravityWithGymnasiumsDefault) {
  const auto read = parameters_read(builtin_registry(), "Pendulum-v1");
  EXPECT_EQ(read, (std::vector<std::pair<std::string, std::string>>{{"g", "10"}}));
}

TEST(EnvDescription, ParametersGivenInTheExampleAreListedWithTheirValues) {
  const auto read = parameters_read(builtin_registry(), "SmaLimb/Robot-v0");
  bool calibration = false;
  for (const auto& [key, value] : read)
    calibration = calibration || (key == "calibration" && value == "none");
  EXPECT_TRUE(calibration);
}

// A description that disagrees with its environment is caught, one problem per disagreement.
TEST(EnvDescription, MismatchesAreNamed) {
  EnvDescription wrong = Pendulum::description();
  wrong.observation.pop_back();                                     // 2 entries for a space of 3
  wrong.action[0].unit.clear();                                     // no unit
  wrong.reward.clear();                                             // no reward text
  wrong.parameters = {{"gravity", "m/s²", "misnamed"},              // not read
                      {"g", "m/s²", "read with a default", true}};  // but marked optional
  Registry registry;
  registry.add({"Wrong-v0", &Pendulum::create, 200, "a pendulum described wrongly",
                [wrong] { return wrong; }});
  const std::vector<std::string> problems = description_mismatches(registry, "Wrong-v0");
  EXPECT_TRUE(mentions(problems, "observation: the description covers 2 entries, the space has 3"))
      << joined(problems);
  EXPECT_TRUE(mentions(problems, "action entry")) << joined(problems);
  EXPECT_TRUE(mentions(problems, "no reward text")) << joined(problems);
  EXPECT_TRUE(mentions(problems, "'gravity' is documented with a default but the factory reads"))
      << joined(problems);
  EXPECT_TRUE(mentions(problems, "'g' is read with the default 10 but documented as optional"))
      << joined(problems);
  EXPECT_EQ(problems.size(), 5u) << joined(problems);

  wrong.parameters.clear();  // g undocumented
  Registry undocumented;
  undocumented.add({"Wrong-v0", &Pendulum::create, 200, "", [wrong] { return wrong; }});
  EXPECT_TRUE(mentions(description_mismatches(undocumented, "Wrong-v0"),
                       "parameter 'g' (10) is read but not documented"));

  Registry silent;
  silent.add({"Silent-v0", &Pendulum::create, 200, "no description"});
  EXPECT_EQ(description_mismatches(silent, "Silent-v0"),
            std::vector<std::string>{"no description"});
}

}  // namespace
}  // namespace tendril::envs
