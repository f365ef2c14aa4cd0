#include "tendril/core/config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "support/error_message.hpp"
#include "tendril/core/error.hpp"

namespace tendril {
namespace {

using testing::error_message;

TEST(Config, ReadsTypedValuesAndNestedMappings) {
  const Config config = Config::parse(R"(
seed: 3
env:
  id: Elastica/Tracking3D-v0
  params: {n_elements: 20, dt: 2.0e-4, gravity: [0, 0, -9.81]}
use_contact: true
steps: 1e6
)");
  EXPECT_EQ(config.get<int>("seed"), 3);
  EXPECT_EQ(config.child("env").get<std::string>("id"), "Elastica/Tracking3D-v0");
  const Config params = config.child("env").child("params");
  EXPECT_EQ(params.get<int64_t>("n_elements"), 20);
  EXPECT_DOUBLE_EQ(params.get<double>("dt"), 2.0e-4);
  EXPECT_EQ(params.get<std::vector<double>>("gravity"), (std::vector<double>{0, 0, -9.81}));
  EXPECT_TRUE(config.get<bool>("use_contact"));
  EXPECT_EQ(config.get<int64_t>("steps"), 1000000);
  EXPECT_EQ(config.get_or<double>("missing", 1.5), 1.5);
  EXPECT_EQ(params.path(), "env.params");
  EXPECT_NO_THROW(config.reject_unknown());
}

TEST(Config, UnknownKeyIsNamedWithItsPath) {
  const Config config = Config::parse("env:\n  id: x\n  n_elemnts: 20\n", "exp.yaml");
  EXPECT_EQ(config.child("env").get<std::string>("id"), "x");
  EXPECT_EQ(error_message([&] { config.reject_unknown(); }),
            "exp.yaml: unknown key 'env.n_elemnts'");
}

TEST(Config, WrongTypeNamesKeyAndExpectedType) {
  const Config config = Config::parse("algo:\n  batch_size: many\n  lr: [1]\n", "exp.yaml");
  EXPECT_EQ(error_message([&] { config.child("algo").get<int>("batch_size"); }),
            "exp.yaml: algo.batch_size: expected an integer, got 'many'");
  EXPECT_EQ(error_message([&] { config.child("algo").get<double>("lr"); }),
            "exp.yaml: algo.lr: expected a number, got a sequence");
  EXPECT_EQ(error_message([&] { config.child("algo").get<double>("gamma"); }),
            "exp.yaml: missing required key 'algo.gamma'");
  EXPECT_EQ(error_message([&] { config.get<double>("algo"); }),
            "exp.yaml: algo: expected a number, got a mapping");
}

TEST(Config, MalformedYamlReportsLine) {
  const std::string message = error_message([] { Config::parse("a: 1\nb: [1, 2\n", "bad.yaml"); });
  EXPECT_NE(message.find("bad.yaml: malformed YAML at line"), std::string::npos) << message;
  EXPECT_EQ(error_message([] { Config::parse("- 1\n- 2\n", "list.yaml"); }),
            "list.yaml: the document must be a mapping, got a sequence");
}

TEST(Config, NestingDeeperThanTheParserTakesIsNamedAsSuch) {
  const std::string deep = "a: " + std::string(5000, '[') + std::string(5000, ']') + "\n";
  const std::string message = error_message([&] { Config::parse(deep, "deep.yaml"); });
  EXPECT_EQ(message.rfind("deep.yaml: lists or mappings nested too deeply", 0), 0u) << message;
}

// Found by tests/fuzz/config_fuzz: in a flow mapping, `0,[ 1, 2, 3, 4]` makes a sequence a key,
// which reading the keys used to turn into a yaml-cpp exception instead of an Error.
TEST(Config, KeysThatAreNotNamesAreRefused) {
  const std::string crash = "gridd:\n  - {key: seed, values: 0,[ 1, 2, 3, 4]}\noutput: runs/s\n";
  EXPECT_EQ(error_message([&] { Config::parse(crash, "sweep.yaml"); }),
            "sweep.yaml: a key must be a name, got a sequence at line 2, column 27");
  EXPECT_EQ(error_message([] { Config::parse("a:\n  {x: 1}: 2\n", "map.yaml"); }),
            "map.yaml: a key must be a name, got a mapping at line 2, column 3");
  Config config = Config::parse("a: 1\n", "exp.yaml");
  EXPECT_EQ(error_message([&] { config.set("b", "{[1, 2]: x}"); }),
            "--set b: a key must be a name, got a sequence at line 1, column 2");
  EXPECT_EQ(config.keys(), (std::vector<std::string>{"a"}));
}

TEST(Config, SetOverridesAndCreatesKeys) {
  Config config = Config::parse("algo:\n  batch_size: 64\n");
  config.set("algo.batch_size", "16000");
  config.set("env.params.n_elements", "50");
  config.set("algo.net", "[64, 64]");
  EXPECT_EQ(config.child("algo").get<int>("batch_size"), 16000);
  EXPECT_EQ(config.child("env").child("params").get<int>("n_elements"), 50);
  EXPECT_EQ(config.child("algo").get<std::vector<int64_t>>("net"), (std::vector<int64_t>{64, 64}));
  EXPECT_THROW(config.set("algo.batch_size.x", "1"), Error);
}

TEST(Config, DumpRoundTrips) {
  const Config config = Config::parse("a: 1\nb:\n  c: [1.5, 2]\n  d: text\n");
  const Config again = Config::parse(config.dump());
  EXPECT_EQ(again.get<int>("a"), 1);
  EXPECT_EQ(again.child("b").get<std::vector<double>>("c"), (std::vector<double>{1.5, 2}));
  EXPECT_EQ(again.child("b").get<std::string>("d"), "text");
}

TEST(Config, ResolvedEntriesListGivenValuesAndTheDefaultsReadsUsed) {
  const Config config = Config::parse("a: 1\nb:\n  c: [1.5, 2]\n");
  const Config params = config.child("b");
  EXPECT_EQ(params.get_or<std::vector<double>>("c", {}), (std::vector<double>{1.5, 2}));
  EXPECT_EQ(params.get_or<double>("d", 0.25), 0.25);
  EXPECT_EQ(params.child("e").get_or<bool>("f", true), true);
  EXPECT_EQ(params.get_or<double>("g", 0.15), 0.15);  // 15 digits: 0.15, not 0.14999999999999999
  EXPECT_FALSE(params.has("never_read"));             // a test of presence records no default
  using Entries = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(params.resolved_entries(),
            (Entries{{"c", "[1.5, 2]"}, {"d", "0.25"}, {"e.f", "true"}, {"g", "0.15"}}));
  EXPECT_EQ(
      config.resolved_entries(),
      (Entries{
          {"a", "1"}, {"b.c", "[1.5, 2]"}, {"b.d", "0.25"}, {"b.e.f", "true"}, {"b.g", "0.15"}}));
}

TEST(Config, LoadFileReportsMissingFile) {
  EXPECT_EQ(error_message([] { Config::load_file("/nonexistent/exp.yaml"); }),
            "/nonexistent/exp.yaml: cannot open config file");
  const auto file = std::filesystem::temp_directory_path() /
                    ("tendril_config_test_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(file) << "n: 7\n";
  EXPECT_EQ(Config::load_file(file).get<int>("n"), 7);
  std::filesystem::remove(file);
}

TEST(Config, NonFiniteNumbersAreRejected) {
  const Config config = Config::parse("x: .nan\ny: .inf\n");
  EXPECT_THROW(config.get<double>("x"), Error);
  EXPECT_THROW(config.get<double>("y"), Error);
}

}  // namespace
}  // namespace tendril
