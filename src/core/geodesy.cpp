// WGS84 geodesy: geodetic <-> ECEF (iterated to machine precision), ENU, transverse Mercator
// (Krueger's series to 6th order in n, as written out by Karney 2011, "Transverse Mercator with
// an accuracy of a few nanometers"), the terrain's local frame, and DIS Euler angles.
#include "core/geodesy.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace npsnet::geo {
namespace {

// --- Krueger series coefficients (functions of the third flattening n) ----------------------
struct TmCoefficients {
  double a_rect = 0;             // rectifying radius A (m)
  std::array<double, 6> alpha{};  // forward: conformal sphere -> TM
  std::array<double, 6> beta{};   // inverse
  double e = 0;                  // first eccentricity
};

TmCoefficients make_tm_coefficients() {
  TmCoefficients c;
  const double n = kWgs84F / (2.0 - kWgs84F);
  const double n2 = n * n, n3 = n2 * n, n4 = n3 * n, n5 = n4 * n, n6 = n5 * n;
  c.a_rect = kWgs84A / (1.0 + n) * (1.0 + n2 / 4.0 + n4 / 64.0 + n6 / 256.0);
  c.alpha = {
      n / 2 - 2 * n2 / 3 + 5 * n3 / 16 + 41 * n4 / 180 - 127 * n5 / 288 + 7891 * n6 / 37800,
      13 * n2 / 48 - 3 * n3 / 5 + 557 * n4 / 1440 + 281 * n5 / 630 - 1983433 * n6 / 1935360,
      61 * n3 / 240 - 103 * n4 / 140 + 15061 * n5 / 26880 + 167603 * n6 / 181440,
      49561 * n4 / 161280 - 179 * n5 / 168 + 6601661 * n6 / 7257600,
      34729 * n5 / 80640 - 3418889 * n6 / 1995840,
      212378941 * n6 / 319334400,
  };
  c.beta = {
      n / 2 - 2 * n2 / 3 + 37 * n3 / 96 - n4 / 360 - 81 * n5 / 512 + 96199 * n6 / 604800,
      n2 / 48 + n3 / 15 - 437 * n4 / 1440 + 46 * n5 / 105 - 1118711 * n6 / 3870720,
      17 * n3 / 480 - 37 * n4 / 840 - 209 * n5 / 4480 + 5569 * n6 / 90720,
      4397 * n4 / 161280 - 11 * n5 / 504 - 830251 * n6 / 7257600,
      4583 * n5 / 161280 - 108847 * n6 / 3991680,
      20648693 * n6 / 638668800,
  };
  c.e = std::sqrt(kWgs84E2);
  return c;
}

const TmCoefficients& tm_coefficients() {
  static const TmCoefficients c = make_tm_coefficients();
  return c;
}

// tan(conformal latitude) from tan(geodetic latitude) (Karney 2011, eq. 7-9).
double taup_from_tau(double tau, double e) {
  const double tau1 = std::hypot(1.0, tau);
  const double sig = std::sinh(e * std::atanh(e * tau / tau1));
  return tau * std::hypot(1.0, sig) - sig * tau1;
}

// Inverse of taup_from_tau by Newton's method (Karney 2011, eq. 19-21).
double tau_from_taup(double taup, double e) {
  const double e2m = 1.0 - e * e;
  double tau = taup / e2m;
  for (int i = 0; i < 8; ++i) {
    const double tp = taup_from_tau(tau, e);
    const double dtau = (taup - tp) * (1.0 + e2m * tau * tau) /
                        (e2m * std::hypot(1.0, tau) * std::hypot(1.0, tp));
    tau += dtau;
    if (std::abs(dtau) <= 1e-15 * std::max(1.0, std::abs(tau))) break;
  }
  return tau;
}

// The series terms of one coordinate (FrameMemo::Terms), j = 1..6: sin and cos of 2j xi, or
// sinh and cosh of 2j eta, from those of 2 xi (2 eta) by the angle-sum formulas, as Karney's
// Clenshaw sums avoid a sin and cos per order: two libm calls, not twelve (issue 13: the exact
// dead-reckoning test of a vehicle spent most of its time in them). The sums never cancel for
// sinh and cosh; for sin and cos each step adds about an ulp of absolute error, far below the
// series' own truncation (the terms are scaled by alpha_j, beta_j <= 8.4e-4).
void xi_series(double xi, FrameMemo::Terms& t) {
  const double s = std::sin(2.0 * xi), c = std::cos(2.0 * xi);
  t.a[0] = s, t.b[0] = c;
  for (int j = 1; j < 6; ++j) t.a[j] = t.a[j - 1] * c + t.b[j - 1] * s, t.b[j] = t.b[j - 1] * c - t.a[j - 1] * s;
}
void eta_series(double eta, FrameMemo::Terms& t) {
  const double s = std::sinh(2.0 * eta), c = std::cosh(2.0 * eta);
  t.a[0] = s, t.b[0] = c;
  for (int j = 1; j < 6; ++j) t.a[j] = t.a[j - 1] * c + t.b[j - 1] * s, t.b[j] = t.b[j - 1] * c + t.a[j - 1] * s;
}

// Forward TM about the central meridian with no offsets: (lat, dlon) rad -> (x, y) m, the grid
// convergence gamma (rad, the azimuth of grid north measured clockwise from true north) and the
// point scale k (grid metres per metre on the ellipsoid; Karney 2011, eq. 13-14 and 25-26).
struct TmRaw {
  double x, y, gamma, k;
};

TmRaw tm_forward_raw(double lat, double dlon) {
  const auto& c = tm_coefficients();
  const double tau = std::tan(lat);
  const double taup = std::abs(lat) >= kPi / 2 ? std::copysign(1e300, lat)
                                               : taup_from_tau(tau, c.e);
  const double cl = std::cos(dlon), sl = std::sin(dlon);
  const double xip = std::atan2(taup, cl);
  const double etap = std::asinh(sl / std::hypot(taup, cl));
  double xi = xip, eta = etap, p = 1.0, q = 0.0;
  FrameMemo::Terms xt, et;
  xi_series(xip, xt);
  eta_series(etap, et);
  for (int j = 1; j <= 6; ++j) {
    const double a = c.alpha[j - 1];
    const double s2 = xt.a[j - 1], c2 = xt.b[j - 1], sh = et.a[j - 1], ch = et.b[j - 1];
    xi += a * s2 * ch;
    eta += a * c2 * sh;
    p += 2.0 * j * a * c2 * ch;
    q += 2.0 * j * a * s2 * sh;
  }
  const double gamma1 = std::atan(std::tan(xip) * std::tanh(etap));
  const double gamma = gamma1 + std::atan2(q, p);
  // k of the conformal sphere's TM, sqrt(1 - e^2 sin^2 lat) sqrt(1 + tau^2) / hypot(taup, cos
  // dlon) = sqrt(1 + (1 - e^2) tau^2) / hypot(taup, cos dlon), times the series' (A / a) |p - i q|.
  const double k = std::sqrt(1.0 + (1.0 - kWgs84E2) * tau * tau) / std::hypot(taup, cl) *
                   (c.a_rect / kWgs84A) * std::hypot(p, q);
  return {c.a_rect * eta, c.a_rect * xi, gamma, k};
}

// Inverse TM (no offsets) from xi = y / A, eta = x / A and their series terms -> (lat, dlon) rad;
// with `grid`, also the convergence (rad) and point scale there from the inverse's own terms
// (the derivative of its series, as Karney 2011 sec. 5 does), instead of a forward projection of
// the result: within a few 1e-16 of forward_at's (test FrameMemo.InverseGivesTheForwardConvergence
// AndScale). Without it the same operations as before, so the same latitude and longitude.
void tm_inverse_terms(double xi, double eta, const FrameMemo::Terms& xt, const FrameMemo::Terms& et, double& lat,
                      double& dlon, FrameMemo::Grid* grid = nullptr) {
  const auto& c = tm_coefficients();
  double xip = xi, etap = eta;
  double p = 1.0, q = 0.0;  // d zeta' / d zeta = p + i q (zeta = xi + i eta)
  for (int j = 1; j <= 6; ++j) {
    const double b = c.beta[j - 1];
    xip -= b * xt.a[j - 1] * et.b[j - 1];  // b sin(2j xi) cosh(2j eta)
    etap -= b * xt.b[j - 1] * et.a[j - 1];  // b cos(2j xi) sinh(2j eta)
    p -= 2.0 * j * b * xt.b[j - 1] * et.b[j - 1];
    q += 2.0 * j * b * xt.a[j - 1] * et.a[j - 1];
  }
  const double sxip = std::sin(xip), cxip = std::cos(xip), shetap = std::sinh(etap);
  const double r = std::hypot(shetap, cxip);
  dlon = std::atan2(shetap, cxip);
  const double taup = sxip / r;
  const double tau = tau_from_taup(taup, c.e);
  lat = std::atan(tau);
  if (grid) {
    // The conformal sphere's convergence atan(tan xi' tanh eta') plus the series' arg(p + i q)
    // (the forward's atan2(q, p) is -arg(d zeta / d zeta'), the same turn); the sphere's scale
    // sqrt(1 + (1 - e^2) tau^2) / hypot(tau', cos dlon) (that hypot is 1 / r here) over the
    // series' |p + i q| (zeta' per zeta), times A / a.
    const double tanh_etap = shetap / std::sqrt(1.0 + shetap * shetap);
    grid->gamma = std::atan2(sxip * tanh_etap, cxip) + std::atan2(q, p);
    grid->k = std::sqrt(1.0 + (1.0 - kWgs84E2) * tau * tau) * r * (c.a_rect / kWgs84A) / std::hypot(p, q);
  }
}

// Inverse TM (no offsets): (x, y) m -> (lat, dlon) rad.
void tm_inverse_raw(double x, double y, double& lat, double& dlon) {
  const auto& c = tm_coefficients();
  const double xi = y / c.a_rect, eta = x / c.a_rect;
  FrameMemo::Terms xt, et;
  xi_series(xi, xt);
  eta_series(eta, et);
  tm_inverse_terms(xi, eta, xt, et, lat, dlon);
}

// ECEF of latitude and longitude given by their sines and cosines, height h (m).
Vec3 ecef_of(double sp, double cp, double sl, double cl, double h) {
  const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * sp * sp);
  return {(n + h) * cp * cl, (n + h) * cp * sl, (n * (1.0 - kWgs84E2) + h) * sp};
}

