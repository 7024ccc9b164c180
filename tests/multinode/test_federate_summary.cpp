// Remote entities in the summaries (issue 10, defect 7), through the real path: a peer's two
// vehicles (one Latin-1 marking, one with a control character) in a running node; SIGUSR1 in the
// middle of the run and the end-of-run summary each list them (id, marking made safe, type and
// kind, owner site/application, last update age, damage). The old node printed only a count.
#include <gtest/gtest.h>
#include <signal.h>

#include <cstring>

#include "peer_support.hpp"

namespace {
size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(FederateSummary, Usr1AndEndOfRunListRemoteEntities) {
  const auto w = fed::world_of("federate.toml");
  lan::Procs procs;
  auto node = fed::start_node(procs, "fed_summary", "federate.toml", 3.0);
  net::Session peer(fed::peer_config(node.port));
  net::EntityStatePdu r1;
  r1.entity_id = peer.entity_id(1);
  r1.entity_type = {1, 1, 225, 1, 1, 3, 0};  // m1a1
  const char tank[] = {'T', static_cast<char>(0xC4), 'N', 'K'};
  std::memcpy(r1.marking.characters.data(), tank, sizeof tank);
  r1.location = fed::ecef(w, 300, 300);
  r1.dead_reckoning.algorithm = 1;
  r1.appearance = 1u << 3;  // slight damage
  auto r2 = r1;
  r2.entity_id = peer.entity_id(2);
  r2.entity_type = {1, 2, 225, 1, 9, 9, 0};  // an aircraft no kind has: generic_air
  r2.marking = {};
  const char ctl[] = {'a', 0x01, 'b'};
  std::memcpy(r2.marking.characters.data(), ctl, sizeof ctl);
  r2.location = fed::ecef(w, 100, 300, 500);
  r2.appearance = 0;
  fed::sleep_until(node.start + 0.3);
  peer.send(r1), peer.send(r2);
  fed::sleep_until(node.start + 1.5);
  ASSERT_EQ(::kill(node.pid, SIGUSR1), 0);
  fed::sleep_until(node.start + 2.0);
  peer.send(r1);
  ASSERT_EQ(procs.wait(node.pid, 30.0), 0) << lan::read_text(node.out);
  const std::string out = lan::read_text(node.out);
  EXPECT_EQ(count_of(out, "remote 1:50:1 \"T\xC3\x84NK\" type 1:1:225:1:1:3:0 (m1a1) owner site 1 app 50 last update "), 2u)
      << "once on SIGUSR1, once at the end:\n" << out;
  EXPECT_EQ(count_of(out, "damage damaged (appearance damage 1)"), 2u) << out;
  EXPECT_EQ(count_of(out, "remote 1:50:2 "), 2u) << out;
  EXPECT_EQ(out.find('\x01'), std::string::npos) << "no control character reaches the terminal";
  EXPECT_NE(out.find("type 1:2:225:1:9:9:0 (generic_air)"), std::string::npos) << out;
  std::filesystem::remove_all(node.dir);
}
