#include "tendril/hardware/link_faults.hpp"

#include <algorithm>

namespace tendril::hardware {

FaultyTransport::FaultyTransport(std::unique_ptr<Transport> inner,
                                 std::shared_ptr<LinkFaults> faults, uint64_t seed)
    : inner_(std::move(inner)), faults_(std::move(faults)), rng_(seed) {
  require(inner_ != nullptr && faults_ != nullptr, "needs a link and its faults",
          "FaultyTransport");
}

void FaultyTransport::send(std::span<const uint8_t> bytes) {
  {
    std::lock_guard lock(faults_->mutex);
    if (faults_->disconnected) throw LinkDown("link disconnected (injected)", name());
    if (faults_->drop_next_sent > 0 ||
        (faults_->send_drop_rate > 0.0 && rng_.uniform() < faults_->send_drop_rate)) {
      if (faults_->drop_next_sent > 0) --faults_->drop_next_sent;
      ++faults_->dropped_sent;
      return;
    }
    if (faults_->corrupt_next_sent > 0 && bytes.size() > 2) {
      --faults_->corrupt_next_sent;
      ++faults_->corrupted_sent;
      std::vector<uint8_t> bad(bytes.begin(), bytes.end());
      bad[bytes.size() - 1] ^= 0x01;  // the checksum's high byte: the robot must drop it
      inner_->send(bad);
      return;
    }
  }
  inner_->send(bytes);
}

bool FaultyTransport::deliver_due(std::vector<uint8_t>& out) {
  const auto now = Clock::now();
  bool any = false;
  while (!pending_.empty() && pending_.front().due <= now) {
    out.insert(out.end(), pending_.front().bytes.begin(), pending_.front().bytes.end());
    pending_.pop_front();
    any = true;
  }
  return any;
}

void FaultyTransport::receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) {
  {
    std::lock_guard lock(faults_->mutex);
    if (faults_->disconnected) throw LinkDown("link disconnected (injected)", name());
  }
  if (deliver_due(out)) return;
  auto wait = timeout;
  if (!pending_.empty()) {
    wait = std::min(wait, std::chrono::duration_cast<std::chrono::microseconds>(
                              pending_.front().due - Clock::now()));
    wait = std::max(wait, std::chrono::microseconds(0));
  }
  std::vector<uint8_t> raw;
  inner_->receive(raw, wait);
  parser_.push(raw);
  while (auto frame = parser_.next()) {
    std::lock_guard lock(faults_->mutex);
    if (faults_->drop_next_received > 0 ||
        (faults_->drop_rate > 0.0 && rng_.uniform() < faults_->drop_rate)) {
      if (faults_->drop_next_received > 0) --faults_->drop_next_received;
      ++faults_->dropped_received;
      continue;
    }
    std::vector<uint8_t> bytes = frame->encode();
    if (faults_->corrupt_next_received > 0 ||
        (faults_->corrupt_rate > 0.0 && rng_.uniform() < faults_->corrupt_rate)) {
      if (faults_->corrupt_next_received > 0) --faults_->corrupt_next_received;
      ++faults_->corrupted_received;
      // One flipped bit past the sync pair: the checksum must catch it.
      const size_t at = 2 + rng_.below(bytes.size() - 2);
      bytes[at] ^= static_cast<uint8_t>(1u << rng_.below(8));
    }
    auto due = Clock::now();
    const double delay = faults_->latency_s + faults_->jitter_s * rng_.uniform();
    due += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(delay));
    if (!pending_.empty()) due = std::max(due, pending_.back().due);  // in order
    pending_.push_back({due, std::move(bytes)});
  }
  deliver_due(out);
}

void FaultyTransport::reopen() {
  {
    std::lock_guard lock(faults_->mutex);
    if (faults_->disconnected) {
      if (faults_->failed_reopens > 0) {
        --faults_->failed_reopens;
        ++faults_->refused_reopens;
        throw LinkDown("link still disconnected (injected)", name());
      }
      faults_->disconnected = false;
    }
  }
  pending_.clear();
  parser_.clear();
  inner_->reopen();
}

}  // namespace tendril::hardware