// Rotation from NED (north, east, down) to ECEF at a latitude and longitude given by their sines
// and cosines: columns N, E, D.
Mat3 ned_to_ecef(double sp, double cp, double sl, double cl) {
  Mat3 m;
  m.col(0) = Vec3(-sp * cl, -sp * sl, cp);
  m.col(1) = Vec3(-sl, cl, 0.0);
  m.col(2) = Vec3(-cp * cl, -cp * sl, -sp);
  return m;
}

// Rotation from NED (north, east, down) to ECEF at (lat, lon) in radians: columns N, E, D.
Mat3 ned_to_ecef(double lat, double lon) { return ned_to_ecef(std::sin(lat), std::cos(lat), std::sin(lon), std::cos(lon)); }

// Rz(yaw) * Ry(pitch) * Rx(roll): the aerospace / DIS z-y'-x'' sequence.
Mat3 zyx_rotation(double yaw, double pitch, double roll) {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}

// Inverse of zyx_rotation: (yaw, pitch, roll) in radians.
Vec3 zyx_angles(const Mat3& r) {
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  const double yaw = std::atan2(r(1, 0), r(0, 0));
  const double roll = std::atan2(r(2, 1), r(2, 2));
  return {yaw, pitch, roll};
}

// DIS Euler angles of a local heading, pitch, roll (deg) where the grid convergence is conv_deg
// and ned is ned_to_ecef (LocalFrame::to_dis_euler).
Vec3 dis_euler(double conv_deg, const Mat3& ned, double heading_deg, double pitch_deg, double roll_deg) {
  // Grid heading -> true heading: grid north lies gamma clockwise of true north.
  const double true_heading = deg2rad(heading_deg + conv_deg);
  const Mat3 body_to_ned = zyx_rotation(true_heading, deg2rad(pitch_deg), deg2rad(roll_deg));
  const Mat3 body_to_ecef = ned * body_to_ned;
  return zyx_angles(body_to_ecef);
}

