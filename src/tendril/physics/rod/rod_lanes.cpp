#include "tendril/physics/rod/rod_lanes.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics {

// Each loop over `l` below is one rod's arithmetic for one element (or node, or Voronoi point),
// written as Rod's kernels write it (rod.cpp, internal_loads.cpp; Gazzola et al. 2018, §3), so
// that the compiler forms the same operations — fused multiply-adds included — for every lane.
// Only the vectorization differs: across rods here, across elements there.

namespace {

// The lanes of component k of node (or element) i.
struct Lanes {
  Lanes(LaneColumns& array, int count) : base(array.data()), count(count) {}
  double* operator()(int k, int i) const { return base + (k * count + i) * kRodLanes; }
  double* base;
  Eigen::Index count;
};
struct ConstLanes {
  ConstLanes(const LaneColumns& array, int count) : base(array.data()), count(count) {}
  const double* operator()(int k, int i) const { return base + (k * count + i) * kRodLanes; }
  const double* base;
  Eigen::Index count;
};

template <typename Matrix>
void copy_in(LaneColumns& array, int lane, const Matrix& values) {
  const Eigen::Index cols = values.cols();
  for (Eigen::Index k = 0; k < values.rows(); ++k) {
    for (Eigen::Index i = 0; i < cols; ++i) array(lane, k * cols + i) = values(k, i);
  }
}

}  // namespace

void RodLanes::resize(const RodModel& model) {
  const int n = model.n_elements, nodes = model.n_nodes(), voronoi = std::max(model.n_voronoi(), 0);
  n_elements = n;
  positions = LaneColumns::Zero(kRodLanes, 3 * nodes);
  velocities = LaneColumns::Zero(kRodLanes, 3 * nodes);
  directors = LaneColumns::Zero(kRodLanes, 9 * n);
  for (int i = 0; i < n; ++i) {
    for (int r = 0; r < 3; ++r) directors.col((3 * r + r) * n + i).setOnes();
  }
  angular_velocities = LaneColumns::Zero(kRodLanes, 3 * n);
  time = LaneColumns::Zero(kRodLanes, 1);
  external_forces = LaneColumns::Zero(kRodLanes, 3 * nodes);
  external_torques = LaneColumns::Zero(kRodLanes, 3 * n);
  muscle_couples = LaneColumns::Zero(kRodLanes, 3 * n);
  lengths = LaneColumns::Zero(kRodLanes, n);
  dilatations = LaneColumns::Ones(kRodLanes, n);
  lab_stresses = LaneColumns::Zero(kRodLanes, 3 * n);
  curvatures = LaneColumns::Zero(kRodLanes, 3 * voronoi);
  cosines = LaneColumns::Ones(kRodLanes, voronoi);
  factors = LaneColumns::Ones(kRodLanes, voronoi);
  bend_couples = LaneColumns::Zero(kRodLanes, 3 * voronoi);
  quadrature = LaneColumns::Zero(kRodLanes, 3 * voronoi);
  internal_forces = LaneColumns::Zero(kRodLanes, 3 * nodes);
  internal_torques = LaneColumns::Zero(kRodLanes, 3 * n);
  saved_directors = directors;
}

void RodLanes::set_lane(int lane, const RodState& state) {
  copy_in(positions, lane, state.positions);
  copy_in(velocities, lane, state.velocities);
  copy_in(directors, lane, state.directors);
  copy_in(angular_velocities, lane, state.angular_velocities);
  time(lane, 0) = state.time;
}

void RodLanes::get_lane(int lane, RodState& state) const {
  const int n = n_elements;
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j <= n; ++j) {
      state.positions(k, j) = positions(lane, k * (n + 1) + j);
      state.velocities(k, j) = velocities(lane, k * (n + 1) + j);
    }
    for (int i = 0; i < n; ++i)
      state.angular_velocities(k, i) = angular_velocities(lane, k * n + i);
  }
  for (int k = 0; k < 9; ++k) {
    for (int i = 0; i < n; ++i) state.directors(k, i) = directors(lane, k * n + i);
  }
  state.time = time(lane, 0);
}

LaneMask RodLanes::finite_lanes() const {
  // A sum is non-finite iff some term is (or the terms overflow, which is a blow-up too).
  Eigen::Matrix<double, kRodLanes, 1> sum = positions.rowwise().sum() + velocities.rowwise().sum() +
                                            directors.rowwise().sum() +
                                            angular_velocities.rowwise().sum();
  LaneMask finite;
  for (int l = 0; l < kRodLanes; ++l) finite[l] = std::isfinite(sum[l]);
  return finite;
}

