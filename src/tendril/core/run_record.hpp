#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "tendril/core/config.hpp"

namespace tendril {

// What every run directory holds, whoever writes it (training, safety co-training, model fits,
// adaptations): config.yaml, the fully resolved configuration ending with a comment line that
// holds the CRC-32C of the lines above, so that a damaged or edited copy is refused before
// anything is computed from it; machine.yaml, the build and CPU that made the run (what decides
// whether a rerun is bit-identical, docs/reproducibility.md); and run.lock while one process
// writes it (core/run_lock).
inline constexpr std::string_view kRunConfigFile = "config.yaml";
inline constexpr std::string_view kMachineFile = "machine.yaml";

// `text` followed by its checksum line.
std::string with_checksum(const std::string& text);

// Writes config.yaml (`resolved_config`, checksummed) and machine.yaml into the existing
// `directory`, each atomically.
void write_run_record(const std::filesystem::path& directory, const std::string& resolved_config);

// config.yaml's text above its checksum line. Raises Error naming the file when the line does
// not match, or when there is no config.yaml ("not a run directory"). A file without the line
// (written before runs carried one) is read as it is.
std::string read_run_config_text(const std::filesystem::path& directory);

// config.yaml as a Config, checked as read_run_config_text checks it.
Config load_run_config(const std::filesystem::path& directory);

}  // namespace tendril
