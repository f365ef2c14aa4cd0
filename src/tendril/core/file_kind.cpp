#include "tendril/core/file_kind.hpp"

#include <string>

#include "tendril/core/error.hpp"

namespace tendril {

namespace {

struct KindReader {
  std::string_view kind;
  std::string_view reader;
};

constexpr KindReader kReaders[] = {
    {file_kind::kExperiment, "tendril train"},
    {file_kind::kSweep, "tendril sweep run"},
    {file_kind::kModelFit, "tendril model fit"},
    {file_kind::kAdaptation, "tendril adapt"},
    {file_kind::kDataProtocol, "tendril data collect|calibrate|replay|coverage|open-loop|prepare"},
    {file_kind::kCalibration, "a robot's `calibration:` parameter (SmaLimb/Robot-v0)"},
    {file_kind::kSimulation, "tendril simulate"},
};

}  // namespace

void expect_kind(const Config& file, std::string_view expected) {
  const std::string kind = file.get_or<std::string>("kind", std::string(expected));
  if (kind == expected) return;
  for (const KindReader& known : kReaders) {
    if (known.kind == kind) {
      throw Error("says `kind: " + kind + "`, a file for " + std::string(known.reader) +
                      "; this command reads `kind: " + std::string(expected) + "` files",
                  file.where("kind"));
    }
  }
  std::string kinds;
  for (const KindReader& known : kReaders) {
    kinds += (kinds.empty() ? "" : ", ") + std::string(known.kind);
  }
  throw Error("'" + kind + "' is not a kind of file tendril reads (" + kinds + ")",
              file.where("kind"));
}

}  // namespace tendril
