#include "tendril/dynamics/model.hpp"

#include "tendril/core/error.hpp"

namespace tendril::dynamics {

Model::Model(ModelDescription description, uint64_t seed) : description_(std::move(description)) {
  description_.validate("dynamics::Model");
  network_ = make_network(description_.architecture);
  Rng rng(seed, 0);
  network_->initialize(rng);
  network_->set_noise(Rng(seed, 1));
  const Normalizer& n = description_.normalizer;
  row_offset_ = torch::from_blob(const_cast<double*>(n.offset.data()), {n.size()}, torch::kDouble)
                    .to(torch::kFloat);
  row_scale_ = torch::from_blob(const_cast<double*>(n.scale.data()), {n.size()}, torch::kDouble)
                   .to(torch::kFloat);
}

torch::Tensor Model::network_input(const torch::Tensor& windows) const {
  const torch::Tensor rows = (windows - row_offset_) / row_scale_;
  if (spec().kind != Architecture::kSoftsignLstm) return rows;
  // Seed 002's eq. (1): X = [x_t, x_{t−1}], τ = [τ_t, τ_{t−1}, τ_{t−2}] from rows t−2, t−1, t.
  const int64_t dx = spec().state_dim, du = spec().input_dim;
  auto state = [&](int64_t row) { return rows.select(1, row).narrow(1, 0, dx); };
  auto input = [&](int64_t row) { return rows.select(1, row).narrow(1, dx, du); };
  return torch::cat({state(2), state(1), input(2), input(1), input(0)}, 1).unsqueeze(1);
}

torch::Tensor Model::next_state(const torch::Tensor& output, const torch::Tensor& current) const {
  if (spec().predicts_change()) return current + output;
  const int64_t dx = spec().state_dim;
  return output * row_scale_.narrow(0, 0, dx) + row_offset_.narrow(0, 0, dx);
}

torch::Tensor Model::target(const torch::Tensor& current, const torch::Tensor& next) const {
  if (spec().predicts_change()) return (next - current).to(torch::kFloat);
  const int64_t dx = spec().state_dim;
  const torch::Tensor offset = row_offset_.narrow(0, 0, dx).to(torch::kDouble);
  const torch::Tensor scale = row_scale_.narrow(0, 0, dx).to(torch::kDouble);
  return ((next - offset) / scale).to(torch::kFloat);
}

torch::Tensor Model::predict(const torch::Tensor& windows) {
  torch::InferenceMode inference;
  network_->eval();
  const torch::Tensor current =
      windows.select(1, windows.size(1) - 1).narrow(1, 0, spec().state_dim);
  return next_state(network_->forward(network_input(windows)), current);
}

void Model::predict(const envs::BatchMatrix& windows, envs::BatchMatrix& next_states) {
  const int64_t row = spec().row_size();
  if (windows.cols() != static_cast<Eigen::Index>(spec().window) * row) {
    throw Error("windows have " + std::to_string(windows.cols()) + " values per env, the model " +
                    std::to_string(spec().window) + " rows of " + std::to_string(row),
                "dynamics::Model::predict");
  }
  const int64_t n = windows.rows();
  const torch::Tensor input =
      torch::from_blob(const_cast<float*>(windows.data()), {n, spec().window, row}, torch::kFloat);
  const torch::Tensor next = predict(input).contiguous();
  next_states.resize(n, spec().state_dim);
  std::copy_n(next.data_ptr<float>(), next.numel(), next_states.data());
}

}  // namespace tendril::dynamics
