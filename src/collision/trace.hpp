// One answer type for every cast (issue 12), as Box2D's cast output and Quake's trace_t: rays
// against models (ray_model), swept spheres (sphere_sweep), the time of impact of two posed
// shapes (cast_shapes) and the contacts the detector reports (Contact extends it).
//   fraction        of the cast, in [0, 1]: a ray's segment [tmin, tmax] along its direction, a
//                   sweep's tick; the first touch (1 when nothing is hit)
//   point, normal   where the first touch is and which way (unit; a sweep's from the first body
//                   towards the second; a ray's: the face's, in the space the ray was given in)
//   started_inside  the two overlap at fraction 0 already (then fraction = 0); for a ray: the
//                   first face crossed is left, not entered (the segment began inside a model)
//   exit_fraction   sweeps: the last touch (<= 1: 1 when still touching at the end)
//   face            rays: the face hit (-1 otherwise)
#pragma once
#include "core/math.hpp"

namespace npsnet::collision {

struct Trace {
  bool hit = false;
  bool started_inside = false;
  double fraction = 1;
  Vec3 point{0, 0, 0};
  Vec3 normal{0, 0, 1};
  double exit_fraction = 1;
  int face = -1;
};

}  // namespace npsnet::collision
