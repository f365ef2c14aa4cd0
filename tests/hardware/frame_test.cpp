#include "tendril/hardware/frame.hpp"

#include <gtest/gtest.h>

#include <string_view>

#include "tendril/core/error.hpp"
#include "tendril/hardware/frame_parser.hpp"
#include "tendril/hardware/messages.hpp"

namespace tendril::hardware {
namespace {

std::vector<Frame> parse(const std::vector<uint8_t>& bytes, FrameParser& parser) {
  parser.push(bytes);
  std::vector<Frame> frames;
  while (auto frame = parser.next()) frames.push_back(*frame);
  return frames;
}

Frame sample_frame(uint16_t seq) {
  Frame frame;
  frame.type = static_cast<uint8_t>(MessageType::kPwmCommand);
  frame.seq = seq;
  frame.stamp_ms = 0x01020304;
  frame.payload = PwmCommand{{30, 0, 0, 25}}.encode();
  return frame;
}

TEST(Crc16, IsCcittFalse) {
  // The catalogue's check value of CRC-16/CCITT-FALSE: "123456789" → 0x29B1.
  const std::string_view text = "123456789";
  const std::vector<uint8_t> bytes(text.begin(), text.end());
  EXPECT_EQ(crc16(bytes), 0x29B1);
}

TEST(Crc8, IsTheSmbusOne) {
  // The catalogue's check value of CRC-8 (poly 0x07, init 0): "123456789" → 0xF4.
  const std::string_view text = "123456789";
  const std::vector<uint8_t> bytes(text.begin(), text.end());
  EXPECT_EQ(crc8(bytes), 0xF4);
}

TEST(Frame, EncodesTheDocumentedLayout) {
  const std::vector<uint8_t> bytes = sample_frame(0x0A0B).encode();
  ASSERT_EQ(bytes.size(), 12u + 4u + 2u);
  EXPECT_EQ(bytes[0], 0xA5);
  EXPECT_EQ(bytes[1], 0x5A);
  EXPECT_EQ(bytes[2], 1);     // version
  EXPECT_EQ(bytes[3], 0x03);  // PWM_COMMAND
  EXPECT_EQ(bytes[4], 0x0B);  // seq, little-endian
  EXPECT_EQ(bytes[5], 0x0A);
  EXPECT_EQ(bytes[6], 0x04);  // stamp
  EXPECT_EQ(bytes[9], 0x01);
  EXPECT_EQ(bytes[10], 4);  // length
  EXPECT_EQ(bytes[11], crc8(std::span(bytes).subspan(2, 9)));
  EXPECT_EQ(bytes[12], 30);
  const uint16_t crc = crc16(std::span(bytes).subspan(2, bytes.size() - 4));
  EXPECT_EQ(bytes[16], crc & 0xFF);
  EXPECT_EQ(bytes[17], crc >> 8);
}

TEST(FrameParser, RoundTripsFramesSplitAnywhere) {
  std::vector<uint8_t> stream;
  for (uint16_t seq = 0; seq < 5; ++seq) {
    const auto bytes = sample_frame(seq).encode();
    stream.insert(stream.end(), bytes.begin(), bytes.end());
  }
  FrameParser parser;
  std::vector<Frame> frames;
  for (const uint8_t byte : stream) {
    parser.push(byte);
    while (auto frame = parser.next()) frames.push_back(*frame);
  }
  ASSERT_EQ(frames.size(), 5u);
  for (uint16_t seq = 0; seq < 5; ++seq) {
    EXPECT_EQ(frames[seq].seq, seq);
    EXPECT_EQ(frames[seq].stamp_ms, 0x01020304u);
    EXPECT_EQ(frames[seq].encode(), sample_frame(seq).encode());
  }
  EXPECT_EQ(parser.errors(), 0u);
}

TEST(FrameParser, DropsEveryCorruptedFrameAndKeepsTheNext) {
  const auto good = sample_frame(7).encode();
  // Every single-bit flip past the sync pair must be caught at once, the length's too (the
  // header check), and the next frame kept.
  for (size_t at = 2; at < good.size(); ++at) {
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<uint8_t> bad = good;
      bad[at] ^= static_cast<uint8_t>(1u << bit);
      std::vector<uint8_t> stream = bad;
      stream.insert(stream.end(), good.begin(), good.end());
      FrameParser parser;
      const auto frames = parse(stream, parser);
      ASSERT_EQ(frames.size(), 1u) << "flip at byte " << at << " bit " << bit;
      EXPECT_EQ(frames[0].encode(), good);
      EXPECT_EQ(parser.errors(), 1u);
    }
  }
}

TEST(FrameParser, ResynchronisesAfterGarbageAndFindsFramesInsideRejectedBytes) {
  const auto a = sample_frame(1).encode();
  const auto b = sample_frame(2).encode();
  // Garbage, a false header (with a valid header check) whose length swallows frame a, then
  // frame b: the payload check fails, and both frames are found in what it swallowed.
  std::vector<uint8_t> stream = {0x00, 0xFF, 0xA5, 0x5A, 0x01, 0x03, 0, 0, 0, 0, 0, 0, 60};
  stream.push_back(crc8(std::span(stream).subspan(4, 9)));
  stream.insert(stream.end(), a.begin(), a.end());
  stream.insert(stream.end(), b.begin(), b.end());
  stream.insert(stream.end(), 60, 0x00);
  FrameParser parser;
  const auto frames = parse(stream, parser);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].seq, 1);
  EXPECT_EQ(frames[1].seq, 2);
  EXPECT_GE(parser.counters().checksum_errors, 1u);
}

