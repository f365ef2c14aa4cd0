#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>

#include "tendril/core/rng.hpp"
#include "tendril/hardware/frame_parser.hpp"
#include "tendril/hardware/transport.hpp"

namespace tendril::hardware {

// Faults to inject into a link, adjustable while it runs (tests, `tendril robot check`):
// delivery latency and jitter of received frames, dropped and corrupted frames both ways, and
// a pulled cable (`disconnected`: every call fails; a reopen succeeds only once
// `failed_reopens` attempts have failed). Counters say what was injected.
struct LinkFaults {
  double latency_s = 0.0;  // added to every received frame
  double jitter_s = 0.0;   // plus uniform [0, jitter_s); order is kept
  double drop_rate = 0.0;  // each received frame
  double corrupt_rate = 0.0;
  double send_drop_rate = 0.0;
  int drop_next_received = 0;  // deterministic: the next N received frames
  int corrupt_next_received = 0;
  int drop_next_sent = 0;
  int corrupt_next_sent = 0;
  bool disconnected = false;
  int failed_reopens = 0;

  int dropped_received = 0, corrupted_received = 0, dropped_sent = 0, corrupted_sent = 0,
      refused_reopens = 0;
  std::mutex mutex;  // tests change faults from another thread
};

// A Transport with LinkFaults between the bridge and the real link. It works on whole frames
// (a FrameParser splits what arrives) so that a fault hits one frame, as line noise would.
class FaultyTransport final : public Transport {
 public:
  FaultyTransport(std::unique_ptr<Transport> inner, std::shared_ptr<LinkFaults> faults,
                  uint64_t seed = 1);

  void send(std::span<const uint8_t> bytes) override;
  void receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) override;
  void reopen() override;
  std::string name() const override { return inner_->name() + " (faults injected)"; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Pending {
    Clock::time_point due;
    std::vector<uint8_t> bytes;
  };
  bool deliver_due(std::vector<uint8_t>& out);

  std::unique_ptr<Transport> inner_;
  std::shared_ptr<LinkFaults> faults_;
  Rng rng_;
  FrameParser parser_;
  std::deque<Pending> pending_;
};

}  // namespace tendril::hardware
