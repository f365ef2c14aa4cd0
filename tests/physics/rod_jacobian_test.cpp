// The implicit step's Newton matrix against finite differences of the loads it differentiates,
// part by part, on a rod bent, stretched, sheared and twisted away from rest and moving.
#include "tendril/physics/rod/rod_jacobian.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "rod_test_support.hpp"
#include "tendril/physics/contact/cylinder_contact.hpp"
#include "tendril/physics/forcing/active_strain.hpp"
#include "tendril/physics/forcing/loads.hpp"
#include "tendril/physics/forcing/tendons.hpp"
#include "tendril/physics/rod/band_matrix.hpp"
#include "tendril/physics/rod/damping.hpp"
#include "tendril/physics/rod/implicit_stepper.hpp"
#include "tendril/physics/rod/internal_load_derivatives.hpp"
#include "tendril/physics/rod/internal_loads.hpp"
#include "tendril/physics/rod/rotation.hpp"
#include "tendril/physics/twins/pneumatic/mass_eccentricity.hpp"

namespace tendril::physics {
namespace {

using testing::ConstantActiveStrain;

// A rod with parts but no stepper of its own: the loads as one vector in RodJacobian's order
// (forces on nodes, torques on elements), and the Newton matrix of a step of effective length h.
class Fixture {
 public:
  explicit Fixture(const RodSpec& spec)
      : model_(RodModel::build(spec)), stepper_(model_, RodIntegrator::kBackwardEuler, {}) {
    state_.resize(model_);
    deform();
    compute_internal_loads(model_, state_);
  }

  template <typename Part, typename... Args>
  Part& add(Args&&... args) {
    auto part = std::make_unique<Part>(std::forward<Args>(args)...);
    Part& reference = *part;
    part->attach(model_, state_);
    stages_.add(part.get());
    parts_.push_back(std::move(part));
    stepper_.configure(model_, stages_);
    return reference;
  }

  RodState& state() { return state_; }
  const RodModel& model() const { return model_; }
  int unknowns() const { return 6 * model_.n_elements + 3; }

  Eigen::VectorXd loads() {
    compute_internal_loads(model_, state_);
    state_.external_forces.setZero();
    state_.external_torques.setZero();
    for (RodPart* part : stages_.loads) part->add_loads(model_, state_);
    for (RodPart* part : stages_.damp_rates) part->add_damping_loads(model_, state_);
    for (RodPart* part : stages_.contact) part->add_contact_loads(model_, state_);
    Eigen::VectorXd all(unknowns());
    for (int j = 0; j <= model_.n_elements; ++j) {
      all.segment<3>(RodJacobian::node(j)) =
          state_.internal_forces.col(j) + state_.external_forces.col(j);
    }
    for (int i = 0; i < model_.n_elements; ++i) {
      all.segment<3>(RodJacobian::element(i)) =
          state_.internal_torques.col(i) + state_.external_torques.col(i);
    }
    return all;
  }

  Eigen::MatrixXd newton_matrix(double h) {
    loads();
    stepper_.assemble_for_test(model_, state_, stages_, h);
    return stepper_.jacobian().matrix().dense();
  }

  // ∂L/∂(x, θ) and ∂L/∂(v, ω) from the Newton matrix K(h) = D − h² S − h C at h = 1 and 2.
  void analytic(Eigen::MatrixXd& stiffness, Eigen::MatrixXd& damping) {
    Eigen::MatrixXd diagonal = Eigen::MatrixXd::Zero(unknowns(), unknowns());
    loads();
    for (int j = 0; j <= model_.n_elements; ++j) {
      for (int c = 0; c < 3; ++c)
        diagonal(RodJacobian::node(j) + c, RodJacobian::node(j) + c) = model_.node_masses[j];
    }
    for (int i = 0; i < model_.n_elements; ++i) {
      for (int c = 0; c < 3; ++c) {
        diagonal(RodJacobian::element(i) + c, RodJacobian::element(i) + c) =
            model_.inertia(c, i) / state_.dilatations[i];
      }
    }
    const Eigen::MatrixXd a = newton_matrix(1.0) - diagonal;  // −S − C
    const Eigen::MatrixXd b = newton_matrix(2.0) - diagonal;  // −4 S − 2 C
    stiffness = (2.0 * a - b) / 2.0;
    damping = -a - stiffness;
  }

