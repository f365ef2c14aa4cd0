#include "tendril/envs/wrappers/history_stack.hpp"

#include <string>

namespace tendril::envs {

namespace {

Space stacked_box(const Space& inner, int length) {
  const std::string where = "envs::HistoryStack";
  require(length >= 1, "length must be at least 1, got " + std::to_string(length), where);
  require(inner.is_box(), "needs a Box observation space, got " + inner.describe(), where);
  return Space::box(inner.low().replicate(length, 1), inner.high().replicate(length, 1));
}

}  // namespace

HistoryStack::HistoryStack(std::unique_ptr<Env> inner, int length)
    : Wrapper(std::move(inner)),
      length_(length),
      frame_size_(inner_->observation_space().size()),
      observation_space_(stacked_box(inner_->observation_space(), length)) {}

Observation HistoryStack::reset(std::optional<uint64_t> seed) {
  const Observation first = inner_->reset(seed);
  history_ = first.replicate(length_, 1);
  return history_;
}

Step HistoryStack::step(const Action& action) {
  require(history_.size() == frame_size_ * length_, "step called before reset",
          "envs::HistoryStack");
  Step result = inner_->step(action);
  const int kept = frame_size_ * (length_ - 1);
  // Shift the older frames one slot towards the front; the segments may overlap, hence eval().
  history_.head(kept) = history_.tail(kept).eval();
  history_.tail(frame_size_) = result.observation;
  result.observation = history_;
  return result;
}

void HistoryStack::save_state(SnapshotWriter& out) const {
  out.section("HistoryStack");
  out.put_matrix(history_);
  inner_->save_state(out);
}

void HistoryStack::load_state(SnapshotReader& in) {
  in.section("HistoryStack");
  // Sized for a full history: a wrapper that was never reset may take a saved state.
  Observation history(static_cast<Eigen::Index>(frame_size_) * length_);
  in.get_matrix(history);
  inner_->load_state(in);
  history_ = std::move(history);
}

}  // namespace tendril::envs
