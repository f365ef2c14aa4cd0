#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "tendril/adapt/gaussian_process.hpp"
#include "tendril/core/rng.hpp"

namespace tendril::adapt {

// What the surrogate's posterior is scored by when choosing the next point (minimisation of f,
// posterior mean μ and standard deviation σ of the latent f):
//   expected_improvement   EI = E[max(f_best − ξ − f, 0)] = (f_best − ξ − μ) Φ(z) + σ φ(z),
//                          z = (f_best − ξ − μ)/σ (Jones, Schonlau & Welch 1998, eq. 15)
//   upper_confidence_bound −μ + κσ, the upper confidence bound of −f (Srinivas et al. 2010)
enum class Acquisition { expected_improvement, upper_confidence_bound };

// The surrogate BayesOptOptions starts from: Matérn 5/2, length scales in [0.01, 100] box widths,
// noise from 1e-8 to 0.1 of the values' variance, two random restarts of the likelihood search.
GpOptions default_surrogate_options();

struct BayesOptOptions {
  Eigen::VectorXd lower, upper;  // the box searched
  // Points drawn uniformly in the box before the surrogate proposes any.
  int initial_points = 5;
  Acquisition acquisition = Acquisition::expected_improvement;
  // ξ of expected improvement, in units of the standard deviation of the values seen so far.
  double exploration = 0.01;
  // κ of the confidence bound. 3 rather than the common 2: with 2, a 1-D test function with a
  // deceptive local minimum (Forrester et al. 2008) kept a third of the runs in it.
  double confidence = 3.0;
  // The acquisition is scored at `candidates` uniform random points, and L-BFGS climbs from the
  // best `restarts` of them; the highest point reached is proposed.
  int acquisition_candidates = 1000;
  int acquisition_restarts = 5;
  // The surrogate GP, over the box mapped to the unit cube (length scales in box fractions); its
  // hyper-parameters are refitted before every proposal.
  GpOptions surrogate = default_surrogate_options();
  uint64_t seed = 0;
};

// Bayesian optimisation (Shahriari et al. 2016, "Taking the human out of the loop"), in the
// ask-and-tell form a trial on a robot needs: `ask` proposes the next point, `tell` reports the
// value measured there. Minimises. Same options and seed, same values told → same proposals.
class BayesianOptimizer {
 public:
  explicit BayesianOptimizer(BayesOptOptions options);

  Eigen::VectorXd ask();
  void tell(const Eigen::VectorXd& point, double value);

  // The acquisition (larger is better) at a point of the box, with its gradient with respect
  // to the point when `gradient` is given. Needs at least one value told.
  double acquisition(const Eigen::VectorXd& point, Eigen::VectorXd* gradient) const;

  int evaluations() const { return static_cast<int>(values_.size()); }
  const Eigen::VectorXd& best_point() const;
  double best_value() const;
  const std::vector<Eigen::VectorXd>& points() const { return points_; }
  const std::vector<double>& values() const { return values_; }
  const GaussianProcess& surrogate() const { return surrogate_; }
  const BayesOptOptions& options() const { return options_; }

 private:
  Eigen::VectorXd to_unit(const Eigen::VectorXd& point) const;
  Eigen::VectorXd from_unit(const Eigen::VectorXd& unit) const;
  double unit_acquisition(const Eigen::VectorXd& unit, Eigen::VectorXd* gradient) const;

  BayesOptOptions options_;
  Rng rng_;
  GaussianProcess surrogate_;
  std::vector<Eigen::VectorXd> points_;
  std::vector<double> values_;
  int best_ = -1;
  double exploration_ = 0.0;  // ξ in the values' units
};

struct BayesOptResult {
  Eigen::VectorXd best_point;
  double best_value = 0.0;
  std::vector<Eigen::VectorXd> points;
  std::vector<double> values;
};

// Minimises `objective` over the box with `budget` evaluations.
BayesOptResult bayes_minimize(const std::function<double(const Eigen::VectorXd&)>& objective,
                              const BayesOptOptions& options, int budget);

}  // namespace tendril::adapt
