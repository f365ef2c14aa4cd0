#include "tendril/sweeps/sweep_share.hpp"

#include <cstdlib>

#include "tendril/core/error.hpp"

namespace tendril::sweeps {

namespace {

// A whole number in [min, max] from an environment variable's text, or Error naming it.
int whole_number(const char* name, const char* text, int min, int max) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  require(*text != 0 && *end == 0 && value >= min && value <= max,
          std::string("expected a whole number in [") + std::to_string(min) + ", " +
              std::to_string(max) + "], got '" + text + "'",
          name);
  return static_cast<int>(value);
}

}  // namespace

SweepShare SweepShare::from_environment() {
  static const char* const pairs[][2] = {{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                                         {"PMI_RANK", "PMI_SIZE"},
                                         {"SLURM_PROCID", "SLURM_NTASKS"}};
  for (const auto& [rank_name, size_name] : pairs) {
    const char* rank = std::getenv(rank_name);
    const char* size = std::getenv(size_name);
    if (rank == nullptr || size == nullptr) continue;
    SweepShare share;
    share.ranks = whole_number(size_name, size, 1, 1 << 20);
    share.rank = whole_number(rank_name, rank, 0, share.ranks - 1);
    share.source = std::string(rank_name) + "/" + size_name;
    return share;
  }
  return SweepShare{};
}

std::vector<int> SweepShare::runs(int run_count) const {
  require(ranks >= 1 && rank >= 0 && rank < ranks,
          "rank " + std::to_string(rank) + " of " + std::to_string(ranks) + " does not exist",
          source.empty() ? "--rank/--ranks" : source);
  std::vector<int> indices;
  for (int i = rank; i < run_count; i += ranks) indices.push_back(i);
  return indices;
}

}  // namespace tendril::sweeps
