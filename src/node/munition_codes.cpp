#include "node/munition_codes.hpp"

#include <array>

namespace npsnet::node {

namespace {
// SISO-REF-010 Detonation Result codes 0..33 (IEEE 1278.1-2012 Detonation PDU field 7.3.3).
constexpr std::array<DetonationResultInfo, 34> kResults{{
    {"other", true, true},                   // 0
    {"entity_impact", false, true},          // 1
    {"entity_proximate", false, true},       // 2
    {"ground_impact", true, true},           // 3
    {"ground_proximate", false, true},       // 4: bursts above the ground
    {"detonation", true, true},              // 5
    {"dud", false, false},                   // 6: none or no detonation
    {"he_hit_small", false, true},           // 7
    {"he_hit_medium", false, true},          // 8
    {"he_hit_large", false, true},           // 9
    {"armor_piercing_hit", false, true},     // 10
    {"dirt_blast_small", true, true},        // 11
    {"dirt_blast_medium", true, true},       // 12
    {"dirt_blast_large", true, true},        // 13
    {"water_blast_small", false, true},      // 14
    {"water_blast_medium", false, true},     // 15
    {"water_blast_large", false, true},      // 16
    {"air_hit", false, true},                // 17
    {"building_hit_small", false, true},     // 18
    {"building_hit_medium", false, true},    // 19
    {"building_hit_large", false, true},     // 20
    {"mine_clearing_line_charge", true, true},  // 21
    {"environment_object_impact", false, true},      // 22
    {"environment_object_proximate", false, true},   // 23
    {"water_impact", false, true},           // 24
    {"airburst", false, true},               // 25
    {"kill_fragment_1", false, true},        // 26
    {"kill_fragment_2", false, true},        // 27
    {"kill_fragment_3", false, true},        // 28
    {"kill_fragment_1_fly_out_failure", false, true},  // 29
    {"kill_fragment_2_fly_out_failure", false, true},  // 30
    {"miss_fly_out_failure", false, false},            // 31
    {"miss_end_game_failure", false, false},           // 32
    {"miss_fly_out_and_end_game_failure", false, false},  // 33
}};

// Munition Descriptor-Fuse classes by thousand (1000 contact ... 9000 pyrotechnic).
constexpr std::array<const char*, 10> kFuses{"other",    "contact",  "timed",    "proximity", "command",
                                             "altitude", "depth",    "acoustic", "pressure",  "pyrotechnic"};
}  // namespace

DetonationResultInfo detonation_result(std::uint8_t code) {
  return code < kResults.size() ? kResults[code] : kResults[0];
}

const char* fuse_class(std::uint16_t code) { return code / 1000 < kFuses.size() ? kFuses[code / 1000] : "other"; }

bool air_fuse(std::uint16_t code) { return code / 1000 == 2 || code / 1000 == 3; }

}  // namespace npsnet::node
