#include "tendril/nn/inference_sync.hpp"

#include "tendril/core/error.hpp"

namespace tendril::nn {

namespace {

using RowMajorMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void copy_linear(const torch::nn::Linear& from, DenseLayer& to) {
  const torch::Tensor weight = from->weight.detach().contiguous();
  const torch::Tensor bias = from->bias.detach().contiguous();
  require(weight.size(0) == to.weight.rows() && weight.size(1) == to.weight.cols(),
          "layer shapes of the module and its inference copy differ", "nn::sync_inference_policy");
  to.weight =
      Eigen::Map<const RowMajorMatrix>(weight.data_ptr<float>(), weight.size(0), weight.size(1));
  to.bias = Eigen::Map<const Eigen::VectorXf>(bias.data_ptr<float>(), bias.size(0));
}

void copy_trunk(const Mlp& from, EigenMlp& to) {
  require(from->layers().size() == to.layers().size(),
          "trunk depths of the module and its inference copy differ", "nn::sync_inference_policy");
  for (std::size_t i = 0; i < to.layers().size(); ++i)
    copy_linear(from->layers()[i], to.layers()[i]);
}

}  // namespace

void sync_inference_policy(const ActorCriticImpl& module, InferencePolicy& policy) {
  copy_trunk(module.policy_trunk(), policy.policy_trunk());
  if (!module.spec().shared_trunk) copy_trunk(module.value_trunk(), policy.value_trunk());
  copy_linear(module.policy_head(), policy.policy_head());
  copy_linear(module.value_head(), policy.value_head());
  if (!module.spec().discrete) {
    const torch::Tensor log_std = module.log_std().detach().contiguous();
    policy.log_std() =
        Eigen::Map<const Eigen::VectorXf>(log_std.data_ptr<float>(), log_std.size(0));
  }
}

InferencePolicy make_inference_policy(const ActorCriticImpl& module) {
  InferencePolicy policy(module.spec());
  sync_inference_policy(module, policy);
  return policy;
}

}  // namespace tendril::nn
