#pragma once

#include <memory>

#include "tendril/core/config.hpp"
#include "tendril/hardware/transport.hpp"

namespace tendril::hardware {

// The link a `bridge:` map names: `port` (a serial device such as /dev/ttyACM0, or an
// emulator's pseudo-terminal) with `baud` (default 115200), or `udp_host` and `udp_port` (the
// robot's address) with an optional `local_port`. An optional `faults` map (latency_s,
// jitter_s, drop_rate, corrupt_rate, send_drop_rate, seed) puts a FaultyTransport in between,
// for rehearsing faults against an emulator. Error naming the key when neither link is given.
std::unique_ptr<Transport> open_transport(const Config& bridge);
// `link` behind the faults of a `faults` map (above); `link` itself for an empty map.
std::unique_ptr<Transport> with_faults(std::unique_ptr<Transport> link, const Config& faults);

}  // namespace tendril::hardware
