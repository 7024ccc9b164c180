// Interop with Wireshark's DIS dissector: PDUs we encode, wrapped in a pcap we write ourselves,
// must dissect without a malformed-packet mark and show the values we set.
// Skips (with a message) only when tshark is not installed.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <unistd.h>

#include "pcap_writer.hpp"
#include "run_command.hpp"
#include "test_util.hpp"

using namespace nettest;

namespace {

std::string pcap_path(const std::string& tag) {
  return binary_dir() + "/interop_" + tag + "_" + std::to_string(::getpid()) + ".pcap";
}

// tshark -T fields for one frame; returns field -> value ("a,b,c" when a field repeats).
std::map<std::string, std::string> tshark_fields(const std::string& pcap, int frame,
                                                 const std::vector<std::string>& fields) {
  std::string cmd = "tshark -r '" + pcap + "' -d udp.port==3000,dis -Y frame.number==" +
                    std::to_string(frame) + " -T fields -E separator='|' -E occurrence=a";
  for (const auto& f : fields) cmd += " -e " + f;
  cmd += " 2>/dev/null";
  const auto r = run_command(cmd);
  EXPECT_EQ(r.rc, 0) << cmd;
  const auto values = split(trim(r.out), '|');
  std::map<std::string, std::string> m;
  for (std::size_t i = 0; i < fields.size(); ++i) m[fields[i]] = i < values.size() ? values[i] : "";
  return m;
}

void expect_number(const std::map<std::string, std::string>& m, const std::string& field,
                   double expected) {
  const auto it = m.find(field);
  ASSERT_NE(it, m.end()) << field;
  ASSERT_FALSE(it->second.empty()) << field << " missing in tshark's dissection";
  const std::string first = split(it->second, ',')[0];
  EXPECT_NEAR(std::stod(first), expected, std::abs(expected) * 1e-6 + 1e-9) << field << " = " << it->second;
}

void expect_text(const std::map<std::string, std::string>& m, const std::string& field,
                 const std::string& expected) {
  EXPECT_EQ(m.at(field), expected) << field;
}

class TsharkInterop : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_tool("tshark")) GTEST_SKIP() << "tshark is not installed: interop test skipped";
  }
};

}  // namespace

