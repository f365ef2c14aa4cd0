#include "tendril/nn/flat_adam.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::nn {

FlatAdam::FlatAdam(std::vector<torch::Tensor> parameters, const Options& options)
    : parameters_(std::move(parameters)), options_(options) {
  first_moment_ = torch::zeros({parameters_.numel()}, torch::kFloat);
  second_moment_ = torch::zeros({parameters_.numel()}, torch::kFloat);
  denominator_ = torch::empty({parameters_.numel()}, torch::kFloat);
}

void FlatAdam::step() {
  torch::NoGradGuard no_grad;
  ++steps_;
  const double bias_correction1 = 1.0 - std::pow(options_.beta1, static_cast<double>(steps_));
  const double bias_correction2 = 1.0 - std::pow(options_.beta2, static_cast<double>(steps_));
  const torch::Tensor& gradient = parameters_.gradients();
  first_moment_.mul_(options_.beta1).add_(gradient, 1.0 - options_.beta1);
  second_moment_.mul_(options_.beta2).addcmul_(gradient, gradient, 1.0 - options_.beta2);
  torch::sqrt_out(denominator_, second_moment_);
  denominator_.div_(std::sqrt(bias_correction2)).add_(options_.epsilon);
  const double step_size = options_.learning_rate / bias_correction1;
  // `values()` is the storage every parameter views, so this moves all of them.
  torch::Tensor values = parameters_.values();
  values.addcdiv_(first_moment_, denominator_, -step_size);
}

void FlatAdam::save(torch::serialize::OutputArchive& archive) const {
  archive.write("steps", torch::tensor({steps_}, torch::kLong));
  archive.write("first_moment", first_moment_);
  archive.write("second_moment", second_moment_);
}

void FlatAdam::load(torch::serialize::InputArchive& archive) {
  torch::Tensor steps, first, second;
  archive.read("steps", steps);
  archive.read("first_moment", first);
  archive.read("second_moment", second);
  const auto fits = [&](const torch::Tensor& moment) {
    return moment.scalar_type() == torch::kFloat && moment.numel() == parameters_.numel();
  };
  require(steps.scalar_type() == torch::kLong && steps.numel() == 1,
          "Adam step count is not one integer", "nn::FlatAdam::load");
  require(fits(first) && fits(second),
          "Adam moments do not fit the " + std::to_string(parameters_.numel()) + " parameters",
          "nn::FlatAdam::load");
  torch::NoGradGuard no_grad;
  steps_ = steps.item<int64_t>();
  first_moment_.copy_(first.reshape({-1}));
  second_moment_.copy_(second.reshape({-1}));
}

}  // namespace tendril::nn
