#include "tendril/adapt/kernel.hpp"

#include <algorithm>
#include <cmath>

#include "tendril/adapt/number_text.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {

namespace {
const double kSqrt5 = std::sqrt(5.0);
// Shape values below this are set to zero (see ArdKernel::shape). Distances are capped before
// the exponential so that it never produces a subnormal number either: exp(−500) and exp(−670)
// are normal, and far below the cut.
constexpr double kNegligible = 1e-100;
constexpr double kMaxSquaredDistance = 1000.0;  // squared exponential: r²/2 ≤ 500
constexpr double kMaxDistance = 300.0;          // Matérn 5/2: √5 r ≤ 671

double cut(double value) { return value < kNegligible ? 0.0 : value; }
}  // namespace

KernelType kernel_type_from_name(std::string_view name, std::string_view where) {
  if (name == "squared_exponential") return KernelType::squared_exponential;
  if (name == "matern52") return KernelType::matern52;
  throw Error(
      "unknown kernel '" + std::string(name) + "' (expected squared_exponential or matern52)",
      std::string(where));
}

std::string kernel_type_name(KernelType type) {
  return type == KernelType::squared_exponential ? "squared_exponential" : "matern52";
}

ArdKernel::ArdKernel(KernelType type, Eigen::VectorXd length_scales, double signal_variance)
    : type_(type), length_scales_(std::move(length_scales)), signal_variance_(signal_variance) {
  require(length_scales_.size() > 0, "a kernel needs at least one input dimension", "ArdKernel");
  for (Eigen::Index j = 0; j < length_scales_.size(); ++j) {
    if (!(length_scales_[j] > 0.0) || !std::isfinite(length_scales_[j])) {
      throw Error("length scale " + std::to_string(j) + " is " + number_text(length_scales_[j]) +
                      " (must be positive and finite)",
                  "ArdKernel");
    }
  }
  if (!(signal_variance_ > 0.0) || !std::isfinite(signal_variance_)) {
    throw Error(
        "signal variance is " + number_text(signal_variance_) + " (must be positive and finite)",
        "ArdKernel");
  }
}

double ArdKernel::shape(KernelType type, double r) {
  if (type == KernelType::squared_exponential) {
    return cut(std::exp(-0.5 * std::min(r * r, kMaxSquaredDistance)));
  }
  r = std::min(r, kMaxDistance);
  return cut((1.0 + kSqrt5 * r + (5.0 / 3.0) * r * r) * std::exp(-kSqrt5 * r));
}

double ArdKernel::slope(KernelType type, double r) {
  if (type == KernelType::squared_exponential) {
    return cut(std::exp(-0.5 * std::min(r * r, kMaxSquaredDistance)));
  }
  r = std::min(r, kMaxDistance);
  return cut((5.0 / 3.0) * (1.0 + kSqrt5 * r) * std::exp(-kSqrt5 * r));
}

void ArdKernel::squared_distances(const Eigen::Ref<const Eigen::MatrixXd>& a,
                                  const Eigen::Ref<const Eigen::MatrixXd>& b,
                                  Eigen::MatrixXd& out) const {
  out.setZero(a.rows(), b.rows());
  Eigen::ArrayXd scaled_a(a.rows());
  for (int j = 0; j < input_dim(); ++j) {
    const double inverse_length = 1.0 / length_scales_[j];
    scaled_a = a.col(j).array() * inverse_length;
    for (Eigen::Index c = 0; c < b.rows(); ++c) {
      out.col(c).array() += (scaled_a - b(c, j) * inverse_length).square();
    }
  }
}

void ArdKernel::apply_shape(Eigen::MatrixXd& squared_distances) const {
  auto v = squared_distances.array();
  if (type_ == KernelType::squared_exponential) {
    v = (-0.5 * v.min(kMaxSquaredDistance)).exp();
  } else {
    const Eigen::ArrayXXd r = v.sqrt().min(kMaxDistance);
    v = (1.0 + kSqrt5 * r + (5.0 / 3.0) * r.square()) * (-kSqrt5 * r).exp();
  }
  v = (v < kNegligible).select(0.0, signal_variance_ * v);
}

void ArdKernel::apply_shape_and_slope(Eigen::MatrixXd& squared_distances,
                                      Eigen::MatrixXd& shape) const {
  auto v = squared_distances.array();
  if (type_ == KernelType::squared_exponential) {
    // g(r) = k(r)/σ_f²: the slope is the shape.
    shape = squared_distances;
    apply_shape(shape);
    squared_distances = shape;
    return;
  }
  const Eigen::ArrayXXd r = v.sqrt().min(kMaxDistance);
  const Eigen::ArrayXXd decay = (-kSqrt5 * r).exp();
  shape = (1.0 + kSqrt5 * r + (5.0 / 3.0) * r.square()) * decay;
  v = (5.0 / 3.0) * (1.0 + kSqrt5 * r) * decay;
  shape = (shape.array() < kNegligible).select(0.0, signal_variance_ * shape.array());
  v = (v < kNegligible).select(0.0, signal_variance_ * v);
}

void ArdKernel::covariance(const Eigen::Ref<const Eigen::MatrixXd>& a,
                           const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd& out) const {
  squared_distances(a, b, out);
  apply_shape(out);
}

void ArdKernel::covariance(const Eigen::Ref<const Eigen::MatrixXd>& points,
                           const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& out) const {
  Eigen::MatrixXd column;
  covariance(points, x.transpose(), column);
  out = column.col(0);
}

void ArdKernel::input_gradient(const Eigen::Ref<const Eigen::MatrixXd>& points,
                               const Eigen::Ref<const Eigen::VectorXd>& x,
                               Eigen::MatrixXd& out) const {
  Eigen::MatrixXd r2;
  squared_distances(points, x.transpose(), r2);
  out.resize(input_dim(), points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double g = signal_variance_ * slope(type_, std::sqrt(r2(i, 0)));
    out.col(i) =
        -g *
        (x - points.row(i).transpose()).cwiseQuotient(length_scales_.cwiseProduct(length_scales_));
  }
}

}  // namespace tendril::adapt
