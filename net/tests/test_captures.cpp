// Conformance corpus: captures from other simulators (net/tests/data/captures, copied from
// ../shared/dis-captures). Every Entity State, Fire and Detonation capture decodes and
// re-encodes to the same bytes; every other file is skipped (or, where malformed, rejected) and
// counted, never crashes.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "test_util.hpp"

using namespace nettest;

namespace {

const std::map<std::string, net::PduType> kDecodable = {
    {"dis7_EntityStatePdu-articulated_parts.raw", net::PduType::EntityState},
    {"dis7_EntityStatePdu-attached_parts.raw", net::PduType::EntityState},
    {"dis7_EntityStatePdu-separationVP.raw", net::PduType::EntityState},
    {"dis_EntityStatePdu-26.raw", net::PduType::EntityState},
    {"dis_EntityStatePdu-vbs-articulated-parameters.raw", net::PduType::EntityState},
    {"dis_EntityStatePdu-vrf-articulated-parameters.raw", net::PduType::EntityState},
    {"dis7_FirePdu_ExpendableDescriptor.raw", net::PduType::Fire},
    {"dis7_FirePdu_MunitionDescriptor.raw", net::PduType::Fire},
    {"dis7_DetonationPdu_Descriptors_VariableParameters.raw", net::PduType::Detonation},
};

// Files that are neither: a well-formed PDU of a type we do not speak -> skipped_unknown_type.
const std::set<std::string> kSkipped = {
    "dis7_IFFPdu.raw",
    "dis7_ReceiverPdu.raw",
    "dis7_SignalPdu.raw",
    "dis7_TransmitterPdu_VariableTransmitterParameters.raw",
    "dis7_UAPdu.raw",
    "dis_AggregateStatePduJCATS.raw",
    "dis_AggregateStatePduVrForces.raw",
    "dis_DataPdu-vbs-script-cmd.raw",
    "dis_ElectromagneticEmissionPdu.raw",
    "dis_IFF_ATC_NAVAIDS_PDU.raw",
    "dis_ReceiverPdu.raw",
    "dis_SetDataPdu-multi-variable-datums.raw",
    "dis_SetDataPdu-vbs-script-cmd.raw",
    "dis_SignalPDIVrForces.raw",
    "dis_SignalPdu.raw",
    "dis_TransmitterPdu-HAVEQUICK.raw",
    "dis_TransmitterPdu.raw",
    "dis_TransmitterPdu_AntennaPattern_Beam.raw",
    "dis_TransmitterPdu_AntennaPattern_OmniDirectional.raw",
    "dis_TransmitterPdu_AntennaPattern_Spherical.raw",
    "dis_TransmitterPdu_CCTTSINCGARS.raw",
    "dis_TransmitterPdu_JtidsMids.raw",
    "dis_UAPduV6.raw",
};

template <class Pdu>
void expect_reencodes(const std::string& name, const std::vector<std::uint8_t>& bytes) {
  auto r = net::decode_as<Pdu>(bytes);
  ASSERT_TRUE(r.ok()) << name << ": " << net::to_string(r.error());
  EXPECT_EQ(bytes_of(r.value()), bytes) << name << " does not re-encode byte for byte";
}

std::vector<std::string> capture_files() {
  std::vector<std::string> names;
  if (!std::filesystem::is_directory(captures_dir())) return names;
  for (const auto& e : std::filesystem::directory_iterator(captures_dir()))
    if (e.path().extension() == ".raw") names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(Captures, EveryFileIsAccountedFor) {
  const auto names = capture_files();
  ASSERT_EQ(names.size(), 34u) << "expected the 34 captures in " << captures_dir();
  for (const auto& n : names) {
    const bool known = kDecodable.count(n) || kSkipped.count(n) ||
                       n == "dis7_StartResumePdu.raw" || n == "dis7_AggregateStatePdu.raw";
    EXPECT_TRUE(known) << n << " is not classified in this test";
  }
}

TEST(Captures, EntityStateFireDetonationReencodeByteExact) {
  std::size_t checked = 0;
  for (const auto& [name, type] : kDecodable) {
    const auto bytes = read_file(captures_dir() / name);
    ASSERT_FALSE(bytes.empty()) << name;
    switch (type) {
      case net::PduType::EntityState: expect_reencodes<net::EntityStatePdu>(name, bytes); break;
      case net::PduType::Fire: expect_reencodes<net::FirePdu>(name, bytes); break;
      case net::PduType::Detonation: expect_reencodes<net::DetonationPdu>(name, bytes); break;
      default: FAIL();
    }
    // And through the datagram walk: decoded once, nothing else counted.
    net::DatagramParser parser;
    net::Counters c;
    EXPECT_EQ(parser.parse(bytes, c, [](const auto&) {}), 1u) << name;
    EXPECT_EQ(c.decoded[static_cast<std::size_t>(type)], 1u) << name;
    EXPECT_EQ(c.pdus_seen, 1u) << name;
    ++checked;
  }
  EXPECT_EQ(checked, 9u);
}

TEST(Captures, KnownContents) {
  // Spot checks of decoded values against the capture bytes.
  auto es = net::decode_as<net::EntityStatePdu>(
      read_file(captures_dir() / "dis_EntityStatePdu-vbs-articulated-parameters.raw"));
  ASSERT_TRUE(es.ok());
  EXPECT_EQ(es.value().header.protocol_version, 6);
  EXPECT_EQ(es.value().variable_parameters.size(), 16u);  // 400 = 144 + 16 x 16
  auto art = net::decode_as<net::EntityStatePdu>(
      read_file(captures_dir() / "dis7_EntityStatePdu-articulated_parts.raw"));
  ASSERT_TRUE(art.ok());
  EXPECT_EQ(art.value().variable_parameters.size(), 2u);
  auto det = net::decode_as<net::DetonationPdu>(
      read_file(captures_dir() / "dis7_DetonationPdu_Descriptors_VariableParameters.raw"));
  ASSERT_TRUE(det.ok());
  EXPECT_EQ(det.value().variable_parameters.size(), 6u);  // 200 = 104 + 16 x 6
}

TEST(Captures, OtherTypesAreSkippedAndCounted) {
  for (const auto& name : kSkipped) {
    const auto bytes = read_file(captures_dir() / name);
    ASSERT_FALSE(bytes.empty()) << name;
    net::DatagramParser parser;
    net::Counters c;
    EXPECT_EQ(parser.parse(bytes, c, [](const auto&) {}), 0u) << name;
    EXPECT_EQ(c.skipped_unknown_type, 1u) << name;
    EXPECT_EQ(c.pdus_seen, 1u) << name;
    EXPECT_EQ(c.rejected_total(), 0u) << name;
    EXPECT_EQ(c.decoded_total(), 0u) << name;
  }
}

TEST(Captures, MalformedFilesAreRejectedCleanly) {
  {
    // First byte 0xFF, no PDU header: its "length" (55837) runs past the 86 octets.
    const auto bytes = read_file(captures_dir() / "dis7_StartResumePdu.raw");
    ASSERT_EQ(bytes.size(), 86u);
    net::DatagramParser parser;
    net::Counters c;
    EXPECT_EQ(parser.parse(bytes, c, [](const auto&) {}), 0u);
    EXPECT_EQ(c.rejected_for(net::DecodeError::LengthExceedsData), 1u);
    EXPECT_EQ(c.pdus_seen, 1u);
  }
  {
    // Aggregate State whose length field (496) is 12 short of the file (508): the PDU is
    // skipped by its length, and the 12 octets left read as a header of length 0 -> rejected.
    const auto bytes = read_file(captures_dir() / "dis7_AggregateStatePdu.raw");
    ASSERT_EQ(bytes.size(), 508u);
    net::DatagramParser parser;
    net::Counters c;
    EXPECT_EQ(parser.parse(bytes, c, [](const auto&) {}), 0u);
    EXPECT_EQ(c.skipped_unknown_type, 1u);
    EXPECT_EQ(c.rejected_for(net::DecodeError::LengthBelowHeader), 1u);
    EXPECT_EQ(c.pdus_seen, 2u);
  }
}

TEST(Captures, AllFilesInOneDatagramStream) {
  // Concatenate every well-formed capture into one buffer and walk it: every PDU is found.
  std::vector<std::uint8_t> all;
  for (const auto& n : capture_files()) {
    if (n == "dis7_StartResumePdu.raw" || n == "dis7_AggregateStatePdu.raw") continue;
    const auto b = read_file(captures_dir() / n);
    all.insert(all.end(), b.begin(), b.end());
  }
  net::DatagramParser parser;
  net::Counters c;
  EXPECT_EQ(parser.parse(all, c, [](const auto&) {}), 9u);
  EXPECT_EQ(c.decoded_total(), 9u);
  EXPECT_EQ(c.skipped_unknown_type, kSkipped.size());
  EXPECT_EQ(c.rejected_total(), 0u);
  EXPECT_EQ(c.pdus_seen, 9u + kSkipped.size());
}
