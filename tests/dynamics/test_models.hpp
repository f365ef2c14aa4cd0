#pragma once

#include <memory>
#include <string>

#include "tendril/dynamics/model.hpp"

namespace tendril::testing {

// A small model of `kind` for 4 states and 2 inputs (seed 001's layout), with a normaliser that
// is not the identity so that tests see it applied.
inline dynamics::ModelDescription small_description(dynamics::Architecture kind, int window = 5,
                                                    int hidden = 8, int layers = 2) {
  dynamics::ModelDescription d;
  d.architecture.kind = kind;
  d.architecture.state_dim = 4;
  d.architecture.input_dim = 2;
  d.architecture.hidden_size = hidden;
  d.architecture.layers = kind == dynamics::Architecture::kSoftsignLstm ? 1 : layers;
  d.architecture.heads = 2;
  d.architecture.window = kind == dynamics::Architecture::kSoftsignLstm ? 3 : window;
  d.architecture.dropout = kind == dynamics::Architecture::kSoftsignLstm ? 0.3 : 0.0;
  d.architecture.normalization = dynamics::Normalization::kStandard;
  d.normalizer.offset = Eigen::VectorXd::LinSpaced(6, -1.0, 1.5);
  d.normalizer.scale = Eigen::VectorXd::LinSpaced(6, 2.0, 20.0);
  d.state_names = {"theta_x", "theta_y", "omega_x", "omega_y"};
  d.input_names = {"u_x", "u_y"};
  d.sample_period = 0.07;
  return d;
}

inline const dynamics::Architecture kAllArchitectures[] = {
    dynamics::Architecture::kRnn, dynamics::Architecture::kLstm, dynamics::Architecture::kSeq2Seq,
    dynamics::Architecture::kSeq2SeqAttention, dynamics::Architecture::kSoftsignLstm};

}  // namespace tendril::testing
