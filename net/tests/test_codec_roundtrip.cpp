// Encode/decode round trips and the encoder's refusals.
#include <gtest/gtest.h>

#include <random>

#include "test_util.hpp"

using namespace nettest;

namespace {

template <class Pdu>
void expect_round_trip(Pdu p) {
  const auto b = bytes_of(p);
  ASSERT_FALSE(b.empty());
  auto r = net::decode_as<Pdu>(b);
  ASSERT_TRUE(r.ok()) << net::to_string(r.error());
  p.header.length = static_cast<std::uint16_t>(b.size());  // decode reports the real length
  EXPECT_TRUE(r.value() == p);
  EXPECT_EQ(bytes_of(r.value()), b);
}

}  // namespace

TEST(CodecRoundTrip, AllFiveTypes) {
  expect_round_trip(sample_entity_state(0));
  expect_round_trip(sample_entity_state(3));
  expect_round_trip(sample_fire());
  expect_round_trip(sample_detonation(0));
  expect_round_trip(sample_detonation(4));
  expect_round_trip(sample_collision());
  expect_round_trip(sample_esu(0));
  expect_round_trip(sample_esu(2));
}

TEST(CodecRoundTrip, RandomEntityStatesKeepEveryBit) {
  std::mt19937_64 rng(42);
  std::vector<std::uint8_t> buf(net::kMaxPduSize);
  net::EntityStatePdu out;
  for (int i = 0; i < 2000; ++i) {
    // Random bytes for the fixed part, a random parameter count: any bit pattern (NaNs too)
    // must come back unchanged.
    const std::size_t n = rng() % 20;
    const std::size_t size = 144 + 16 * n;
    for (std::size_t k = 0; k < size; ++k) buf[k] = static_cast<std::uint8_t>(rng());
    buf[0] = 7;
    buf[2] = 1;
    buf[8] = static_cast<std::uint8_t>(size >> 8);
    buf[9] = static_cast<std::uint8_t>(size);
    buf[19] = static_cast<std::uint8_t>(n);
    const std::span<const std::uint8_t> in(buf.data(), size);
    ASSERT_EQ(net::decode(in, out), net::DecodeError::None);
    std::vector<std::uint8_t> again(size);
    auto r = net::encode(out, again);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.value(), size);
    ASSERT_TRUE(std::equal(again.begin(), again.end(), in.begin())) << "iteration " << i;
  }
}

TEST(CodecRoundTrip, DecodeReusesTheStruct) {
  net::EntityStatePdu out;
  ASSERT_EQ(net::decode(bytes_of(sample_entity_state(5)), out), net::DecodeError::None);
  EXPECT_EQ(out.variable_parameters.size(), 5u);
  ASSERT_EQ(net::decode(bytes_of(sample_entity_state(1)), out), net::DecodeError::None);
  EXPECT_EQ(out.variable_parameters.size(), 1u);
  EXPECT_GE(out.variable_parameters.capacity(), 5u);
}

TEST(CodecEncode, RefusesSmallBufferWithoutWriting) {
  std::vector<std::uint8_t> buf(95, 0xAA);
  auto r = net::encode(sample_fire(), buf);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), net::EncodeError::BufferTooSmall);
  for (auto b : buf) EXPECT_EQ(b, 0xAA);
  std::vector<std::uint8_t> es(175);
  EXPECT_EQ(net::encode(sample_entity_state(2), es).error(), net::EncodeError::BufferTooSmall);
  std::vector<std::uint8_t> col(59);
  EXPECT_EQ(net::encode(sample_collision(), col).error(), net::EncodeError::BufferTooSmall);
}

TEST(CodecEncode, RefusesTooManyVariableParameters) {
  std::vector<std::uint8_t> buf(net::kMaxPduSize * 2);
  auto p = sample_entity_state(256);
  EXPECT_EQ(net::encode(p, buf).error(), net::EncodeError::TooManyVariableParameters);
  p.variable_parameters.resize(255);  // 144 + 4080 = 4224 octets: fine
  auto r = net::encode(p, buf);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value(), 4224u);
  EXPECT_EQ(buf[19], 255);
}

TEST(CodecDecode, WrongTypeAndVersion) {
  auto b = bytes_of(sample_fire());
  EXPECT_EQ(net::decode_as<net::EntityStatePdu>(b).error(), net::DecodeError::WrongType);
  b[0] = 4;
  EXPECT_EQ(net::decode_as<net::FirePdu>(b).error(), net::DecodeError::UnsupportedVersion);
  b[0] = 5;  // DIS 5 (1278.1-1995): the same layout, accepted
  EXPECT_TRUE(net::decode_as<net::FirePdu>(b).ok());
  b[0] = 6;  // DIS 6 has the same layout and is accepted; the version is kept
  auto r = net::decode_as<net::FirePdu>(b);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value().header.protocol_version, 6);
  EXPECT_EQ(bytes_of(r.value()), b);
}

TEST(CodecDecode, TrailingBytesAfterLengthAreIgnored) {
  auto b = bytes_of(sample_collision());
  b.push_back(1);
  b.push_back(2);
  auto r = net::decode_as<net::CollisionPdu>(b);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(bytes_of(r.value()).size(), 60u);
}

TEST(CodecNames, ReasonsHaveNames) {
  for (std::size_t e = 0; e < net::kDecodeErrorCount; ++e)
    EXPECT_NE(net::to_string(static_cast<net::DecodeError>(e)), "unknown");
  EXPECT_EQ(net::to_string(net::DecodeError::VariableCountMismatch), "variable_count_mismatch");
}