// ECEF metres per local metre (columns: local x, y, z) at latitude and longitude given by their
// sines and cosines, height h, convergence gamma (rad) and scale k: a grid metre along local +y
// is 1 / k metres on the ellipsoid at azimuth gamma, along +x at gamma + 90 deg, and a metre on
// the ellipsoid is (M + h) / M (north) and (N + h) / N (east) metres at height h.
Mat3 jacobian_of(double sp, double cp, double sl, double cl, double h, double gamma, double k) {
  const double w2 = 1.0 - kWgs84E2 * sp * sp;
  const double n = kWgs84A / std::sqrt(w2), m = n * (1.0 - kWgs84E2) / w2;  // prime vertical, meridian radii
  const Vec3 north(-sp * cl, -sp * sl, cp), east(-sl, cl, 0.0);
  const Vec3 dn = north * ((m + h) / (m * k)), de = east * ((n + h) / (n * k));
  const double sg = std::sin(gamma), cg = std::cos(gamma);
  Mat3 j;
  j.col(0) = de * cg - dn * sg;
  j.col(1) = dn * cg + de * sg;
  j.col(2) = Vec3(cp * cl, cp * sl, sp);
  return j;
}

// The forward TM of a geodetic point about tm's central meridian (its convergence and scale).
TmRaw forward_at(const TransverseMercator& tm, const Geodetic& g) {
  const double dlon = std::remainder(g.lon_deg - tm.lon0(), 360.0);
  return tm_forward_raw(deg2rad(g.lat_deg), deg2rad(dlon));
}

}  // namespace

