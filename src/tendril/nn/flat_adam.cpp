#include "tendril/nn/flat_adam.hpp"

#include <string>
#include <utility>

#include "tendril/core/error.hpp"

namespace tendril::nn {

FlatAdam::FlatAdam(std::vector<torch::Tensor> parameters, const Options& options)
    : parameters_(std::move(parameters)),
      adam_(parameters_.numel(), {.learning_rate = options.learning_rate,
                                  .beta1 = options.beta1,
                                  .beta2 = options.beta2,
                                  .epsilon = options.epsilon}) {}

void FlatAdam::step() {
  // `values()` is the storage every parameter views, so this moves all of them.
  const int64_t n = parameters_.numel();
  adam_.step(Eigen::Map<Eigen::VectorXf>(parameters_.values().data_ptr<float>(), n),
             Eigen::Map<const Eigen::VectorXf>(parameters_.gradients().data_ptr<float>(), n));
}

void FlatAdam::save(torch::serialize::OutputArchive& archive) const {
  const auto tensor_of = [](const Eigen::VectorXf& moment) {
    return torch::from_blob(const_cast<float*>(moment.data()), {moment.size()}, torch::kFloat)
        .clone();
  };
  archive.write("steps", torch::tensor({adam_.steps()}, torch::kLong));
  archive.write("first_moment", tensor_of(adam_.first_moment()));
  archive.write("second_moment", tensor_of(adam_.second_moment()));
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
  const auto vector_of = [](const torch::Tensor& moment) {
    const torch::Tensor values = moment.reshape({-1}).contiguous();
    return Eigen::VectorXf(
        Eigen::Map<const Eigen::VectorXf>(values.data_ptr<float>(), values.numel()));
  };
  adam_.set_state(steps.item<int64_t>(), vector_of(first), vector_of(second));
}

}  // namespace tendril::nn
