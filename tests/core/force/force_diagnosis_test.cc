// Force-curve diagnosis on the public force cases and on bad inputs.
#include "cablefit/core/force/force_diagnosis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/force/force_rig.h"
#include "force_test_data.h"
#include "test_support.h"

namespace cablefit {
namespace {

TEST(ForceDiagnosis, IdentifiesPublicCases) {
  const auto cases = testing::LoadPublicForceCases();
  ASSERT_GE(cases.size(), 3u);
  for (const auto& c : cases) {
    const ForceDiagnosis d = DiagnoseForceCurve(c.rod, c.test, c.curve, {}, c.file);
    std::cout << c.name << ": " << ToString(d.effect) << " (confidence " << d.confidence << ") — "
              << d.explanation << "\n";
    for (const auto& cand : d.candidates) {
      std::cout << "   " << ToString(cand.effect) << " score " << cand.score << " criterion "
                << cand.criterion << " p " << cand.parameter_count << "\n";
    }
    EXPECT_EQ(ToString(d.effect), c.truth_effect) << c.name;
    EXPECT_GE(d.confidence, 0.5) << c.name;
    EXPECT_TRUE(d.adequacy.passed) << c.name << ": runs z " << d.adequacy.z;
    if (c.truth_effect == "stiffness") {
      ASSERT_TRUE(c.truth_ratio.has_value());
      EXPECT_NEAR(d.parameters.at("ratio"), *c.truth_ratio, 0.15 * *c.truth_ratio) << c.name;
    }
    if (c.truth_effect == "hysteresis") {
      ASSERT_TRUE(c.truth_loop_area.has_value());
      std::cout << "   loop_area fitted " << d.parameters.at("loop_area") << " truth "
                << *c.truth_loop_area << "\n";
      EXPECT_NEAR(d.parameters.at("loop_area"), *c.truth_loop_area, 0.15 * *c.truth_loop_area);
    }
    // The fitted curve explains the data at least as well as the nominal one.
    EXPECT_LE(d.fitted.rms_deviation, d.baseline.rms_deviation + 1e-15) << c.name;
    EXPECT_EQ(d.fitted_curve.size(), c.curve.x.size());
    EXPECT_EQ(d.nominal_curve.size(), c.curve.x.size());
    EXPECT_FALSE(d.explanation.empty());
  }
}

// A cable that softens elastically (the same path loading and unloading, 30 % softer at the
// largest angle) is none of the catalogue's effects: the best fit leaves long runs of one sign,
// and the diagnosis says that nothing explains the curve instead of naming the closest effect.
TEST(ForceDiagnosis, ACurveNoCatalogueEffectMakesIsNotExplained) {
  RodSpec rod;
  rod.length = 0.6;
  rod.material.torsional_stiffness = 0.01;
  rod.gravity = Vec3::Zero();
  ForceTestSpec test;
  test.type = ForceTestType::kClampedTorsion;
  test.max_angle = 0.4;
  ForceCurve curve;
  std::vector<double> x;
  for (int c = 0; c < 2; ++c) {
    for (int i = 0; i <= 20; ++i) x.push_back(test.max_angle * i / 20);
    for (int i = 19; i >= 0; --i) x.push_back(test.max_angle * i / 20);
  }
  curve.x = Eigen::Map<Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
  const Eigen::VectorXd nominal = NominalForceCurve(rod, test, curve.x);
  const double peak = nominal.cwiseAbs().maxCoeff();
  curve.y = nominal;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.005 * peak);
  for (Eigen::Index i = 0; i < curve.y.size(); ++i) {
    const double u = curve.x[i] / test.max_angle;
    curve.y[i] = nominal[i] * (1.0 - 0.3 * u * u) + noise(rng);
  }
  const ForceDiagnosis d = DiagnoseForceCurve(rod, test, curve, {}, "softening.csv");
  EXPECT_FALSE(d.adequacy.passed) << "runs z " << d.adequacy.z;
  EXPECT_LT(d.adequacy.z, -3.09);
  EXPECT_NE(d.explanation.find("no catalogue effect explains"), std::string::npos)
      << d.explanation;
  const ForceCaseDiagnosis all = CombineForceDiagnoses({d});
  EXPECT_FALSE(all.explained);
  EXPECT_LE(all.confidence, 0.1);
  EXPECT_NE(all.explanation.find("softening.csv: no catalogue effect"), std::string::npos)
      << all.explanation;

