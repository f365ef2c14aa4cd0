// A limb-sized policy's C header on the SMA limb's microcontroller (seed 001: an Arduino Uno,
// ATmega328P: 32 KiB flash, 2 KiB RAM, 16 MHz): compiled with avr-gcc, it fits, and run on
// simavr's simulated ATmega328P it computes tendril's actions, in a measured time.
//
// The policy: SAC's actor for SmaLimb/LearnedReach-v0 without a history (14 inputs: state
// θx, θy, θ̇x, θ̇y; previous throttles; goal; the four power proxies), one hidden layer of 256
// ReLU units as the seed's configs (configs/sma_limb/learned_reach_sac_no_head.yaml), two
// throttles in [−10, 10]; with observation normalization.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

#include "rl/export/sample_policies.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/rl/export/c_header.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;

constexpr int kObservations = 14;
constexpr int kSamples = 6;
constexpr long kFlashBytes = 32768 - 512;  // the Uno's bootloader (optiboot) keeps 512 bytes
constexpr long kRamBytes = 2048;

class AvrHeader : public testing::ScratchDirectoryTest {
 protected:
  AvrHeader() : ScratchDirectoryTest("c_header_avr_test") {}
};

std::string run(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  if (::pclose(pipe) != 0) {
    throw std::runtime_error(command + " failed (scripts/setup installs gcc-avr, avr-libc and " +
                             "simavr):\n" + output);
  }
  return output;
}

std::unique_ptr<Policy> limb_policy() {
  Rng rng(3);
  auto policy = std::make_unique<SquashedGaussianPolicy>(
      Space::box(kObservations, -1e3f, 1e3f), Space::box(2, -10.0f, 10.0f),
      std::vector<int64_t>{256}, nn::Activation::kRelu, false);
  testing::randomize(policy->parameters(), kObservations, 2.0, rng);
  policy->set_observation_normalization(testing::sample_normalization(kObservations, rng));
  return policy;
}

// The firmware: acts on each observation (kept in flash), timing each call with Timer1 (clock
// / 256: 16 µs ticks at 16 MHz), and writes the actions' bit patterns and the ticks in hex to
// simavr's console register; then sleeps with interrupts off, which ends the simulation.
std::string firmware(const Eigen::MatrixXf& observations) {
  std::ostringstream out;
  out << "#include <avr/io.h>\n#include <avr/interrupt.h>\n#include <avr/sleep.h>\n"
      << "#include <string.h>\n#include \"avr_mcu_section.h\"\n"
      << "#include \"limb.h\"\n"
      << "AVR_MCU(16000000, \"atmega328p\");\n"
      << "AVR_MCU_SIMAVR_CONSOLE(&GPIOR0);\n"
      << "static const float observations[" << observations.size() << "] PROGMEM = {";
  for (Eigen::Index i = 0; i < observations.rows(); ++i) {
    for (Eigen::Index j = 0; j < observations.cols(); ++j) {
      char text[40];
      std::snprintf(text, sizeof text, "%.9gf,", static_cast<double>(observations(i, j)));
      out << text;
    }
  }
  out << "};\n"
      << "static void put(char c) { GPIOR0 = c; }\n"
      << "static void hex(unsigned long v) {\n"
      << "  int k; for (k = 28; k >= 0; k -= 4) put(\"0123456789abcdef\"[(v >> k) & 15]);\n"
      << "  put(' ');\n}\n"
      << "int main(void) {\n"
      << "  float observation[LIMB_OBSERVATION_SIZE], action[LIMB_ACTION_SIZE];\n"
      << "  int n, i;\n"
      << "  TCCR1A = 0; TCCR1B = _BV(CS12);\n"
      << "  for (n = 0; n < " << observations.rows() << "; ++n) {\n"
      << "    unsigned int start, ticks;\n"
      << "    for (i = 0; i < LIMB_OBSERVATION_SIZE; ++i)\n"
      << "      observation[i] = pgm_read_float(&observations[n * LIMB_OBSERVATION_SIZE + i]);\n"
      << "    start = TCNT1;\n"
      << "    limb_act(observation, action);\n"
      << "    ticks = TCNT1 - start;\n"
      << "    for (i = 0; i < LIMB_ACTION_SIZE; ++i) {\n"
      << "      unsigned long bits; memcpy(&bits, &action[i], 4); hex(bits);\n"
      << "    }\n"
      << "    hex(ticks); put('\\r');\n"  // simavr prints the console's line at a CR
      << "  }\n"
      << "  cli(); sleep_enable(); sleep_cpu();\n"
      << "  return 0;\n}\n";
  return out.str();
}

long section_bytes(const std::string& sizes, const std::string& section) {
  const std::regex line("(^|\\n)" + section + "\\s+(\\d+)");
  std::smatch match;
  return std::regex_search(sizes, match, line) ? std::stol(match[2]) : 0;
}