void lanes_kinematic_step(const RodModel& model, RodLanes& lanes, double h,
                          const LaneMask& active) {
  const int n = model.n_elements;
  {
    double* x = lanes.positions.data();
    const double* v = lanes.velocities.data();
    const Eigen::Index size = lanes.positions.size();
#pragma omp simd
    for (Eigen::Index c = 0; c < size; ++c) x[c] += h * v[c];
  }
  const ConstLanes w(lanes.angular_velocities, n);
  const Lanes q(lanes.directors, n);

  // Rod's test for a rotation beyond 0.1 rad in one step (or a non-finite rate), per lane.
  double largest[kRodLanes] = {};
  for (int i = 0; i < n; ++i) {
    const double *w0 = w(0, i), *w1 = w(1, i), *w2 = w(2, i);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) {
      const double s = w0[l] * w0[l] + w1[l] * w1[l] + w2[l] * w2[l];
      largest[l] = (s > largest[l] || s != s) ? s : largest[l];
    }
  }
  bool general = false;
  LaneMask large{};
  for (int l = 0; l < kRodLanes; ++l) {
    large[l] = active[l] && !(largest[l] * h * h < 1e-2);
    general = general || large[l];
  }
  if (general) lanes.saved_directors = lanes.directors;

  // Q ← exp(−h [ω]×) Q by Rodrigues' formula with the series of sin φ/φ and (1 − cos φ)/φ².
  for (int i = 0; i < n; ++i) {
    const double *w0 = w(0, i), *w1 = w(1, i), *w2 = w(2, i);
    double* p[9];
    for (int k = 0; k < 9; ++k) p[k] = q(k, i);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) {
      const double x = h * w0[l], y = h * w1[l], z = h * w2[l];
      const double p2 = x * x + y * y + z * z;
      const double a = 1.0 - p2 / 6.0 * (1.0 - p2 / 20.0 * (1.0 - p2 / 42.0 * (1.0 - p2 / 72.0)));
      const double b =
          0.5 * (1.0 - p2 / 12.0 * (1.0 - p2 / 30.0 * (1.0 - p2 / 56.0 * (1.0 - p2 / 90.0))));
      const double r00 = 1.0 + b * (x * x - p2), r11 = 1.0 + b * (y * y - p2),
                   r22 = 1.0 + b * (z * z - p2);
      const double r01 = a * z + b * x * y, r10 = -a * z + b * x * y;
      const double r02 = -a * y + b * x * z, r20 = a * y + b * x * z;
      const double r12 = a * x + b * y * z, r21 = -a * x + b * y * z;
      double old[9];
      for (int k = 0; k < 9; ++k) old[k] = p[k][l];
      for (int c = 0; c < 3; ++c) {
        p[0 + c][l] = r00 * old[c] + r01 * old[3 + c] + r02 * old[6 + c];
        p[3 + c][l] = r10 * old[c] + r11 * old[3 + c] + r12 * old[6 + c];
        p[6 + c][l] = r20 * old[c] + r21 * old[3 + c] + r22 * old[6 + c];
      }
    }
  }
  if (!general) return;
  // The general formula, as Rod takes it, for the lanes that need it.
  for (int l = 0; l < kRodLanes; ++l) {
    if (!large[l]) continue;
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d omega;
      Eigen::Matrix3d old;
      for (int k = 0; k < 3; ++k) omega[k] = w(k, i)[l];
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) old(r, c) = lanes.saved_directors(l, (3 * r + c) * n + i);
      }
      const Eigen::Matrix3d rotated = exp_rotation_minus(h * omega) * old;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) q(3 * r + c, i)[l] = rotated(r, c);
      }
    }
  }
}