  // The same curve without the softening is explained.
  for (Eigen::Index i = 0; i < curve.y.size(); ++i) curve.y[i] = nominal[i] + noise(rng);
  const ForceDiagnosis plain = DiagnoseForceCurve(rod, test, curve);
  EXPECT_TRUE(plain.adequacy.passed) << "runs z " << plain.adequacy.z;
  EXPECT_TRUE(CombineForceDiagnoses({plain}).explained);
}

TEST(ForceDiagnosis, CombinesCurvesOfOneCase) {
  const auto cases = testing::LoadPublicForceCases();
  std::vector<ForceDiagnosis> diagnoses;
  for (const auto& c : cases) diagnoses.push_back(DiagnoseForceCurve(c.rod, c.test, c.curve));
  for (const auto& d : diagnoses) {
    const ForceCaseDiagnosis single = CombineForceDiagnoses({d});
    EXPECT_EQ(single.effect, d.effect);
    EXPECT_NEAR(single.confidence, d.confidence, 1e-12);
  }
  EXPECT_THROW_WITH(CombineForceDiagnoses({}), InvalidInput, "no force curves");
}

// Two curves of one case are one hypothesis per effect: their likelihoods add, the prior against
// complexity is counted once (summing it per curve made a case with two hysteretic curves
// demand twice the evidence of one).
TEST(ForceDiagnosis, JointCurvesCountTheComplexityPriorOnce) {
  const auto cases = testing::LoadPublicForceCases();
  ASSERT_GE(cases.size(), 2u);
  const ForceDiagnosisOptions options;
  std::vector<ForceDiagnosis> d;
  for (size_t i = 0; i < 2; ++i)
    d.push_back(DiagnoseForceCurve(cases[i].rod, cases[i].test, cases[i].curve, options));
  const ForceCaseDiagnosis joint = CombineForceDiagnoses(d, options);
  std::map<ForceEffect, double> criterion;
  double best = INFINITY;
  for (const ForceCandidate& c : d[0].candidates) {
    double sum = -options.complexity_margin * (c.effect == ForceEffect::kNone        ? 0
                                               : c.effect == ForceEffect::kStiffness ? 1
                                                                                     : 2);
    for (const ForceDiagnosis& one : d)
      for (const ForceCandidate& o : one.candidates)
        if (o.effect == c.effect) sum += o.criterion;
    criterion[c.effect] = sum;
    best = std::min(best, sum);
  }
  double total = 0.0;
  for (const auto& [e, c] : criterion) total += std::exp(-0.5 * (c - best));
  for (const auto& [e, score] : joint.candidates)
    EXPECT_NEAR(score, std::exp(-0.5 * (criterion[e] - best)) / total, 1e-9) << ToString(e);
}

TEST(ForceDiagnosis, CaseWithSofterBendingAndNominalTorsionIsStiffness) {
  RodSpec rod;
  rod.length = 0.7;
  rod.material.bending_stiffness = 0.012;
  rod.material.torsional_stiffness = 0.009;
  ForceTestSpec torsion;
  torsion.type = ForceTestType::kClampedTorsion;
  ForceCurve twist;
  twist.x = (Eigen::VectorXd(7) << 0, 0.1, 0.2, 0.3, 0.2, 0.1, 0).finished();
  twist.y = NominalForceCurve(rod, torsion, twist.x);
  ForceTestSpec bending;
  ForceCurve bend;
  bend.x =
      (Eigen::VectorXd(9) << 0.01, 0.015, 0.02, 0.025, 0.03, 0.025, 0.02, 0.015, 0.01).finished();
  bend.y = 0.7 * NominalForceCurve(rod, bending, bend.x);
  // Deterministic +-0.5 % "noise" so the criterion sees a finite residual.
  for (Eigen::Index i = 0; i < bend.y.size(); ++i) bend.y[i] *= 1.0 + 0.005 * std::sin(3.0 * i);
  for (Eigen::Index i = 0; i < twist.y.size(); ++i) {
    twist.y[i] += 0.005 * 0.009 * 0.3 / 0.7 * std::cos(2.0 * i);
  }
  const ForceDiagnosis dt = DiagnoseForceCurve(rod, torsion, twist, {}, "torsion.csv");
  const ForceDiagnosis db = DiagnoseForceCurve(rod, bending, bend, {}, "bending.csv");
  EXPECT_EQ(dt.effect, ForceEffect::kNone);
  EXPECT_EQ(db.effect, ForceEffect::kStiffness);
  const ForceCaseDiagnosis c = CombineForceDiagnoses({dt, db});
  EXPECT_EQ(c.effect, ForceEffect::kStiffness);
  EXPECT_EQ(c.strongest_curve, 1);
  EXPECT_NEAR(c.parameters.at("ratio"), 0.7, 0.01);
  ASSERT_EQ(c.curves.size(), 2u);
  EXPECT_EQ(c.curves[0].effect, ForceEffect::kStiffness);  // re-expressed with the case effect
  EXPECT_NEAR(c.curves[0].parameters.at("ratio"), 1.0, 0.02);
  EXPECT_NE(c.explanation.find("bending.csv"), std::string::npos);
  EXPECT_NE(c.explanation.find("lower than nominal"), std::string::npos);
  EXPECT_GE(c.baseline.max_deviation, db.baseline.max_deviation);
  EXPECT_LT(c.fitted.max_deviation, 0.1 * c.baseline.max_deviation);
}

TEST(ForceDiagnosis, RecoversNoiseFreeIwanLoopAndStiffness) {
  RodSpec rod;
  rod.length = 0.5;
  rod.material.torsional_stiffness = 0.01;
  ForceTestSpec torsion;
  torsion.type = ForceTestType::kClampedTorsion;
  ForceCurve curve;
  std::vector<double> xs;
  for (int cycle = 0; cycle < 2; ++cycle) {
    for (int i = 0; i <= 8; ++i) xs.push_back(0.04 * i);
    for (int i = 7; i >= 0; --i) xs.push_back(0.04 * i);
  }
  curve.x = Eigen::Map<Eigen::VectorXd>(xs.data(), static_cast<Eigen::Index>(xs.size()));
  const std::vector<JenkinsElement> elements = {{0.05, 0.0004}, {0.02, 0.0006}};
  const Eigen::VectorXd clean =
      1.2 * NominalForceCurve(rod, torsion, curve.x) + IwanResponse(elements, curve.x);
  curve.y = clean;
  const ForceDiagnosis d = DiagnoseForceCurve(rod, torsion, curve);
  EXPECT_EQ(d.effect, ForceEffect::kHysteresis);
  EXPECT_NEAR(d.parameters.at("ratio"), 1.2, 0.02);
  EXPECT_NEAR(d.parameters.at("loop_area"), FirstCycleLoopArea(curve.x, clean),
              0.03 * FirstCycleLoopArea(curve.x, clean));
  EXPECT_NEAR(d.parameters.at("slip_force_total"), 0.001, 1e-4);
  EXPECT_LT(d.fitted.max_deviation, 0.05 * d.baseline.max_deviation);
}

class ForceDiagnosisBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    rod_.length = 0.6;
    rod_.material.bending_stiffness = 0.01;
    rod_.material.torsional_stiffness = 0.008;
    test_.type = ForceTestType::kPinnedBending;
    curve_.x = Eigen::VectorXd::LinSpaced(9, 0.005, 0.02);
    curve_.y = NominalForceCurve(rod_, test_, curve_.x);
  }
  RodSpec rod_;
  ForceTestSpec test_;
  ForceCurve curve_;
};