// --- ECEF -------------------------------------------------------------------------------------
Vec3 geodetic_to_ecef(const Geodetic& g) {
  const double lat = deg2rad(g.lat_deg), lon = deg2rad(g.lon_deg);
  return ecef_of(std::sin(lat), std::cos(lat), std::sin(lon), std::cos(lon), g.h_m);
}

Geodetic ecef_to_geodetic(const Vec3& ecef) {
  const double x = ecef.x(), y = ecef.y(), z = ecef.z();
  const double p = std::hypot(x, y);
  const double lon = (p == 0.0) ? 0.0 : std::atan2(y, x);
  // Fixed-point iteration on the latitude, started from the geocentric-on-ellipsoid estimate
  // (Bowring's parametric start). Converges to machine precision in a few steps for any height
  // above a few km below the surface; h uses the form that is well conditioned at every
  // latitude, poles included.
  const double ep2 = kWgs84E2 / (1.0 - kWgs84E2);
  const double u = std::atan2(z * kWgs84A, p * kWgs84B);
  double lat = std::atan2(z + ep2 * kWgs84B * std::pow(std::sin(u), 3),
                          p - kWgs84E2 * kWgs84A * std::pow(std::cos(u), 3));
  double h = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double sp = std::sin(lat), cp = std::cos(lat);
    const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * sp * sp);
    h = p * cp + z * sp - kWgs84A * std::sqrt(1.0 - kWgs84E2 * sp * sp);
    const double next = std::atan2(z, p * (1.0 - kWgs84E2 * n / (n + h)));
    const bool done = std::abs(next - lat) < 1e-15;
    lat = next;
    if (done) break;
  }
  const double sp = std::sin(lat), cp = std::cos(lat);
  h = p * cp + z * sp - kWgs84A * std::sqrt(1.0 - kWgs84E2 * sp * sp);
  return {rad2deg(lat), rad2deg(lon), h};
}

// --- ENU --------------------------------------------------------------------------------------
Mat3 enu_rotation(double lat_deg, double lon_deg) {
  const double lat = deg2rad(lat_deg), lon = deg2rad(lon_deg);
  const double sp = std::sin(lat), cp = std::cos(lat), sl = std::sin(lon), cl = std::cos(lon);
  Mat3 r;
  r.row(0) = Vec3(-sl, cl, 0.0).transpose();
  r.row(1) = Vec3(-sp * cl, -sp * sl, cp).transpose();
  r.row(2) = Vec3(cp * cl, cp * sl, sp).transpose();
  return r;
}

Vec3 ecef_to_enu(const Vec3& ecef, const Geodetic& origin) {
  return enu_rotation(origin.lat_deg, origin.lon_deg) * (ecef - geodetic_to_ecef(origin));
}

