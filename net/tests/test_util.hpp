// test_util.hpp — shared helpers for the net/ tests: sample PDUs, big-endian peeks, files.
#pragma once

#include <unistd.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "net/net.hpp"

namespace nettest {

inline std::uint16_t be16(std::span<const std::uint8_t> b, std::size_t o) {
  return static_cast<std::uint16_t>((b[o] << 8) | b[o + 1]);
}
inline std::uint32_t be32(std::span<const std::uint8_t> b, std::size_t o) {
  return (std::uint32_t{b[o]} << 24) | (std::uint32_t{b[o + 1]} << 16) |
         (std::uint32_t{b[o + 2]} << 8) | b[o + 3];
}
inline std::uint64_t be64(std::span<const std::uint8_t> b, std::size_t o) {
  return (std::uint64_t{be32(b, o)} << 32) | be32(b, o + 4);
}
inline float bef32(std::span<const std::uint8_t> b, std::size_t o) {
  return std::bit_cast<float>(be32(b, o));
}
inline double bef64(std::span<const std::uint8_t> b, std::size_t o) {
  return std::bit_cast<double>(be64(b, o));
}

inline std::vector<std::uint8_t> read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The checkout's and build's folders (test_dirs.cpp): the captures, the open-dis scripts, the
// build tree (scratch files).
std::filesystem::path captures_dir();
std::string js_dir();
std::string binary_dir();

inline net::VariableParameter vp(std::uint8_t type, std::uint8_t seed) {
  net::VariableParameter v;
  v.record_type = type;
  for (std::size_t i = 0; i < v.data.size(); ++i) v.data[i] = static_cast<std::uint8_t>(seed + i);
  return v;
}

// Entity State with a distinct value in every field.
inline net::EntityStatePdu sample_entity_state(std::size_t parts = 2) {
  net::EntityStatePdu p;
  p.header.exercise_id = 9;
  p.header.timestamp = 0x12345678;
  p.header.pdu_status = 0x02;
  p.entity_id = {11, 22, 33};
  p.force_id = 2;
  p.entity_type = {1, 2, 225, 3, 4, 5, 6};
  p.alternative_entity_type = {1, 3, 222, 7, 8, 9, 10};
  p.linear_velocity = {1.5f, -2.25f, 3.125f};
  p.location = {-2707522.125, -4353260.5, 3781450.75};
  p.orientation = {0.5f, -0.25f, 0.125f};
  p.appearance = 0x00A1B2C3;
  p.dead_reckoning.algorithm = 4;
  for (std::size_t i = 0; i < 15; ++i) p.dead_reckoning.other[i] = static_cast<std::uint8_t>(0xE0 + i);
  p.dead_reckoning.linear_acceleration = {0.5f, 0.75f, -9.75f};
  p.dead_reckoning.angular_velocity = {0.01f, -0.02f, 0.03f};
  p.marking = net::make_marking("tank1").value();
  p.capabilities = 0xCAFEBABE;
  for (std::size_t i = 0; i < parts; ++i) p.variable_parameters.push_back(vp(0, static_cast<std::uint8_t>(16 * i)));
  return p;
}

inline net::FirePdu sample_fire() {
  net::FirePdu p;
  p.header.exercise_id = 9;
  p.header.timestamp = 0x0000BEEF;
  p.firing_entity_id = {11, 22, 33};
  p.target_entity_id = {44, 55, 66};
  p.munition_id = {11, 22, 900};
  p.event_id = {11, 22, 7};
  p.fire_mission_index = 0xDEADBEEF;
  p.location = {-2707500.5, -4353200.25, 3781400.125};
  p.descriptor = {{2, 2, 225, 2, 14, 0, 0}, 1000, 1010, 3, 600};
  p.velocity = {250.0f, 125.5f, 30.25f};
  p.range = 1500.0f;
  return p;
}

inline net::DetonationPdu sample_detonation(std::size_t parts = 1) {
  net::DetonationPdu p;
  p.header.exercise_id = 9;
  p.firing_entity_id = {11, 22, 33};
  p.target_entity_id = {44, 55, 66};
  p.exploding_entity_id = {11, 22, 900};
  p.event_id = {11, 22, 7};
  p.velocity = {-10.0f, 20.0f, -300.5f};
  p.location = {-2707400.5, -4353100.25, 3781300.125};
  p.descriptor = {{2, 2, 225, 2, 14, 0, 0}, 1000, 1010, 1, 0};
  p.location_in_entity = {1.0f, -0.5f, 0.25f};
  p.detonation_result = 5;
  p.padding = 0x0102;
  for (std::size_t i = 0; i < parts; ++i) p.variable_parameters.push_back(vp(1, static_cast<std::uint8_t>(100 + i)));
  return p;
}

inline net::CollisionPdu sample_collision() {
  net::CollisionPdu p;
  p.header.exercise_id = 9;
  p.issuing_entity_id = {11, 22, 33};
  p.colliding_entity_id = {44, 55, 66};
  p.event_id = {11, 22, 8};
  p.collision_type = 1;
  p.padding = 0x5A;
  p.velocity = {5.0f, -6.0f, 0.5f};
  p.mass = 62000.0f;
  p.location_in_entity = {3.5f, 0.0f, -1.25f};
  return p;
}

inline net::EntityStateUpdatePdu sample_esu(std::size_t parts = 1) {
  net::EntityStateUpdatePdu p;
  p.header.exercise_id = 9;
  p.entity_id = {11, 22, 33};
  p.padding = 0x77;
  p.linear_velocity = {1.0f, 2.0f, 3.0f};
  p.location = {-2707522.125, -4353260.5, 3781450.75};
  p.orientation = {0.5f, -0.25f, 0.125f};
  p.appearance = 0x00000042;
  for (std::size_t i = 0; i < parts; ++i) p.variable_parameters.push_back(vp(0, static_cast<std::uint8_t>(50 + i)));
  return p;
}

template <class Pdu>
std::vector<std::uint8_t> bytes_of(const Pdu& p) {
  std::vector<std::uint8_t> out;
  auto r = net::encode_append(p, out);
  if (!r) out.clear();
  return out;
}

// A port for this test process, so parallel ctest runs of the transport tests do not meet.
inline std::uint16_t test_port(int slot) {
  return static_cast<std::uint16_t>(20000 + (::getpid() % 9000) * 4 + slot);
}

}  // namespace nettest
