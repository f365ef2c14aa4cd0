// The exported C header compiled by the host's C compiler (as C89, warnings as errors) computes
// the policy's deterministic actions, for every kind of policy.
#include "tendril/rl/export/c_header.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "rl/export/sample_policies.hpp"
#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"

namespace tendril::rl {
namespace {

namespace fs = std::filesystem;
using testing::sample_observations;
using testing::sample_policies;

class CHeader : public testing::ScratchDirectoryTest {
 protected:
  CHeader() : ScratchDirectoryTest("c_header_test") {}
};

// Runs `command` through the shell; its standard output, or a failure naming the command.
std::string run(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  if (status != 0) throw std::runtime_error(command + " failed:\n" + output);
  return output;
}

// A program that reads observations as hexadecimal floats (exact) from its standard input and
// prints each action the same way.
std::string driver(const std::string& name) {
  std::string macro = name;
  for (char& c : macro) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  std::ostringstream out;
  out << "#include <stdio.h>\n#include \"" << name << ".h\"\n"
      << "int main(void) {\n"
      << "  float observation[" << macro << "_OBSERVATION_SIZE], action[" << macro
      << "_ACTION_SIZE];\n"
      << "  int i;\n"
      << "  for (;;) {\n"
      << "    for (i = 0; i < " << macro << "_OBSERVATION_SIZE; ++i)\n"
      << "      if (scanf(\"%a\", &observation[i]) != 1) return 0;\n"
      << "    " << name << "_act(observation, action);\n"
      << "    for (i = 0; i < " << macro
      << "_ACTION_SIZE; ++i) printf(\"%a \", (double)action[i]);\n"
      << "    printf(\"\\n\");\n"
      << "  }\n}\n";
  return out.str();
}

// 300 observations per policy, through the compiled header: continuous actions within 2e-5 of
// the action's range of Policy::act's (float rounding: the header sums each product in order
// and uses the C library's tanh, Policy::act uses BLAS and Eigen's vectorised tanh); discrete
// actions the same index unless the two best outputs lie within 1e-4 of each other.
TEST_F(CHeader, CompiledHeaderActsAsThePolicy) {
  double largest = 0.0;  // of |header − tendril| / range, printed for the record
  for (const auto& [name, policy] : sample_policies()) {
    const fs::path header = directory_ / (name + ".h");
    write_c_header(*policy, header, name, "sample policy " + name);
    std::ofstream(directory_ / (name + "_main.c")) << driver(name);
    const fs::path program = directory_ / name;
    // The header alone as strict C89; the driver (C99 for %a) with it.
    run(std::string(TENDRIL_HOST_CC) + " -std=c89 -pedantic -Wall -Wextra -Werror -fsyntax-only " +
        "-x c " + header.string());
    run(std::string(TENDRIL_HOST_CC) + " -std=c99 -pedantic -Wall -Wextra -Werror -O2 -o " +
        program.string() + " " + (directory_ / (name + "_main.c")).string() + " -lm");

    const int size = policy->observation_space().size();
    const Eigen::MatrixXf observations = sample_observations(300, size, 5);
    std::ostringstream input;
    for (Eigen::Index i = 0; i < observations.rows(); ++i) {
      for (int j = 0; j < size; ++j) {
        char text[64];
        std::snprintf(text, sizeof text, "%a ", static_cast<double>(observations(i, j)));
        input << text;
      }
    }
    std::ofstream(directory_ / "observations.txt") << input.str();
    std::istringstream output(
        run(program.string() + " < " + (directory_ / "observations.txt").string()));

    Rng rng(0);
    envs::BatchMatrix actions;
    policy->act(observations, true, rng, actions);
    const Space& space = policy->action_space();
    for (Eigen::Index i = 0; i < observations.rows(); ++i) {
      for (Eigen::Index j = 0; j < actions.cols(); ++j) {
        std::string word;
        ASSERT_TRUE(output >> word) << name << ": output ends at observation " << i;
        const float value = std::strtof(word.c_str(), nullptr);
        if (space.is_discrete()) {
          EXPECT_EQ(value, actions(i, j)) << name << " observation " << i;
        } else {
          const float range = space.high()[j] - space.low()[j];
          EXPECT_NEAR(value, actions(i, j), 2e-5f * range) << name << " observation " << i;
          largest = std::max(largest, std::abs(static_cast<double>(value - actions(i, j))) / range);
        }
      }
    }
    std::string extra;
    EXPECT_FALSE(output >> extra) << name << ": more actions than observations";
  }
  std::printf("largest difference from Policy::act: %.2e of the action's range\n", largest);
}

TEST_F(CHeader, RefusesANameThatIsNotACIdentifier) {
  const auto policies = sample_policies();
  for (const std::string name : {"2fast", "my-policy", ""}) {
    EXPECT_NE(testing::error_message([&] {
                write_c_header(*policies.front().policy, directory_ / "x.h", name, "");
              }).find("not a C identifier"),
              std::string::npos)
        << name;
  }
  EXPECT_FALSE(fs::exists(directory_ / "x.h"));
}

TEST_F(CHeader, NeverOverwritesAFile) {
  const auto policies = sample_policies();
  std::ofstream(directory_ / "kept.h") << "kept";
  EXPECT_NE(testing::error_message([&] {
              write_c_header(*policies.front().policy, directory_ / "kept.h", "p", "");
            }).find("exists"),
            std::string::npos);
  std::ifstream in(directory_ / "kept.h");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "kept");
}

}  // namespace
}  // namespace tendril::rl
