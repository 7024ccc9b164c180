// DIS munition enumerations we read from other simulators' Fire and Detonation PDUs
// (SISO-REF-010: Detonation Result, Munition Descriptor-Fuse), as names for the event log and
// the effect each allows. Pure tables, no state.
//  * detonation_result(code): its name ("ground_impact", "dud", "airburst", ...), whether it can
//    make a crater (only results at the ground: other, ground impact, detonation, dirt blasts,
//    mine-clearing line charge) and whether it explodes at all (not a dud (6), not a miss
//    (31-33)). Unknown codes read as "other": crater and blast.
//  * fuse_class(code): "contact", "timed", "proximity", ... by the code's thousand (0-999 "other").
//  * air_fuse(code): timed or proximity fuse, which bursts in the air (a "detonation" above the
//    ground with such a fuse is logged as an airburst).
#pragma once
#include <cstdint>

namespace npsnet::node {

struct DetonationResultInfo {
  const char* name;
  bool crater;  // may leave a crater (still only where the point is near the ground)
  bool blast;   // explodes: blast damage around the point, a hit destroys its target
};

DetonationResultInfo detonation_result(std::uint8_t code);
const char* fuse_class(std::uint16_t code);
bool air_fuse(std::uint16_t code);

}  // namespace npsnet::node
