// The default world's terrain: value noise, the heights at the posts, and the GeoTIFF writer.
// Units: metres, x east and y north from the SW corner. Heights are kPosts * kPosts floats,
// row-major from the SW corner (post (i, j) at x = i * kSpacing, y = j * kSpacing), rounded to
// 1/32 m. Only + - * /, floor and sqrt decide them: the same on every platform.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "default_world/layout.hpp"

namespace npsnet::default_world {

// Value noise in [-1, 1) at (x, y) in lattice units; each octave is an independent lattice.
double value_noise(double x, double y, uint64_t octave);
// Distance (m) from (x, y) to the proving-ground reserve; 0 inside it.
double reserve_distance(double x, double y);

// The heights of the whole map: hills, the proving ground and the lake.
std::vector<float> make_heights();

inline float post(const std::vector<float>& h, int i, int j) { return h[static_cast<size_t>(j) * kPosts + i]; }
// Bilinear height (m) at (x, y) (m), clamped to the map.
double height_at(const std::vector<float>& h, double x, double y);
// Slope (deg) at post (i, j): central differences, one-sided on the map edge.
double slope_deg(const std::vector<float>& h, int i, int j);
// Writes h to p: Float32, north up, DEFLATE + floating-point predictor; throws std::runtime_error.
void write_tif(const std::filesystem::path& p, const std::vector<float>& h);

}  // namespace npsnet::default_world
