// Generated corpus for force-curve diagnosis: synthetic curves from this project's own rig and
// Iwan models (random geometry, stiffness ratios, Iwan elements, sensor offsets, 0.5 % noise),
// both rigs. Prints a confusion matrix; asserts >= 95 % correct and no false positive on `none`.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "cablefit/core/force/force_diagnosis.h"
#include "cablefit/core/force/force_hysteresis.h"
#include "cablefit/core/force/force_rig.h"

namespace cablefit {
namespace {

struct Synthetic {
  RodSpec rod;
  ForceTestSpec test;
  ForceCurve curve;
  ForceEffect effect = ForceEffect::kNone;
  double ratio = 1.0;
  double loop_area = 0.0;  // of the noise-free first cycle
};

// Rows: start -> max -> start, `cycles` times, `steps` increments per branch.
Eigen::VectorXd Protocol(double start, double max, int steps, int cycles) {
  std::vector<double> v{start};
  for (int c = 0; c < cycles; ++c) {
    for (int i = 1; i <= steps; ++i) v.push_back(start + (max - start) * i / steps);
    for (int i = steps - 1; i >= 0; --i) v.push_back(start + (max - start) * i / steps);
  }
  return Eigen::Map<Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

Synthetic Generate(ForceEffect effect, bool torsion, std::mt19937& rng) {
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  Synthetic s;
  s.effect = effect;
  s.rod.length = uni(0.4, 1.0);
  s.rod.material.bending_stiffness = uni(0.005, 0.03);
  s.rod.material.torsional_stiffness = uni(0.005, 0.025);
  s.rod.gravity = Vec3::Zero();
  const int steps = pick(3, 5);
  const int cycles = pick(1, 2);
  if (torsion) {
    s.test.type = ForceTestType::kClampedTorsion;
    s.test.max_angle = uni(0.1, 0.5);
    s.curve.x = Protocol(0.0, s.test.max_angle, steps, cycles);
  } else {
    s.test.type = ForceTestType::kPinnedBending;
    s.test.prebend = s.rod.length * uni(0.005, 0.015);
    s.test.max_displacement = s.test.prebend + s.rod.length * uni(0.01, 0.03);
    s.curve.x = Protocol(s.test.prebend, s.test.max_displacement, steps, cycles);
  }
  const Eigen::VectorXd nominal = NominalForceCurve(s.rod, s.test, s.curve.x);
  const double peak = nominal.cwiseAbs().maxCoeff();
  Eigen::VectorXd clean = nominal;
  if (effect == ForceEffect::kStiffness) {
    s.ratio = pick(0, 1) == 0 ? uni(0.6, 0.9) : uni(1.1, 1.5);
    clean = s.ratio * nominal;
  } else if (effect == ForceEffect::kHysteresis) {
    const double range = s.curve.x.maxCoeff() - s.curve.x.minCoeff();
    const double total_slip = 0.5 * uni(0.03, 0.12) * peak;  // loop height 3-12 % of peak
    const int count = pick(2, 6);
    std::vector<double> weights;
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += weights.emplace_back(uni(0.2, 1.0));
    std::vector<JenkinsElement> elements;
    for (int i = 0; i < count; ++i) {
      const double f = total_slip * weights[static_cast<size_t>(i)] / sum;
      elements.push_back({f / (range * uni(0.03, 0.6)), f});
    }
    if (pick(0, 3) == 0) s.ratio = uni(0.8, 1.2);  // sometimes a stiffness change on top
    clean = s.ratio * nominal + IwanResponse(elements, s.curve.x, 0.0);
    s.loop_area = FirstCycleLoopArea(s.curve.x, clean);
  }
  std::normal_distribution<double> noise(0.0, 0.005 * peak);
  const double offset = uni(-0.01, 0.01) * peak;
  s.curve.y = clean;
  for (Eigen::Index i = 0; i < s.curve.y.size(); ++i) s.curve.y[i] += offset + noise(rng);
  return s;
}

TEST(ForceCorpus, ConfusionMatrixOnGeneratedCurves) {
  std::mt19937 rng(20240611);
  const std::array<ForceEffect, 3> effects = {ForceEffect::kNone, ForceEffect::kStiffness,
                                              ForceEffect::kHysteresis};
  int confusion[3][3] = {};
  int total = 0, correct = 0, ratio_ok = 0, ratio_n = 0, area_ok = 0, area_n = 0;
  int not_explained = 0;  // curves of catalogue effects whose fit failed the adequacy test
  double worst_ratio_err = 0.0, worst_area_err = 0.0;
  for (int trial = 0; trial < 100; ++trial) {
    for (int e = 0; e < 3; ++e) {
      const bool torsion = trial % 2 == 1;
      const Synthetic s = Generate(effects[static_cast<size_t>(e)], torsion, rng);
      const ForceDiagnosis d = DiagnoseForceCurve(s.rod, s.test, s.curve);
      const int got = static_cast<int>(d.effect);
      ++confusion[e][got];
      ++total;
      if (!d.adequacy.passed) {
        ++not_explained;
        std::printf("  not explained: %s as %s, runs z %.2f, residual %.2f %% of peak\n",
                    ToString(s.effect), ToString(d.effect), d.adequacy.z,
                    100 * d.adequacy.rms_fraction);
      }
      correct += got == e;
      if (got == e && s.effect == ForceEffect::kStiffness) {
        const double err = std::abs(d.parameters.at("ratio") / s.ratio - 1.0);
        worst_ratio_err = std::max(worst_ratio_err, err);
        ratio_ok += err <= 0.15;
        ++ratio_n;
      }
      if (got != e) {
        std::printf("  missed %s as %s: %s, %ld rows, confidence %.2f\n", ToString(s.effect),
                    ToString(d.effect), torsion ? "torsion" : "bending",
                    static_cast<long>(s.curve.x.size()), d.confidence);
      }
      if (got == e && s.effect == ForceEffect::kHysteresis) {
        const double err = std::abs(d.parameters.at("loop_area") / s.loop_area - 1.0);
        worst_area_err = std::max(worst_area_err, err);
        area_ok += err <= 0.15;
        if (err > 0.15 || std::getenv("FORCE_CORPUS_VERBOSE") != nullptr) {
          std::printf(
              "  loop area off by %.2f: %s, %ld rows, truth %.3g fitted %.3g "
              "elements %zu\n",
              err, torsion ? "torsion" : "bending", static_cast<long>(s.curve.x.size()),
              s.loop_area, d.parameters.at("loop_area"), d.elements.size());
        }
        ++area_n;
      }
    }
  }
  std::printf("force corpus confusion (rows truth, cols diagnosed: none stiffness hysteresis)\n");
  for (int e = 0; e < 3; ++e) {
    std::printf("  %-10s %4d %4d %4d\n", ToString(effects[static_cast<size_t>(e)]), confusion[e][0],
                confusion[e][1], confusion[e][2]);
  }
  std::printf(
      "  correct %d / %d; ratio within 15 %%: %d / %d (worst %.3f); loop area within "
      "15 %%: %d / %d (worst %.3f); not explained %d\n",
      correct, total, ratio_ok, ratio_n, worst_ratio_err, area_ok, area_n, worst_area_err,
      not_explained);
  // The adequacy test is one-sided at 99.9 %: on curves the catalogue made, about 0.3 of 300.
  EXPECT_LE(not_explained, 2);
  EXPECT_GE(correct, static_cast<int>(std::ceil(0.95 * total)));
  EXPECT_EQ(confusion[0][1] + confusion[0][2], 0) << "false positives on none";
  EXPECT_EQ(ratio_ok, ratio_n);
  EXPECT_GE(area_ok, static_cast<int>(std::ceil(0.9 * area_n)));
}

}  // namespace
}  // namespace cablefit
