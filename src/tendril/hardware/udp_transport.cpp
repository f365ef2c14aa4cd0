#include "tendril/hardware/udp_transport.hpp"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tendril::hardware {

namespace {

sockaddr_in address_of(const std::string& host, int port, const std::string& where) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  const std::string numeric = host == "localhost" ? "127.0.0.1" : host;
  if (inet_pton(AF_INET, numeric.c_str(), &address.sin_addr) != 1) {
    throw Error("not an IPv4 address: '" + host + "'", where);
  }
  return address;
}

}  // namespace

UdpTransport::UdpTransport(std::string bind_host, int local_port, std::string peer_host,
                           int peer_port)
    : bind_host_(std::move(bind_host)),
      peer_host_(std::move(peer_host)),
      local_port_(local_port),
      peer_port_(peer_port) {
  require(local_port >= 0 && local_port < 65536 && peer_port >= 0 && peer_port < 65536,
          "UDP ports must be in 0–65535", "udp");
  if (peer_port_ > 0) {
    peer_ = address_of(peer_host_, peer_port_, "udp peer");
    has_peer_ = true;
  }
  open_socket();
}

UdpTransport::~UdpTransport() {
  if (fd_ >= 0) ::close(fd_);
}

void UdpTransport::open_socket() {
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0)
    throw LinkDown(std::string("cannot open a UDP socket: ") + std::strerror(errno), name());
  const int yes = 1;
  setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in local = address_of(bind_host_, local_port_, "udp bind");
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    fd_ = -1;
    throw LinkDown("cannot bind UDP port " + std::to_string(local_port_) + ": " + why, name());
  }
  socklen_t length = sizeof local;
  getsockname(fd_, reinterpret_cast<sockaddr*>(&local), &length);
  local_port_ = ntohs(local.sin_port);
}

void UdpTransport::reopen() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  open_socket();
}

std::string UdpTransport::name() const {
  return "udp " + bind_host_ + ":" + std::to_string(local_port_) +
         (peer_port_ > 0 ? " -> " + peer_host_ + ":" + std::to_string(peer_port_) : "");
}

void UdpTransport::send(std::span<const uint8_t> bytes) {
  if (fd_ < 0) throw LinkDown("UDP socket is closed", name());
  if (!has_peer_) throw LinkDown("no peer to send to yet", name());
  const ssize_t n = ::sendto(fd_, bytes.data(), bytes.size(), 0,
                             reinterpret_cast<const sockaddr*>(&peer_), sizeof peer_);
  // A datagram the network refused (ECONNREFUSED: nobody listens yet) is lost like any other.
  if (n < 0 && errno != ECONNREFUSED && errno != EAGAIN) {
    throw LinkDown(std::string("UDP send failed: ") + std::strerror(errno), name());
  }
}

void UdpTransport::receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) {
  if (fd_ < 0) throw LinkDown("UDP socket is closed", name());
  pollfd p{fd_, POLLIN, 0};
  const int ms = static_cast<int>((timeout.count() + 999) / 1000);
  if (::poll(&p, 1, ms) <= 0) return;
  uint8_t buffer[2048];
  sockaddr_in from{};
  socklen_t length = sizeof from;
  const ssize_t n =
      ::recvfrom(fd_, buffer, sizeof buffer, 0, reinterpret_cast<sockaddr*>(&from), &length);
  if (n <= 0) return;
  out.insert(out.end(), buffer, buffer + n);
  if (peer_port_ == 0) {
    peer_ = from;
    has_peer_ = true;
  }
}

}  // namespace tendril::hardware
