#pragma once

#include <netinet/in.h>

#include <string>

#include "tendril/hardware/transport.hpp"

namespace tendril::hardware {

// UDP datagrams, one frame each: bound to `local_port` (0: any free port) on `bind_host`, and
// sending to `peer_host:peer_port` — or, with peer_port 0, to whoever sent the last datagram
// (a device answering its host). Sending before any peer is known is a LinkDown.
class UdpTransport final : public Transport {
 public:
  UdpTransport(std::string bind_host, int local_port, std::string peer_host, int peer_port);
  ~UdpTransport() override;
  UdpTransport(const UdpTransport&) = delete;
  UdpTransport& operator=(const UdpTransport&) = delete;

  void send(std::span<const uint8_t> bytes) override;
  void receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) override;
  void reopen() override;
  std::string name() const override;
  int local_port() const { return local_port_; }
  bool has_peer() const { return has_peer_; }

 private:
  void open_socket();

  std::string bind_host_, peer_host_;
  int local_port_, peer_port_;
  int fd_ = -1;
  sockaddr_in peer_{};
  bool has_peer_ = false;
};

}  // namespace tendril::hardware
