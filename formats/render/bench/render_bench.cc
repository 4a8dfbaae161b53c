// Rendering throughput (reports, never asserts). Targets: a 3-view map of one cable
// <= 0.5 s, a 30-cable harness <= 5 s, both at the default 1600 x 1000 with 2x supersampling.
#include <benchmark/benchmark.h>

#include "../../../tests/formats/render/synthetic_scene.h"
#include "cablefit/formats/deviation_views.h"

namespace {

void BM_OneCable(benchmark::State& state) {
  const cablefit::Scene scene = cablefit::testing::SaggingCable{}.Build();
  for (auto _ : state) benchmark::DoNotOptimize(cablefit::RenderDeviationViews(scene, {}));
}
BENCHMARK(BM_OneCable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Harness30(benchmark::State& state) {
  cablefit::Scene harness;
  for (int k = 0; k < 30; ++k) {
    cablefit::testing::SaggingCable cable;
    cable.offset = Eigen::Vector3d(0.0, 0.03 * k, 0.004 * k);
    cable.peak_s = 0.1 + 0.015 * k;
    const cablefit::Scene one = cable.Build();
    harness.tubes.push_back(one.tubes[0]);
    harness.ghosts.push_back(one.ghosts[0]);
  }
  for (auto _ : state) benchmark::DoNotOptimize(cablefit::RenderDeviationViews(harness, {}));
}
BENCHMARK(BM_Harness30)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
