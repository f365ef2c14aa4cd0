#include "tendril/physics/lattice/beam_lattice.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "tendril/core/error.hpp"

namespace tendril::physics {

namespace {

constexpr const char* kWhere = "BeamLatticeSpec";

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw Error(std::string(field) + " must be finite and positive, got " + std::to_string(value),
                kWhere);
  }
}

void require_non_negative(double value, const char* field) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw Error(
        std::string(field) + " must be finite and non-negative, got " + std::to_string(value),
        kWhere);
  }
}

}  // namespace

void BeamLatticeSpec::validate() const {
  if (rows < 2) throw Error("rows must be at least 2, got " + std::to_string(rows), kWhere);
  if (columns < 2) {
    throw Error("columns must be at least 2, got " + std::to_string(columns), kWhere);
  }
  require_positive(width, "width");
  require_positive(length, "length");
  require_positive(surface_density, "surface_density");
  require_non_negative(tensile_stiffness, "tensile_stiffness");
  require_non_negative(shear_stiffness, "shear_stiffness");
  require_non_negative(bending_stiffness, "bending_stiffness");
  require_non_negative(mass_damping, "mass_damping");
  require_non_negative(stiffness_damping, "stiffness_damping");
  for (int row : torque_rows) {
    if (row < 1 || row >= rows) {
      throw Error("torque_rows entry " + std::to_string(row) + " is not a free row (1 … " +
                      std::to_string(rows - 1) + ")",
                  kWhere);
    }
  }
  numerics.validate(kWhere);
}

LatticeModel build_beam_model(const BeamLatticeSpec& spec) {
  spec.validate();
  const int n = spec.rows * spec.columns;
  const double dx = spec.width / (spec.columns - 1);
  const double dy = spec.length / (spec.rows - 1);
  LatticeModel model;
  model.rest_positions.resize(2, n);
  model.masses = Eigen::VectorXd::Zero(n);
  model.fixed.assign(n, 0);
  model.mass_damping = spec.mass_damping;
  for (int r = 0; r < spec.rows; ++r) {
    for (int c = 0; c < spec.columns; ++c) {
      model.rest_positions.col(spec.node(r, c)) << -0.5 * spec.width + c * dx, r * dy;
      model.fixed[spec.node(r, c)] = r == 0 ? 1 : 0;
    }
  }
  const double corner_mass = 0.25 * spec.surface_density * dx * dy;
  for (int r = 0; r + 1 < spec.rows; ++r) {
    for (int c = 0; c + 1 < spec.columns; ++c) {
      for (int node :
           {spec.node(r, c), spec.node(r, c + 1), spec.node(r + 1, c), spec.node(r + 1, c + 1)}) {
        model.masses[node] += corner_mass;
      }
    }
  }
  const auto add = [&](int a, int b, double stiffness) {
    const double rest = (model.rest_positions.col(b) - model.rest_positions.col(a)).norm();
    model.springs.push_back(Spring{a, b, rest, stiffness, spec.stiffness_damping * stiffness});
  };
  for (int r = 0; r < spec.rows; ++r) {
    for (int c = 0; c + 1 < spec.columns; ++c) {
      add(spec.node(r, c), spec.node(r, c + 1), spec.tensile_stiffness);
    }
  }
  for (int r = 0; r + 1 < spec.rows; ++r) {
    for (int c = 0; c < spec.columns; ++c) {
      add(spec.node(r, c), spec.node(r + 1, c), spec.tensile_stiffness);
    }
  }
  for (int r = 0; r + 1 < spec.rows; ++r) {
    for (int c = 0; c + 1 < spec.columns; ++c) {
      add(spec.node(r, c), spec.node(r + 1, c + 1), spec.shear_stiffness);
      add(spec.node(r, c + 1), spec.node(r + 1, c), spec.shear_stiffness);
    }
  }
  if (spec.bending_stiffness > 0.0) {
    for (int r = 0; r < spec.rows; ++r) {
      for (int c = 0; c + 2 < spec.columns; ++c) {
        add(spec.node(r, c), spec.node(r, c + 2), spec.bending_stiffness);
      }
    }
    for (int r = 0; r + 2 < spec.rows; ++r) {
      for (int c = 0; c < spec.columns; ++c) {
        add(spec.node(r, c), spec.node(r + 2, c), spec.bending_stiffness);
      }
    }
  }
  return model;
}

BeamLattice::BeamLattice(const BeamLatticeSpec& spec)
    : spec_(spec), lattice_(build_beam_model(spec), spec.numerics) {
  std::vector<RowCouples::Pair> pairs;
  for (int row : spec_.torque_rows) {
    pairs.push_back({spec_.node(row, 0), spec_.node(row, spec_.columns - 1)});
  }
  couples_ = &lattice_.add<RowCouples>(std::move(pairs));
}

Eigen::Vector2d BeamLattice::row_centre(int row) const {
  return lattice_.state().positions.middleCols(spec_.node(row, 0), spec_.columns).rowwise().mean();
}

Eigen::Vector2d BeamLattice::row_velocity(int row) const {
  return lattice_.state().velocities.middleCols(spec_.node(row, 0), spec_.columns).rowwise().mean();
}

double BeamLattice::row_angle(int row) const {
  const Eigen::Matrix2Xd& x = lattice_.state().positions;
  const auto direction = [&](int r) {
    const Eigen::Vector2d across =
        x.col(spec_.node(r, spec_.columns - 1)) - x.col(spec_.node(r, 0));
    return std::atan2(across.y(), across.x());
  };
  double angle = 0.0;
  double previous = direction(0);
  for (int r = 1; r <= row; ++r) {
    const double current = direction(r);
    double turn = current - previous;
    if (turn > std::numbers::pi) turn -= 2.0 * std::numbers::pi;
    if (turn <= -std::numbers::pi) turn += 2.0 * std::numbers::pi;
    angle += turn;
    previous = current;
  }
  return angle;
}

}  // namespace tendril::physics

namespace tendril::physics {

int BeamLattice::inverted_cells() const {
  const Eigen::Matrix2Xd& x = lattice_.state().positions;
  int inverted = 0;
  for (int r = 0; r + 1 < spec_.rows; ++r) {
    for (int c = 0; c + 1 < spec_.columns; ++c) {
      // Shoelace over the corners in rest counter-clockwise order.
      const int corners[4] = {spec_.node(r, c), spec_.node(r, c + 1), spec_.node(r + 1, c + 1),
                              spec_.node(r + 1, c)};
      double twice_area = 0.0;
      for (int k = 0; k < 4; ++k) {
        const Eigen::Vector2d a = x.col(corners[k]), b = x.col(corners[(k + 1) % 4]);
        twice_area += a.x() * b.y() - a.y() * b.x();
      }
      if (twice_area < 0.0) ++inverted;
    }
  }
  return inverted;
}

}  // namespace tendril::physics
