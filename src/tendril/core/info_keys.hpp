#pragma once

namespace tendril::info_keys {

// Names of the scalars environments report in Info, one meaning per name across environments
// (DESIGN.md, "The one interface"). An environment with a quantity of this meaning uses this name.
inline constexpr const char* kDistance = "distance";     // tip/end effector to goal, m
inline constexpr const char* kIsSuccess = "is_success";  // 1 when the task's goal is reached
inline constexpr const char* kNan = "nan";               // 1 when the state became non-finite
inline constexpr const char* kCost = "cost";             // safety cost of the step (≥ 0)
inline constexpr const char* kCollision = "collision";   // 1 when the robot hit an obstacle
inline constexpr const char* kContacts = "contacts";     // number of active contacts
inline constexpr const char* kEpisodeReturn = "episode_return";  // on an episode's last step
inline constexpr const char* kEpisodeLength = "episode_length";  // on an episode's last step

}  // namespace tendril::info_keys
