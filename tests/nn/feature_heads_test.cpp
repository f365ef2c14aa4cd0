// Policy-head specs, the MLP head, and the kinds a program knows.
#include "tendril/nn/feature_heads.hpp"

#include <gtest/gtest.h>

#include "support/error_message.hpp"
#include "tendril/core/dynamics_layer.hpp"
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

// A program that loads the dynamics layer on demand (the command line) loads it at the first
// lookup of a learned-model kind, and only then; the kinds it installs are the ones found. An
// MLP head stands in for the learned-model head here.
TEST(FeatureHeads, ALearnedModelKindLoadsTheDynamicsLayerOnDemand) {
  int loads = 0;
  set_dynamics_layer_loader([&] {
    ++loads;
    FeatureHeadKind stand_in;
    stand_in.create = [](const FeatureHeadSpec&, Rng& rng) {
      FeatureHeadSpec mlp;
      mlp.kind = "mlp";
      mlp.inputs = 4;
      mlp.layers = {3};
      return MlpHead::create(mlp, rng);
    };
    stand_in.read = &MlpHead::read;
    install_feature_head_kind("lk_full", stand_in);
  });
  FeatureHeadSpec mlp;
  mlp.kind = "mlp";
  mlp.inputs = 2;
  mlp.layers = {2};
  Rng rng(3);
  create_feature_head(mlp, rng);
  EXPECT_EQ(loads, 0) << "an MLP head needs no dynamics layer";

  FeatureHeadSpec learned;
  learned.kind = "lk_full";
  learned.model = "runs/m";
  EXPECT_EQ(create_feature_head(learned, rng).head->output_size(), 3);
  EXPECT_EQ(create_feature_head(learned, rng).parameters.size(), 5 * 3);
  EXPECT_EQ(loads, 1);
  set_dynamics_layer_loader({});
}

}  // namespace
}  // namespace tendril::nn