Vec3 enu_to_ecef(const Vec3& enu, const Geodetic& origin) {
  return geodetic_to_ecef(origin) + enu_rotation(origin.lat_deg, origin.lon_deg).transpose() * enu;
}

// --- Transverse Mercator ----------------------------------------------------------------------
TransverseMercator::TransverseMercator(double lat0_deg, double lon0_deg, double false_e,
                                       double false_n)
    : lat0_(lat0_deg), lon0_(lon0_deg), fe_(false_e), fn_(false_n) {
  y0_ = tm_forward_raw(deg2rad(lat0_deg), 0.0).y;
}

Vec2 TransverseMercator::forward(double lat_deg, double lon_deg) const {
  const double dlon = std::remainder(lon_deg - lon0_, 360.0);
  const TmRaw r = tm_forward_raw(deg2rad(lat_deg), deg2rad(dlon));
  return {r.x + fe_, r.y - y0_ + fn_};
}

Geodetic TransverseMercator::inverse(double x, double y) const {
  double lat = 0, dlon = 0;
  tm_inverse_raw(x - fe_, y - fn_ + y0_, lat, dlon);
  return {rad2deg(lat), std::remainder(lon0_ + rad2deg(dlon), 360.0), 0.0};
}

// --- Local frame ------------------------------------------------------------------------------
LocalFrame::LocalFrame(const Geodetic& sw, double width_m, double height_m) {
  // Find the centre C such that, in the TM centred at C, the SW corner lies at
  // (-width/2, -height/2). Fixed-point iteration: each step moves C to the point that the
  // current TM puts half the extent from the SW corner; it converges in a few steps.
  Geodetic c = sw;
  for (int i = 0; i < 20; ++i) {
    const TransverseMercator tm(c.lat_deg, c.lon_deg);
    const Vec2 s = tm.forward(sw.lat_deg, sw.lon_deg);
    const Geodetic next = tm.inverse(s.x() + width_m / 2.0, s.y() + height_m / 2.0);
    const bool done = std::abs(next.lat_deg - c.lat_deg) < 1e-13 &&
                      std::abs(std::remainder(next.lon_deg - c.lon_deg, 360.0)) < 1e-13;
    c = next;
    if (done) break;
  }
  const TransverseMercator tm(c.lat_deg, c.lon_deg);
  const Vec2 s = tm.forward(sw.lat_deg, sw.lon_deg);
  tm_ = TransverseMercator(c.lat_deg, c.lon_deg, -s.x(), -s.y());
}

Geodetic LocalFrame::to_geodetic(const Vec3& local) const {
  Geodetic g = tm_.inverse(local.x(), local.y());
  g.h_m = local.z();
  return g;
}

Vec3 LocalFrame::to_local(const Geodetic& g) const {
  const Vec2 xy = tm_.forward(g.lat_deg, g.lon_deg);
  return {xy.x(), xy.y(), g.h_m};
}

double LocalFrame::convergence_deg(const Geodetic& g) const { return rad2deg(forward_at(tm_, g).gamma); }

Mat3 LocalFrame::jacobian(const Geodetic& g) const {
  const double lat = deg2rad(g.lat_deg), lon = deg2rad(g.lon_deg);
  const TmRaw r = forward_at(tm_, g);
  return jacobian_of(std::sin(lat), std::cos(lat), std::sin(lon), std::cos(lon), g.h_m, r.gamma, r.k);
}

Vec3 LocalFrame::to_dis_euler(const Vec3& local_pos, double heading_deg, double pitch_deg,
                              double roll_deg) const {
  return to_dis_euler(to_geodetic(local_pos), heading_deg, pitch_deg, roll_deg);
}

Vec3 LocalFrame::to_dis_euler(const Geodetic& g, double heading_deg, double pitch_deg, double roll_deg) const {
  return dis_euler(convergence_deg(g), ned_to_ecef(deg2rad(g.lat_deg), deg2rad(g.lon_deg)), heading_deg, pitch_deg,
                   roll_deg);
}