TEST_F(TsharkInterop, OurPdusDissectCleanlyWithTheValuesWeSet) {
  net::EntityStatePdu es = sample_entity_state(2);
  es.header.exercise_id = 9;
  es.entity_id = {11, 22, 33};
  es.entity_type = {1, 1, 225, 1, 1, 3, 0};  // platform, land, USA, tank
  es.location = {-2707522.125, -4353260.5, 3781450.75};
  es.orientation = {1.5f, -0.25f, 0.125f};
  es.marking = net::make_marking("tank1").value();
  const net::FirePdu fire = sample_fire();
  const net::DetonationPdu det = sample_detonation(1);
  const net::CollisionPdu col = sample_collision();
  const net::EntityStateUpdatePdu esu = sample_esu(1);

  const std::string path = pcap_path("tshark");
  {
    PcapWriter w(path);
    ASSERT_TRUE(w.ok()) << path;
    w.add(bytes_of(es));
    w.add(bytes_of(fire));
    w.add(bytes_of(det));
    w.add(bytes_of(col));
    w.add(bytes_of(esu));
    // A captured Entity State from another simulator, re-encoded by us.
    auto vbs = net::decode_as<net::EntityStatePdu>(
        read_file(captures_dir() / "dis_EntityStatePdu-vbs-articulated-parameters.raw"));
    ASSERT_TRUE(vbs.ok());
    w.add(bytes_of(vbs.value()));
  }

  // 1. Nothing malformed.
  const auto malformed = run_command("tshark -r '" + path + "' -d udp.port==3000,dis -Y _ws.malformed 2>/dev/null");
  EXPECT_EQ(malformed.rc, 0);
  EXPECT_EQ(malformed.out, "") << "tshark marks frames malformed:\n" << malformed.out;
  // And it did dissect six DIS frames.
  const auto all = run_command("tshark -r '" + path + "' -d udp.port==3000,dis -Y dis -T fields -e dis.pdu_type 2>/dev/null");
  EXPECT_EQ(all.out, "1\n2\n3\n4\n67\n1\n");

  // 2. Values, frame by frame.
  auto f = tshark_fields(path, 1,
                         {"dis.proto_ver", "dis.exer_id", "dis.pdu_type", "dis.proto_fam",
                          "dis.pdu_length", "dis.entity_id_site", "dis.entity_id_application",
                          "dis.entity_id_entity", "dis.force_id", "dis.entityKind", "dis.entityDomain",
                          "dis.country", "dis.entity_marking", "dis.entity_location.x",
                          "dis.entity_location.y", "dis.entity_location.z",
                          "dis.entity_orientation.psi", "dis.entity_orientation.theta",
                          "dis.entity_orientation.phi", "dis.entity_linear_velocity.x",
                          "dis.entity_linear_velocity.z", "dis.appearance", "dis.capabilities",
                          "dis.entity_linear_acceleration.z", "dis.entity_angular_velocity.y"});
  expect_text(f, "dis.proto_ver", "7");
  expect_text(f, "dis.exer_id", "9");
  expect_text(f, "dis.pdu_type", "1");
  expect_text(f, "dis.proto_fam", "1");
  expect_text(f, "dis.pdu_length", "176");
  expect_text(f, "dis.entity_id_site", "11");
  expect_text(f, "dis.entity_id_application", "22");
  expect_text(f, "dis.entity_id_entity", "33");
  expect_text(f, "dis.force_id", "2");
  expect_text(f, "dis.entityKind", "1,1");  // entity type, alternative type
  expect_text(f, "dis.entityDomain", "1,3");
  expect_number(f, "dis.country", 225);
  expect_text(f, "dis.entity_marking", "tank1");
  expect_number(f, "dis.entity_location.x", -2707522.125);
  expect_number(f, "dis.entity_location.y", -4353260.5);
  expect_number(f, "dis.entity_location.z", 3781450.75);
  expect_number(f, "dis.entity_orientation.psi", 1.5);
  expect_number(f, "dis.entity_orientation.theta", -0.25);
  expect_number(f, "dis.entity_orientation.phi", 0.125);
  expect_number(f, "dis.entity_linear_velocity.x", 1.5);
  expect_number(f, "dis.entity_linear_velocity.z", 3.125);
  expect_text(f, "dis.appearance", "0x00a1b2c3");
  expect_number(f, "dis.capabilities", 3405691582.0);  // 0xCAFEBABE
  expect_number(f, "dis.entity_linear_acceleration.z", -9.75);
  expect_number(f, "dis.entity_angular_velocity.y", -0.02);

  f = tshark_fields(path, 2,
                    {"dis.pdu_type", "dis.proto_fam", "dis.entity_id_site", "dis.entity_id_entity",
                     "dis.event_number", "dis.fire.mission_index", "dis.fire.location.x",
                     "dis.fire.location.y", "dis.fire.location.z", "dis.warhead", "dis.fuse",
                     "dis.quality", "dis.rate", "dis.linear_velocity.x", "dis.range"});
  expect_text(f, "dis.pdu_type", "2");
  expect_text(f, "dis.proto_fam", "2");
  expect_text(f, "dis.entity_id_site", "11,44,11");       // firing, target, munition
  expect_text(f, "dis.entity_id_entity", "33,66,900");
  expect_text(f, "dis.event_number", "7");
  expect_number(f, "dis.fire.mission_index", 3735928559.0);  // 0xDEADBEEF
  expect_number(f, "dis.fire.location.x", -2707500.5);
  expect_number(f, "dis.fire.location.y", -4353200.25);
  expect_number(f, "dis.fire.location.z", 3781400.125);
  expect_number(f, "dis.warhead", 1000);
  expect_number(f, "dis.fuse", 1010);
  expect_number(f, "dis.quality", 3);  // tshark's name for the quantity
  expect_number(f, "dis.rate", 600);
  expect_number(f, "dis.linear_velocity.x", 250.0);
  expect_number(f, "dis.range", 1500.0);

  f = tshark_fields(path, 3,
                    {"dis.pdu_type", "dis.entity_id_entity", "dis.detonation.location.x",
                     "dis.detonation.location.z", "dis.detonation.result", "dis.entity_location.x",
                     "dis.entity_location.y", "dis.linear_velocity.z", "dis.warhead"});
  expect_text(f, "dis.pdu_type", "3");
  expect_text(f, "dis.entity_id_entity", "33,66,900");
  expect_number(f, "dis.detonation.location.x", -2707400.5);
  expect_number(f, "dis.detonation.location.z", 3781300.125);
  expect_text(f, "dis.detonation.result", "5");
  expect_number(f, "dis.entity_location.x", 1.0);  // location in entity coordinates
  expect_number(f, "dis.entity_location.y", -0.5);
  expect_number(f, "dis.linear_velocity.z", -300.5);
  expect_number(f, "dis.warhead", 1000);

  f = tshark_fields(path, 4,
                    {"dis.pdu_type", "dis.proto_fam", "dis.entity_id_site", "dis.entity_id_entity",
                     "dis.event_number", "dis.collision.type", "dis.collision.mass",
                     "dis.collision.location.x", "dis.collision.location.z", "dis.linear_velocity.y"});
  expect_text(f, "dis.pdu_type", "4");
  expect_text(f, "dis.proto_fam", "1");
  expect_text(f, "dis.entity_id_site", "11,44");
  expect_text(f, "dis.entity_id_entity", "33,66");
  expect_text(f, "dis.event_number", "8");
  expect_text(f, "dis.collision.type", "1");
  expect_number(f, "dis.collision.mass", 62000.0);
  expect_number(f, "dis.collision.location.x", 3.5);
  expect_number(f, "dis.collision.location.z", -1.25);

  f = tshark_fields(path, 5,
                    {"dis.pdu_type", "dis.entity_id_entity", "dis.entity_location.x",
                     "dis.entity_location.z", "dis.entity_orientation.psi", "dis.appearance"});
  expect_text(f, "dis.pdu_type", "67");
  expect_text(f, "dis.entity_id_entity", "33");
  expect_number(f, "dis.entity_location.x", -2707522.125);
  expect_number(f, "dis.entity_location.z", 3781450.75);
  expect_number(f, "dis.entity_orientation.psi", 0.5);
  expect_text(f, "dis.appearance", "0x00000042");

  f = tshark_fields(path, 6, {"dis.proto_ver", "dis.pdu_type", "dis.pdu_length"});
  expect_text(f, "dis.proto_ver", "6");
  expect_text(f, "dis.pdu_length", "400");
  std::filesystem::remove(path);
}

TEST_F(TsharkInterop, MalformedFilterCatchesATruncatedPdu) {
  // Control for the check above: a cut Entity State is flagged, so an empty answer means something.
  const std::string path = pcap_path("tshark_bad");
  {
    PcapWriter w(path);
    auto b = bytes_of(sample_entity_state(2));
    b.resize(100);
    w.add(b);
  }
  const auto r = run_command("tshark -r '" + path + "' -d udp.port==3000,dis -Y _ws.malformed 2>/dev/null");
  EXPECT_NE(r.out.find("Malformed"), std::string::npos) << r.out;
  std::filesystem::remove(path);
}
