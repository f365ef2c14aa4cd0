// The hand-written MLP passes and Adam against LibTorch's autograd and torch::optim::Adam.
#include "tendril/nn/dense_mlp.hpp"

#include <gtest/gtest.h>
#include <torch/torch.h>

#include "support/error_message.hpp"
#include "tendril/nn/adam.hpp"

namespace tendril::nn {
namespace {

torch::Tensor to_tensor(const Eigen::MatrixXf& matrix) {
  // Eigen is column-major: (rows × cols) column-major == (cols × rows) row-major, transposed.
  return torch::from_blob(const_cast<float*>(matrix.data()), {matrix.cols(), matrix.rows()})
      .clone()
      .t();
}

Eigen::MatrixXf to_matrix(const torch::Tensor& tensor) {
  const torch::Tensor contiguous = tensor.t().contiguous();
  Eigen::MatrixXf matrix(tensor.size(0), tensor.size(1));
  std::copy_n(contiguous.data_ptr<float>(), matrix.size(), matrix.data());
  return matrix;
}

struct TorchMirror {
  std::vector<torch::Tensor> weights, biases;
};

// The same network as leaf tensors read from the flat vector.
TorchMirror mirror(const DenseMlp& mlp, const Eigen::VectorXf& parameters) {
  TorchMirror result;
  int64_t offset = 0;
  for (std::size_t layer = 0; layer + 1 < mlp.sizes().size(); ++layer) {
    const int64_t in = mlp.sizes()[layer];
    const int64_t out = mlp.sizes()[layer + 1];
    using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    Eigen::MatrixXf weight = Eigen::Map<const RowMajor>(parameters.data() + offset, out, in);
    offset += out * in;
    Eigen::MatrixXf bias = Eigen::Map<const Eigen::MatrixXf>(parameters.data() + offset, out, 1);
    offset += out;
    result.weights.push_back(to_tensor(weight).requires_grad_(true));
    result.biases.push_back(to_tensor(bias).reshape({out}).requires_grad_(true));
  }
  return result;
}

torch::Tensor activated(Activation activation, const torch::Tensor& x) {
  switch (activation) {
    case Activation::kTanh:
      return torch::tanh(x);
    case Activation::kRelu:
      return torch::relu(x);
    case Activation::kSoftsign:
      return x / (1 + torch::abs(x));
  }
  return x;
}

void check_against_autograd(Activation hidden, bool tanh_output, bool trunk = false) {
  const DenseMlp mlp = trunk ? DenseMlp::trunk({5, 16, 12, 3}, hidden)
                             : DenseMlp({5, 16, 12, 3}, hidden, tanh_output);
  Rng rng(7);
  Eigen::VectorXf parameters(mlp.parameter_count());
  mlp.initialize(parameters, rng);
  const Eigen::MatrixXf inputs = Eigen::MatrixXf::Random(5, 9);
  const Eigen::MatrixXf output_gradient = Eigen::MatrixXf::Random(3, 9);

  DenseMlp::Tape tape;
  mlp.forward(parameters, inputs, tape);
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(mlp.parameter_count());
  Eigen::MatrixXf input_gradient;
  std::vector<Eigen::MatrixXf> scratch;
  mlp.backward(parameters, tape, output_gradient, gradient, &input_gradient, scratch);

  TorchMirror net = mirror(mlp, parameters);
  torch::Tensor x = to_tensor(inputs).t().contiguous().requires_grad_(true);  // batch × in
  torch::Tensor y = x;
  for (std::size_t layer = 0; layer < net.weights.size(); ++layer) {
    y = torch::nn::functional::linear(y, net.weights[layer], net.biases[layer]);
    const bool last = layer + 1 == net.weights.size();
    if (!last || trunk) y = activated(hidden, y);
    if (last && tanh_output) y = torch::tanh(y);
  }
  (y * to_tensor(output_gradient).t()).sum().backward();

  EXPECT_TRUE(tape.output().isApprox(to_matrix(y.detach().t()), 1e-5f));
  EXPECT_TRUE(input_gradient.isApprox(to_matrix(x.grad().t()), 1e-4f));
  int64_t offset = 0;
  for (std::size_t layer = 0; layer < net.weights.size(); ++layer) {
    const Eigen::MatrixXf expected_weight = to_matrix(net.weights[layer].grad());
    const auto size = expected_weight.size();
    using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const Eigen::Map<const RowMajor> weight_gradient(
        gradient.data() + offset, expected_weight.rows(), expected_weight.cols());
    EXPECT_TRUE(weight_gradient.isApprox(expected_weight, 1e-4f)) << "layer " << layer;
    offset += size;
    const Eigen::MatrixXf expected_bias = to_matrix(net.biases[layer].grad().reshape({-1, 1}));
    const Eigen::Map<const Eigen::MatrixXf> bias_gradient(gradient.data() + offset,
                                                          expected_bias.rows(), 1);
    EXPECT_TRUE(bias_gradient.isApprox(expected_bias, 1e-4f)) << "layer " << layer;
    offset += expected_bias.size();
  }
  EXPECT_EQ(offset, mlp.parameter_count());
}

TEST(DenseMlp, ReluPassesMatchAutograd) { check_against_autograd(Activation::kRelu, false); }
TEST(DenseMlp, TanhPassesMatchAutograd) { check_against_autograd(Activation::kTanh, false); }
TEST(DenseMlp, SoftsignPassesMatchAutograd) {
  check_against_autograd(Activation::kSoftsign, false);
  check_against_autograd(Activation::kSoftsign, false, /*trunk=*/true);
}
TEST(DenseMlp, SoftsignIsXOverOnePlusAbsX) {
  // One unit with weight 1 and bias 0: the output is softsign(x) itself; its derivative
  // 1 / (1 + |x|)² by hand: x = 3 → 0.75 and 1/16, x = −1 → −0.5 and 1/4.
  const DenseMlp mlp = DenseMlp::trunk({1, 1}, Activation::kSoftsign);
  Eigen::VectorXf parameters(2);
  parameters << 1.0f, 0.0f;
  DenseMlp::Tape tape;
  Eigen::MatrixXf inputs(1, 2);
  inputs << 3.0f, -1.0f;
  mlp.forward(parameters, inputs, tape);
  EXPECT_FLOAT_EQ(tape.output()(0, 0), 0.75f);
  EXPECT_FLOAT_EQ(tape.output()(0, 1), -0.5f);
  Eigen::VectorXf gradient = Eigen::VectorXf::Zero(2);
  Eigen::MatrixXf input_gradient;
  std::vector<Eigen::MatrixXf> scratch;
  mlp.backward(parameters, tape, Eigen::MatrixXf::Ones(1, 2), gradient, &input_gradient, scratch);
  EXPECT_FLOAT_EQ(input_gradient(0, 0), 1.0f / 16.0f);
  EXPECT_FLOAT_EQ(input_gradient(0, 1), 0.25f);
  EXPECT_EQ(parse_activation("softsign", "test"), Activation::kSoftsign);
  EXPECT_EQ(activation_name(Activation::kSoftsign), "softsign");
}
TEST(DenseMlp, TanhOutputPassesMatchAutograd) { check_against_autograd(Activation::kRelu, true); }
TEST(DenseMlp, TrunkPassesMatchAutograd) {
  check_against_autograd(Activation::kTanh, false, /*trunk=*/true);
  check_against_autograd(Activation::kRelu, false, /*trunk=*/true);
}

// J v against autograd: with g(u) = Jᵀu (a backward pass kept differentiable), J v = ∂(g·v)/∂u.
TEST(DenseMlp, JacobianVectorProductMatchesAutograd) {
  for (const bool trunk : {false, true}) {
    const DenseMlp mlp = trunk ? DenseMlp::trunk({4, 8, 6}, Activation::kTanh)
                               : DenseMlp({4, 8, 6, 3}, Activation::kRelu, /*tanh_output=*/true);
    Rng rng(12);
    Eigen::VectorXf parameters(mlp.parameter_count()), tangent(mlp.parameter_count());
    mlp.initialize(parameters, rng);
    for (Eigen::Index i = 0; i < tangent.size(); ++i) tangent[i] = static_cast<float>(rng.normal());
    const Eigen::MatrixXf inputs = Eigen::MatrixXf::Random(4, 7);
    const Eigen::MatrixXf input_tangent = Eigen::MatrixXf::Random(4, 7);

    DenseMlp::Tape tape;
    mlp.forward(parameters, inputs, tape);
    std::vector<Eigen::MatrixXf> scratch;
    Eigen::MatrixXf output_tangent;
    mlp.jvp(parameters, tape, tangent, &input_tangent, output_tangent, scratch);

    torch::Tensor theta = torch::from_blob(parameters.data(), {parameters.size()}).clone();
    theta.requires_grad_(true);
    torch::Tensor x = to_tensor(inputs).t().contiguous().requires_grad_(true);
    int64_t offset = 0;
    torch::Tensor y = x;
    for (std::size_t layer = 0; layer + 1 < mlp.sizes().size(); ++layer) {
      const int64_t in = mlp.sizes()[layer], out = mlp.sizes()[layer + 1];
      y = torch::nn::functional::linear(y, theta.narrow(0, offset, out * in).reshape({out, in}),
                                        theta.narrow(0, offset + out * in, out));
      offset += out * (in + 1);
      const bool last = layer + 2 == mlp.sizes().size();
      if (!last || trunk) {
        y = trunk ? torch::tanh(y) : torch::relu(y);
      } else {
        y = torch::tanh(y);
      }
    }
    const torch::Tensor u = torch::zeros_like(y).requires_grad_(true);
    const auto g = torch::autograd::grad({(y * u).sum()}, {theta, x}, {}, true, true);
    const torch::Tensor v_theta = torch::from_blob(tangent.data(), {tangent.size()}).clone();
    const torch::Tensor v_x = to_tensor(input_tangent).t().contiguous();
    const torch::Tensor jv =
        torch::autograd::grad({(g[0] * v_theta).sum() + (g[1] * v_x).sum()}, {u})[0];
    EXPECT_TRUE(output_tangent.isApprox(to_matrix(jv.t()), 1e-4f)) << "trunk " << trunk;
  }
}

TEST(DenseMlp, OrthogonalInitialisationHasTheGainsAndZeroBiases) {
  const DenseMlp mlp({3, 10, 2}, Activation::kTanh);
  Eigen::VectorXf parameters(mlp.parameter_count());
  Rng rng(8);
  mlp.initialize_orthogonal(parameters, 1.5, 0.1, rng);
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const Eigen::Map<const RowMajor> tall(parameters.data(), 10, 3);  // orthonormal columns
  EXPECT_TRUE((tall.transpose() * tall).isApprox(2.25f * Eigen::MatrixXf::Identity(3, 3), 1e-5f));
  EXPECT_EQ(parameters.segment(30, 10).norm(), 0.0f);
  const Eigen::Map<const RowMajor> wide(parameters.data() + 40, 2, 10);  // orthonormal rows
  EXPECT_TRUE((wide * wide.transpose()).isApprox(0.01f * Eigen::MatrixXf::Identity(2, 2), 1e-5f));
  EXPECT_EQ(parameters.tail(2).norm(), 0.0f);
}

TEST(DenseMlp, BackwardAccumulatesIntoTheGradient) {
  const DenseMlp mlp({2, 4, 1}, Activation::kTanh);
  Rng rng(1);
  Eigen::VectorXf parameters(mlp.parameter_count());
  mlp.initialize(parameters, rng);
  DenseMlp::Tape tape;
  mlp.forward(parameters, Eigen::MatrixXf::Random(2, 3), tape);
  std::vector<Eigen::MatrixXf> scratch;
  Eigen::VectorXf once = Eigen::VectorXf::Zero(mlp.parameter_count());
  mlp.backward(parameters, tape, Eigen::MatrixXf::Ones(1, 3), once, nullptr, scratch);
  Eigen::VectorXf twice = once;
  mlp.backward(parameters, tape, Eigen::MatrixXf::Ones(1, 3), twice, nullptr, scratch);
  EXPECT_TRUE(twice.isApprox(2.0f * once));
}

TEST(DenseMlp, InitialisationIsTorchsDefaultBoundAndSeeded) {
  const DenseMlp mlp({16, 64, 1}, Activation::kRelu);
  Eigen::VectorXf a(mlp.parameter_count()), b(mlp.parameter_count());
  Rng rng_a(3), rng_b(3);
  mlp.initialize(a, rng_a);
  mlp.initialize(b, rng_b);
  EXPECT_EQ(a, b);
  // First layer: ±1/√16; second layer: ±1/√64.
  EXPECT_LE(a.head(64 * 17).cwiseAbs().maxCoeff(), 0.25f);
  EXPECT_GT(a.head(64 * 17).cwiseAbs().maxCoeff(), 0.24f);
  EXPECT_LE(a.tail(65).cwiseAbs().maxCoeff(), 0.125f);
}

TEST(DenseMlp, RejectsDegenerateShapes) {
  EXPECT_NE(
      testing::error_message([] { DenseMlp({3}, Activation::kRelu); }).find("input and an output"),
      std::string::npos);
  EXPECT_NE(testing::error_message([] {
              DenseMlp({3, 0, 1}, Activation::kRelu);
            }).find("positive"),
            std::string::npos);
}

TEST(Adam, MatchesTorchAdam) {
  torch::manual_seed(0);
  torch::Tensor reference = torch::randn({10}).requires_grad_(true);
  Eigen::VectorXf parameters(10);
  std::copy_n(reference.data_ptr<float>(), 10, parameters.data());
  torch::optim::Adam torch_adam({reference}, torch::optim::AdamOptions(3e-3).eps(1e-5));
  Adam adam(10, {3e-3, 0.9, 0.999, 1e-5});
  for (int step = 0; step < 20; ++step) {
    const torch::Tensor g = torch::randn({10});
    torch_adam.zero_grad();
    reference.mutable_grad() = g.clone();
    torch_adam.step();
    Eigen::VectorXf gradient(10);
    std::copy_n(g.data_ptr<float>(), 10, gradient.data());
    adam.step(parameters, gradient);
  }
  for (int i = 0; i < 10; ++i) EXPECT_NEAR(parameters[i], reference[i].item<float>(), 1e-6f) << i;
  EXPECT_EQ(adam.steps(), 20);
}

TEST(Adam, RestoredStateContinuesIdentically) {
  Adam a(4, {}), b(4, {});
  Eigen::VectorXf pa = Eigen::VectorXf::Ones(4), pb;
  a.step(pa, Eigen::VectorXf::Constant(4, 0.5f));
  pb = pa;
  b.set_state(a.steps(), a.first_moment(), a.second_moment());
  a.step(pa, Eigen::VectorXf::Constant(4, -0.25f));
  b.step(pb, Eigen::VectorXf::Constant(4, -0.25f));
  EXPECT_EQ(pa, pb);
  EXPECT_NE(testing::error_message([&] {
              b.set_state(1, Eigen::VectorXf(3), Eigen::VectorXf(3));
            }).find("expected 4"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::nn
