// The harness diagnosis on a Y breakout whose recording is the hidden truth's centrelines with
// noise: a clean recording is none, a stiffer branch is named on that branch with its factor, a
// junction that sits elsewhere along the trunk is named at that junction with its shift.
#include "cablefit/core/diagnosis/harness_diagnosis.h"

#include <gtest/gtest.h>

#include <random>

#include "cablefit/core/network/network_simulation.h"
#include "harness_layouts.h"

namespace cablefit {
namespace {

// Centre points every ~8 mm along each solved branch of `truth`, away from the junction ends,
// with Gaussian noise `sigma`; arc lengths as the nominal would give them (the truth's).
HarnessObservation Recorded(const NetworkSpec& truth, double sigma, unsigned seed) {
  NetworkOptions opt;
  opt.element_length = 0.002;
  const NetworkSolution sol = SolveNetwork(truth, opt);
  EXPECT_TRUE(sol.converged());
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  HarnessObservation obs;
  for (size_t b = 0; b < truth.branches.size(); ++b) {
    const Polyline& c = sol.branches[b];
    const double length = c.s[c.size() - 1];
    ShapeObservation o;
    std::vector<Vec3> p;
    std::vector<double> s;
    for (int i = 0; i < c.size(); i += 4) {
      if (c.s[i] < 0.015 || c.s[i] > length - 0.015) continue;
      p.push_back(Vec3(c.points.col(i)) + Vec3(noise(rng), noise(rng), noise(rng)));
      s.push_back(c.s[i]);
    }
    o.points.resize(3, static_cast<Eigen::Index>(p.size()));
    o.s.resize(static_cast<Eigen::Index>(s.size()));
    for (size_t i = 0; i < p.size(); ++i) {
      o.points.col(static_cast<Eigen::Index>(i)) = p[i];
      o.s[static_cast<Eigen::Index>(i)] = s[i];
    }
    o.noise_sigma = sigma;
    obs.branches.push_back(o);
  }
  return obs;
}

NetworkSpec YHarness() {
  std::mt19937 rng(5);
  return testing::HarnessLayouts(rng).front().spec;
}

HarnessDiagnosisOptions Options() {
  HarnessDiagnosisOptions o;
  o.threads = 2;
  return o;
}

TEST(HarnessDiagnosis, ACleanRecordingIsNone) {
  const NetworkSpec nominal = YHarness();
  const HarnessDiagnosis d = DiagnoseHarness(nominal, Recorded(nominal, 5e-5, 1), Options());
  EXPECT_TRUE(d.explained);
  EXPECT_TRUE(d.effects.empty()) << ToString(d.effects.front().effect);
  ASSERT_EQ(d.branches.size(), 3u);
  for (const HarnessBranchDeviation& b : d.branches) EXPECT_LT(b.nominal_max, 5e-4);
}

TEST(HarnessDiagnosis, AStifferBranchIsNamedOnItsBranch) {
  const NetworkSpec nominal = YHarness();
  NetworkSpec truth = nominal;
  truth.branches[2].material.bending_stiffness *= 3.0;
  truth.branches[2].material.torsional_stiffness *= 3.0;
  const HarnessDiagnosis d = DiagnoseHarness(nominal, Recorded(truth, 5e-5, 2), Options());
  ASSERT_TRUE(d.explained);
  ASSERT_EQ(d.effects.size(), 1u);
  EXPECT_EQ(d.effects[0].effect, HarnessEffect::kBranchStiffness);
  EXPECT_EQ(d.effects[0].branch, 2);
  EXPECT_NEAR(d.effects[0].parameters.at("factor"), 3.0, 0.6);
  // The mismatch is on the branch that differs.
  EXPECT_GT(d.branches[2].nominal_max, d.branches[1].nominal_max);
  EXPECT_GT(d.baseline_max / d.fitted_max, 10.0);
}

TEST(HarnessDiagnosis, AJunctionElsewhereAlongTheTrunkIsNamedAtThatJunction) {
  const NetworkSpec nominal = YHarness();
  NetworkSpec truth = nominal;
  // 25 mm further out: the trunk is that much longer, each breakout branch that much shorter
  // from the breakout to its clamp... of the straightest one only: the trunk continues into it.
  const Vec3 tj = nominal.branches[0].route.points.rightCols<1>() - nominal.branches[0].route.points.col(0);
  int onward = 1;
  double best = -2.0;
  for (int b : {1, 2}) {
    const Polyline& r = nominal.branches[static_cast<size_t>(b)].route;
    const double c = (r.points.col(1) - r.points.col(0)).normalized().dot(tj.normalized());
    if (c > best) {
      best = c;
      onward = b;
    }
  }
  truth.branches[0].length += 0.025;
  truth.branches[static_cast<size_t>(onward)].length -= 0.025;
  for (SupportSpec& sp : truth.branches[static_cast<size_t>(onward)].supports) sp.s -= 0.025;
  const HarnessDiagnosis d = DiagnoseHarness(nominal, Recorded(truth, 5e-5, 3), Options());
  ASSERT_TRUE(d.explained);
  ASSERT_FALSE(d.effects.empty());
  EXPECT_EQ(d.effects[0].effect, HarnessEffect::kJunctionPosition) << ToString(d.effects[0].effect);
  EXPECT_EQ(d.effects[0].junction, 0);
  EXPECT_NEAR(std::abs(d.effects[0].parameters.at("shift")), 0.025, 0.006);
}

}  // namespace
}  // namespace cablefit
