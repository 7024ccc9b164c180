// Every constant taken from the 1991 thesis (Osborne, NPSNET, shared/seed), with its source.
// Nothing else in src/ writes these numbers inline. The DIS 7 Annex C network defaults live in
// net/ (net::annex_c in net/dead_reckoning.hpp), which builds on its own; src/ takes them there.
// Threading: constants only; core/ holds no state (math, geodesy are pure functions).
#pragma once

namespace npsnet::thesis {

// --- World segmentation (ch. III.B, p. 8) -----------------------------------------------------
inline constexpr double kGridsquareM = 125.0;          // "gridsquares ... 125 meters square" (p. 8)
inline constexpr int kGridsquaresPerSide = 400;        // 160,000 gridsquares (Table 1, p. 10)
inline constexpr int kGridsquaresTotal = 160000;       // Table 1
inline constexpr double kWorldSizeM = kGridsquareM * kGridsquaresPerSide;  // 50 km (p. 1-2)

// --- Table 1: dispersion of fixed objects (p. 10) -------------------------------------------
inline constexpr int kTable1Trees = 30813;
inline constexpr int kTable1Bushes = 9422;
inline constexpr int kTable1TelephonePoles = 54;
inline constexpr int kTable1Buildings = 3;
inline constexpr int kTable1Watertowers = 1;
inline constexpr int kTable1OtherManMade = 5;
inline constexpr int kTable1OtherNatural = 5;
inline constexpr int kTable1Total = 40303;
inline constexpr int kTable1MinPerGridsquare = 0;
inline constexpr int kTable1MaxPerGridsquare = 18;
inline constexpr double kTable1AveragePerGridsquare = 3.9;  // over occupied gridsquares

// --- Table 2: vehicle movement limitations (p. 11) ------------------------------------------
inline constexpr double kTable2GroundKmh = 60.0;
inline constexpr double kTable2ShipKmh = 50.0;
inline constexpr double kTable2AirKmh = 1000.0;
inline constexpr double kTable2FrameRateHz = 10.0;     // "a frame rate of 10 frames per second"
inline constexpr double kDefaultDtS = 1.0 / kTable2FrameRateHz;

// --- Collision detection (ch. III.C) ----------------------------------------------------------
// Fixed objects are checked only below a threshold height (p. 9). The thesis gives no number;
// we take the tallest fixed object's top (the watertower) plus a margin, in metres above ground.
inline constexpr double kFixedCheckThresholdHeightM = 60.0;
// First-level check: "If the X or Z position of any other vehicle is within 100 meters" (p. 11).
inline constexpr double kFirstLevelWindowM = 100.0;
// The thesis's failure speed: two 3 m tanks pass through each other above ~216 km/h (p. 23).
inline constexpr double kTunnellingSpeedKmh = 216.0;
// "A slightly smaller value than the actual radius of the object is used" (p. 14): bounding
// radii in models/kinds.toml are this fraction of the model's true radius.
inline constexpr double kBoundingRadiusFraction = 0.9;

// --- Collision response, Figure 8 (p. 22) ------------------------------------------------------
// Angle bands, degrees, on the angle between the two headings: inclusive edges as in Figure 8.
inline constexpr double kBandHalfWidthDeg = 5.0;       // 85..95, 175..185, 265..275, <=5, >=355
// Figure 8 compares the "mass of colliding vehicle" with constant1 > constant2 > constant3; the
// text (p. 20) grades damage "based upon the speed and mass of the colliding object", so we
// compare momentum (kg m/s) with these. A 63 t M1A1 at 40 km/h carries 7.0e5 kg m/s, at
// 8 km/h 1.4e5; a 2.4 t HMMWV at 60 km/h 4.0e4 (Appendix A: slow vs fast tree and tower).
inline constexpr double kFixedMomentumHi = 4.0e5;   // constant1: fixed object destroyed
inline constexpr double kFixedMomentumMed = 1.0e5;  // constant2: two damage levels
inline constexpr double kFixedMomentumLow = 1.5e4;  // constant3: one damage level; below: none
// "if large and mobile object is moving quickly, kill mobile object" (Figure 8): a fixed object
// is large when its mass is at least this, and quick is at least this closing speed.
inline constexpr double kLargeFixedMassKg = 50000.0;
inline constexpr double kQuickSpeedMps = 8.0;        // ~29 km/h
// Mobile vs mobile in an angle band: "if (speed of colliding vehicle > constant) Kill both;
// else Stop both" (Figure 8).
inline constexpr double kKillClosingSpeedMps = 5.0;  // 18 km/h
// "Bounce off each other; Diminish speed of both" (Figure 8, Figure 7): restitution of the
// normal component and the fraction of speed kept.
inline constexpr double kBounceRestitution = 0.3;
inline constexpr double kBounceSpeedKept = 0.5;
// "decrease speed of mobile object" after running down a small fixed object (Figure 8).
inline constexpr double kFixedHitSpeedKept = 0.6;

}  // namespace npsnet::thesis