TEST(FrameParser, RejectsOtherVersionsAndOverlongFrames) {
  auto bytes = sample_frame(3).encode();
  bytes[2] = 2;
  FrameParser parser;
  EXPECT_TRUE(parse(bytes, parser).empty());
  EXPECT_EQ(parser.counters().version_errors, 1u);
  std::vector<uint8_t> overlong = {0xA5, 0x5A, 0x01, 0x03, 0, 0, 0, 0, 0, 0, 201};
  overlong.push_back(crc8(std::span(overlong).subspan(2, 9)));
  EXPECT_TRUE(parse(overlong, parser).empty());
  EXPECT_EQ(parser.counters().length_errors, 1u);
}

TEST(Messages, RoundTripEveryPayload) {
  Identity identity;
  identity.robot = "sma-limb";
  identity.firmware = {1, 2, 3};
  identity.protocol = 1;
  identity.limits = {{"max_pwm", 128}, {"cutoff_mdeg", 100000}, {"offset", -5}};
  const Identity back = Identity::decode(identity.encode());
  EXPECT_EQ(back.robot, "sma-limb");
  EXPECT_EQ(back.firmware_version(), "1.2.3");
  EXPECT_EQ(back.limit("offset"), -5);
  EXPECT_EQ(back.limit("cutoff_mdeg"), 100000);
  EXPECT_FALSE(back.limit("missing").has_value());

  LimbReading reading;
  reading.reset_seq = 4;
  reading.index = 70000;
  reading.acked_seq = 9;
  reading.counts = {-1234, 987};
  reading.pwm = {0, 35, 20, 0};
  reading.flags = LimbReading::kCutoff | LimbReading::kEstop;
  const LimbReading r = LimbReading::decode(reading.encode());
  EXPECT_EQ(r.index, 70000u);
  EXPECT_EQ(r.counts, reading.counts);
  EXPECT_EQ(r.pwm, reading.pwm);
  EXPECT_EQ(r.flags, reading.flags);

  MocapFrame mocap;
  mocap.reset_seq = 2;
  mocap.sample = 150;
  mocap.time_s = 1.5000000000000002;
  mocap.markers = {Eigen::Vector3d(0.1, -0.2, -0.3), Eigen::Vector3d(1e-17, 2, 3),
                   Eigen::Vector3d(4, 5, 6)};
  const MocapFrame m = MocapFrame::decode(mocap.encode());
  EXPECT_EQ(m.time_s, mocap.time_s);  // exact: doubles travel as their bits
  EXPECT_EQ(m.markers[1], mocap.markers[1]);

  EXPECT_EQ(ResetRequest::decode(ResetRequest{42}.encode()).seed, 42u);
  EXPECT_FALSE(ResetRequest::decode(ResetRequest{}.encode()).seed.has_value());
}

TEST(Messages, NameTheMessageOfAWrongSizedPayload) {
  const std::vector<uint8_t> short_payload = {1, 2, 3};
  try {
    LimbReading::decode(short_payload);
    FAIL() << "a 3-byte LIMB_READING decoded";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("LIMB_READING"), std::string::npos);
  }
  const std::vector<uint8_t> long_payload = {1, 2, 3, 4, 5};
  EXPECT_THROW(PwmCommand::decode(long_payload), Error);
}

}  // namespace
}  // namespace tendril::hardware
