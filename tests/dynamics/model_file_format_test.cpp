// The model file's layout without LibTorch: what dynamics::load_model and the fuzz target read.
#include "tendril/dynamics/model_file_format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/error_message.hpp"
#include "tendril/core/crc32c.hpp"

namespace tendril::dynamics {
namespace {

using testing::error_message;

// A two-layer LSTM of seed 001's layout whose parameters are one flat table entry of
// parameter_count() values, so the file is whole without a network.
ModelFileContents lstm_contents() {
  ModelFileContents contents;
  ModelDescription& d = contents.description;
  d.architecture.kind = Architecture::kLstm;
  d.architecture.hidden_size = 8;
  d.architecture.layers = 2;
  d.architecture.window = 5;
  d.normalizer.offset = Eigen::VectorXd::LinSpaced(6, -1.0, 1.5);
  d.normalizer.scale = Eigen::VectorXd::LinSpaced(6, 0.1, 20.0);
  d.state_names = {"theta_x", "theta_y", "omega_x", "omega_y"};
  d.input_names = {"u_x", "u_y"};
  d.sample_period = 0.075;
  const int64_t count = d.architecture.parameter_count();
  std::vector<float> values(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 1.0f / (1.0f + i) - 0.3f;
  contents.parameters.push_back({"weights", {count - 4, 1}, {values.begin(), values.end() - 4}});
  contents.parameters.push_back({"head.bias", {4}, {values.end() - 4, values.end()}});
  return contents;
}

// `bytes` with the first `from` (in the header, else after it) replaced by `to`, the header's
// byte count and the checksum line made right again.
std::string edited(const std::string& bytes, const std::string& from, const std::string& to) {
  const std::size_t count_line = bytes.find("header_bytes ");
  const std::size_t header_begin = bytes.find('\n', count_line) + 1;
  const std::size_t header_size =
      std::stoull(bytes.substr(count_line + 13, header_begin - count_line - 14));
  std::string header = bytes.substr(header_begin, header_size);
  std::string rest = bytes.substr(header_begin + header_size);
  rest.erase(rest.rfind("crc32c "));
  std::string& part = header.find(from) != std::string::npos ? header : rest;
  const std::size_t at = part.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) part.replace(at, from.size(), to);
  const std::string body = bytes.substr(0, count_line) + "header_bytes " +
                           std::to_string(header.size()) + "\n" + header + rest;
  return body + "crc32c " + checksum_text(crc32c(body.data(), body.size())) + "\n";
}

TEST(ModelFileFormat, DecodingWhatWasEncodedGivesTheSameContentsAndBytes) {
  const ModelFileContents contents = lstm_contents();
  const std::string bytes = encode_model_file(contents);
  const ModelFileContents read = decode_model_file(bytes, "m.tdm");
  const ModelDescription& d = read.description;
  EXPECT_EQ(d.architecture.kind, Architecture::kLstm);
  EXPECT_EQ(d.architecture.hidden_size, 8);
  EXPECT_EQ(d.architecture.layers, 2);
  EXPECT_EQ(d.architecture.window, 5);
  EXPECT_EQ(d.normalizer.offset, contents.description.normalizer.offset);  // shortest exact text
  EXPECT_EQ(d.normalizer.scale, contents.description.normalizer.scale);
  EXPECT_EQ(d.state_names, contents.description.state_names);
  EXPECT_EQ(d.sample_period, 0.075);
  ASSERT_EQ(read.parameters.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(read.parameters[i].name, contents.parameters[i].name);
    EXPECT_EQ(read.parameters[i].shape, contents.parameters[i].shape);
    EXPECT_EQ(read.parameters[i].values, contents.parameters[i].values);
  }
  EXPECT_EQ(encode_model_file(read), bytes);
}

TEST(ModelFileFormat, AHeaderClaimingALargerNetworkThanItsTableIsRefused) {
  const std::string bytes = encode_model_file(lstm_contents());
  // 8192 × 32 is within the size limits: the architecture's 1.7e10 parameters are compared with
  // the 1,124 the table lists before anything is allocated for them.
  ArchitectureSpec big = lstm_contents().description.architecture;
  big.hidden_size = 8192;
  big.layers = 32;
  const std::string message = error_message([&] {
    decode_model_file(
        edited(edited(bytes, "hidden_size: 8", "hidden_size: 8192"), "layers: 2", "layers: 32"),
        "big.tdm");
  });
  EXPECT_NE(message.find("holds 1124 values: they do not match the architecture's " +
                         std::to_string(big.parameter_count())),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("big.tdm"), std::string::npos) << message;
}

TEST(ModelFileFormat, ShapesWithMoreValuesThanTheFileHoldsAreRefusedWithoutOverflow) {
  const std::string bytes = encode_model_file(lstm_contents());
  for (const std::string shape :
       {"[1120, 1000000]", "[4294967296, 4294967296, 4294967296]", "[0, 5]", "[-1, -1120]"}) {
    SCOPED_TRACE(shape);
    const std::string message =
        error_message([&] { decode_model_file(edited(bytes, "[1120, 1]", shape), "shape.tdm"); });
    EXPECT_NE(message.find("parameter 'weights' has shape " + shape), std::string::npos) << message;
  }
}

TEST(ModelFileFormat, SizesOutsideTheirLimitsNameTheField) {
  const std::string bytes = encode_model_file(lstm_contents());
  EXPECT_NE(error_message([&] {
              decode_model_file(edited(bytes, "hidden_size: 8", "hidden_size: 100000"), "m.tdm");
            }).find("model.hidden_size: must lie in [1, 8192], got 100000"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              decode_model_file(edited(bytes, "window: 5", "window: 0"), "m.tdm");
            }).find("model.window: must lie in [1, 100000], got 0"),
            std::string::npos);
}

TEST(ModelFileFormat, APayloadThatDoesNotMatchTheTableIsRefused) {
  const std::string bytes = encode_model_file(lstm_contents());
  // Eight bytes more payload than the table (which matches the architecture) describes.
  const std::string longer =
      edited(bytes, "payload_bytes 4496\n", "payload_bytes 4504\n" + std::string(8, '\0'));
  EXPECT_NE(error_message([&] {
              decode_model_file(longer, "m.tdm");
            }).find("payload has 4504 bytes, the parameter table 4496"),
            std::string::npos);
  // A table that lists fewer values than the architecture has.
  const std::string shorter = edited(bytes, "  - {name: head.bias, shape: [4]}\n", "");
  EXPECT_NE(error_message([&] {
              decode_model_file(shorter, "m.tdm");
            }).find("holds 1120 values: they do not match the architecture's 1124"),
            std::string::npos);

  ModelFileContents short_values = lstm_contents();
  short_values.parameters[1].values.pop_back();
  EXPECT_NE(error_message([&] {
              encode_model_file(short_values);
            }).find("parameter 'head.bias' of shape [4] has 3 values"),
            std::string::npos);
}

// A file someone crafted, its checksum made right: weights that are not numbers, or an output
// bound that overflows float32, are refused at load instead of evaluating to "RMSE nan".
TEST(ModelFileFormat, CraftedWeightsAndBoundsThatCannotBeComputedAreRefused) {
  const std::string bytes = encode_model_file(lstm_contents());
  const std::size_t payload = bytes.find('\n', bytes.find("payload_bytes ")) + 1;
  std::string nan_weight = bytes.substr(0, bytes.rfind("crc32c "));
  const float nan = std::nanf("");
  nan_weight.replace(payload + 8, sizeof nan, reinterpret_cast<const char*>(&nan), sizeof nan);
  nan_weight += "crc32c " + checksum_text(crc32c(nan_weight.data(), nan_weight.size())) + "\n";
  EXPECT_NE(error_message([&] {
              decode_model_file(nan_weight, "m.tdm");
            }).find("m.tdm: parameter 'weights' holds a non-finite value (nan) at index 2"),
            std::string::npos);
  for (const std::string bound : {"1e300", "1e7", "2e6"}) {
    const std::string message = error_message([&] {
      decode_model_file(edited(bytes, "output_bound: 100", "output_bound: " + bound), "m.tdm");
    });
    EXPECT_NE(message.find("output_bound: must lie in (0, 1e6]"), std::string::npos)
        << bound << ": " << message;
  }
}

// Every single bit flipped anywhere in a model file: refused, never decoded.
TEST(ModelFileFormat, EveryFlippedBitIsRefused) {
  const std::string bytes = encode_model_file(lstm_contents());
  int refused = 0;
  for (std::size_t position = 0; position < bytes.size(); ++position) {
    std::string flipped = bytes;
    flipped[position] = static_cast<char>(flipped[position] ^ (1 << (position % 8)));
    try {
      decode_model_file(flipped, "m.tdm");
      ADD_FAILURE() << "a flip at byte " << position << " was decoded";
    } catch (const Error& e) {
      ++refused;
      EXPECT_EQ(std::string(e.what()).rfind("m.tdm", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(refused, static_cast<int>(bytes.size()));
  for (std::size_t size = 0; size < bytes.size(); size += 7) {
    EXPECT_THROW(decode_model_file(bytes.substr(0, size), "m.tdm"), Error) << size;
  }
}

TEST(ModelFileFormat, DamagedFramingIsNamed) {
  const std::string bytes = encode_model_file(lstm_contents());
  std::string flipped = bytes;
  flipped[flipped.size() / 2] ^= 0x01;
  EXPECT_NE(
      error_message([&] { decode_model_file(flipped, "m.tdm"); }).find("checksum does not match"),
      std::string::npos);
  EXPECT_NE(
      error_message([&] { decode_model_file(bytes.substr(0, 300), "m.tdm"); }).find("truncated"),
      std::string::npos);
  EXPECT_NE(error_message([&] {
              decode_model_file("", "m.tdm");
            }).find("not a tendril dynamics model file"),
            std::string::npos);
  EXPECT_NE(error_message([&] {
              decode_model_file(edited(bytes, "payload_bytes 4496", "payload_bytes 4492"), "m.tdm");
            }).find("truncated model file (no checksum at the end)"),
            std::string::npos);
}

}  // namespace
}  // namespace tendril::dynamics
