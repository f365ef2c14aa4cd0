#include "tendril/dynamics/model_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/crc32c.hpp"
#include "tendril/dynamics/model.hpp"
#include "test_models.hpp"

namespace tendril::dynamics {
namespace {

using testing::error_message;
using testing::kAllArchitectures;
using testing::small_description;

class ModelFile : public testing::ScratchDirectoryTest {
 protected:
  ModelFile() : ScratchDirectoryTest("model_file") {}

  static std::string read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  static void write(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
  }
  // Re-seals edited bytes with a valid checksum line.
  static std::string reseal(std::string bytes) {
    bytes.erase(bytes.rfind("crc32c "));
    char line[32];
    std::snprintf(line, sizeof line, "crc32c %08x\n", crc32c(bytes.data(), bytes.size()));
    return bytes + line;
  }

  // Random physical windows for a model of the small layout.
  static envs::BatchMatrix windows(int n, int window) {
    return envs::BatchMatrix::Random(n, window * 6) * 50.0f;
  }
};

TEST_F(ModelFile, SaveThenLoadPredictsIdenticallyForEveryArchitecture) {
  for (Architecture kind : kAllArchitectures) {
    SCOPED_TRACE(architecture_name(kind));
    Model model(small_description(kind), 11);
    const auto file = directory_ / (architecture_name(kind) + ".tdm");
    save_model(model, file);
    const std::unique_ptr<Model> loaded = load_model(file);
    EXPECT_EQ(loaded->spec().kind, kind);
    EXPECT_EQ(loaded->window_length(), model.window_length());
    EXPECT_EQ(loaded->sample_period(), 0.07);
    EXPECT_EQ(loaded->description().normalizer.offset, model.description().normalizer.offset);
    EXPECT_EQ(loaded->description().normalizer.scale, model.description().normalizer.scale);
    const envs::BatchMatrix input = windows(5, model.window_length());
    envs::BatchMatrix before, after;
    model.predict(input, before);
    loaded->predict(input, after);
    EXPECT_EQ(before, after);
  }
}

TEST_F(ModelFile, LoadsFromARunDirectory) {
  Model model(small_description(Architecture::kRnn), 2);
  save_model(model, directory_ / kModelFileName);
  EXPECT_EQ(load_model(directory_)->spec().kind, Architecture::kRnn);
}

TEST_F(ModelFile, NeverOverwritesUnlessReplacingItsOwnFile) {
  Model model(small_description(Architecture::kLstm), 2);
  const auto file = directory_ / "model.tdm";
  write(file, "precious");
  EXPECT_NE(error_message([&] { save_model(model, file); }).find("nothing is overwritten"),
            std::string::npos);
  EXPECT_EQ(read(file), "precious");
  save_model(model, file, /*replace=*/true);
  EXPECT_NO_THROW(load_model(file));
}

TEST_F(ModelFile, CorruptTruncatedAndForeignFilesGiveClearErrors) {
  Model model(small_description(Architecture::kSeq2SeqAttention), 2);
  const auto file = directory_ / "good.tdm";
  save_model(model, file);
  const std::string bytes = read(file);

  const auto flipped = directory_ / "flipped.tdm";
  std::string corrupt = bytes;
  corrupt[corrupt.size() / 2] ^= 0x10;  // inside the payload
  write(flipped, corrupt);
  EXPECT_NE(error_message([&] { load_model(flipped); }).find("checksum does not match"),
            std::string::npos);
  EXPECT_EQ(read(flipped), corrupt);  // a failed load leaves the file alone

  const auto truncated = directory_ / "truncated.tdm";
  write(truncated, bytes.substr(0, bytes.size() / 3));
  const std::string message = error_message([&] { load_model(truncated); });
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated.tdm"), std::string::npos) << message;

  const auto foreign = directory_ / "foreign.tdm";
  write(foreign, "PK\x03\x04 a zip archive");
  EXPECT_NE(error_message([&] { load_model(foreign); }).find("not a tendril dynamics model"),
            std::string::npos);
  EXPECT_NE(error_message([&] { load_model(directory_ / "none.tdm"); }).find("no model file"),
            std::string::npos);

  std::string future = bytes;
  future.replace(future.find("format 1"), 8, "format 7");
  const auto newer = directory_ / "newer.tdm";
  write(newer, reseal(future));
  EXPECT_NE(error_message([&] { load_model(newer); }).find("format 7; this build reads format 1"),
            std::string::npos);
}

TEST_F(ModelFile, HeaderThatDoesNotMatchTheWeightsIsRefused) {
  Model model(small_description(Architecture::kLstm), 2);
  const auto file = directory_ / "good.tdm";
  save_model(model, file);
  const std::string bytes = read(file);
  // The same byte count but another architecture: hidden size 8 → layers 1 drops parameters.
  std::string edited = bytes;
  edited.replace(edited.find("layers: 2"), 9, "layers: 1");
  const auto fewer_layers = directory_ / "fewer_layers.tdm";
  write(fewer_layers, reseal(edited));
  const std::string message = error_message([&] { load_model(fewer_layers); });
  EXPECT_NE(message.find("do not match the architecture"), std::string::npos) << message;

  std::string wrong_shape = bytes;
  const std::size_t at = wrong_shape.find("shape: [32, 6]");
  ASSERT_NE(at, std::string::npos);
  // As many values, transposed: the count matches, the shape does not.
  wrong_shape.replace(at, 14, "shape: [6, 32]");
  const auto reshaped = directory_ / "reshaped.tdm";
  write(reshaped, reseal(wrong_shape));
  EXPECT_NE(error_message([&] {
              load_model(reshaped);
            }).find("has shape [6, 32] in the file, the architecture [32, 6]"),
            std::string::npos);

  std::string unknown_key = bytes;
  unknown_key.replace(unknown_key.find("heads: 2"), 8, "hedas: 2");
  const auto misspelt = directory_ / "misspelt.tdm";
  write(misspelt, reseal(unknown_key));
  EXPECT_THROW(load_model(misspelt), Error);
}

}  // namespace
}  // namespace tendril::dynamics
