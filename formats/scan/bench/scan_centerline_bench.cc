// ExtractScanCenterline on synthetic hand-held scans of a 0.58 m helix (5 mm cable, 200 degrees
// seen, one 4 cm gap, 0.5 % outliers) at 10k, 20k and 40k points.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cablefit/formats/scan_centerline_extractor.h"
#include "synthetic_tube_scan.h"

namespace {

void BM_ExtractScanCenterline(benchmark::State& state) {
  using namespace cablefit;
  const Polyline curve = testing::SampleCurve([](double u) {
    const double th = 3.0 * M_PI * u;
    return Vec3(0.06 * std::cos(th), 0.06 * std::sin(th), 0.08 / (2.0 * M_PI) * th);
  });
  testing::SyntheticScanSpec spec;
  spec.diameter = 5e-3;
  spec.points = static_cast<int>(state.range(0));
  spec.gaps = {{0.2, 0.24}};
  const auto scan = testing::MakeSyntheticScan(curve, spec);
  ScanCenterlineOptions options;
  options.diameter = spec.diameter;
  for (auto _ : state) benchmark::DoNotOptimize(ExtractScanCenterline(scan.cloud, options));
  state.counters["points"] = scan.cloud.size();
}
BENCHMARK(BM_ExtractScanCenterline)->Arg(10000)->Arg(20000)->Arg(40000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
