// The learned-model policy heads (seed 001, thesis §5.1.2, Fig. 5.2): LK Encoder and LK Full give
// what the model gives — the encoder's last output as LibTorch's own LSTM computes it, the full
// model's predicted change of state — and their parameter gradients agree with autograd of those
// independent computations; pretrained heads carry the model's weights; a policy file with such
// a head acts identically once loaded.
#include "tendril/dynamics/learned_model_head.hpp"

#include <gtest/gtest.h>

#include "support/scratch_directory.hpp"
#include "support/torch_networks.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model_file.hpp"
#include "tendril/dynamics/policy_heads.hpp"
#include "tendril/rl/sac/squashed_gaussian_policy.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

constexpr int kWindow = 5;
constexpr int kRow = 6;
constexpr int kBatch = 7;

using Part = LearnedModelHead::Part;

// Windows of physical rows, one column per sample (the head's input layout).
Eigen::MatrixXf random_windows(uint64_t seed) {
  Rng rng(seed);
  Eigen::MatrixXf windows(kWindow * kRow, kBatch);
  for (Eigen::Index i = 0; i < windows.size(); ++i) {
    windows.data()[i] = static_cast<float>(rng.uniform(-20.0, 20.0));
  }
  return windows;
}

// The same windows as a [B, window, row] tensor, normalised as the model normalises them.
torch::Tensor normalised(const Model& model, const Eigen::MatrixXf& windows) {
  const torch::Tensor rows =
      torch::from_blob(const_cast<float*>(windows.data()), {kBatch, kWindow, kRow}).clone();
  return model.network_input(rows);
}

std::shared_ptr<torch::nn::LSTMImpl> encoder_of(SequenceNetwork& network) {
  for (const auto& child : network.named_children()) {
    if (child.key() == "encoder")
      return std::dynamic_pointer_cast<torch::nn::LSTMImpl>(child.value());
  }
  return nullptr;
}

Eigen::VectorXf gradients_of(const std::vector<torch::Tensor>& parameters) {
  std::vector<torch::Tensor> pieces;
  for (const torch::Tensor& p : parameters) pieces.push_back(p.grad().reshape({-1}));
  const torch::Tensor flat = torch::cat(pieces).contiguous();
  return Eigen::Map<const Eigen::VectorXf>(flat.data_ptr<float>(), flat.numel());
}

class LearnedModelHeadTest : public ::testing::TestWithParam<Architecture> {};

TEST_P(LearnedModelHeadTest, EncoderIsTheModelsLstmAndItsGradientIsAutogradsOfTorchsLstm) {
  Model model(testing::small_description(GetParam(), kWindow), 11);
  const LearnedModelHead head(model.description(), Part::kEncoder);
  ASSERT_EQ(head.input_size(), kWindow * kRow);
  ASSERT_EQ(head.output_size(), 8);
  Eigen::VectorXf weights = head.weights_of(model.network());
  const Eigen::MatrixXf windows = random_windows(2);

  auto tape = head.make_tape();
  head.forward(weights, windows, /*record=*/true, *tape);
  // LibTorch's own LSTM (not tendril's fused one) on the model's encoder weights.
  auto encoder = encoder_of(model.network());
  ASSERT_NE(encoder, nullptr);
  for (auto& p : encoder->parameters()) p.mutable_grad().reset();
  const torch::Tensor outputs = std::get<0>(encoder->forward(normalised(model, windows)));
  const torch::Tensor last = outputs.select(1, kWindow - 1);
  const Eigen::MatrixXf expected = testing::columns_of(last);
  EXPECT_LT((tape->output - expected).cwiseAbs().maxCoeff(), 1e-5f);

  const Eigen::MatrixXf output_gradient = Eigen::MatrixXf::Random(8, kBatch);
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(head.parameter_count());
  head.backward(weights, *tape, output_gradient, gradient);
  const torch::Tensor weights_of_outputs =
      torch::from_blob(const_cast<float*>(output_gradient.data()), {kBatch, 8}).clone();
  (last * weights_of_outputs).sum().backward();
  const Eigen::VectorXf reference = gradients_of(encoder->parameters());
  ASSERT_EQ(reference.size(), gradient.size());
  EXPECT_GT(reference.cwiseAbs().maxCoeff(), 1e-3f);
  EXPECT_LT((gradient - reference).cwiseAbs().maxCoeff(), 1e-4f * reference.cwiseAbs().maxCoeff());
}