  // Central differences of the loads: displacements, rotations (Q → exp(−[δθ]×) Q), rates.
  void finite_differences(Eigen::MatrixXd& stiffness, Eigen::MatrixXd& damping) {
    const int size = unknowns();
    stiffness.resize(size, size);
    damping.resize(size, size);
    const RodState saved = state_;
    const double length = model_.rest_lengths[0];
    for (int u = 0; u < size; ++u) {
      const bool is_node = u % 6 < 3;
      const int index = u / 6, axis = u % 3;
      for (int kind = 0; kind < 2; ++kind) {
        const double delta = kind == 0 ? (is_node ? 1e-6 * length : 1e-6) : 1e-6;
        Eigen::VectorXd sides[2];
        for (int side = 0; side < 2; ++side) {
          state_ = saved;
          const double d = side == 0 ? delta : -delta;
          if (kind == 0 && is_node) {
            state_.positions(axis, index) += d;
          } else if (kind == 0) {
            const Eigen::Vector3d rotation = d * Eigen::Vector3d::Unit(axis);
            state_.set_director(index, exp_rotation_minus(rotation) * saved.director(index));
          } else if (is_node) {
            state_.velocities(axis, index) += d;
          } else {
            state_.angular_velocities(axis, index) += d;
          }
          sides[side] = loads();
        }
        (kind == 0 ? stiffness : damping).col(u) = (sides[0] - sides[1]) / (2.0 * delta);
      }
    }
    state_ = saved;
  }

 private:
  // Bent, twisted, stretched and sheared, with every rate non-zero.
  void deform() {
    const int n = model_.n_elements;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    for (int i = 0; i <= n; ++i) {
      state_.positions.col(i) = position;
      if (i == n) break;
      const double s = static_cast<double>(i) / n;
      const Eigen::Matrix3d frame =
          exp_rotation_minus(Eigen::Vector3d(0.35 * s, -0.25 * s * s, 0.3 * s));
      state_.set_director(i, frame);
      // The edge along d3, stretched by up to 4 %, with a little shear along d1 and d2.
      const Eigen::Vector3d material_edge(0.03 * std::sin(3.0 * i), -0.02 * std::cos(2.0 * i),
                                          1.0 + 0.04 * std::sin(1.7 * i));
      position += model_.rest_lengths[i] * frame.transpose() * material_edge;
    }
    for (int j = 0; j <= n; ++j) {
      state_.velocities.col(j) = Eigen::Vector3d(0.3 * std::sin(j), 0.2 * std::cos(1.3 * j), -0.1);
    }
    for (int i = 0; i < n; ++i) {
      state_.angular_velocities.col(i) =
          Eigen::Vector3d(0.5 * std::cos(i), -0.4 * std::sin(0.7 * i), 0.3);
    }
  }

