#include "tendril/hardware/serial_transport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tendril::hardware {

namespace {

speed_t speed_of(int baud, const std::string& where) {
  switch (baud) {
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    case 460800:
      return B460800;
    case 921600:
      return B921600;
  }
  throw Error("unsupported baud rate " + std::to_string(baud) +
                  " (9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)",
              where);
}

}  // namespace

SerialTransport::SerialTransport(std::string path, int baud) : path_(std::move(path)), baud_(baud) {
  speed_of(baud_, path_);
  open_port();
}

SerialTransport::~SerialTransport() { close_port(); }

void SerialTransport::open_port() {
  fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0)
    throw LinkDown(std::string("cannot open serial port: ") + std::strerror(errno), path_);
  termios tio{};
  if (tcgetattr(fd_, &tio) != 0) {
    close_port();
    throw LinkDown("not a serial port (tcgetattr failed)", path_);
  }
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~CRTSCTS;
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  cfsetispeed(&tio, speed_of(baud_, path_));
  cfsetospeed(&tio, speed_of(baud_, path_));
  tcsetattr(fd_, TCSANOW, &tio);
  tcflush(fd_, TCIOFLUSH);
}

void SerialTransport::close_port() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SerialTransport::reopen() {
  close_port();
  open_port();
}

void SerialTransport::send(std::span<const uint8_t> bytes) {
  if (fd_ < 0) throw LinkDown("serial port is closed", path_);
  size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + sent, bytes.size() - sent);
    if (n > 0) {
      sent += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, 100) < 0 && errno != EINTR) break;
      if (p.revents & (POLLHUP | POLLERR)) break;
      continue;
    }
    break;
  }
  if (sent < bytes.size()) {
    throw LinkDown(std::string("serial write failed: ") + std::strerror(errno), path_);
  }
}

void SerialTransport::receive(std::vector<uint8_t>& out, std::chrono::microseconds timeout) {
  if (fd_ < 0) throw LinkDown("serial port is closed", path_);
  pollfd p{fd_, POLLIN, 0};
  const int ms = static_cast<int>((timeout.count() + 999) / 1000);
  const int ready = ::poll(&p, 1, ms);
  if (ready < 0) {
    if (errno == EINTR) return;
    throw LinkDown(std::string("serial poll failed: ") + std::strerror(errno), path_);
  }
  if (ready == 0) return;
  uint8_t buffer[512];
  const ssize_t n = ::read(fd_, buffer, sizeof buffer);
  if (n > 0) {
    out.insert(out.end(), buffer, buffer + n);
    return;
  }
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return;
  // 0 bytes after POLLIN, EIO, or a hang-up: the other end is gone.
  throw LinkDown("serial port hung up (the robot or its cable is gone)", path_);
}

}  // namespace tendril::hardware