TEST_P(LearnedModelHeadTest, FullHeadPredictsTheModelsChangeAndBackPropagatesAsAutograd) {
  Model model(testing::small_description(GetParam(), kWindow), 12);
  const LearnedModelHead head(model.description(), Part::kFull);
  ASSERT_EQ(head.output_size(), 4);
  Eigen::VectorXf weights = head.weights_of(model.network());
  ASSERT_EQ(head.parameter_count(), model.spec().parameter_count());
  const Eigen::MatrixXf windows = random_windows(3);

  auto tape = head.make_tape();
  head.forward(weights, windows, /*record=*/true, *tape);
  // x̂_{t+1} − x_t from the model's own prediction.
  envs::BatchMatrix physical = windows.transpose(), next;
  model.predict(physical, next);
  for (int i = 0; i < kBatch; ++i) {
    for (int k = 0; k < 4; ++k) {
      const float change = next(i, k) - windows((kWindow - 1) * kRow + k, i);
      EXPECT_NEAR(tape->output(k, i), change, 1e-4f * (1.0f + std::abs(change))) << i << "," << k;
    }
  }
  const Eigen::MatrixXf output_gradient = Eigen::MatrixXf::Random(4, kBatch);
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(head.parameter_count());
  head.backward(weights, *tape, output_gradient, gradient);
  for (auto& p : model.network().parameters()) p.mutable_grad().reset();
  const torch::Tensor change = model.network().forward(normalised(model, windows));
  const torch::Tensor weights_of_outputs =
      torch::from_blob(const_cast<float*>(output_gradient.data()), {kBatch, 4}).clone();
  (change * weights_of_outputs).sum().backward();
  const Eigen::VectorXf reference = gradients_of(model.network().parameters());
  EXPECT_GT(reference.cwiseAbs().maxCoeff(), 1e-3f);
  EXPECT_LT((gradient - reference).cwiseAbs().maxCoeff(), 1e-4f * reference.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(Seq2Seq, LearnedModelHeadTest,
                         ::testing::Values(Architecture::kSeq2Seq, Architecture::kSeq2SeqAttention),
                         [](const auto& info) { return architecture_name(info.param); });

TEST(LearnedModelHead, RunningWithOtherWeightsBeforeTheBackwardPassIsRefused) {
  Model model(testing::small_description(Architecture::kSeq2Seq, kWindow), 13);
  const LearnedModelHead head(model.description(), Part::kEncoder);
  Eigen::VectorXf online = head.weights_of(model.network()), target = online;
  auto recorded = head.make_tape(), other = head.make_tape();
  head.forward(online, random_windows(4), true, *recorded);
  head.forward(target, random_windows(4), false, *other);
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(head.parameter_count());
  EXPECT_THROW(head.backward(online, *recorded, Eigen::MatrixXf::Ones(8, kBatch), gradient), Error);
  auto unrecorded = head.make_tape();
  head.forward(online, random_windows(4), false, *unrecorded);
  EXPECT_THROW(head.backward(online, *unrecorded, Eigen::MatrixXf::Ones(8, kBatch), gradient),
               Error);
}

class PolicyHeads : public testing::ScratchDirectoryTest {
 protected:
  PolicyHeads() : ScratchDirectoryTest("policy_heads") {}
};

TEST_F(PolicyHeads, PretrainedHeadsCarryTheModelsWeightsAndRandomOnesDoNot) {
  Model model(testing::small_description(Architecture::kSeq2Seq, kWindow), 14);
  save_model(model, directory_ / kModelFileName);
  install_policy_heads();
  nn::FeatureHeadSpec spec;
  spec.kind = "lk_encoder";
  spec.model = directory_.string();
  Rng rng(1);
  const nn::CreatedHead pretrained = nn::create_feature_head(spec, rng);
  const auto& head = dynamic_cast<const LearnedModelHead&>(*pretrained.head);
  EXPECT_TRUE(pretrained.parameters == head.weights_of(model.network()));
  spec.pretrained = false;
  Rng first(1), second(1);
  const nn::CreatedHead fresh = nn::create_feature_head(spec, first);
  EXPECT_FALSE(fresh.parameters == pretrained.parameters);
  EXPECT_TRUE(nn::create_feature_head(spec, second).parameters == fresh.parameters);
  spec.model = (directory_ / "missing").string();
  EXPECT_THROW(nn::create_feature_head(spec, rng), Error);
}

TEST_F(PolicyHeads, APolicyFileWithALearnedModelHeadActsAsThePolicy) {
  Model model(testing::small_description(Architecture::kSeq2SeqAttention, kWindow), 15);
  install_policy_heads();
  for (Part part : {Part::kEncoder, Part::kFull}) {
    auto head = std::make_shared<LearnedModelHead>(model.description(), part);
    // Observations of the reaching task: 14 direct values, then the window.
    const Space observations = Space::box(14 + kWindow * kRow, -1e3f, 1e3f);
    rl::SquashedGaussianPolicy policy(observations, Space::box(2, -10.0f, 10.0f), {16},
                                      nn::Activation::kRelu, false, head);
    Rng init(2);
    policy.network().initialize(policy.parameters(), init);
    policy.head_parameters() = head->weights_of(model.network());
    policy.save(directory_ / "policy");
    const auto loaded = rl::load_policy(directory_ / "policy");
    envs::BatchMatrix batch(kBatch, observations.size()), expected, actual;
    batch.leftCols(14).setRandom();
    batch.rightCols(kWindow * kRow) = random_windows(5).transpose();
    Rng a(7), b(7);
    policy.act(batch, false, a, expected);
    loaded->act(batch, false, b, actual);
    EXPECT_TRUE(expected == actual) << head->kind();
  }
}

}  // namespace
}  // namespace tendril::dynamics