namespace {

// Rod's element pass with loads: geometry, σ = Q (x_{i+1} − x_i)/l̂ − ẑ, n = S (σ − σ̂), the
// lab-frame stress Qᵀ n / e and the element's own torques (shear couple, Lagrangian transport,
// unsteady dilatation).
void element_pass(const RodModel& model, RodLanes& lanes) {
  const int n = model.n_elements;
  const ConstLanes x(lanes.positions, n + 1), v(lanes.velocities, n + 1);
  const ConstLanes w(lanes.angular_velocities, n), q(lanes.directors, n);
  const Lanes lab(lanes.lab_stresses, n), torque(lanes.internal_torques, n);
  const Lanes length_lanes(lanes.lengths, n), dilatation_lanes(lanes.dilatations, n);
  for (int i = 0; i < n; ++i) {
    const double *xa0 = x(0, i), *xa1 = x(1, i), *xa2 = x(2, i);
    const double *xb0 = x(0, i + 1), *xb1 = x(1, i + 1), *xb2 = x(2, i + 1);
    const double *va0 = v(0, i), *va1 = v(1, i), *va2 = v(2, i);
    const double *vb0 = v(0, i + 1), *vb1 = v(1, i + 1), *vb2 = v(2, i + 1);
    const double *w0p = w(0, i), *w1p = w(1, i), *w2p = w(2, i);
    const double* qp[9];
    for (int k = 0; k < 9; ++k) qp[k] = q(k, i);
    double *lab0 = lab(0, i), *lab1 = lab(1, i), *lab2 = lab(2, i);
    double *t0 = torque(0, i), *t1 = torque(1, i), *t2 = torque(2, i);
    double* length = length_lanes(0, i);
    double* dilatation = dilatation_lanes(0, i);
    const double lh = model.rest_lengths[i];
    const double k0 = model.shear_stiffness(0, i), k1 = model.shear_stiffness(1, i),
                 k2 = model.shear_stiffness(2, i);
    const double rs0 = model.rest_shear_strains(0, i), rs1 = model.rest_shear_strains(1, i),
                 rs2 = model.rest_shear_strains(2, i);
    const double in0 = model.inertia(0, i), in1 = model.inertia(1, i), in2 = model.inertia(2, i);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) {
      const double ex = xb0[l] - xa0[l], ey = xb1[l] - xa1[l], ez = xb2[l] - xa2[l];
      const double len = std::sqrt(ex * ex + ey * ey + ez * ez);
      const double inv_l = 1.0 / len;
      const double e = len / lh, inv_e = lh * inv_l;
      length[l] = len;
      dilatation[l] = e;
      const double q00 = qp[0][l], q01 = qp[1][l], q02 = qp[2][l];
      const double q10 = qp[3][l], q11 = qp[4][l], q12 = qp[5][l];
      const double q20 = qp[6][l], q21 = qp[7][l], q22 = qp[8][l];
      const double m0 = q00 * ex + q01 * ey + q02 * ez;
      const double m1 = q10 * ex + q11 * ey + q12 * ez;
      const double m2 = q20 * ex + q21 * ey + q22 * ez;
      const double inv_lh = 1.0 / lh;
      const double s0 = m0 * inv_lh, s1 = m1 * inv_lh, s2 = m2 * inv_lh - 1.0;
      const double n0 = k0 * (s0 - rs0);
      const double n1 = k1 * (s1 - rs1);
      const double n2 = k2 * (s2 - rs2);
      lab0[l] = (q00 * n0 + q10 * n1 + q20 * n2) * inv_e;
      lab1[l] = (q01 * n0 + q11 * n1 + q21 * n2) * inv_e;
      lab2[l] = (q02 * n0 + q12 * n1 + q22 * n2) * inv_e;
      const double rate =
          (ex * (vb0[l] - va0[l]) + ey * (vb1[l] - va1[l]) + ez * (vb2[l] - va2[l])) * inv_l *
          inv_lh;
      const double w0 = w0p[l], w1 = w1p[l], w2 = w2p[l];
      const double j0 = in0 * w0 * inv_e, j1 = in1 * w1 * inv_e, j2 = in2 * w2 * inv_e;
      const double c = inv_l * lh;
      const double unsteady = rate * inv_e;
      t0[l] = (m1 * n2 - m2 * n1) * c + (j1 * w2 - j2 * w1) + j0 * unsteady;
      t1[l] = (m2 * n0 - m0 * n2) * c + (j2 * w0 - j0 * w2) + j1 * unsteady;
      t2[l] = (m0 * n1 - m1 * n0) * c + (j0 * w1 - j1 * w0) + j2 * unsteady;
    }
  }
}

