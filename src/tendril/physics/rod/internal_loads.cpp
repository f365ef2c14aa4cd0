#include "tendril/physics/rod/internal_loads.hpp"

#include <cmath>

#include "tendril/physics/rod/rotation.hpp"

namespace tendril::physics {

// The kernels below run over component-major arrays (Vectors, Frames) in plain loops, so the
// compiler vectorizes them across elements; each loop body is one element's (or one Voronoi
// point's) equations. Equation numbers: Gazzola et al. 2018, §3.

namespace {

// Row pointers of a component-major array.
template <typename Array>
struct Rows {
  explicit Rows(Array& a) : stride(a.cols()), base(a.data()) {}
  auto* operator[](int k) const { return base + k * stride; }
  Eigen::Index stride;
  decltype(std::declval<Array&>().data()) base;
};

// Element geometry and shear/stretch strain, σ_i = Q_i (x_{i+1} − x_i)/l̂_i − ẑ; with loads also
// the stress, the lab-frame stress Qᵀn/e and the element's own torque terms: shear couple
// (Q t × n) l̂, Lagrangian transport (J ω/e) × ω and unsteady dilatation (J ω/e²) de/dt.
template <bool kWithLoads>
void element_pass(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  const Rows x(state.positions), v(state.velocities), w(state.angular_velocities);
  const Rows q(state.directors);
  const Rows tangent(state.tangents), sigma(state.shear_strains), stress(state.internal_stresses);
  const Rows lab(state.element_lab_stresses), torque(state.internal_torques);
  const Rows stiffness(model.shear_stiffness), rest_sigma(model.rest_shear_strains);
  const Rows inertia(model.inertia);
  const double* rest_length = model.rest_lengths.data();
  const double* rest_radius = model.rest_radii.data();
  double* length = state.lengths.data();
  double* dilatation = state.dilatations.data();
  double* dilatation_rate = state.dilatation_rates.data();
  double* radius = state.radii.data();

#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double ex = x[0][i + 1] - x[0][i], ey = x[1][i + 1] - x[1][i], ez = x[2][i + 1] - x[2][i];
    const double l = std::sqrt(ex * ex + ey * ey + ez * ez);
    const double inv_l = 1.0 / l;
    const double lh = rest_length[i];
    const double e = l / lh, inv_e = lh * inv_l;
    length[i] = l;
    dilatation[i] = e;
    radius[i] = rest_radius[i] * std::sqrt(inv_e);  // volume conservation: r = r̂ / √e
    tangent[0][i] = ex * inv_l;
    tangent[1][i] = ey * inv_l;
    tangent[2][i] = ez * inv_l;
    const double q00 = q[0][i], q01 = q[1][i], q02 = q[2][i];
    const double q10 = q[3][i], q11 = q[4][i], q12 = q[5][i];
    const double q20 = q[6][i], q21 = q[7][i], q22 = q[8][i];
    // Q (x_{i+1} − x_i): the edge in the material frame.
    const double m0 = q00 * ex + q01 * ey + q02 * ez;
    const double m1 = q10 * ex + q11 * ey + q12 * ez;
    const double m2 = q20 * ex + q21 * ey + q22 * ez;
    const double inv_lh = 1.0 / lh;
    const double s0 = m0 * inv_lh, s1 = m1 * inv_lh, s2 = m2 * inv_lh - 1.0;
    sigma[0][i] = s0;
    sigma[1][i] = s1;
    sigma[2][i] = s2;
    if constexpr (kWithLoads) {
      // n = S (σ − σ̂)
      const double n0 = stiffness[0][i] * (s0 - rest_sigma[0][i]);
      const double n1 = stiffness[1][i] * (s1 - rest_sigma[1][i]);
      const double n2 = stiffness[2][i] * (s2 - rest_sigma[2][i]);
      stress[0][i] = n0;
      stress[1][i] = n1;
      stress[2][i] = n2;
      lab[0][i] = (q00 * n0 + q10 * n1 + q20 * n2) * inv_e;
      lab[1][i] = (q01 * n0 + q11 * n1 + q21 * n2) * inv_e;
      lab[2][i] = (q02 * n0 + q12 * n1 + q22 * n2) * inv_e;

      // de/dt = (x_{i+1} − x_i)·(v_{i+1} − v_i) / (l l̂)
      const double rate = (ex * (v[0][i + 1] - v[0][i]) + ey * (v[1][i + 1] - v[1][i]) +
                           ez * (v[2][i + 1] - v[2][i])) * inv_l * inv_lh;
      dilatation_rate[i] = rate;

      const double w0 = w[0][i], w1 = w[1][i], w2 = w[2][i];
      const double j0 = inertia[0][i] * w0 * inv_e, j1 = inertia[1][i] * w1 * inv_e,
                   j2 = inertia[2][i] * w2 * inv_e;
      // Shear couple (Q t × n) l̂ with Q t = m / l.
      const double c = inv_l * lh;
      const double unsteady = rate * inv_e;
      torque[0][i] = (m1 * n2 - m2 * n1) * c + (j1 * w2 - j2 * w1) + j0 * unsteady;
      torque[1][i] = (m2 * n0 - m0 * n2) * c + (j2 * w0 - j0 * w2) + j1 * unsteady;
      torque[2][i] = (m0 * n1 - m1 * n0) * c + (j0 * w1 - j1 * w0) + j2 * unsteady;
    }
  }
}

// Voronoi point j between elements j and j + 1: Q_{j+1} = exp(−D̂ [κ]×) Q_j, so
// κ_j = −log(Q_{j+1} Q_jᵀ)^∨ / D̂_j; with loads also τ = B (κ − κ̂) and its two torque terms.
template <bool kWithLoads>
void voronoi_pass(const RodModel& model, RodState& state) {
  const int count = model.n_voronoi();
  if (count <= 0) return;
  // Separate declarations: each deduces its own Rows type (directors are 9 × n, the rest 3 × n).
  const Rows q(state.directors);
  const Rows kappa(state.curvatures), couple(state.internal_couples);
  const Rows bend(state.voronoi_bend_couples), quadrature(state.voronoi_quadrature);
  const Rows stiffness(model.bend_stiffness), rest_kappa(model.rest_curvatures);
  const double* rest_voronoi = model.rest_voronoi_lengths.data();
  const double* rest_length = model.rest_lengths.data();
  const double* length = state.lengths.data();
  double* voronoi_dilatation = state.voronoi_dilatations.data();
  double* cosine = state.voronoi_cosines.data();
  double* factor = state.voronoi_factors.data();

  // R = Q_{j+1} Q_jᵀ; ½(R − Rᵀ)^∨ = sin θ · axis (kept in `kappa` for now) and (tr R − 1)/2 = cos θ.
  int large_angles = 0;
#pragma omp simd reduction(+ : large_angles)
  for (int j = 0; j < count; ++j) {
    // A = Q_{j+1}, B = Q_j; R(r, c) = Σ_k A(r, k) B(c, k).
    const double a0 = q[0][j + 1], a1 = q[1][j + 1], a2 = q[2][j + 1], a3 = q[3][j + 1],
                 a4 = q[4][j + 1], a5 = q[5][j + 1], a6 = q[6][j + 1], a7 = q[7][j + 1],
                 a8 = q[8][j + 1];
    const double b0 = q[0][j], b1 = q[1][j], b2 = q[2][j], b3 = q[3][j], b4 = q[4][j],
                 b5 = q[5][j], b6 = q[6][j], b7 = q[7][j], b8 = q[8][j];
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
    kappa[0][j] = s0;
    kappa[1][j] = s1;
    kappa[2][j] = s2;
    cosine[j] = cos_theta;
    factor[j] = theta_over_sin_theta_series(x);
    large_angles += static_cast<int>(cos_theta <= 0.0) | static_cast<int>(x >= kSmallAngleSine2);
  }
  if (large_angles > 0) {
    for (int j = 0; j < count; ++j) {
      const double x = kappa[0][j] * kappa[0][j] + kappa[1][j] * kappa[1][j] + kappa[2][j] * kappa[2][j];
      factor[j] = theta_over_sin_theta(x, cosine[j]);
    }
  }

#pragma omp simd
  for (int j = 0; j < count; ++j) {
    const double scale = -factor[j] / rest_voronoi[j];
    const double k0 = kappa[0][j] * scale, k1 = kappa[1][j] * scale, k2 = kappa[2][j] * scale;
    kappa[0][j] = k0;
    kappa[1][j] = k1;
    kappa[2][j] = k2;
    const double eps = (length[j] + length[j + 1]) / (rest_length[j] + rest_length[j + 1]);
    voronoi_dilatation[j] = eps;
    if constexpr (kWithLoads) {
      const double t0 = stiffness[0][j] * (k0 - rest_kappa[0][j]);
      const double t1 = stiffness[1][j] * (k1 - rest_kappa[1][j]);
      const double t2 = stiffness[2][j] * (k2 - rest_kappa[2][j]);
      couple[0][j] = t0;
      couple[1][j] = t1;
      couple[2][j] = t2;
      const double inv_eps3 = 1.0 / (eps * eps * eps);
      bend[0][j] = t0 * inv_eps3;
      bend[1][j] = t1 * inv_eps3;
      bend[2][j] = t2 * inv_eps3;
      const double h = 0.5 * rest_voronoi[j] * inv_eps3;
      quadrature[0][j] = (k1 * t2 - k2 * t1) * h;
      quadrature[1][j] = (k2 * t0 - k0 * t2) * h;
      quadrature[2][j] = (k0 * t1 - k1 * t0) * h;
    }
  }
}

// Forces on nodes: Δʰ of the lab-frame element stresses (ghost values zero at both ends).
void node_force_pass(const RodModel& model, RodState& state) {
  const int n = model.n_elements;
  const Rows lab(state.element_lab_stresses), force(state.internal_forces);
  for (int k = 0; k < 3; ++k) {
    double* f = force[k];
    const double* s = lab[k];
    f[0] = s[0];
#pragma omp simd
    for (int j = 1; j < n; ++j) f[j] = s[j] - s[j - 1];
    f[n] = -s[n - 1];
  }
}

// Torques on elements from the Voronoi couples: Δʰ(τ/ε³) + Aʰ(κ × τ D̂/ε³).
void voronoi_torque_pass(const RodModel& model, RodState& state) {
  const int count = model.n_voronoi();
  if (count <= 0) return;
  const Rows bend(state.voronoi_bend_couples), quadrature(state.voronoi_quadrature);
  const Rows torque(state.internal_torques);
  for (int k = 0; k < 3; ++k) {
    double* t = torque[k];
    const double* b = bend[k];
    const double* a = quadrature[k];
    t[0] += b[0] + a[0];
#pragma omp simd
    for (int i = 1; i < count; ++i) t[i] += b[i] - b[i - 1] + a[i] + a[i - 1];
    t[count] += -b[count - 1] + a[count - 1];
  }
}

}  // namespace

void compute_strains(const RodModel& model, RodState& state) {
  element_pass<false>(model, state);
  voronoi_pass<false>(model, state);
}

void compute_internal_loads(const RodModel& model, RodState& state) {
  element_pass<true>(model, state);
  voronoi_pass<true>(model, state);
  node_force_pass(model, state);
  voronoi_torque_pass(model, state);
}

}  // namespace tendril::physics
