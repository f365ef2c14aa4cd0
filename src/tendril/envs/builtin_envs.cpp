#include "tendril/envs/builtin_envs.hpp"

#include "tendril/envs/classic_control/cart_pole.hpp"
#include "tendril/envs/classic_control/mountain_car_continuous.hpp"
#include "tendril/envs/classic_control/pendulum.hpp"
#include "tendril/envs/identity/identity.hpp"
#include "tendril/envs/identity/identity_box.hpp"

namespace tendril::envs {

void register_builtin_envs(Registry& registry) {
  // Gymnasium's classic-control reference tasks, with Gymnasium's registered time limits.
  registry.add({"Pendulum-v1", &Pendulum::create, 200, "swing up a pendulum (Gymnasium)"});
  registry.add({"CartPole-v1", &CartPole::create, 500, "balance a pole on a cart (Gymnasium)"});
  registry.add({"MountainCarContinuous-v0", &MountainCarContinuous::create, 999,
                "drive an under-powered car up a hill (Gymnasium)"});
  // Stable-Baselines3's identity sanity checks, episodes of 100 steps.
  registry.add(
      {"Identity-v0", &Identity::create, 100, "repeat a one-hot state as a discrete action"});
  registry.add({"IdentityBox-v0", &IdentityBox::create, 100, "repeat a scalar state within eps"});
}

}  // namespace tendril::envs
