#include "tendril/hardware/framed_link.hpp"

namespace tendril::hardware {

FramedLink::FramedLink(std::unique_ptr<Transport> transport) : transport_(std::move(transport)) {
  require(transport_ != nullptr, "needs a transport", "FramedLink");
}

uint16_t FramedLink::send(MessageType type, const std::vector<uint8_t>& payload) {
  Frame frame;
  frame.type = static_cast<uint8_t>(type);
  frame.seq = next_seq_++;
  if (next_seq_ == kNoSeq) next_seq_ = 0;  // kNoSeq means "none" on the wire
  frame.stamp_ms = static_cast<uint32_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - epoch_).count());
  frame.payload = payload;
  transport_->send(frame.encode());
  ++frames_sent_;
  return frame.seq;
}

std::optional<Frame> FramedLink::next(Clock::time_point deadline) {
  for (;;) {
    if (auto frame = parser_.next()) return frame;
    const auto now = Clock::now();
    if (now >= deadline) return std::nullopt;
    buffer_.clear();
    transport_->receive(buffer_,
                        std::chrono::duration_cast<std::chrono::microseconds>(deadline - now));
    parser_.push(buffer_);
  }
}

void FramedLink::reopen() {
  parser_.clear();
  while (parser_.next()) {
  }
  transport_->reopen();
}

double FramedLink::ping(double timeout_s, const std::function<void(const Frame&)>& other,
                        const std::string& who) {
  const auto sent = Clock::now();
  const uint16_t seq = send(MessageType::kPing);
  const auto deadline =
      sent + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  while (auto frame = next(deadline)) {
    if (frame->type == static_cast<uint8_t>(MessageType::kPong) &&
        Pong::decode(frame->payload).ping_seq == seq) {
      return std::chrono::duration<double>(Clock::now() - sent).count();
    }
    other(*frame);
  }
  throw LinkDown("no PONG within " + std::to_string(timeout_s) + " s", who);
}

}  // namespace tendril::hardware