  RodModel model_;
  RodState state_;
  std::vector<std::unique_ptr<RodPart>> parts_;
  PartsByStage stages_;
  ImplicitStepper stepper_;
};

RodSpec test_rod() {
  RodSpec spec;
  spec.n_elements = 6;
  spec.length = 0.6;
  spec.radius = 0.03;
  spec.density = 1200.0;
  spec.youngs_modulus = 2.0e5;
  spec.shear_modulus = spec.youngs_modulus / 3.0;
  spec.rest_curvature = Eigen::Vector3d(0.8, -0.5, 0.3);
  spec.direction = Eigen::Vector3d::UnitZ();
  spec.normal = Eigen::Vector3d::UnitX();
  return spec;
}

// Largest block error of `analytic` against `reference`, each 3 × 3 block relative to the
// largest block of its row of blocks (loads of one node or element).
double largest_block_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  const int blocks = static_cast<int>(reference.rows()) / 3;
  double worst = 0.0;
  for (int r = 0; r < blocks; ++r) {
    double row_scale = 0.0;
    for (int c = 0; c < blocks; ++c) {
      row_scale = std::max(row_scale, reference.block<3, 3>(3 * r, 3 * c).norm());
    }
    if (row_scale == 0.0) continue;
    for (int c = 0; c < blocks; ++c) {
      const double error =
          (analytic.block<3, 3>(3 * r, 3 * c) - reference.block<3, 3>(3 * r, 3 * c)).norm();
      worst = std::max(worst, error / row_scale);
    }
  }
  return worst;
}

// Central differences of step 10⁻⁶ are exact to about 10⁻⁹ of a row's largest block for the
// configuration; the rates' blocks (the small inertial torques of an element) to about 10⁻⁷.
void expect_derivatives_match(Fixture& fixture, const char* what, double tolerance = 1e-8) {
  Eigen::MatrixXd stiffness, damping, fd_stiffness, fd_damping;
  fixture.analytic(stiffness, damping);
  fixture.finite_differences(fd_stiffness, fd_damping);
  const double stiffness_error = largest_block_error(stiffness, fd_stiffness);
  const double damping_error = largest_block_error(damping, fd_damping);
  std::printf("%s: largest block error %.2e (stiffness), %.2e (damping)\n", what, stiffness_error,
              damping_error);
  EXPECT_LT(stiffness_error, tolerance) << what;
  EXPECT_LT(damping_error, std::max(tolerance, 1e-6)) << what;
  // Not vacuous: the loads do depend on the configuration.
  EXPECT_GT(fd_stiffness.norm(), 0.0);
}

TEST(RodJacobian, BandMatrixFactorsSolveAsTheDenseMatrix) {
  BandMatrix band;
  band.resize(9, 2, 3);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(9, 9);
  for (int r = 0; r < 9; ++r) {
    for (int c = band.first_column(r); c < band.end_column(r); ++c) {
      const double value = r == c ? 10.0 + r : std::sin(1.0 + r * 9 + c);
      band(r, c) = value;
      dense(r, c) = value;
    }
  }
  EXPECT_EQ(band.dense(), dense);
  Eigen::VectorXd rhs(9);
  for (int k = 0; k < 9; ++k) rhs[k] = std::cos(k);
  const Eigen::VectorXd expected = dense.lu().solve(rhs);
  ASSERT_TRUE(band.factorize());
  band.solve(rhs.data());
  EXPECT_LT((rhs - expected).norm(), 1e-13 * expected.norm());
}

// The contact band (20 diagonals) with no entry beyond 11 — a rod touching no wall — is solved by
// the 11-diagonal kernel, to the same numbers as the matrix stored in the narrow band; one entry
// further out and the wide kernel solves it, as the dense matrix does.
TEST(RodJacobian, WideBandMatrixSolvesWithinTheBandItFills) {
  const int size = 63;
  BandMatrix wide, narrow;
  wide.resize(size, 20, 20);
  narrow.resize(size, 11, 11);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(size, size);
  for (int r = 0; r < size; ++r) {
    for (int c = narrow.first_column(r); c < narrow.end_column(r); ++c) {
      const double value = r == c ? 30.0 + r : std::sin(1.0 + r * 9 + c);
      wide(r, c) = narrow(r, c) = dense(r, c) = value;
    }
  }
  Eigen::VectorXd rhs(size);
  for (int k = 0; k < size; ++k) rhs[k] = std::cos(k);
  ASSERT_TRUE(wide.factorize());
  ASSERT_TRUE(narrow.factorize());
  EXPECT_EQ(wide.solve_lower(), 11);
  EXPECT_EQ(wide.solve_upper(), 11);
  Eigen::VectorXd from_wide = rhs, from_narrow = rhs;
  wide.solve(from_wide.data());
  narrow.solve(from_narrow.data());
  EXPECT_EQ(from_wide, from_narrow);
  const Eigen::VectorXd expected = dense.lu().solve(rhs);
  EXPECT_LT((from_wide - expected).norm(), 1e-13 * expected.norm());

  BandMatrix wider;
  wider.resize(size, 20, 20);
  for (int r = 0; r < size; ++r) {
    for (int c = narrow.first_column(r); c < narrow.end_column(r); ++c) wider(r, c) = dense(r, c);
  }
  wider(40, 25) = dense(40, 25) = 0.5;  // 15 below the diagonal
  ASSERT_TRUE(wider.factorize());
  EXPECT_EQ(wider.solve_lower(), 20);
  Eigen::VectorXd solution = rhs;
  wider.solve(solution.data());
  const Eigen::VectorXd dense_solution = dense.lu().solve(rhs);
  EXPECT_LT((solution - dense_solution).norm(), 1e-13 * dense_solution.norm());
}

TEST(RodJacobian, SingularBandMatrixIsReported) {
  BandMatrix band;
  band.resize(3, 1, 1);
  band(0, 0) = 1.0;
  band(1, 1) = 0.0;
  band(2, 2) = 1.0;
  EXPECT_FALSE(band.factorize());
}

TEST(RodJacobian, InternalLoadsMatchFiniteDifferences) {
  Fixture fixture(test_rod());
  expect_derivatives_match(fixture, "internal loads");
}

TEST(RodJacobian, InverseLeftJacobianInvertsTheLogOfAPerturbedRotation) {
  for (double angle : {0.01, 0.3, 1.2, 2.5}) {
    const Eigen::Vector3d psi = angle * Eigen::Vector3d(0.3, -0.8, 0.52).normalized();
    const Eigen::Vector3d a(1e-7, -2e-7, 1.5e-7);
    // log(exp([a]×) exp([ψ]×)); exp([v]×) = exp_rotation_minus(−v).
    const Eigen::Matrix3d product = exp_rotation_minus(-a) * exp_rotation_minus(-psi);
    const Eigen::Vector3d log = log_rotation(product);
    const Eigen::Vector3d predicted = psi + inverse_left_jacobian(psi) * a;
    EXPECT_LT((log - predicted).norm(), 1e-6 * a.norm()) << "angle " << angle;
  }
}

TEST(RodJacobian, InternalDampingMatchesFiniteDifferences) {
  Fixture fixture(test_rod());
  fixture.add<InternalDamping>(20.0);
  expect_derivatives_match(fixture, "internal damping");
}

TEST(RodJacobian, LinearDampingAsLoadsMatchesFiniteDifferences) {
  Fixture fixture(test_rod());
  fixture.add<AnalyticalLinearDamping>(3.0, 0.02);
  expect_derivatives_match(fixture, "linear damping");
}

TEST(RodJacobian, ActiveStrainMatchesFiniteDifferences) {
  const int n = test_rod().n_elements;
  Vectors stretch(3, n), curvature(3, n - 1);
  for (int i = 0; i < n; ++i) stretch.col(i) = Eigen::Vector3d(0.01 * i, -0.02, 0.08);
  for (int j = 0; j + 1 < n; ++j) curvature.col(j) = Eigen::Vector3d(2.0, -1.0 + 0.3 * j, 0.5);
  Fixture fixture(test_rod());
  fixture.add<ConstantActiveStrain>(stretch, curvature);
  expect_derivatives_match(fixture, "active strain");
}

TEST(RodJacobian, MassEccentricityMatchesFiniteDifferences) {
  const int n = test_rod().n_elements;
  Vectors offsets = Vectors::Zero(3, n);
  for (int i = 0; i < n; ++i) offsets.col(i) = Eigen::Vector3d(0.004, -0.003, 0.0);
  Fixture fixture(test_rod());
  fixture.add<pneumatic::MassEccentricity>(offsets, Eigen::Vector3d(0.0, 0.0, -9.81));
  expect_derivatives_match(fixture, "mass eccentricity");
}

// Element 3 pressed 2 mm into a wall that no other element touches, with a load pushing it in
// (so that the response cancels the push). With one contact, the cancelled push, the penalty
// (the radius thinning with stretch included), the damping and, for a cylinder, the normal
// turning with the closest points are all exact.
class PressedElement {
 public:
  static constexpr int kElement = 3;
  explicit PressedElement(Fixture& fixture) {
    const RodState& state = fixture.state();
    const int n = fixture.model().n_elements;
    // The normal across the element (perpendicular to it) that keeps the others furthest away.
    const Eigen::Vector3d t = state.tangents.col(kElement);
    const Eigen::Vector3d across = t.unitOrthogonal(), other = t.cross(across);
    double best = -INFINITY;
    for (int k = 0; k < 72; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / 72;
      const Eigen::Vector3d candidate = std::cos(angle) * across + std::sin(angle) * other;
      double margin = INFINITY;
      for (int i = 0; i < n; ++i) {
        if (i != kElement) {
          margin = std::min(
              margin, (middle(state, i) - middle(state, kElement)).dot(candidate) - state.radii[i]);
        }
      }
      if (margin > best) {
        best = margin;
        normal = candidate;
      }
    }
    contact_point = middle(state, kElement) - normal * (state.radii[kElement] - 0.002);
    for (int i = 0; i < n; ++i) {
      const double penetration = state.radii[i] - (middle(state, i) - contact_point).dot(normal);
      EXPECT_EQ(penetration > 0.0, i == kElement) << "element " << i;
    }
    auto& push = fixture.add<NodeForces>();
    push.forces().col(kElement) = -400.0 * normal;
    push.forces().col(kElement + 1) = -400.0 * normal;
  }
  static Eigen::Vector3d middle(const RodState& state, int i) {
    return 0.5 * (state.positions.col(i) + state.positions.col(i + 1));
  }
  Eigen::Vector3d normal, contact_point;
};

TEST(RodJacobian, PlaneContactMatchesFiniteDifferences) {
  for (bool cancel_push : {false, true}) {
    Fixture fixture(test_rod());
    const PressedElement pressed(fixture);
    fixture.add<PlaneContact>(pressed.contact_point, pressed.normal,
                              SoftWall{8.0e4, 4.0, cancel_push});
    expect_derivatives_match(
        fixture, cancel_push ? "plane contact, push cancelled" : "plane contact, penalty only");
  }
}

TEST(RodJacobian, CylinderContactMatchesFiniteDifferences) {
  Fixture fixture(test_rod());
  const PressedElement pressed(fixture);
  // An axis perpendicular to the normal and to the element, 10 cm behind the contact point.
  const RodState& state = fixture.state();
  const Eigen::Vector3d along =
      pressed.normal.cross(Eigen::Vector3d(state.tangents.col(PressedElement::kElement)))
          .normalized();
  const double radius = 0.1;
  const Eigen::Vector3d centre = pressed.contact_point - radius * pressed.normal;
  fixture.add<CylinderContact>(
      std::vector<Cylinder>{Cylinder{centre - 0.3 * along, along, 0.6, radius}},
      SoftWall{8.0e4, 4.0, true});
  expect_derivatives_match(fixture, "cylinder contact");
}

// Every element of a rod lying on a plane, pressed into it: each element's cancelled push sees
// the responses of the elements before it (as the contact loads are applied element by
// element), a chain the matrix follows as far as its band reaches. What lies beyond (the fifth
// element back and further, shares of a quarter to the fourth power) stays below 1 % of a row.
TEST(RodJacobian, ChainOfContactsOnAPlaneIsFollowedAsFarAsTheBand) {
  RodSpec spec = test_rod();
  spec.rest_curvature.setZero();
  spec.direction = Eigen::Vector3d::UnitX();
  spec.normal = Eigen::Vector3d::UnitZ();
  Fixture fixture(spec);
  RodState& state = fixture.state();
  const int n = spec.n_elements;
  for (int j = 0; j <= n; ++j) {
    state.positions.col(j) =
        Eigen::Vector3d(0.1 * j, 0.002 * std::sin(j), spec.radius - 0.001 - 0.0005 * std::cos(j));
  }
  for (int i = 0; i < n; ++i) {
    state.set_director(
        i, exp_rotation_minus(Eigen::Vector3d(0.01 * i, -0.02, 0.005 * i)) * state.director(i));
  }
  compute_internal_loads(fixture.model(), state);
  auto& push = fixture.add<NodeForces>();
  push.forces().row(2).setConstant(-50.0);
  fixture.add<PlaneContact>(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                            SoftWall{8.0e4, 4.0, true});
  expect_derivatives_match(fixture, "chain of contacts", 0.01);
}

}  // namespace
}  // namespace tendril::physics
