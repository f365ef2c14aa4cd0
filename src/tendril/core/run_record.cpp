#include "tendril/core/run_record.hpp"

#include <fstream>
#include <iterator>

#include "tendril/core/atomic_file.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/core/error.hpp"
#include "tendril/core/numerics_mode.hpp"

namespace tendril {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kChecksumLine = "# CRC-32C of the lines above: ";

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  require(in.good(), "cannot be read", file.string());
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::string with_checksum(const std::string& text) {
  return text + std::string(kChecksumLine) + checksum_text(crc32c(text.data(), text.size())) + "\n";
}

void write_run_record(const fs::path& directory, const std::string& resolved_config) {
  write_file_atomically(directory / kRunConfigFile, with_checksum(resolved_config), "config.yaml");
  write_file_atomically(directory / kMachineFile, machine_record(), "machine.yaml");
}

std::string read_run_config_text(const fs::path& directory) {
  const fs::path file = directory / kRunConfigFile;
  require(fs::is_regular_file(file), "not a run directory (no config.yaml)", directory.string());
  const std::string text = file_text(file);
  const std::size_t at = text.rfind(kChecksumLine);
  if (at == std::string::npos || (at != 0 && text[at - 1] != '\n')) return text;
  const std::string above = text.substr(0, at);
  if (with_checksum(above) != text) {
    throw Error(
        "damaged or edited since the run started (its checksum line does not match); what "
        "was computed beside it belongs to the configuration it held",
        file.string());
  }
  return above;
}

Config load_run_config(const fs::path& directory) {
  read_run_config_text(directory);                       // refuses a damaged copy
  return Config::load_file(directory / kRunConfigFile);  // bounded; names the file in errors
}

}  // namespace tendril
