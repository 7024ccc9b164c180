// The 2D layer over a frame (drawn by Renderer::render after the 3D scene), in pixels of a
// W x H frame, top-left origin:
//  - the scenario clock (top-left);
//  - with hud.show, the HUD panel (bottom-left): the vehicle's id and kind, speed (km/h), heading,
//    pitch and roll (deg), rounds, fuel (l) and, when hud.camera is set, the camera mode;
//  - with map_inset, the map of the whole terrain (top-right): a dot per active entity (blue
//    this node's, red remote, yellow munitions, black wrecks), the driven vehicle as a white
//    square, and its view triangle (the camera's horizontal field of view, `reach_m` long).
#pragma once
#include "render/overlay.hpp"
#include "render/renderer.hpp"
#include "render/view.hpp"

namespace npsnet::render {

void draw_hud_and_map(Overlay& overlay, const world::World& w, const SceneView& v, const ViewMath& vm, const Hud& hud,
                      bool map_inset, double reach_m);

}  // namespace npsnet::render
