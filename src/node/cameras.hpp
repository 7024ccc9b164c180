// The player's cameras around the vehicle `e` (shared/ARCHITECTURE.md, "Player"), in metres:
//  driver: the eye inside the vehicle (the thesis's Figure A.1), at its driver's station, looking
//          along its heading and pitch, the frame rolled with it; the vehicle itself not drawn
//          (Camera::hide_entity);
//  chase:  behind and above it, looking past it;
//  orbit:  around it at `orbit_deg` (0 = behind, + clockwise seen from above) and `orbit_m`;
//  map:    straight down from kMapCameraHeightM over it, north up.
#pragma once
#include "collision/collision.hpp"
#include "input/action.hpp"
#include "render/renderer.hpp"

namespace npsnet::node {

inline constexpr double kMapCameraHeightM = 2500.0;
inline constexpr double kOrbitDefaultM = 40.0;

// The view volume a frame of `cam` at width x height pixels shows (render::make_view's frustum):
// what the collision detector's scene-aware tier counts as seen (collision::ViewVolume).
collision::ViewVolume view_volume(const render::Camera& cam, int width, int height);

render::Camera player_camera(const world::World& w, const world::Entities& ents, int e, input::CameraMode mode,
                             double orbit_deg = 45.0, double orbit_m = kOrbitDefaultM);

}  // namespace npsnet::node
