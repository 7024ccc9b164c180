// Writes the hand-made datagram seeds (fuzz/corpus/datagram/node_*): PDUs that speak for node 2
// of fuzz/data/scenarios/net.toml (site 1, app 2), at the places of that world, so that the fuzzer
// starts from inputs that reach deep into the bridge. Run: replay build's make_datagram_seeds DIR.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "net/net.hpp"
#include "world/scenario.hpp"

using namespace npsnet;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_datagram_seeds DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  const auto sc = world::load_scenario(fuzz::data_dir() / "scenarios" / "net.toml");
  const world::World w = world::build_world(sc);
  const auto& frame = w.terrain.frame();
  auto ecef = [&](double x, double y, double z) {
    const Vec3 p = frame.to_ecef(Vec3(x, y, z));
    return net::Vec3d{p.x(), p.y(), p.z()};
  };
  auto ground = [&](double x, double y) { return ecef(x, y, w.terrain.height(x, y)); };
  auto type_of = [&](const char* kind) {
    const auto& d = w.kinds[w.kinds.find(kind)].dis;
    return net::EntityType{d.kind, d.domain, d.country, d.category, d.subcategory, d.specific, d.extra};
  };
  auto es = [&](std::uint16_t entity, const char* kind, const char* marking, net::Vec3d at) {
    net::EntityStatePdu p;
    p.entity_id = {1, 2, entity};
    p.entity_type = type_of(kind);
    p.marking = net::make_marking(marking).value();
    p.location = at;
    p.linear_velocity = {3.f, 0.f, 0.f};
    p.dead_reckoning.algorithm = 4;  // RVW
    return p;
  };
  auto write = [&](const std::string& name, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(dir + "/node_" + name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                                  static_cast<std::streamsize>(bytes.size()));
  };
  auto bytes = [](const auto&... pdus) {
    std::vector<std::uint8_t> out;
    (net::encode_append(pdus, out), ...);
    return out;
  };
  // apc2 is entity 2 of node 2 (entity number = scenario index + 1), heli2 entity 3.
  const auto apc = es(2, "bmp", "apc2", ground(1255.0, 260.0));
  auto heli = es(3, "ah64", "heli2", ecef(1250.0, 240.0, 400.0));
  heli.dead_reckoning.algorithm = 5;  // RVB
  const auto stranger = es(40, "f16", "stranger", ecef(500.0, 300.0, 900.0));
  auto dead = apc;
  dead.appearance = 3u << 3;  // destroyed
  auto gone = apc;
  gone.appearance = 1u << 23;  // deactivated
  net::EntityStateUpdatePdu esu;
  esu.entity_id = apc.entity_id;
  esu.location = ground(1252.0, 260.0);
  net::CollisionPdu col;
  col.issuing_entity_id = apc.entity_id;
  col.colliding_entity_id = {1, 1, 1};  // tank1, ours
  col.mass = 13000.f;
  col.velocity = {-5.f, 0.f, 0.f};
  net::FirePdu fire;
  fire.firing_entity_id = apc.entity_id;
  fire.target_entity_id = {1, 1, 1};
  fire.munition_id = {1, 2, 500};
  fire.location = apc.location;
  fire.descriptor.munition_type = type_of("he_round");
  net::DetonationPdu det;
  det.firing_entity_id = apc.entity_id;
  det.exploding_entity_id = fire.munition_id;
  det.location = ground(1233.34, 249.02);  // the first tree of the objects file
  det.descriptor.munition_type = type_of("he_round");
  det.detonation_result = 3;  // ground impact
  auto tree = es(1, "tree", "T0000001", ground(1233.34, 249.02));
  tree.entity_id.application = 0x8000 | 2;  // cultural feature: object index 0
  tree.appearance = 2;                      // stump
  write("es_apc2", bytes(apc));
  write("es_heli2_rvb", bytes(heli));
  write("es_unknown_marking", bytes(stranger));
  write("es_then_esu", bytes(apc, esu));
  write("es_destroyed", bytes(dead));
  write("es_deactivated", bytes(apc, gone));
  write("collision_with_ours", bytes(apc, col));
  write("fire_detonation", bytes(apc, fire, det));
  write("cultural_tree_stump", bytes(tree));
  return 0;
}