// The stack frames of the header's two functions (avr-gcc -fstack-usage writes them to .su
// files in its working directory), in bytes, from the .su files whose names start with `stem`.
long stack_bytes(const fs::path& directory, const std::string& stem) {
  long total = 0;
  const std::regex frame("limb_(act|dense)\\s+(\\d+)");
  for (const auto& entry : fs::directory_iterator(directory)) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".su" || file.rfind(stem, 0) != 0) continue;
    std::ifstream in(entry.path());
    std::string line;
    while (std::getline(in, line)) {
      std::smatch match;
      if (std::regex_search(line, match, frame)) total += std::stol(match[2]);
    }
  }
  return total;
}

// Flash ≤ 32,256 bytes and static RAM + the two functions' stack frames ≤ 2,048 bytes; on the
// simulated chip the actions equal tendril's within 2e-5 of the throttle range (the AVR's float
// is IEEE single precision, its tanh avr-libc's); prints the sizes and the time per action.
TEST_F(AvrHeader, LimbPolicyFitsAnAtmega328pAndActsAsTendril) {
  const std::unique_ptr<Policy> policy = limb_policy();
  write_c_header(*policy, directory_ / "limb.h", "limb", "SAC actor, limb-sized (test)");
  const Eigen::MatrixXf observations = testing::sample_observations(kSamples, kObservations, 9);
  std::ofstream(directory_ / "main.c") << firmware(observations);
  const fs::path elf = directory_ / "limb.elf";
  const std::string in_directory = "cd " + directory_.string() + " && ";
  run(in_directory + TENDRIL_AVR_GCC + " -mmcu=atmega328p -Os -std=c99 -Wall -Wextra -Werror " +
      "-I" + TENDRIL_SIMAVR_INCLUDE + " -o limb.elf main.c -lm " +
      "-Wl,--undefined=_mmcu,--section-start=.mmcu=0x910000");  // simavr's settings section
  // The header alone, for its own size: flash and RAM of a firmware that only calls limb_act.
  std::ofstream(directory_ / "only.c")
      << "#include \"limb.h\"\nvolatile float o[LIMB_OBSERVATION_SIZE], "
         "a[LIMB_ACTION_SIZE];\nint main(void) { float x[LIMB_OBSERVATION_SIZE], "
         "y[LIMB_ACTION_SIZE]; int i; for (i = 0; i < LIMB_OBSERVATION_SIZE; ++i) x[i] = o[i]; "
         "limb_act(x, y); for (i = 0; i < LIMB_ACTION_SIZE; ++i) a[i] = y[i]; return 0; }\n";
  const fs::path only = directory_ / "only.elf";
  run(in_directory + TENDRIL_AVR_GCC + " -mmcu=atmega328p -Os -std=c99 -Wall -Wextra -Werror " +
      "-fstack-usage -o only.elf only.c -lm");
  const std::string sizes = run(std::string(TENDRIL_AVR_SIZE) + " -A " + only.string());
  const long text = section_bytes(sizes, ".text"), data = section_bytes(sizes, ".data"),
             bss = section_bytes(sizes, ".bss");
  const long stack = stack_bytes(directory_, "only");
  const long flash = text + data, ram = data + bss + stack;
  std::printf(
      "ATmega328P, %lld parameters: flash %ld bytes (of %ld), RAM %ld bytes static + %ld "
      "stack (of %ld)\n",
      static_cast<long long>(policy_network(*policy).parameter_count()), flash, kFlashBytes,
      data + bss, stack, kRamBytes);
  EXPECT_GT(text, 4 * policy_network(*policy).parameter_count());  // the weights are in flash
  EXPECT_LE(flash, kFlashBytes);
  EXPECT_GT(stack, 0) << "no stack usage found for limb_act";
  EXPECT_LE(ram, kRamBytes);

  const std::string simulated = run(std::string(TENDRIL_SIMAVR) + " " + elf.string());
  std::istringstream console(simulated);
  Rng rng(0);
  envs::BatchMatrix actions;
  policy->act(observations, true, rng, actions);
  int rows = 0;
  double ticks_total = 0.0;
  std::string line;
  while (std::getline(console, line)) {
    std::smatch match;
    // simavr prefixes the console's lines; the three hex words end the line.
    if (!std::regex_search(line, match,
                           std::regex("([0-9a-f]{8}) ([0-9a-f]{8}) ([0-9a-f]{8}) ?$"))) {
      continue;
    }
    ASSERT_LT(rows, kSamples);
    for (int j = 0; j < 2; ++j) {
      const uint32_t bits = static_cast<uint32_t>(std::stoul(match[j + 1], nullptr, 16));
      float value;
      std::memcpy(&value, &bits, sizeof value);
      EXPECT_NEAR(value, actions(rows, j), 2e-5f * 20.0f) << "observation " << rows;
    }
    ticks_total += static_cast<double>(std::stoul(match[3], nullptr, 16));
    ++rows;
  }
  EXPECT_EQ(rows, kSamples) << "simavr's console did not show every action:\n" << simulated;
  if (rows > 0) {
    std::printf("simulated ATmega328P at 16 MHz: %.1f ms per action\n", ticks_total / rows * 16e-3);
  }
}

}  // namespace
}  // namespace tendril::rl
