// The beam's lattice is the seed's (Suryadevara, Sec. III-A table) and bad models are refused
// by name.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "support/error_message.hpp"
#include "tendril/physics/lattice/beam_lattice.hpp"

namespace tendril::physics {
namespace {

TEST(BeamModel, NodesSpringsAndMassesOfTheSeedsTable) {
  const BeamLatticeSpec spec;
  const LatticeModel model = build_beam_model(spec);
  EXPECT_EQ(model.n_nodes(), 93);  // 3 per row × 31
  // 152 tensile (62 across + 90 along) + 120 shear; the seed's "360 edges" is 60 quads × 6.
  EXPECT_EQ(model.n_springs(), 272);
  int tensile = 0, shear = 0;
  for (const Spring& spring : model.springs) {
    const bool diagonal = std::abs(spring.rest_length - 0.025 * std::sqrt(2.0)) < 1e-12;
    (diagonal ? shear : tensile) += 1;
    EXPECT_EQ(spring.stiffness, 18750.0);
    EXPECT_DOUBLE_EQ(spring.damping, 18750.0 * 1e-3);  // c = β k
  }
  EXPECT_EQ(tensile, 152);
  EXPECT_EQ(shear, 120);
  EXPECT_EQ((spec.rows - 1) * (spec.columns - 1) * 6, 360);

  // 60 kg/m² × 0.05 m × 0.75 m, a quarter of each quad's mass to each of its corners.
  EXPECT_NEAR(model.masses.sum(), 2.25, 1e-12);
  EXPECT_NEAR(model.masses[spec.node(0, 0)], 0.009375, 1e-15);   // corner
  EXPECT_NEAR(model.masses[spec.node(0, 1)], 0.01875, 1e-15);    // base edge
  EXPECT_NEAR(model.masses[spec.node(10, 0)], 0.01875, 1e-15);   // side edge
  EXPECT_NEAR(model.masses[spec.node(10, 1)], 0.0375, 1e-15);    // interior
  EXPECT_NEAR(model.masses[spec.node(30, 2)], 0.009375, 1e-15);  // tip corner

  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(model.fixed[spec.node(0, c)]);
    EXPECT_FALSE(model.fixed[spec.node(1, c)]);
  }
  EXPECT_EQ(model.rest_positions.col(spec.node(30, 0)), Eigen::Vector2d(-0.025, 0.75));
  EXPECT_EQ(model.rest_positions.col(spec.node(0, 2)), Eigen::Vector2d(0.025, 0.0));
}

TEST(BeamModel, BendingSpringsAreTheSkipOneNeighbours) {
  BeamLatticeSpec spec;
  spec.bending_stiffness = 100.0;
  EXPECT_EQ(build_beam_model(spec).n_springs(), 272 + 31 + 87);
}

TEST(BeamModel, TorqueGroupsAreTheSeedsNodes) {
  // "Between nodes 16–18, 34–36, 52–54, 70–72 and 88–90" (1-based): the outer nodes of those
  // groups, 0-based.
  BeamLattice beam(BeamLatticeSpec{});
  const std::vector<RowCouples::Pair> expected = {{15, 17}, {33, 35}, {51, 53}, {69, 71}, {87, 89}};
  EXPECT_EQ(beam.couples().pairs(), expected);
  EXPECT_NEAR(beam.row_centre(29).y(), 0.725, 1e-15);
  EXPECT_EQ(beam.tip_position(), Eigen::Vector2d(0.0, 0.75));
}

TEST(BeamModel, InvalidFieldsAreNamed) {
  const auto error_for = [](auto spoil) {
    BeamLatticeSpec spec;
    spoil(spec);
    return testing::error_message([&] { build_beam_model(spec); });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_for([](BeamLatticeSpec& s) { s.rows = 1; }).find("rows"), std::string::npos);
  EXPECT_NE(error_for([](BeamLatticeSpec& s) { s.width = 0.0; }).find("width"), std::string::npos);
  EXPECT_NE(error_for([&](BeamLatticeSpec& s) { s.surface_density = nan; }).find("surface_density"),
            std::string::npos);
  EXPECT_NE(
      error_for([](BeamLatticeSpec& s) { s.tensile_stiffness = -1.0; }).find("tensile_stiffness"),
      std::string::npos);
  EXPECT_NE(error_for([](BeamLatticeSpec& s) { s.torque_rows = {0}; }).find("torque_rows"),
            std::string::npos);
  EXPECT_NE(error_for([](BeamLatticeSpec& s) { s.numerics.time_step = 0.0; }).find("time_step"),
            std::string::npos);
  EXPECT_NE(error_for([](BeamLatticeSpec& s) {
              s.numerics.newton_iterations = 0;
            }).find("newton_iterations"),
            std::string::npos);
  EXPECT_EQ(error_for([](BeamLatticeSpec&) {}), "no error");
}

TEST(LatticeModel, BadSpringsAndMassesAreNamed) {
  LatticeModel model;
  model.rest_positions = Eigen::Matrix2Xd::Zero(2, 2);
  model.rest_positions(0, 1) = 1.0;
  model.masses = Eigen::Vector2d(1.0, 1.0);
  model.fixed = {1, 0};
  model.springs = {Spring{0, 1, 1.0, 10.0, 0.0}};
  EXPECT_EQ(testing::error_message([&] { model.validate("m"); }), "no error");
  LatticeModel bad = model;
  bad.springs[0].b = 2;
  EXPECT_NE(testing::error_message([&] { bad.validate("m"); }).find("spring 0"), std::string::npos);
  bad = model;
  bad.springs[0].rest_length = 0.0;
  EXPECT_NE(testing::error_message([&] { bad.validate("m"); }).find("rest_length"),
            std::string::npos);
  bad = model;
  bad.masses[1] = 0.0;
  EXPECT_NE(testing::error_message([&] { bad.validate("m"); }).find("free node 1"),
            std::string::npos);
  bad = model;
  bad.fixed = {1};
  EXPECT_NE(testing::error_message([&] { bad.validate("m"); }).find("one entry per node"),
            std::string::npos);
  bad = model;
  bad.mass_damping = -1.0;
  EXPECT_NE(testing::error_message([&] { bad.validate("m"); }).find("mass_damping"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::physics
