#pragma once

#include <string>

#include "tendril/hardware/transport.hpp"

namespace tendril::hardware {

// A serial port (a USB-serial tty such as /dev/ttyACM0, or a pseudo-terminal) in raw 8N1 mode
// at `baud`. Opening flushes whatever the port held, so a session starts on fresh bytes.
class SerialTransport final : public Transport {
 public:
  SerialTransport(std::string path, int baud);
  ~SerialTransport() override;
  SerialTransport(const SerialTransport&) = delete;
  SerialTransport& operator=(const SerialTransport&) = delete;

  void send(std::span<const uint8_t> bytes) override;
  void receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) override;
  void reopen() override;
  std::string name() const override { return path_; }

 private:
  void open_port();
  void close_port();

  std::string path_;
  int baud_;
  int fd_ = -1;
};

}  // namespace tendril::hardware
