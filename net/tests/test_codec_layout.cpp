// Byte-level layout of each PDU type at the offsets of DIS7-NOTES.md.
#include <gtest/gtest.h>

#include "test_util.hpp"

using namespace nettest;

namespace {

void expect_header(std::span<const std::uint8_t> b, std::uint8_t type, std::uint8_t family,
                   std::size_t length, std::uint32_t timestamp) {
  EXPECT_EQ(b[0], 7);  // protocol version
  EXPECT_EQ(b[1], 9);  // exercise
  EXPECT_EQ(b[2], type);
  EXPECT_EQ(b[3], family);
  EXPECT_EQ(be32(b, 4), timestamp);
  EXPECT_EQ(be16(b, 8), length);
  EXPECT_EQ(b.size(), length);
}

void expect_id(std::span<const std::uint8_t> b, std::size_t o, std::uint16_t a, std::uint16_t s,
               std::uint16_t c) {
  EXPECT_EQ(be16(b, o), a) << "offset " << o;
  EXPECT_EQ(be16(b, o + 2), s) << "offset " << o + 2;
  EXPECT_EQ(be16(b, o + 4), c) << "offset " << o + 4;
}

}  // namespace

TEST(CodecLayout, EntityStateOffsets) {
  const auto p = sample_entity_state(2);
  const auto b = bytes_of(p);
  ASSERT_EQ(b.size(), 144u + 32u);
  expect_header(b, 1, 1, 176, 0x12345678);
  EXPECT_EQ(b[10], 0x02);  // PDU status
  expect_id(b, 12, 11, 22, 33);
  EXPECT_EQ(b[18], 2);  // force
  EXPECT_EQ(b[19], 2);  // number of variable parameters
  const std::uint8_t type[8] = {1, 2, 0, 225, 3, 4, 5, 6};
  const std::uint8_t alt[8] = {1, 3, 0, 222, 7, 8, 9, 10};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(b[20 + i], type[i]) << i;
    EXPECT_EQ(b[28 + i], alt[i]) << i;
  }
  EXPECT_EQ(bef32(b, 36), 1.5f);
  EXPECT_EQ(bef32(b, 40), -2.25f);
  EXPECT_EQ(bef32(b, 44), 3.125f);
  EXPECT_EQ(bef64(b, 48), -2707522.125);
  EXPECT_EQ(bef64(b, 56), -4353260.5);
  EXPECT_EQ(bef64(b, 64), 3781450.75);
  EXPECT_EQ(bef32(b, 72), 0.5f);
  EXPECT_EQ(bef32(b, 76), -0.25f);
  EXPECT_EQ(bef32(b, 80), 0.125f);
  EXPECT_EQ(be32(b, 84), 0x00A1B2C3u);
  EXPECT_EQ(b[88], 4);
  for (int i = 0; i < 15; ++i) EXPECT_EQ(b[89 + i], 0xE0 + i);
  EXPECT_EQ(bef32(b, 104), 0.5f);
  EXPECT_EQ(bef32(b, 108), 0.75f);
  EXPECT_EQ(bef32(b, 112), -9.75f);
  EXPECT_EQ(bef32(b, 116), 0.01f);
  EXPECT_EQ(bef32(b, 120), -0.02f);
  EXPECT_EQ(bef32(b, 124), 0.03f);
  EXPECT_EQ(b[128], 1);  // ASCII
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&b[129]), 5), "tank1");
  for (int i = 134; i < 140; ++i) EXPECT_EQ(b[i], 0) << "marking NUL padding at " << i;
  EXPECT_EQ(be32(b, 140), 0xCAFEBABEu);
  EXPECT_EQ(b[144], 0);   // first record type
  EXPECT_EQ(b[145], 0);   // its data (seed 0)
  EXPECT_EQ(b[159], 14);
  EXPECT_EQ(b[160], 0);   // second record type
  EXPECT_EQ(b[161], 16);  // seed 16
}

