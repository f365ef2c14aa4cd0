// Bad input is rejected by name; non-finite state is reported, never propagated silently.
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "tendril/core/error.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/rod/boundary.hpp"
#include "tendril/physics/rod/rod.hpp"

namespace tendril::physics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string error_for(const std::function<void(RodSpec&)>& spoil) {
  RodSpec spec;
  spoil(spec);
  try {
    Rod rod(spec);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RodValidation, EachInvalidParameterIsNamed) {
  auto names = [](const std::string& message, const std::string& field) {
    return message.find(field) != std::string::npos && message.find("RodSpec") == 0;
  };
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.n_elements = 0; }), "n_elements"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.length = -1.0; }), "length"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.length = kNaN; }), "length"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.radius = 0.0; }), "radius"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.density = INFINITY; }), "density"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.youngs_modulus = -5.0; }), "youngs_modulus"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.shear_modulus = 0.0; }), "shear_modulus"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.shear_coefficient = kNaN; }), "shear_coefficient"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.time_step = 0.0; }), "time_step"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.direction = Eigen::Vector3d(1, 1, 0); }), "direction"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.normal = s.direction; }), "normal"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.base_position.x() = kNaN; }), "base_position"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.tip_mass = -0.01; }), "tip_mass"));
  EXPECT_TRUE(names(error_for([](RodSpec& s) { s.rotary_inertia_scale = 0.0; }),
                    "rotary_inertia_scale"));
  EXPECT_EQ(error_for([](RodSpec&) {}), "accepted");
}

// The scale multiplies the elements' rotary inertia and nothing else.
TEST(RodValidation, RotaryInertiaScaleMultipliesOnlyTheRotaryInertia) {
  RodSpec spec;
  Rod plain(spec);
  spec.rotary_inertia_scale = 4.0;
  Rod scaled(spec);
  EXPECT_EQ(scaled.model().inertia, 4.0 * plain.model().inertia);
  EXPECT_EQ(scaled.model().node_masses, plain.model().node_masses);
  EXPECT_EQ(scaled.model().bend_stiffness, plain.model().bend_stiffness);
}

TEST(RodValidation, PartsThatDoNotFitAreRejected) {
  Rod rod(RodSpec{});
  EXPECT_THROW(rod.add<GeneralConstraint>(21, std::array<bool, 3>{true, true, true}, 0,
                                          std::array<bool, 3>{}),
               Error);
  EXPECT_THROW(rod.add<FixedEnd>(Eigen::Vector3d::Zero(), 2.0 * Eigen::Matrix3d::Identity()), Error);
}

TEST(RodValidation, PlantedNaNIsReportedOnTheNextStep) {
  Rod rod(RodSpec{});
  rod.add<FixedEnd>();
  ASSERT_TRUE(rod.advance(10));
  rod.mutable_state().velocities(1, 7) = kNaN;
  EXPECT_FALSE(rod.advance(1));
  EXPECT_FALSE(rod.advance(1)) << "a non-finite rod stays reported";
  EXPECT_FALSE(rod.state_is_finite());
}

TEST(RodValidation, OverflowingLoadIsReported) {
  Rod rod(RodSpec{});
  rod.add<FixedEnd>();
  auto& couples = rod.add<ElementCouples>();
  ASSERT_TRUE(rod.advance(5));
  couples.couples()(0, 10) = std::numeric_limits<double>::max();
  EXPECT_FALSE(rod.advance(3));
}

}  // namespace
}  // namespace tendril::physics
