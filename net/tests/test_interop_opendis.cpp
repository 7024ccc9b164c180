// Interop with the npm open-dis 1.3.6 DIS 7 implementation (net/tests/js):
//  (a) PDUs we encode are decoded by open-dis, field by field equal to ours;
//  (b) PDUs open-dis encodes are decoded by us, field by field equal to what it set.
// Both sides print "index.path=value" lines with open-dis's field names. Skips (with a message)
// only when node/npm are absent; runs `npm ci` (under a lock) if node_modules is missing.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <map>
#include <unistd.h>
#include <variant>

#include "run_command.hpp"
#include "test_util.hpp"

using namespace nettest;

namespace {

using Fields = std::map<std::string, std::string>;

std::string num(double v) {
  if (std::isnan(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

class Flat {
 public:
  explicit Flat(std::string prefix) : p_(std::move(prefix)) {}
  void put(const std::string& k, double v) { f_[p_ + "." + k] = num(v); }
  void id(const std::string& k, const net::EntityId& e) {
    put(k + ".siteID", e.site), put(k + ".applicationID", e.application), put(k + ".entityID", e.entity);
  }
  void event(const std::string& k, const net::EventId& e) {
    put(k + ".simulationAddress.site", e.site), put(k + ".simulationAddress.application", e.application);
    put(k + ".eventNumber", e.event_number);
  }
  void type(const std::string& k, const net::EntityType& t) {
    put(k + ".entityKind", t.kind), put(k + ".domain", t.domain), put(k + ".country", t.country);
    put(k + ".category", t.category), put(k + ".subcategory", t.subcategory);
    put(k + ".specific", t.specific), put(k + ".extra", t.extra);
  }
  void vec(const std::string& k, const net::Vec3f& v) { put(k + ".x", v.x), put(k + ".y", v.y), put(k + ".z", v.z); }
  void vec(const std::string& k, const net::Vec3d& v) { put(k + ".x", v.x), put(k + ".y", v.y), put(k + ".z", v.z); }
  void header(const net::PduHeader& h) {
    put("protocolVersion", h.protocol_version), put("exerciseID", h.exercise_id);
    put("pduType", h.pdu_type), put("protocolFamily", h.protocol_family);
    put("timestamp", h.timestamp), put("length", h.length), put("pduStatus", h.pdu_status);
    put("padding", h.padding);
  }
  void descriptor(const std::string& k, const net::MunitionDescriptor& d) {
    type(k + ".munitionType", d.munition_type);
    put(k + ".warhead", d.warhead), put(k + ".fuse", d.fuse), put(k + ".quantity", d.quantity);
    put(k + ".rate", d.rate);
  }
  // open-dis reads a record as u8 type, f64, u32, u16, u8.
  void params(const std::vector<net::VariableParameter>& vs) {
    put("numberOfVariableParameters", static_cast<double>(vs.size()));
    for (std::size_t i = 0; i < vs.size(); ++i) {
      const auto& d = vs[i].data;
      const std::string k = "variableParameters." + std::to_string(i);
      std::uint64_t f1 = 0;
      for (int b = 0; b < 8; ++b) f1 = (f1 << 8) | d[b];
      put(k + ".recordType", vs[i].record_type);
      put(k + ".variableParameterFields1", std::bit_cast<double>(f1));
      put(k + ".variableParameterFields2", (std::uint32_t{d[8]} << 24) | (d[9] << 16) | (d[10] << 8) | d[11]);
      put(k + ".variableParameterFields3", (d[12] << 8) | d[13]);
      put(k + ".variableParameterFields4", d[14]);
    }
  }
  Fields& fields() { return f_; }

 private:
  std::string p_;
  Fields f_;
};

Fields flatten(const net::EntityStatePdu& p, const std::string& i) {
  Flat f(i);
  f.header(p.header);
  f.id("entityID", p.entity_id);
  f.put("forceId", p.force_id);
  f.type("entityType", p.entity_type);
  f.type("alternativeEntityType", p.alternative_entity_type);
  f.vec("entityLinearVelocity", p.linear_velocity);
  f.vec("entityLocation", p.location);
  f.put("entityOrientation.psi", p.orientation.psi);
  f.put("entityOrientation.theta", p.orientation.theta);
  f.put("entityOrientation.phi", p.orientation.phi);
  f.put("entityAppearance", p.appearance);
  f.put("deadReckoningParameters.deadReckoningAlgorithm", p.dead_reckoning.algorithm);
  for (int k = 0; k < 15; ++k)
    f.put("deadReckoningParameters.parameters." + std::to_string(k), p.dead_reckoning.other[k]);
  f.vec("deadReckoningParameters.entityLinearAcceleration", p.dead_reckoning.linear_acceleration);
  f.vec("deadReckoningParameters.entityAngularVelocity", p.dead_reckoning.angular_velocity);
  f.put("marking.characterSet", p.marking.character_set);
  f.fields()[i + ".marking.text"] = net::marking_text(p.marking);
  f.put("capabilities", p.capabilities);
  f.params(p.variable_parameters);
  return f.fields();
}

Fields flatten(const net::FirePdu& p, const std::string& i) {
  Flat f(i);
  f.header(p.header);
  f.id("firingEntityID", p.firing_entity_id);
  f.id("targetEntityID", p.target_entity_id);
  f.id("munitionExpendibleID", p.munition_id);
  f.event("eventID", p.event_id);
  f.put("fireMissionIndex", p.fire_mission_index);
  f.vec("locationInWorldCoordinates", p.location);
  f.descriptor("descriptor", p.descriptor);
  f.vec("velocity", p.velocity);
  f.put("range", p.range);
  return f.fields();
}

Fields flatten(const net::DetonationPdu& p, const std::string& i) {
  Flat f(i);
  f.header(p.header);
  f.id("firingEntityID", p.firing_entity_id);
  f.id("targetEntityID", p.target_entity_id);
  f.id("explodingEntityID", p.exploding_entity_id);
  f.event("eventID", p.event_id);
  f.vec("velocity", p.velocity);
  f.vec("locationInWorldCoordinates", p.location);
  f.descriptor("descriptor", p.descriptor);
  f.vec("locationOfEntityCoordinates", p.location_in_entity);
  f.put("detonationResult", p.detonation_result);
  f.put("pad", p.padding);
  f.params(p.variable_parameters);
  return f.fields();
}

Fields flatten(const net::CollisionPdu& p, const std::string& i) {
  Flat f(i);
  f.header(p.header);
  f.id("issuingEntityID", p.issuing_entity_id);
  f.id("collidingEntityID", p.colliding_entity_id);
  f.event("eventID", p.event_id);
  f.put("collisionType", p.collision_type);
  f.put("pad", static_cast<std::int8_t>(p.padding));  // open-dis reads it signed
  f.vec("velocity", p.velocity);
  f.put("mass", p.mass);
  f.vec("location", p.location_in_entity);
  return f.fields();
}

Fields flatten(const net::EntityStateUpdatePdu& p, const std::string& i) {
  Flat f(i);
  f.header(p.header);
  f.id("entityID", p.entity_id);
  f.put("padding1", static_cast<std::int8_t>(p.padding));  // open-dis reads it signed
  f.vec("entityLinearVelocity", p.linear_velocity);
  f.vec("entityLocation", p.location);
  f.put("entityOrientation.psi", p.orientation.psi);
  f.put("entityOrientation.theta", p.orientation.theta);
  f.put("entityOrientation.phi", p.orientation.phi);
  f.put("entityAppearance", p.appearance);
  f.params(p.variable_parameters);
  return f.fields();
}

// Simulation management (open-dis dis7 field names).
template <class Pdu>
Flat siman(const Pdu& p, const std::string& i) {
  Flat f(i);
  f.header(p.header);
  f.id("originatingEntityID", p.originating_id);
  f.id("receivingEntityID", p.receiving_id);
  f.put("requestID", p.request_id);
  return f;
}
void clock(Flat& f, const std::string& k, const net::ClockTime& c) {
  f.put(k + ".hour", c.hour), f.put(k + ".timePastHour", c.time_past_hour);
}
Fields flatten(const net::RemoveEntityPdu& p, const std::string& i) { return siman(p, i).fields(); }
Fields flatten(const net::StartResumePdu& p, const std::string& i) {
  Flat f = siman(p, i);
  clock(f, "realWorldTime", p.real_world_time);
  clock(f, "simulationTime", p.simulation_time);
  return f.fields();
}
Fields flatten(const net::StopFreezePdu& p, const std::string& i) {
  Flat f = siman(p, i);
  clock(f, "realWorldTime", p.real_world_time);
  f.put("reason", p.reason), f.put("frozenBehavior", p.frozen_behavior), f.put("padding1", p.padding);
  return f.fields();
}
Fields flatten(const net::AcknowledgePdu& p, const std::string& i) {
  Flat f = siman(p, i);
  f.put("acknowledgeFlag", p.acknowledge_flag), f.put("responseFlag", p.response_flag);
  return f.fields();
}

Fields parse_lines(const std::string& text) {
  Fields m;
  for (const auto& line : split(text, '\n')) {
    const auto eq = line.find('=');
    if (eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return m;
}

bool same_value(const std::string& a, const std::string& b) {
  if (a == b) return true;
  char* ea = nullptr;
  char* eb = nullptr;
  const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
  return ea && eb && *ea == '\0' && *eb == '\0' && !a.empty() && !b.empty() && x == y;
}

// Every key on both sides, equal values.
void expect_same(const Fields& ours, const Fields& theirs, const std::string& what) {
  std::size_t compared = 0;
  for (const auto& [k, v] : ours) {
    auto it = theirs.find(k);
    if (it == theirs.end()) {
      ADD_FAILURE() << what << ": open-dis has no field " << k;
      continue;
    }
    EXPECT_TRUE(same_value(v, it->second)) << what << ": " << k << " ours " << v << " open-dis " << it->second;
    ++compared;
  }
  for (const auto& [k, v] : theirs)
    if (k != "count" && !ours.count(k)) ADD_FAILURE() << what << ": we lack open-dis field " << k << "=" << v;
  EXPECT_GT(compared, 20u) << what;
}


class OpenDisInterop : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_tool("node")) GTEST_SKIP() << "node is not installed: open-dis interop test skipped";
    if (!std::filesystem::exists(js_dir() + "/node_modules/open-dis/dist/dis7.min.js")) {
      if (!have_tool("npm")) GTEST_SKIP() << "npm is not installed: open-dis interop test skipped";
      // Serialised: ctest may run the tests of this fixture in parallel.
      const std::string cmd = "cd '" + js_dir() + "' && flock .npm-ci.lock sh -c 'test -e "
                              "node_modules/open-dis/dist/dis7.min.js || npm ci --no-audit --no-fund' 2>&1";
      const auto r = run_command(cmd);
      ASSERT_EQ(r.rc, 0) << "npm ci in " << js_dir() << " failed:\n" << r.out;
    }
    path_ = binary_dir() + "/opendis_" + std::to_string(::getpid()) + ".bin";
  }
  void TearDown() override {
    if (!path_.empty()) std::filesystem::remove(path_);
  }
  std::string path_;
};

}  // namespace

TEST_F(OpenDisInterop, OpenDisDecodesWhatWeEncode) {
  const auto es = sample_entity_state(2);
  const auto fire = sample_fire();
  const auto det = sample_detonation(1);
  const auto col = sample_collision();
  const auto esu = sample_esu(1);
  std::vector<std::uint8_t> all;
  for (auto b : {bytes_of(es), bytes_of(fire), bytes_of(det), bytes_of(col), bytes_of(esu)})
    all.insert(all.end(), b.begin(), b.end());
  {
    std::ofstream out(path_, std::ios::binary);
    out.write(reinterpret_cast<const char*>(all.data()), static_cast<std::streamsize>(all.size()));
  }
  const auto r = run_command("cd '" + js_dir() + "' && node decode.js '" + path_ + "' 2>&1");
  ASSERT_EQ(r.rc, 0) << r.out;
  const Fields theirs = parse_lines(r.out);
  ASSERT_EQ(theirs.at("count"), "5");
  // Our structs carry length 0 until decoded; compare with what went on the wire.
  auto with_len = [](auto p) {
    p.header.length = static_cast<std::uint16_t>(net::encoded_size(p));
    p.header.pdu_type = static_cast<std::uint8_t>(bytes_of(p)[2]);
    return p;
  };
  auto sub = [&](const std::string& i) {
    Fields m;
    for (const auto& [k, v] : theirs)
      if (k.rfind(i + ".", 0) == 0) m[k] = v;
    return m;
  };
  expect_same(flatten(with_len(es), "0"), sub("0"), "entity state");
  expect_same(flatten(with_len(fire), "1"), sub("1"), "fire");
  expect_same(flatten(with_len(det), "2"), sub("2"), "detonation");
  expect_same(flatten(with_len(col), "3"), sub("3"), "collision");
  expect_same(flatten(with_len(esu), "4"), sub("4"), "entity state update");
}

TEST_F(OpenDisInterop, WeDecodeWhatOpenDisEncodes) {
  const auto r = run_command("cd '" + js_dir() + "' && node encode.js '" + path_ + "' 2>&1");
  ASSERT_EQ(r.rc, 0) << r.out;
  const Fields set = parse_lines(r.out);
  ASSERT_EQ(set.at("count"), "5");
  const auto bytes = read_file(path_);
  ASSERT_EQ(bytes.size(), 176u + 96u + 120u + 60u + 72u);

  // Walk the five PDUs as one datagram, as a receiver would.
  net::DatagramParser parser;
  net::Counters counters;
  Fields ours;
  int index = 0;
  parser.parse(bytes, counters, [&](const auto& pdu) {
    const auto f = flatten(pdu, std::to_string(index++));
    ours.insert(f.begin(), f.end());
  });
  EXPECT_EQ(index, 5) << counters.summary();
  EXPECT_EQ(counters.rejected_total(), 0u) << counters.summary();
  Fields theirs = set;
  theirs.erase("count");
  expect_same(ours, theirs, "open-dis encoded");
  // And our re-encoding of their bytes is byte-exact.
  std::vector<std::uint8_t> again;
  std::size_t off = 0;
  auto es = net::decode_as<net::EntityStatePdu>(std::span(bytes).subspan(off));
  ASSERT_TRUE(es.ok());
  EXPECT_EQ(net::marking_text(es.value().marking), "f16-lead");
  for (auto b : {bytes_of(es.value())}) again.insert(again.end(), b.begin(), b.end());
  off += 176;
  auto fire = net::decode_as<net::FirePdu>(std::span(bytes).subspan(off));
  ASSERT_TRUE(fire.ok());
  auto fb = bytes_of(fire.value());
  again.insert(again.end(), fb.begin(), fb.end());
  EXPECT_TRUE(std::equal(again.begin(), again.end(), bytes.begin()));
}
