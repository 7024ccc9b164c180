// WGS84 geodesy: geodetic <-> ECEF <-> local ENU, and the transverse Mercator that maps the
// terrain's local frame (x east, y north, metres, origin at the SW corner) to geodetic.
// Angles in degrees at the API, heights in metres above the ellipsoid. Accurate to < 1 mm.
#pragma once
#include <cstdint>

#include "core/math.hpp"

namespace npsnet::geo {

inline constexpr double kWgs84A = 6378137.0;                 // semi-major axis (m)
inline constexpr double kWgs84F = 1.0 / 298.257223563;       // flattening
inline constexpr double kWgs84B = kWgs84A * (1.0 - kWgs84F);  // semi-minor axis (m)
inline constexpr double kWgs84E2 = kWgs84F * (2.0 - kWgs84F); // first eccentricity squared

struct Geodetic {
  double lat_deg = 0, lon_deg = 0, h_m = 0;
};

Vec3 geodetic_to_ecef(const Geodetic& g);
Geodetic ecef_to_geodetic(const Vec3& ecef);

// Rotation whose rows are the east, north, up unit vectors at (lat, lon): enu = R * (ecef - o).
Mat3 enu_rotation(double lat_deg, double lon_deg);
Vec3 ecef_to_enu(const Vec3& ecef, const Geodetic& origin);
Vec3 enu_to_ecef(const Vec3& enu, const Geodetic& origin);

// Transverse Mercator (Krueger series to 6th order, scale 1 on the central meridian), centred
// at (lat0, lon0) with false easting/northing so that a chosen point maps to (0, 0).
class FrameMemo;

class TransverseMercator {
 public:
  TransverseMercator() = default;
  TransverseMercator(double lat0_deg, double lon0_deg, double false_e = 0, double false_n = 0);
  Vec2 forward(double lat_deg, double lon_deg) const;  // -> (x east, y north) metres
  Geodetic inverse(double x, double y) const;          // h_m = 0
  double lat0() const { return lat0_; }
  double lon0() const { return lon0_; }
  double false_easting() const { return fe_; }
  double false_northing() const { return fn_; }

 private:
  friend class FrameMemo;
  double lat0_ = 0, lon0_ = 0, fe_ = 0, fn_ = 0, y0_ = 0;
};

// The terrain's local frame: TM centred on the terrain, SW corner at local (0, 0).
class LocalFrame {
 public:
  LocalFrame() = default;
  // The SW corner's geodetic position and the terrain's extent in metres.
  LocalFrame(const Geodetic& sw_corner, double width_m, double height_m);
  Geodetic to_geodetic(const Vec3& local) const;  // z is height above the ellipsoid
  Vec3 to_local(const Geodetic& g) const;
  Vec3 to_ecef(const Vec3& local) const { return geodetic_to_ecef(to_geodetic(local)); }
  Vec3 from_ecef(const Vec3& ecef) const { return to_local(ecef_to_geodetic(ecef)); }
  // Local heading/pitch/roll (compass deg, deg, deg) <-> DIS Euler psi, theta, phi (rad).
  // Heading is the local (grid) compass heading: 0 = +y, 90 = +x; pitch is nose up positive,
  // roll right wing down positive. The DIS angles (IEEE 1278.1) orient the body frame (x forward,
  // y right, z down) against ECEF: rotate psi about Z, then theta about the new Y, then phi about
  // the new X. The TM grid convergence at local_pos is applied, so both directions round-trip.
  Vec3 to_dis_euler(const Vec3& local_pos, double heading_deg, double pitch_deg,
                    double roll_deg) const;
  // The same at g = to_geodetic(local_pos), already known (one TM inverse fewer).
  Vec3 to_dis_euler(const Geodetic& g, double heading_deg, double pitch_deg, double roll_deg) const;
  Vec3 from_dis_euler(const Vec3& local_pos, const Vec3& psi_theta_phi) const;  // -> h, p, r deg
  // Grid convergence at g (deg): the azimuth of local +y (grid north) clockwise from true
  // north. A local (grid) heading plus this is the true heading.
  double convergence_deg(const Geodetic& g) const;
  // The derivative of to_ecef at g = to_geodetic(local): ECEF metres per local metre, columns
  // local x, y, z (from the convergence and the TM point scale; exact but for rounding).
  Mat3 jacobian(const Geodetic& g) const;
  const TransverseMercator& projection() const { return tm_; }

