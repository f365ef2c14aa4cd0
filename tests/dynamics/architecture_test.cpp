#include "tendril/dynamics/architecture.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dynamics/model.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

using testing::kAllArchitectures;
using testing::small_description;

int64_t counted(Model& model) {
  int64_t total = 0;
  for (const auto& parameter : model.network().parameters()) total += parameter.numel();
  return total;
}

// Closed forms for 4 states, 2 inputs (F = 6 features per row), hidden 8, 2 layers, by hand:
//   RNN layer: H (F + H + 2); LSTM layer: 4 H (F + H + 2); head: 8·4 + 4 = 36.
TEST(Architecture, ParameterCountsMatchTheClosedFormsComputedByHand) {
  const int64_t rnn = 8 * (6 + 8 + 2) + 8 * (8 + 8 + 2) + 36;           // 128 + 144 + 36
  const int64_t lstm = 4 * 8 * (6 + 8 + 2) + 4 * 8 * (8 + 8 + 2) + 36;  // 512 + 576 + 36
  const int64_t seq2seq = 2 * (lstm - 36) + 36;
  // + query 6·8+8, attention 4·8·8 + 4·8, back 8·6+6.
  const int64_t attention = seq2seq + 56 + 288 + 54;
  // Softsign LSTM on 2·4 + 3·2 = 14 inputs, one bias: 4·8·(14 + 8 + 1), head 36.
  const int64_t softsign = 4 * 8 * (14 + 8 + 1) + 36;
  const int64_t expected[] = {rnn, lstm, seq2seq, attention, softsign};
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(architecture_name(kAllArchitectures[i]));
    Model model(small_description(kAllArchitectures[i]), 1);
    EXPECT_EQ(model.spec().parameter_count(), expected[i]);
    EXPECT_EQ(counted(model), expected[i]);
  }
}

TEST(Architecture, ThesisSizeCountsAgreeWithTheNetworks) {
  for (Architecture kind : {Architecture::kLstm, Architecture::kSeq2SeqAttention}) {
    ModelDescription d = small_description(kind, 100, 512, 3);
    d.architecture.heads = 4;
    Model model(d, 1);
    EXPECT_EQ(counted(model), model.spec().parameter_count());
  }
  // LSTM(6, 512, 3) + Linear(512, 4): 4·512·(6+512+2) + 2·4·512·(512+512+2) + 2052.
  ModelDescription d = small_description(Architecture::kLstm, 100, 512, 3);
  EXPECT_EQ(d.architecture.parameter_count(), 1064960 + 2 * 2101248 + 2052);
}

TEST(Architecture, OutputsHaveOneBoundedChangePerState) {
  for (Architecture kind : kAllArchitectures) {
    SCOPED_TRACE(architecture_name(kind));
    ModelDescription d = small_description(kind);
    d.architecture.output_bound = 0.5;
    Model model(d, 3);
    const auto& spec = model.spec();
    const torch::Tensor input =
        torch::randn({7, spec.sequence_length(), spec.feature_size()}) * 100.0;
    model.network().eval();
    const torch::Tensor output = model.network().forward(input);
    EXPECT_EQ(output.sizes(), (std::vector<int64_t>{7, 4}));
    const double bound = spec.predicts_change() ? 0.5 : 1.0;  // softsign: (−1, 1)
    EXPECT_LE(output.abs().max().item<double>(), bound);
  }
}

TEST(Architecture, ConfigReadsEveryKeyAndRejectsBadValues) {
  const Config good = Config::parse(
      "architecture: seq2seq_attention\nhidden_size: 16\nlayers: 3\nheads: 4\nwindow: 20\n"
      "output_bound: 50\nnormalization: minmax\n",
      "fit.yaml");
  const ArchitectureSpec spec = ArchitectureSpec::from_config(good, 4, 2);
  EXPECT_EQ(spec.kind, Architecture::kSeq2SeqAttention);
  EXPECT_EQ(spec.hidden_size, 16);
  EXPECT_EQ(spec.layers, 3);
  EXPECT_EQ(spec.window, 20);
  EXPECT_EQ(spec.output_bound, 50.0);
  EXPECT_EQ(spec.normalization, Normalization::kMinMax);
  EXPECT_NO_THROW(good.reject_unknown());

  const ArchitectureSpec seed002 =
      ArchitectureSpec::from_config(Config::parse("architecture: softsign_lstm\n"), 9, 9);
  EXPECT_EQ(seed002.hidden_size, 128);
  EXPECT_EQ(seed002.window, 3);
  EXPECT_EQ(seed002.dropout, 0.3);
  EXPECT_EQ(seed002.normalization, Normalization::kMinMax);
  EXPECT_EQ(seed002.feature_size(), 45);  // seed 002 Sec. IV-A1: input dimension 45

  using testing::error_message;
  EXPECT_NE(error_message([] {
              ArchitectureSpec::from_config(Config::parse("architecture: gru\n", "f.yaml"), 4, 2);
            }).find("unknown architecture 'gru'"),
            std::string::npos);
  EXPECT_NE(
      error_message([] {
        ArchitectureSpec::from_config(
            Config::parse("architecture: seq2seq_attention\nhidden_size: 10\nheads: 4\n", "f.yaml"),
            4, 2);
      }).find("heads"),
      std::string::npos);
  EXPECT_THROW(ArchitectureSpec::from_config(
                   Config::parse("architecture: softsign_lstm\nwindow: 5\n"), 4, 2),
               Error);
  EXPECT_THROW(
      ArchitectureSpec::from_config(Config::parse("architecture: lstm\nwindow: 0\n"), 4, 2), Error);
  EXPECT_THROW(
      ArchitectureSpec::from_config(Config::parse("architecture: lstm\ndropout: 0.2\n"), 4, 2),
      Error);
}

TEST(Architecture, SameSeedSameWeightsOtherSeedOtherWeights) {
  for (Architecture kind : kAllArchitectures) {
    SCOPED_TRACE(architecture_name(kind));
    Model a(small_description(kind), 5), b(small_description(kind), 5),
        c(small_description(kind), 6);
    const auto pa = a.network().parameters(), pb = b.network().parameters(),
               pc = c.network().parameters();
    bool all_equal = true, any_differs = false;
    for (std::size_t i = 0; i < pa.size(); ++i) {
      all_equal = all_equal && torch::equal(pa[i], pb[i]);
      any_differs = any_differs || !torch::equal(pa[i], pc[i]);
    }
    EXPECT_TRUE(all_equal);
    EXPECT_TRUE(any_differs);
  }
}

}  // namespace
}  // namespace tendril::dynamics
