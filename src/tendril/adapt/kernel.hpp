#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

namespace tendril::adapt {

// The covariance of a stationary kernel as a function of the scaled distance
// r = sqrt(Σ_j (x_j − x'_j)² / ℓ_j²) (automatic relevance determination: one length scale ℓ_j
// per input dimension). Rasmussen & Williams, "Gaussian Processes for Machine Learning" (2006),
// eq. (4.9) and (4.17):
//   squared_exponential  k(r) = σ_f² exp(−r²/2)
//   matern52             k(r) = σ_f² (1 + √5 r + 5r²/3) exp(−√5 r)
enum class KernelType { squared_exponential, matern52 };

// "squared_exponential" or "matern52"; anything else raises Error naming `where`.
KernelType kernel_type_from_name(std::string_view name, std::string_view where = {});
std::string kernel_type_name(KernelType type);

// An ARD kernel without its noise term. Points are the rows of a matrix (n × input_dim), in
// the units of the inputs; the length scales share those units and σ_f² has the units of the
// targets squared.
class ArdKernel {
 public:
  ArdKernel(KernelType type, Eigen::VectorXd length_scales, double signal_variance);

  KernelType type() const { return type_; }
  int input_dim() const { return static_cast<int>(length_scales_.size()); }
  const Eigen::VectorXd& length_scales() const { return length_scales_; }
  double signal_variance() const { return signal_variance_; }

  // k(r) / σ_f². Values below 1e-100 are returned as zero: next to σ_f² they are invisible in
  // double precision, and letting them decay into subnormal numbers would slow every product
  // that meets them a hundredfold (far points at short length scales, common early in a
  // hyper-parameter search).
  static double shape(KernelType type, double r);
  // The factor g(r) with ∂k/∂log ℓ_j = σ_f² g(r) Δ_j²/ℓ_j² and ∂k/∂x_j = −σ_f² g(r) Δ_j/ℓ_j²
  // (Δ = x − x'): exp(−r²/2) for the squared exponential, (5/3)(1 + √5 r) exp(−√5 r) for
  // Matérn 5/2. It stays finite at r = 0, where Matérn's dk/dr alone would need r in a
  // denominator. Cut at 1e-100 like `shape`.
  static double slope(KernelType type, double r);

  // Squared scaled distances r² between the rows of `a` and `b` (a.rows() × b.rows()),
  // accumulated one dimension at a time, which keeps nearby points exact (no |a|² + |b|² − 2ab
  // cancellation).
  void squared_distances(const Eigen::Ref<const Eigen::MatrixXd>& a,
                         const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd& out) const;

  // σ_f² k(r)/σ_f², elementwise, from squared scaled distances r² (in place).
  void apply_shape(Eigen::MatrixXd& squared_distances) const;
  // The shape and σ_f² g(r) from one exponential: `shape` receives σ_f² k/σ_f²,
  // `squared_distances` becomes σ_f² g.
  void apply_shape_and_slope(Eigen::MatrixXd& squared_distances, Eigen::MatrixXd& shape) const;

  // K(a, b) (a.rows() × b.rows()).
  void covariance(const Eigen::Ref<const Eigen::MatrixXd>& a,
                  const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd& out) const;
  // k(x, point_i) for every row of `points`.
  void covariance(const Eigen::Ref<const Eigen::MatrixXd>& points,
                  const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& out) const;
  // ∂k(x, point_i)/∂x as the columns of `out` (input_dim × points.rows()).
  void input_gradient(const Eigen::Ref<const Eigen::MatrixXd>& points,
                      const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::MatrixXd& out) const;

 private:
  KernelType type_;
  Eigen::VectorXd length_scales_;
  double signal_variance_;
};

}  // namespace tendril::adapt