// Rod's Voronoi pass with loads: κ_j = −log(Q_{j+1} Q_jᵀ)^∨ / D̂_j, τ = B (κ − κ̂), and the
// two torque terms τ / ε³ and ½ (κ × τ) D̂ / ε³.
void voronoi_pass(const RodModel& model, RodLanes& lanes, const LaneMask& active) {
  const int n = model.n_elements, count = model.n_voronoi();
  if (count <= 0) return;
  const ConstLanes q(lanes.directors, n), length(lanes.lengths, n);
  const Lanes kappa(lanes.curvatures, count), cosine_lanes(lanes.cosines, count),
      factor_lanes(lanes.factors, count);
  const Lanes bend(lanes.bend_couples, count), quadrature(lanes.quadrature, count);

  int large[kRodLanes] = {};
  for (int j = 0; j < count; ++j) {
    const double *a[9], *b[9];
    for (int k = 0; k < 9; ++k) {
      a[k] = q(k, j + 1);
      b[k] = q(k, j);
    }
    double *kappa0 = kappa(0, j), *kappa1 = kappa(1, j), *kappa2 = kappa(2, j);
    double* cosine = cosine_lanes(0, j);
    double* factor = factor_lanes(0, j);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) {
      const double a0 = a[0][l], a1 = a[1][l], a2 = a[2][l], a3 = a[3][l], a4 = a[4][l],
                   a5 = a[5][l], a6 = a[6][l], a7 = a[7][l], a8 = a[8][l];
      const double b0 = b[0][l], b1 = b[1][l], b2 = b[2][l], b3 = b[3][l], b4 = b[4][l],
                   b5 = b[5][l], b6 = b[6][l], b7 = b[7][l], b8 = b[8][l];
      const double r00 = a0 * b0 + a1 * b1 + a2 * b2;
      const double r11 = a3 * b3 + a4 * b4 + a5 * b5;
      const double r22 = a6 * b6 + a7 * b7 + a8 * b8;
      const double r01 = a0 * b3 + a1 * b4 + a2 * b5;
      const double r10 = a3 * b0 + a4 * b1 + a5 * b2;
      const double r02 = a0 * b6 + a1 * b7 + a2 * b8;
      const double r20 = a6 * b0 + a7 * b1 + a8 * b2;
      const double r12 = a3 * b6 + a4 * b7 + a5 * b8;
      const double r21 = a6 * b3 + a7 * b4 + a8 * b5;
      const double s0 = 0.5 * (r21 - r12), s1 = 0.5 * (r02 - r20), s2 = 0.5 * (r10 - r01);
      const double x = s0 * s0 + s1 * s1 + s2 * s2;
      const double cos_theta = 0.5 * (r00 + r11 + r22 - 1.0);
      kappa0[l] = s0;
      kappa1[l] = s1;
      kappa2[l] = s2;
      cosine[l] = cos_theta;
      factor[l] = theta_over_sin_theta_series(x);
      large[l] |= static_cast<int>(cos_theta <= 0.0) | static_cast<int>(x >= kSmallAngleSine2);
    }
  }
  for (int l = 0; l < kRodLanes; ++l) {
    if (!(active[l] && large[l])) continue;
    // As Rod: one frame angle beyond the series' range recomputes the rod's every factor.
    for (int j = 0; j < count; ++j) {
      const double k0 = kappa(0, j)[l], k1 = kappa(1, j)[l], k2 = kappa(2, j)[l];
      const double x = k0 * k0 + k1 * k1 + k2 * k2;
      factor_lanes(0, j)[l] = theta_over_sin_theta(x, cosine_lanes(0, j)[l]);
    }
  }

  for (int j = 0; j < count; ++j) {
    const double *kappa0 = kappa(0, j), *kappa1 = kappa(1, j), *kappa2 = kappa(2, j);
    const double* factor = factor_lanes(0, j);
    const double *la = length(0, j), *lb = length(0, j + 1);
    double *bend0 = bend(0, j), *bend1 = bend(1, j), *bend2 = bend(2, j);
    double *quad0 = quadrature(0, j), *quad1 = quadrature(1, j), *quad2 = quadrature(2, j);
    const double rest_voronoi = model.rest_voronoi_lengths[j];
    const double rest_sum = model.rest_lengths[j] + model.rest_lengths[j + 1];
    const double b0s = model.bend_stiffness(0, j), b1s = model.bend_stiffness(1, j),
                 b2s = model.bend_stiffness(2, j);
    const double rk0 = model.rest_curvatures(0, j), rk1 = model.rest_curvatures(1, j),
                 rk2 = model.rest_curvatures(2, j);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) {
      const double scale = -factor[l] / rest_voronoi;
      const double k0 = kappa0[l] * scale, k1 = kappa1[l] * scale, k2 = kappa2[l] * scale;
      const double eps = (la[l] + lb[l]) / rest_sum;
      const double t0 = b0s * (k0 - rk0);
      const double t1 = b1s * (k1 - rk1);
      const double t2 = b2s * (k2 - rk2);
      const double inv_eps3 = 1.0 / (eps * eps * eps);
      bend0[l] = t0 * inv_eps3;
      bend1[l] = t1 * inv_eps3;
      bend2[l] = t2 * inv_eps3;
      const double h = 0.5 * rest_voronoi * inv_eps3;
      quad0[l] = (k1 * t2 - k2 * t1) * h;
      quad1[l] = (k2 * t0 - k0 * t2) * h;
      quad2[l] = (k0 * t1 - k1 * t0) * h;
    }
  }
}

