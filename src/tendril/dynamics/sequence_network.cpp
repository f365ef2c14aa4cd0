#include "tendril/dynamics/sequence_network.hpp"

#include "tendril/dynamics/recurrent_network.hpp"
#include "tendril/dynamics/seq2seq_network.hpp"
#include "tendril/dynamics/softsign_lstm_network.hpp"

namespace tendril::dynamics {

std::shared_ptr<SequenceNetwork> make_network(const ArchitectureSpec& spec) {
  spec.validate();
  switch (spec.kind) {
    case Architecture::kRnn:
    case Architecture::kLstm:
      return std::make_shared<RecurrentNetwork>(spec);
    case Architecture::kSeq2Seq:
    case Architecture::kSeq2SeqAttention:
      return std::make_shared<Seq2SeqNetwork>(spec);
    case Architecture::kSoftsignLstm:
      return std::make_shared<SoftsignLstmNetwork>(spec);
  }
  return nullptr;
}

}  // namespace tendril::dynamics
