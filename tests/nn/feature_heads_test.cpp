// Policy-head specs, the MLP head, and the kinds a program knows.
#include "tendril/nn/feature_heads.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"
#include "tendril/nn/mlp_head.hpp"

namespace tendril::nn {
namespace {

TEST(FeatureHeadSpec, ReadsEachKindsKeysAndRefusesTheOthers) {
  const FeatureHeadSpec mlp =
      FeatureHeadSpec::from_config(Config::parse("kind: mlp\ninputs: 600\nlayers: [64, 32]"));
  EXPECT_EQ(mlp.kind, "mlp");
  EXPECT_FALSE(mlp.trainable);
  EXPECT_EQ(mlp.inputs, 600);
  EXPECT_EQ(mlp.layers, (std::vector<int64_t>{64, 32}));
  const FeatureHeadSpec lk = FeatureHeadSpec::from_config(
      Config::parse("kind: lk_encoder\nmodel: runs/m\npretrained: false\ntrainable: true"));
  EXPECT_EQ(lk.model, "runs/m");
  EXPECT_FALSE(lk.pretrained);
  EXPECT_TRUE(lk.trainable);

  EXPECT_THROW(FeatureHeadSpec::from_config(Config::parse("kind: transformer")), Error);
  EXPECT_THROW(FeatureHeadSpec::from_config(Config::parse("kind: lk_full")), Error);  // no model
  EXPECT_THROW(FeatureHeadSpec::from_config(Config::parse("kind: mlp")), Error);      // no inputs
  EXPECT_THROW(FeatureHeadSpec::from_config(Config::parse("kind: mlp\ninputs: 6\nmodel: m")),
               Error);
  EXPECT_THROW(
      FeatureHeadSpec::from_config(Config::parse("kind: lk_encoder\nmodel: m\nlayers: [4]")),
      Error);
  EXPECT_THROW(FeatureHeadSpec::from_config(Config::parse("kind: mlp\ninputs: 6\nlayers: [0]")),
               Error);
}

TEST(FeatureHeads, AnMlpHeadIsMadeWrittenAndReadBack) {
  FeatureHeadSpec spec;
  spec.kind = "mlp";
  spec.inputs = 12;
  spec.layers = {16, 5};
  Rng rng(4);
  const CreatedHead created = create_feature_head(spec, rng);
  EXPECT_EQ(created.head->input_size(), 12);
  EXPECT_EQ(created.head->output_size(), 5);
  EXPECT_EQ(created.parameters.size(), 13 * 16 + 17 * 5);

  ArchiveWriter writer("policy");
  write_feature_head(writer, "head", *created.head);
  const ArchiveReader reader = ArchiveReader::from_bytes(writer.serialize(), "policy", "test");
  const auto read = read_feature_head(reader, "head");
  auto first = created.head->make_tape(), second = read->make_tape();
  const Eigen::MatrixXf inputs = Eigen::MatrixXf::Random(12, 3);
  created.head->forward(created.parameters, inputs, false, *first);
  read->forward(created.parameters, inputs, false, *second);
  EXPECT_TRUE(first->output == second->output);
}

TEST(FeatureHeads, AKindThisProgramDoesNotHaveIsAClearError) {
  FeatureHeadSpec spec;
  spec.kind = "lk_encoder";
  spec.model = "runs/m";
  Rng rng(1);
  // The test program does not link the dynamics layer's heads.
  const std::string message = testing::error_message([&] { create_feature_head(spec, rng); });
  EXPECT_NE(message.find("needs the dynamics layer"), std::string::npos) << message;
}

}  // namespace
}  // namespace tendril::nn