Vec3 LocalFrame::from_dis_euler(const Vec3& local_pos, const Vec3& psi_theta_phi) const {
  const Geodetic g = to_geodetic(local_pos);
  const Mat3 body_to_ecef = zyx_rotation(psi_theta_phi.x(), psi_theta_phi.y(), psi_theta_phi.z());
  const Mat3 body_to_ned =
      ned_to_ecef(deg2rad(g.lat_deg), deg2rad(g.lon_deg)).transpose() * body_to_ecef;
  const Vec3 ypr = zyx_angles(body_to_ned);
  return {wrap360(rad2deg(ypr.x()) - convergence_deg(g)), rad2deg(ypr.y()), rad2deg(ypr.z())};
}

// --- FrameMemo ---------------------------------------------------------------------------------
Geodetic FrameMemo::to_geodetic(const Vec3& local) {
  Grid unused;
  return to_geodetic(local, unused);
}

Geodetic FrameMemo::to_geodetic(const Vec3& local, Grid& grid) {
  // LocalFrame::to_geodetic -> TransverseMercator::inverse -> tm_inverse_raw, step by step.
  const TransverseMercator& tm = f_.tm_;
  const double x = local.x() - tm.fe_, y = local.y() - tm.fn_ + tm.y0_;
  const auto& c = tm_coefficients();
  const double xi = y / c.a_rect, eta = x / c.a_rect;
  const LatLon& ll = inv_.get(Key2{std::bit_cast<std::uint64_t>(xi), std::bit_cast<std::uint64_t>(eta)}, [&](LatLon& v) {
    const Terms& xt = xi_.get(std::bit_cast<std::uint64_t>(xi), [&](Terms& t) { xi_series(xi, t); });
    const Terms& et = eta_.get(std::bit_cast<std::uint64_t>(eta), [&](Terms& t) { eta_series(eta, t); });
    double lat = 0, dlon = 0;
    tm_inverse_terms(xi, eta, xt, et, lat, dlon, &v.grid);
    v.lat_deg = rad2deg(lat), v.lon_deg = std::remainder(tm.lon0_ + rad2deg(dlon), 360.0);
  });
  grid = ll.grid;
  return {ll.lat_deg, ll.lon_deg, local.z()};
}

namespace {
template <class Kept>
const auto& sincos_deg(Kept& kept, double deg) {
  return kept.get(std::bit_cast<std::uint64_t>(deg), [&](auto& v) {
    const double r = deg2rad(deg);
    v.s = std::sin(r), v.c = std::cos(r);
  });
}
}  // namespace

Vec3 FrameMemo::geodetic_to_ecef(const Geodetic& g) {
  const SinCos& la = sincos_deg(lat_, g.lat_deg);
  const SinCos& lo = sincos_deg(lon_, g.lon_deg);
  return ecef_of(la.s, la.c, lo.s, lo.c, g.h_m);
}

const FrameMemo::Grid& FrameMemo::grid(const Geodetic& g) {
  return fwd_.get(Key2{std::bit_cast<std::uint64_t>(g.lat_deg), std::bit_cast<std::uint64_t>(g.lon_deg)}, [&](Grid& v) {
    const TmRaw r = forward_at(f_.tm_, g);
    v = {r.gamma, r.k};
  });
}

Vec3 FrameMemo::to_dis_euler(const Geodetic& g, double heading_deg, double pitch_deg, double roll_deg) {
  return to_dis_euler(g, grid(g), heading_deg, pitch_deg, roll_deg);
}

Vec3 FrameMemo::to_dis_euler(const Geodetic& g, const Grid& grid, double heading_deg, double pitch_deg,
                              double roll_deg) {
  const SinCos& la = sincos_deg(lat_, g.lat_deg);
  const SinCos& lo = sincos_deg(lon_, g.lon_deg);
  return dis_euler(rad2deg(grid.gamma), ned_to_ecef(la.s, la.c, lo.s, lo.c), heading_deg, pitch_deg, roll_deg);
}

Mat3 FrameMemo::jacobian(const Geodetic& g) { return jacobian(g, grid(g)); }

Mat3 FrameMemo::jacobian(const Geodetic& g, const Grid& grid) {
  const SinCos& la = sincos_deg(lat_, g.lat_deg);
  const SinCos& lo = sincos_deg(lon_, g.lon_deg);
  return jacobian_of(la.s, la.c, lo.s, lo.c, g.h_m, grid.gamma, grid.k);
}

}  // namespace npsnet::geo
