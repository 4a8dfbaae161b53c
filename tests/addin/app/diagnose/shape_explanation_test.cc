#include "cablefit/app/diagnose/shape_explanation.h"

#include <gtest/gtest.h>

#include <string>

namespace cablefit::addin {
namespace {

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

RodSpec TwoClamps() {
  RodSpec spec;
  spec.length = 1.0;
  SupportSpec a, b;
  b.s = 1.0;
  spec.supports = {a, b};
  return spec;
}

ShapeDiagnosis TwistAtFirstClamp() {
  ShapeDiagnosis d;
  d.effect = ShapeEffect::kTwistPreload;
  d.clamp = 0;
  d.confidence = 0.6;
  d.parameters = {{"angle", 0.5}, {"torque", 0.002}, {"alternative_clamp", 1},
                  {"alternative_angle", -0.5}};
  d.baseline_max = 0.004;
  d.fitted_max = 0.0002;
  FoundEffect found;
  found.effect = d.effect;
  found.clamp = d.clamp;
  found.parameters = d.parameters;
  found.share = 0.99;
  d.effects = {found};
  EffectCandidate twist, compliance;
  twist.effect = ShapeEffect::kTwistPreload;
  twist.score = 0.6;
  compliance.effect = ShapeEffect::kClampCompliance;
  compliance.score = 0.4;
  d.candidates = {twist, compliance};
  return d;
}

TEST(ShapeExplanationTest, TheNominalNeedsNoChange) {
  ShapeDiagnosis d;
  d.baseline_max = 0.0003;
  d.baseline_rms = 0.0001;
  const std::string text = ExplainShapeDiagnosis(d, TwoClamps());
  EXPECT_EQ(text.rfind("The nominal model explains the recording within its noise (max deviation "
                       "0.3 mm, rms 0.1 mm)",
                       0),
            0u)
      << text;
}

TEST(ShapeExplanationTest, AnEffectIsWordedFromItsParameters) {
  const std::string text = ExplainShapeDiagnosis(TwistAtFirstClamp(), TwoClamps());
  EXPECT_TRUE(Has(text, "The clamp at s=0.000 m is rotated 28.6 deg about the cable axis")) << text;
  EXPECT_TRUE(Has(text, "a torque of 2.00 mN m")) << text;
  EXPECT_TRUE(Has(text, "from 4 mm to 0.2 mm")) << text;
  // The alternative the shape cannot tell apart, at the other clamp.
  EXPECT_TRUE(Has(text, "the clamp at s=1.000 m turned -28.6 deg gives the same shape")) << text;
  // A close runner-up is named.
  EXPECT_TRUE(Has(text, "hardly separates it from clamp_compliance (scores 0.60 and 0.40)"))
      << text;
}

TEST(ShapeExplanationTest, AnUnexplainedRecordingSaysWhatToCheck) {
  ShapeDiagnosis d = TwistAtFirstClamp();
  d.explained = false;
  d.adequacy.noise_sigma = 1e-4;
  d.adequacy.noise_allowance = 3.0;
  d.adequacy.chi_square = 5000;
  d.adequacy.degrees_of_freedom = 300;
  d.adequacy.limit = 390;
  const std::string text = ExplainShapeDiagnosis(d, TwoClamps());
  EXPECT_EQ(text.rfind("No effect of the catalogue, alone or in pairs, explains the recording: "
                       "the best fit (twist_preload)",
                       0),
            0u)
      << text;
  EXPECT_TRUE(Has(text, "5000 for 300 degrees of freedom, 99.9 % limit 390")) << text;
  EXPECT_TRUE(Has(text, "Best candidate: The clamp at s=0.000 m")) << text;
  EXPECT_FALSE(Has(text, "hardly separates")) << text;
}

TEST(ShapeExplanationTest, TwoEffectsAreEachWordedWithTheirShare) {
  ShapeDiagnosis d;
  d.baseline_max = 0.012;
  d.fitted_max = 0.0001;
  FoundEffect curvature, clamp;
  curvature.effect = ShapeEffect::kIntrinsicCurvature;
  curvature.interval = std::make_pair(0.2, 0.35);
  curvature.parameters = {{"curvature", 4.0}};
  curvature.share = 0.62;
  clamp.effect = ShapeEffect::kClampOrientation;
  clamp.clamp = 1;
  clamp.parameters = {{"angle", 0.1}};
  clamp.share = 0.37;
  d.effects = {curvature, clamp};
  d.effect = curvature.effect;
  const std::string text = ExplainShapeDiagnosis(d, TwoClamps());
  EXPECT_EQ(text.rfind("2 pieces of physics were left out; fitting them together reduces the max "
                       "deviation from 12 mm to 0.1 mm.",
                       0),
            0u)
      << text;
  EXPECT_TRUE(Has(text, "(1) The cable has a natural curvature of 4.00 1/m")) << text;
  EXPECT_TRUE(Has(text, "between s=0.200 m and s=0.350 m")) << text;
  EXPECT_TRUE(Has(text, "62 % of the mismatch")) << text;
  EXPECT_TRUE(Has(text, "(2) The clamp at s=1.000 m holds the cable 5.7 deg off")) << text;
  EXPECT_TRUE(Has(text, "37 % of the mismatch")) << text;
}

TEST(ShapeExplanationTest, EveryNoteIsASentenceWithItsFigures) {
  DiagnosisNote reversed;
  reversed.kind = DiagnosisNote::Kind::kRecordingReversed;
  reversed.gap_as_listed = 0.412;
  reversed.gap_reversed = 0.0003;
  EXPECT_EQ(DescribeNote(reversed),
            "the recording runs from the last clamp to the first (its ends are 412 mm from their "
            "clamps as listed, 0.3 mm reversed); it was reversed");
  DiagnosisNote held;
  held.kind = DiagnosisNote::Kind::kFitDidNotHold;
  held.effect = ShapeEffect::kSupportContact;
  held.solved = false;
  EXPECT_TRUE(Has(DescribeNote(held), "the support_contact fit did not hold"))
      << DescribeNote(held);
  EXPECT_TRUE(Has(DescribeNote(held), "(not solved)")) << DescribeNote(held);
  DiagnosisNote branch;
  branch.kind = DiagnosisNote::Kind::kFitFromOtherEquilibrium;
  branch.effect = ShapeEffect::kTwistPreload;
  branch.start = NominalStart::kMirroredSag;
  EXPECT_TRUE(Has(DescribeNote(branch), "the twist_preload fit started from another equilibrium"))
      << DescribeNote(branch);
  EXPECT_TRUE(Has(DescribeNote(branch), "the recorded sag mirrored through the chord"))
      << DescribeNote(branch);
}

}  // namespace
}  // namespace cablefit::addin