TEST(CodecLayout, FireOffsets) {
  const auto b = bytes_of(sample_fire());
  ASSERT_EQ(b.size(), 96u);
  expect_header(b, 2, 2, 96, 0xBEEF);
  expect_id(b, 12, 11, 22, 33);
  expect_id(b, 18, 44, 55, 66);
  expect_id(b, 24, 11, 22, 900);
  expect_id(b, 30, 11, 22, 7);
  EXPECT_EQ(be32(b, 36), 0xDEADBEEFu);
  EXPECT_EQ(bef64(b, 40), -2707500.5);
  EXPECT_EQ(bef64(b, 48), -4353200.25);
  EXPECT_EQ(bef64(b, 56), 3781400.125);
  EXPECT_EQ(b[64], 2);  // munition kind
  EXPECT_EQ(b[65], 2);  // domain
  EXPECT_EQ(be16(b, 66), 225);
  EXPECT_EQ(b[68], 2);
  EXPECT_EQ(b[69], 14);
  EXPECT_EQ(be16(b, 72), 1000);  // warhead
  EXPECT_EQ(be16(b, 74), 1010);  // fuse
  EXPECT_EQ(be16(b, 76), 3);     // quantity
  EXPECT_EQ(be16(b, 78), 600);   // rate
  EXPECT_EQ(bef32(b, 80), 250.0f);
  EXPECT_EQ(bef32(b, 84), 125.5f);
  EXPECT_EQ(bef32(b, 88), 30.25f);
  EXPECT_EQ(bef32(b, 92), 1500.0f);
}

TEST(CodecLayout, DetonationOffsets) {
  const auto b = bytes_of(sample_detonation(1));
  ASSERT_EQ(b.size(), 120u);
  expect_header(b, 3, 2, 120, 0);
  expect_id(b, 12, 11, 22, 33);
  expect_id(b, 18, 44, 55, 66);
  expect_id(b, 24, 11, 22, 900);
  expect_id(b, 30, 11, 22, 7);
  EXPECT_EQ(bef32(b, 36), -10.0f);
  EXPECT_EQ(bef32(b, 40), 20.0f);
  EXPECT_EQ(bef32(b, 44), -300.5f);
  EXPECT_EQ(bef64(b, 48), -2707400.5);
  EXPECT_EQ(bef64(b, 56), -4353100.25);
  EXPECT_EQ(bef64(b, 64), 3781300.125);
  EXPECT_EQ(b[72], 2);
  EXPECT_EQ(be16(b, 80), 1000);
  EXPECT_EQ(be16(b, 84), 1);  // quantity
  EXPECT_EQ(bef32(b, 88), 1.0f);
  EXPECT_EQ(bef32(b, 92), -0.5f);
  EXPECT_EQ(bef32(b, 96), 0.25f);
  EXPECT_EQ(b[100], 5);  // result
  EXPECT_EQ(b[101], 1);  // number of variable parameters
  EXPECT_EQ(be16(b, 102), 0x0102);
  EXPECT_EQ(b[104], 1);    // record type
  EXPECT_EQ(b[105], 100);  // data
}

TEST(CodecLayout, CollisionOffsets) {
  const auto b = bytes_of(sample_collision());
  ASSERT_EQ(b.size(), 60u);
  expect_header(b, 4, 1, 60, 0);
  expect_id(b, 12, 11, 22, 33);
  expect_id(b, 18, 44, 55, 66);
  expect_id(b, 24, 11, 22, 8);
  EXPECT_EQ(b[30], 1);
  EXPECT_EQ(b[31], 0x5A);
  EXPECT_EQ(bef32(b, 32), 5.0f);
  EXPECT_EQ(bef32(b, 36), -6.0f);
  EXPECT_EQ(bef32(b, 40), 0.5f);
  EXPECT_EQ(bef32(b, 44), 62000.0f);
  EXPECT_EQ(bef32(b, 48), 3.5f);
  EXPECT_EQ(bef32(b, 52), 0.0f);
  EXPECT_EQ(bef32(b, 56), -1.25f);
}

TEST(CodecLayout, EntityStateUpdateOffsets) {
  const auto b = bytes_of(sample_esu(1));
  ASSERT_EQ(b.size(), 88u);
  expect_header(b, 67, 1, 88, 0);
  expect_id(b, 12, 11, 22, 33);
  EXPECT_EQ(b[18], 0x77);
  EXPECT_EQ(b[19], 1);
  EXPECT_EQ(bef32(b, 20), 1.0f);
  EXPECT_EQ(bef32(b, 28), 3.0f);
  EXPECT_EQ(bef64(b, 32), -2707522.125);
  EXPECT_EQ(bef64(b, 48), 3781450.75);
  EXPECT_EQ(bef32(b, 56), 0.5f);
  EXPECT_EQ(bef32(b, 64), 0.125f);
  EXPECT_EQ(be32(b, 68), 0x42u);
  EXPECT_EQ(b[72], 0);
  EXPECT_EQ(b[73], 50);
}

TEST(CodecLayout, EncodeWritesTypeAndLengthWhateverTheHeaderSays) {
  auto p = sample_fire();
  p.header.pdu_type = 99;
  p.header.length = 3;
  const auto b = bytes_of(p);
  EXPECT_EQ(b[2], 2);
  EXPECT_EQ(be16(b, 8), 96);
}