 private:
  friend class FrameMemo;
  TransverseMercator tm_;
};

// LocalFrame's to_geodetic, to_ecef, to_dis_euler and jacobian, bit for bit, for a run of points
// that share coordinates (issue 13: an exact dead-reckoning test turns p into ECEF and DIS angles
// and takes the Jacobian there; points that share p's northing, easting or both reuse its
// terms). It keeps the transverse Mercator inverse's series terms of the last three northings
// (sin and cos of 2j xi) and eastings (sinh and cosh of 2j eta), the last two inverses, the last
// two latitudes' and longitudes' sines and cosines, and the last two points' convergence and
// scale, each keyed by the bits of its argument, so what it returns is a function of the point's
// bits only (the same libm calls on the same arguments, the same operations after). Not shared
// between threads; small enough for the stack.
// The Grid forms take the convergence and scale the inverse itself gives (to_geodetic(local,
// grid): the derivative of its series, no forward projection; within a few 1e-16 of LocalFrame's,
// not its bits): the exact dead-reckoning test's one projection (issue 13).
class FrameMemo {
 public:
  struct Grid {  // the grid convergence (rad: grid north clockwise from true north) and TM point scale
    double gamma = 0, k = 1;
  };
  explicit FrameMemo(const LocalFrame& f) : f_(f) {}
  Geodetic to_geodetic(const Vec3& local);
  Geodetic to_geodetic(const Vec3& local, Grid& grid);  // and the convergence and scale there
  Vec3 to_ecef(const Vec3& local) { return geodetic_to_ecef(to_geodetic(local)); }
  Vec3 geodetic_to_ecef(const Geodetic& g);
  Vec3 to_dis_euler(const Geodetic& g, double heading_deg, double pitch_deg, double roll_deg);
  Vec3 to_dis_euler(const Geodetic& g, const Grid& grid, double heading_deg, double pitch_deg, double roll_deg);
  Mat3 jacobian(const Geodetic& g);
  Mat3 jacobian(const Geodetic& g, const Grid& grid);
  // Series terms (of one coordinate) and whole inverses computed so far (tests).
  int terms_computed() const { return xi_.made + eta_.made; }
  int inverses_computed() const { return inv_.made; }

  struct Terms {  // sin, cos of 2j xi (or sinh, cosh of 2j eta), j = 1..6
    double a[6] = {}, b[6] = {};
  };

 private:
  struct Key2 {  // the bits of two doubles
    std::uint64_t a = 0, b = 0;
    bool operator==(const Key2&) const = default;
  };
  struct LatLon {
    double lat_deg = 0, lon_deg = 0;
    Grid grid;  // from the inverse (to_geodetic's Grid form)
  };
  struct SinCos {
    double s = 0, c = 0;
  };
  // The values of the last N keys; the oldest is replaced.
  template <int N, class K, class V>
  struct Kept {
    K key[N] = {};
    bool valid[N] = {};
    V val[N] = {};
    int next = 0, made = 0;
    template <class Make>
    const V& get(const K& k, Make make) {
      for (int i = 0; i < N; ++i)
        if (valid[i] && key[i] == k) return val[i];
      const int i = next;
      next = (next + 1) % N;
      make(val[i]);
      key[i] = k, valid[i] = true, ++made;
      return val[i];
    }
  };
  const LocalFrame& f_;
  Kept<3, std::uint64_t, Terms> xi_, eta_;
  Kept<2, Key2, LatLon> inv_;
  Kept<2, std::uint64_t, SinCos> lat_, lon_;
  Kept<2, Key2, Grid> fwd_;  // the forward TM's, at a latitude and longitude
  const Grid& grid(const Geodetic& g);
};

}  // namespace npsnet::geo
