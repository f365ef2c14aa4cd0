#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tendril/core/archive.hpp"
#include "tendril/core/config.hpp"
#include "tendril/core/rng.hpp"
#include "tendril/nn/feature_head.hpp"

namespace tendril::nn {

// What an experiment says about a policy head (`algo.head`, seed 001 §5.1.2, Fig. 5.2):
//
//   head:
//     kind: lk_encoder        # mlp | lk_encoder | lk_full
//     trainable: false        # frozen: the head's weights never change
//     model: runs/sma_stiff_seq2seq   # lk_*: the learned model (model file or fit run)
//     pretrained: true        # lk_*: the model's weights; false: a fresh initialisation
//     layers: [1024, 1024, 512]       # mlp: hidden sizes, then the output size
//     inputs: 600             # mlp: how many values it reads from the end of the observation
struct FeatureHeadSpec {
  std::string kind;
  bool trainable = false;
  std::string model;
  bool pretrained = true;
  std::vector<int64_t> layers{1024, 1024, 512};
  int64_t inputs = 0;

  // Reads the mapping; raises Error naming the key on an unknown kind, a missing model, a key of
  // another kind, or a bad size.
  static FeatureHeadSpec from_config(const Config& head);
  bool uses_model() const { return kind == "lk_encoder" || kind == "lk_full"; }
};

// A new head and its first weights.
struct CreatedHead {
  std::shared_ptr<const FeatureHead> head;
  Eigen::VectorXf parameters;
};

// How one kind of head is made from a spec (weights drawn from `rng` unless pretrained) and
// read back from a policy file.
struct FeatureHeadKind {
  std::function<CreatedHead(const FeatureHeadSpec& spec, Rng& rng)> create;
  std::function<std::shared_ptr<const FeatureHead>(const ArchiveReader& reader,
                                                   const std::string& prefix)>
      read;
};

// Heads are implemented in more than one layer (the MLP head here, the learned-model heads in
// dynamics/), so a program that links the upper layer installs their kinds at start-up
// (dynamics::install_policy_heads), as it installs the model loader of learned-model envs; a
// program that loads the layer on demand (core/dynamics_layer.hpp) loads it at the first lookup
// of a learned-model kind. "mlp" is always known. Installing a kind again replaces it.
void install_feature_head_kind(const std::string& kind, FeatureHeadKind builder);

// Raises Error naming the kind when it is unknown or not installed in this program.
CreatedHead create_feature_head(const FeatureHeadSpec& spec, Rng& rng);
// The head written under `prefix` (its kind at `<prefix>_kind`) by FeatureHead::write.
std::shared_ptr<const FeatureHead> read_feature_head(const ArchiveReader& reader,
                                                     const std::string& prefix);
void write_feature_head(ArchiveWriter& writer, const std::string& prefix, const FeatureHead& head);

}  // namespace tendril::nn
