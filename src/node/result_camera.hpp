// The camera of a collision's result frame when a fixed object was hit: the frame must show the
// object in its new state (a stump, a crushed tower), which the vehicle, driven on over it, may
// hide. Candidate eyes around the object (the first: the side view of the vehicle's track,
// 35 degrees up; then every 30 degrees around at 20, 35, 55 and 80 degrees up); each is scored by
// how many of the object's model vertices (its current state) it sees: inside the 960 x 540
// frame clear of the HUD panel and the map inset, not behind the terrain, not behind any
// entity's polygons. Chosen: the first candidate (in that order) that sees at least 90 % of what
// the best one sees, one with the vehicle in frame before one without. When no candidate sees
// half of the object (the vehicle stands on it: a tank over the stump of the tree it knocked
// down), the choice is made as if the vehicle were not there, and the vehicle is drawn
// see-through (Camera::ghost_entity). Distances in metres; pure geometry, deterministic.
#pragma once
#include "render/renderer.hpp"
#include "world/world.hpp"

namespace npsnet::node {

render::Camera changed_object_camera(const world::World& w, int vehicle, int object);

// The share (0..1) of fixed object `object`'s model vertices (current state) seen from `cam` in a
// 960 x 540 frame (as above); exposed for tests.
double object_visible_share(const world::World& w, int object, const render::Camera& cam);

}  // namespace npsnet::node
