// libFuzzer target: the CSV data sets a user's files hold — the SMA limb's recorded data set
// and its prepared form (core/data_table with their schemas), the pneumatic arm's recording
// (envs/pneumatic/pneumatic_dataset) — and the dashboard's reader of a run's progress.csv from
// an offset. Bad input must raise tendril::Error.
#include <cstddef>
#include <cstdint>

#include "fuzz_file.hpp"
#include "tendril/core/error.hpp"
#include "tendril/dashboard/csv_slice.hpp"
#include "tendril/data/limb_data_set.hpp"
#include "tendril/data/prepare.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = tendril::fuzzing::write_file("data.csv", data, size);
  try {
    (void)tendril::data::read_limb_data_set(file);
  } catch (const tendril::Error&) {
  }
  try {
    (void)tendril::data::read_prepared(file);
  } catch (const tendril::Error&) {
  }
  try {
    (void)tendril::envs::pneumatic::read_pneumatic_dataset(file);
  } catch (const tendril::Error&) {
  }
  for (const uint64_t offset : {uint64_t{0}, uint64_t{size / 2}}) {
    try {
      (void)tendril::dashboard::read_csv_slice(file, offset, {.max_bytes = 1000});
    } catch (const tendril::Error&) {
    }
  }
  return 0;
}