// Forces on nodes: Δʰ of the lab-frame element stresses (ghost values zero at both ends).
void node_force_pass(const RodModel& model, RodLanes& lanes) {
  const int n = model.n_elements;
  const ConstLanes lab(lanes.lab_stresses, n);
  const Lanes force(lanes.internal_forces, n + 1);
  for (int k = 0; k < 3; ++k) {
    {
      double* f = force(k, 0);
      const double* s = lab(k, 0);
#pragma omp simd
      for (int l = 0; l < kRodLanes; ++l) f[l] = s[l];
    }
    for (int j = 1; j < n; ++j) {
      double* f = force(k, j);
      const double *s = lab(k, j), *sp = lab(k, j - 1);
#pragma omp simd
      for (int l = 0; l < kRodLanes; ++l) f[l] = s[l] - sp[l];
    }
    double* f = force(k, n);
    const double* sp = lab(k, n - 1);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) f[l] = -sp[l];
  }
}

// Torques on elements from the Voronoi couples: Δʰ(τ/ε³) + Aʰ(κ × τ D̂/ε³).
void voronoi_torque_pass(const RodModel& model, RodLanes& lanes) {
  const int n = model.n_elements, count = model.n_voronoi();
  if (count <= 0) return;
  const ConstLanes bend(lanes.bend_couples, count), quadrature(lanes.quadrature, count);
  const Lanes torque(lanes.internal_torques, n);
  for (int k = 0; k < 3; ++k) {
    {
      double* t = torque(k, 0);
      const double *b = bend(k, 0), *a = quadrature(k, 0);
#pragma omp simd
      for (int l = 0; l < kRodLanes; ++l) t[l] += b[l] + a[l];
    }
    for (int i = 1; i < count; ++i) {
      double* t = torque(k, i);
      const double *b = bend(k, i), *bp = bend(k, i - 1);
      const double *a = quadrature(k, i), *ap = quadrature(k, i - 1);
#pragma omp simd
      for (int l = 0; l < kRodLanes; ++l) t[l] += b[l] - bp[l] + a[l] + ap[l];
    }
    double* t = torque(k, count);
    const double *bp = bend(k, count - 1), *ap = quadrature(k, count - 1);
#pragma omp simd
    for (int l = 0; l < kRodLanes; ++l) t[l] += -bp[l] + ap[l];
  }
}

}  // namespace

void lanes_internal_loads(const RodModel& model, RodLanes& lanes, const LaneMask& active) {
  element_pass(model, lanes);
  voronoi_pass(model, lanes, active);
  node_force_pass(model, lanes);
  voronoi_torque_pass(model, lanes);
}

void lanes_dynamic_step(const RodModel& model, RodLanes& lanes, double dt) {
  const int n = model.n_elements;
  const Lanes v(lanes.velocities, n + 1), w(lanes.angular_velocities, n);
  const ConstLanes fi(lanes.internal_forces, n + 1), fe(lanes.external_forces, n + 1);
  const ConstLanes ti(lanes.internal_torques, n), te(lanes.external_torques, n);
  const ConstLanes e(lanes.dilatations, n);
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j <= n; ++j) {
      double* vp = v(k, j);
      const double *a = fi(k, j), *b = fe(k, j);
      const double inverse_mass = model.inverse_node_masses[j];
#pragma omp simd
      for (int l = 0; l < kRodLanes; ++l) vp[l] += dt * inverse_mass * (a[l] + b[l]);
    }
    for (int i = 0; i < n; ++i) {
      double* wp = w(k, i);
      const double *a = ti(k, i), *b = te(k, i), *ep = e(0, i);
      const double inverse_inertia = model.inverse_inertia(k, i);
#pragma omp simd
      for (int l = 0; l < kRodLanes; ++l) wp[l] += dt * ep[l] * inverse_inertia * (a[l] + b[l]);
    }
  }
}

}  // namespace tendril::physics
