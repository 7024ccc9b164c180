// DIS timestamps (relative / absolute) and ASCII markings.
#include <gtest/gtest.h>
#include <cstring>

#include "test_util.hpp"

TEST(Timestamp, RelativeHasLowBitZeroAbsoluteOne) {
  EXPECT_EQ(net::relative_timestamp(0.0), 0u);
  EXPECT_EQ(net::absolute_timestamp(0.0), 1u);
  const auto r = net::relative_timestamp(1800.0);  // half past: 2^30 units
  EXPECT_EQ(r, (1u << 30) << 1);
  EXPECT_EQ(r & 1u, 0u);
  EXPECT_EQ(net::absolute_timestamp(1800.0), ((1u << 30) << 1) | 1u);
}

TEST(Timestamp, RoundTripWithinOneUnit) {
  for (double s : {0.0, 0.1, 1.0, 59.999, 1234.5678, 3599.9999}) {
    const auto d = net::decode_timestamp(net::relative_timestamp(s));
    EXPECT_FALSE(d.absolute);
    EXPECT_NEAR(d.seconds_past_hour, s, net::kTimestampUnitSeconds) << s;
    const auto a = net::decode_timestamp(net::absolute_timestamp(s));
    EXPECT_TRUE(a.absolute);
    EXPECT_NEAR(a.seconds_past_hour, s, net::kTimestampUnitSeconds) << s;
  }
}

TEST(Timestamp, WrapsAtTheHour) {
  EXPECT_EQ(net::relative_timestamp(3600.0), 0u);
  EXPECT_EQ(net::relative_timestamp(3600.0 + 10.0), net::relative_timestamp(10.0));
  EXPECT_EQ(net::relative_timestamp(-10.0), net::relative_timestamp(3590.0));
  EXPECT_EQ(net::absolute_timestamp_from_unix(1700000000.0 + 0.5),
            net::absolute_timestamp(std::fmod(1700000000.0, 3600.0) + 0.5));
  // 3599 s -> 1 s across the hour is +2 s, not -3598 s.
  EXPECT_NEAR(net::timestamp_difference(net::relative_timestamp(1.0), net::relative_timestamp(3599.0)),
              2.0, 1e-5);
  EXPECT_NEAR(net::timestamp_difference(net::relative_timestamp(3599.0), net::relative_timestamp(1.0)),
              -2.0, 1e-5);
  EXPECT_EQ(net::relative_timestamp(std::nan("")), 0u);
}

TEST(Marking, AsciiNulPadded) {
  auto m = net::make_marking("tank1");
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m.value().character_set, 1);
  EXPECT_EQ(m.value().characters[4], '1');
  for (std::size_t i = 5; i < 11; ++i) EXPECT_EQ(m.value().characters[i], '\0');
  EXPECT_EQ(net::marking_text(m.value()), "tank1");
  auto full = net::make_marking("ABCDEFGHIJK");
  ASSERT_TRUE(full.ok());
  EXPECT_EQ(net::marking_text(full.value()), "ABCDEFGHIJK");
}

TEST(Marking, RejectsLongAndNonAscii) {
  auto longer = net::make_marking("ABCDEFGHIJKL");
  ASSERT_FALSE(longer.ok());
  EXPECT_NE(longer.error().find("at most 11"), std::string::npos) << longer.error();
  auto bad = net::make_marking("t\xC3\xA4nk");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("not printable ASCII"), std::string::npos) << bad.error();
}

TEST(Marking, DecodedByCharacterSetIntoSafeUtf8) {
  net::Marking m;
  const unsigned char b[11] = {'T', 0xC4, 'N', 'K', 0x01, 0x7F, 0x85, 0xFF, '"', 0, 'x'};
  std::memcpy(m.characters.data(), b, sizeof b);
  EXPECT_EQ(net::marking_text(m), "T\xC3\x84NK\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD\xC3\xBF\"");
  net::Marking c;
  c.character_set = net::kMarkingDigitChevron;
  const unsigned char d[3] = {1, 2, '3'};
  std::memcpy(c.characters.data(), d, sizeof d);
  EXPECT_EQ(net::marking_text(c), "123");
  net::Marking full;  // 11 characters, no NUL: all 11, nothing past them
  full.characters.fill('A');
  EXPECT_EQ(net::marking_text(full), std::string(11, 'A'));
}
