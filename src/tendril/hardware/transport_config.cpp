#include "tendril/hardware/transport_config.hpp"

#include <cmath>

#include "tendril/hardware/link_faults.hpp"
#include "tendril/hardware/serial_transport.hpp"
#include "tendril/hardware/udp_transport.hpp"

namespace tendril::hardware {

std::unique_ptr<Transport> open_transport(const Config& bridge) {
  std::unique_ptr<Transport> link;
  if (bridge.has("port")) {
    link = std::make_unique<SerialTransport>(bridge.get<std::string>("port"),
                                             bridge.get_or<int>("baud", 115200));
  } else if (bridge.has("udp_port")) {
    link = std::make_unique<UdpTransport>("127.0.0.1", bridge.get_or<int>("local_port", 0),
                                          bridge.get_or<std::string>("udp_host", "127.0.0.1"),
                                          bridge.get<int>("udp_port"));
  } else {
    throw Error("the bridge needs `port` (a serial device) or `udp_port` (a UDP robot)",
                bridge.where("port"));
  }
  return with_faults(std::move(link), bridge.child("faults"));
}

std::unique_ptr<Transport> with_faults(std::unique_ptr<Transport> link, const Config& f) {
  if (f.keys().empty()) return link;
  auto faults = std::make_shared<LinkFaults>();
  faults->latency_s = f.get_or<double>("latency_s", 0.0);
  faults->jitter_s = f.get_or<double>("jitter_s", 0.0);
  faults->drop_rate = f.get_or<double>("drop_rate", 0.0);
  faults->corrupt_rate = f.get_or<double>("corrupt_rate", 0.0);
  faults->send_drop_rate = f.get_or<double>("send_drop_rate", 0.0);
  for (const char* key : {"latency_s", "jitter_s"}) {
    const double value = f.get<double>(key);
    require(std::isfinite(value) && value >= 0.0, "must be >= 0", f.where(key));
  }
  for (const char* key : {"drop_rate", "corrupt_rate", "send_drop_rate"}) {
    const double value = f.get<double>(key);
    require(value >= 0.0 && value <= 1.0, "must be a probability in [0, 1]", f.where(key));
  }
  return std::make_unique<FaultyTransport>(std::move(link), std::move(faults),
                                           f.get_or<uint64_t>("seed", 1));
}

}  // namespace tendril::hardware
