#pragma once

#include <string>

namespace tendril::hardware {

// How an emulated robot's clock relates to the wall clock.
//   lockstep  robot time stands still while the robot waits for its host (after each reading
//             for the limb, after each control period for the arm), for up to host_wait_s of
//             wall time; beyond that, and whenever no host is there, it runs in real time. The
//             host's computing then costs no robot time, so a bridge run reproduces the twin
//             run exactly, faster than real time.
//   realtime  robot time follows the wall clock: the timing a real robot would see.
enum class EmulatorPace { kLockstep, kRealtime };

// "lockstep" or "realtime"; Error naming `where` otherwise.
EmulatorPace pace_from(const std::string& name, const std::string& where);

}  // namespace tendril::hardware
