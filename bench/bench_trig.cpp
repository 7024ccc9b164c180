// The hot loops' trigonometry (core/trig.hpp) against the libm forms it replaced (issue 13):
// pose_rotation from heading, pitch and roll (was three Eigen AngleAxis of libm sines and
// cosines), heading_to_dir (was std::sin, std::cos of radians) and dir_to_heading (was
// std::atan2). Each over the same 100,000 float angles a vehicle crowd has (heading 0-360,
// pitch and roll +-20 degrees), side by side in one run:
//   build/bench/bench_trig --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "core/math.hpp"
#include "world/pose.hpp"

using namespace npsnet;

namespace {

struct Angles {
  std::vector<float> h, p, r;
  std::vector<Vec2> dir;
  Angles() {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> heading(0, 360), tilt(-20, 20);
    for (int i = 0; i < 100000; ++i) {
      h.push_back(heading(rng)), p.push_back(tilt(rng)), r.push_back(tilt(rng));
      dir.push_back(Vec2(std::sin(deg2rad(h.back())), std::cos(deg2rad(h.back()))) * (1 + i % 7));
    }
  }
};
const Angles& angles() {
  static const Angles a;
  return a;
}

Mat3 libm_pose_rotation(double heading_deg, double pitch_deg, double roll_deg) {  // before 2 Dec
  const Eigen::AngleAxisd yaw(-deg2rad(heading_deg), Vec3::UnitZ());
  const Eigen::AngleAxisd pitch(deg2rad(pitch_deg), Vec3::UnitX());
  const Eigen::AngleAxisd roll(deg2rad(roll_deg), Vec3::UnitY());
  return (yaw * pitch * roll).toRotationMatrix();
}

template <class F>
void over_angles(benchmark::State& st, F&& f) {
  const Angles& a = angles();
  for (auto _ : st) {
    for (size_t i = 0; i < a.h.size(); ++i) benchmark::DoNotOptimize(f(a, i));
  }
  st.SetItemsProcessed(static_cast<int64_t>(st.iterations() * a.h.size()));
}

void BM_PoseRotationLibm(benchmark::State& st) {
  over_angles(st, [](const Angles& a, size_t i) { return libm_pose_rotation(a.h[i], a.p[i], a.r[i]); });
}
void BM_PoseRotation(benchmark::State& st) {
  over_angles(st, [](const Angles& a, size_t i) { return world::pose_rotation(a.h[i], a.p[i], a.r[i]); });
}
void BM_HeadingToDirLibm(benchmark::State& st) {
  over_angles(st, [](const Angles& a, size_t i) {
    const double h = deg2rad(a.h[i]);
    return Vec2(std::sin(h), std::cos(h));
  });
}
void BM_HeadingToDir(benchmark::State& st) {
  over_angles(st, [](const Angles& a, size_t i) { return heading_to_dir(a.h[i]); });
}
void BM_DirToHeadingLibm(benchmark::State& st) {
  over_angles(st, [](const Angles& a, size_t i) { return wrap360(rad2deg(std::atan2(a.dir[i].x(), a.dir[i].y()))); });
}
void BM_DirToHeading(benchmark::State& st) {
  over_angles(st, [](const Angles& a, size_t i) { return dir_to_heading(a.dir[i]); });
}

}  // namespace

BENCHMARK(BM_PoseRotationLibm);
BENCHMARK(BM_PoseRotation);
BENCHMARK(BM_HeadingToDirLibm);
BENCHMARK(BM_HeadingToDir);
BENCHMARK(BM_DirToHeadingLibm);
BENCHMARK(BM_DirToHeading);
BENCHMARK_MAIN();
