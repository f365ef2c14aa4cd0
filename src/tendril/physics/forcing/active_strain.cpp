#include "tendril/physics/forcing/active_strain.hpp"

#include <string>

#include "tendril/core/error.hpp"
#include "tendril/physics/rod/internal_load_derivatives.hpp"

namespace tendril::physics {

// Plain loops over the component-major arrays, as in the rod's own kernel (internal_loads.cpp),
// so they vectorize across elements: row k of a Vectors is component k of every element; row
// 3 r + c of the directors is Q(r, c), row r of Q being d_{r+1} in the lab frame.

void ActiveStrainLoads::resize(const RodModel& model) {
  stresses_ = Vectors::Zero(3, model.n_elements);
  couples_ = Vectors::Zero(3, model.n_voronoi());
  lab_stresses_.resize(3, model.n_elements);
  bend_.resize(3, model.n_voronoi());
  quadrature_.resize(3, model.n_voronoi());
}

void ActiveStrainLoads::add(const RodModel& model, RodState& state, const Vectors& stretch,
                            const Vectors& curvature) {
  const int n = model.n_elements;
  const int count = model.n_voronoi();
  if (lab_stresses_.cols() != n || bend_.cols() != count || stretch.cols() != n ||
      curvature.cols() != count) {
    throw Error("sized for another rod: " + std::to_string(n) + " elements", "ActiveStrainLoads");
  }
  const auto row = [](auto& array, int k) { return array.row(k).data(); };
  const double* q[9];
  for (int k = 0; k < 9; ++k) q[k] = row(state.directors, k);
  const double* tangent[3] = {row(state.tangents, 0), row(state.tangents, 1),
                              row(state.tangents, 2)};
  const double* sigma[3] = {row(stretch, 0), row(stretch, 1), row(stretch, 2)};
  const double* stiffness[3] = {row(model.shear_stiffness, 0), row(model.shear_stiffness, 1),
                                row(model.shear_stiffness, 2)};
  double* lab[3] = {row(lab_stresses_, 0), row(lab_stresses_, 1), row(lab_stresses_, 2)};
  double* torque[3] = {row(state.external_torques, 0), row(state.external_torques, 1),
                       row(state.external_torques, 2)};
  const double* dilatation = state.dilatations.data();
  const double* rest_length = model.rest_lengths.data();
  double* kept_stress[3] = {row(stresses_, 0), row(stresses_, 1), row(stresses_, 2)};

  // Stretch and shear: δn_i = −S_i δσ_i (material frame); the lab-frame stress Q_iᵀ δn_i / e_i,
  // and element i's couple (Q t × δn) l̂.
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double n0 = -stiffness[0][i] * sigma[0][i];
    const double n1 = -stiffness[1][i] * sigma[1][i];
    const double n2 = -stiffness[2][i] * sigma[2][i];
    kept_stress[0][i] = n0;
    kept_stress[1][i] = n1;
    kept_stress[2][i] = n2;
    const double inv_e = 1.0 / dilatation[i];
    lab[0][i] = (q[0][i] * n0 + q[3][i] * n1 + q[6][i] * n2) * inv_e;
    lab[1][i] = (q[1][i] * n0 + q[4][i] * n1 + q[7][i] * n2) * inv_e;
    lab[2][i] = (q[2][i] * n0 + q[5][i] * n1 + q[8][i] * n2) * inv_e;
    const double t0 = tangent[0][i], t1 = tangent[1][i], t2 = tangent[2][i];
    const double m0 = q[0][i] * t0 + q[1][i] * t1 + q[2][i] * t2;
    const double m1 = q[3][i] * t0 + q[4][i] * t1 + q[5][i] * t2;
    const double m2 = q[6][i] * t0 + q[7][i] * t1 + q[8][i] * t2;
    const double l = rest_length[i];
    torque[0][i] += (m1 * n2 - m2 * n1) * l;
    torque[1][i] += (m2 * n0 - m0 * n2) * l;
    torque[2][i] += (m0 * n1 - m1 * n0) * l;
  }
  // Forces on nodes: Δʰ of the lab-frame stresses, zero ghosts at both ends.
  for (int c = 0; c < 3; ++c) {
    double* f = row(state.external_forces, c);
    const double* s = lab[c];
    f[0] += s[0];
#pragma omp simd
    for (int j = 1; j < n; ++j) f[j] += s[j] - s[j - 1];
    f[n] -= s[n - 1];
  }
  if (count <= 0) return;

  // Bending and twist: δτ_j = −B_j δκ_j at Voronoi point j (between elements j and j + 1);
  // b = δτ/ε³ and a = ½ (κ × δτ) D̂/ε³ give element i the torque b_i − b_{i−1} + a_i + a_{i−1}.
  const double* kappa_shift[3] = {row(curvature, 0), row(curvature, 1), row(curvature, 2)};
  const double* bend_stiffness[3] = {row(model.bend_stiffness, 0), row(model.bend_stiffness, 1),
                                     row(model.bend_stiffness, 2)};
  const double* kappa[3] = {row(state.curvatures, 0), row(state.curvatures, 1),
                            row(state.curvatures, 2)};
  double* b[3] = {row(bend_, 0), row(bend_, 1), row(bend_, 2)};
  double* a[3] = {row(quadrature_, 0), row(quadrature_, 1), row(quadrature_, 2)};
  double* kept_couple[3] = {row(couples_, 0), row(couples_, 1), row(couples_, 2)};
  const double* voronoi_dilatation = state.voronoi_dilatations.data();
  const double* rest_voronoi = model.rest_voronoi_lengths.data();
#pragma omp simd
  for (int j = 0; j < count; ++j) {
    const double d0 = -bend_stiffness[0][j] * kappa_shift[0][j];
    const double d1 = -bend_stiffness[1][j] * kappa_shift[1][j];
    const double d2 = -bend_stiffness[2][j] * kappa_shift[2][j];
    kept_couple[0][j] = d0;
    kept_couple[1][j] = d1;
    kept_couple[2][j] = d2;
    const double eps = voronoi_dilatation[j];
    const double inv_eps3 = 1.0 / (eps * eps * eps);
    const double h = 0.5 * rest_voronoi[j] * inv_eps3;
    const double k0 = kappa[0][j], k1 = kappa[1][j], k2 = kappa[2][j];
    b[0][j] = d0 * inv_eps3;
    b[1][j] = d1 * inv_eps3;
    b[2][j] = d2 * inv_eps3;
    a[0][j] = (k1 * d2 - k2 * d1) * h;
    a[1][j] = (k2 * d0 - k0 * d2) * h;
    a[2][j] = (k0 * d1 - k1 * d0) * h;
  }
  for (int c = 0; c < 3; ++c) {
    double* t = torque[c];
    t[0] += b[c][0] + a[c][0];
#pragma omp simd
    for (int i = 1; i < count; ++i) t[i] += b[c][i] - b[c][i - 1] + a[c][i] + a[c][i - 1];
    t[count] += -b[c][count - 1] + a[c][count - 1];
  }
}

void ActiveStrainLoads::add_derivatives(const RodModel& model, const RodState& state,
                                        RodJacobian& jacobian) const {
  add_fixed_stress_derivatives(model, state, stresses_, couples_, jacobian);
}

}  // namespace tendril::physics
