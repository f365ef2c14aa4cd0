#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::hardware {

// The link itself failed (port gone, cable out, socket error): what a bridge answers by
// reconnecting, unlike a bad frame, which it only counts.
class LinkDown : public Error {
 public:
  using Error::Error;
};

// A byte link to a robot: a serial port (SerialTransport) or UDP datagrams (UdpTransport).
class Transport {
 public:
  virtual ~Transport() = default;
  // Sends the bytes whole; LinkDown if the link failed.
  virtual void send(std::span<const uint8_t> bytes) = 0;
  // Appends to `out` what arrives within `timeout` (returning as soon as anything arrived);
  // LinkDown if the link failed.
  virtual void receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) = 0;
  // Closes and opens the link again; LinkDown if it cannot.
  virtual void reopen() = 0;
  virtual std::string name() const = 0;
};

}  // namespace tendril::hardware