TEST_F(ForceDiagnosisBadInput, TooFewRows) {
  curve_.x.conservativeResize(3);
  curve_.y.conservativeResize(3);
  EXPECT_THROW_WITH(DiagnoseForceCurve(rod_, test_, curve_, {}, "bending.csv"), FileError,
                    "bending.csv: 3 rows");
}

TEST_F(ForceDiagnosisBadInput, NaNIsRejected) {
  curve_.y[4] = std::nan("");
  EXPECT_THROW_WITH(DiagnoseForceCurve(rod_, test_, curve_, {}, "b.csv"), InvalidInput,
                    "row 5 is not a finite number");
}

TEST_F(ForceDiagnosisBadInput, DisplacementBeyondGeometricLimit) {
  curve_.x[8] = 0.7;  // longer than the cable
  EXPECT_THROW_WITH(DiagnoseForceCurve(rod_, test_, curve_, {}, "b.csv"), InvalidInput,
                    "geometric range");
}

TEST_F(ForceDiagnosisBadInput, MismatchedColumnsAndConstantX) {
  ForceCurve c = curve_;
  c.y.conservativeResize(8);
  EXPECT_THROW_WITH(DiagnoseForceCurve(rod_, test_, c), InvalidInput, "differ in length");
  c = curve_;
  c.x.setConstant(0.01);
  EXPECT_THROW_WITH(DiagnoseForceCurve(rod_, test_, c), InvalidInput, "never changes");
}

TEST_F(ForceDiagnosisBadInput, NonMonotonicStepsAreFine) {
  std::swap(curve_.x[2], curve_.x[6]);
  curve_.y = NominalForceCurve(rod_, test_, curve_.x);
  const ForceDiagnosis d = DiagnoseForceCurve(rod_, test_, curve_);
  EXPECT_EQ(d.effect, ForceEffect::kNone);
}

TEST_F(ForceDiagnosisBadInput, InvalidOptions) {
  ForceDiagnosisOptions options;
  options.offset_prior_fraction = -1.0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("offset_prior_fraction"), std::string::npos);
  // Options come from code, not from the user's data: caller misuse, not InvalidInput.
  EXPECT_THROW_WITH(DiagnoseForceCurve(rod_, test_, curve_, options), UsageError,
                    "offset_prior_fraction");
  EXPECT_TRUE(ForceDiagnosisOptions{}.IsValid(nullptr));
}

}  // namespace
}  // namespace cablefit
