#include "model_selection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cablefit::internal {
namespace {

ModelFit Null(double cost) { return {0, 0, cost, true, 0}; }
ModelFit Effect(int group, int parameters, double cost) {
  return {group, parameters, cost, true, 1};
}

double ScoreOf(const ModelRanking& r, std::size_t fit) {
  for (const RankedModel& m : r.ranked)
    if (m.fit == fit) return m.score;
  return -1.0;
}

TEST(ModelSelectionTest, MoreParametersWithTheSameResidualLose) {
  // No margin for the null model: only the parameter count separates them.
  const std::vector<ModelFit> fits = {Effect(1, 1, 1e-6), Effect(2, 4, 1e-6)};
  const ModelRanking r = RankModels(fits, 200, 1e-4, 0.0);
  ASSERT_EQ(r.ranked.size(), 2u);
  EXPECT_EQ(r.ranked.front().fit, 0u);
  EXPECT_NEAR(r.ranked[1].bic - r.ranked[0].bic, 3.0 * std::log(200.0), 1e-9);
  EXPECT_GT(r.ranked[0].score, 0.99);
}

TEST(ModelSelectionTest, TheNullModelWinsUnlessAnEffectGainsTheMargin) {
  // sigma^2 is floored by the noise (1e-8 m^2); the effect lowers chi^2 by 2 * 2e-9 / 1e-8 = 0.4.
  const std::vector<ModelFit> fits = {Null(1e-8), Effect(1, 1, 0.8e-8)};
  const ModelRanking r = RankModels(fits, 1000, 1e-4, 10.0);
  EXPECT_EQ(r.ranked.front().fit, 0u);
  EXPECT_DOUBLE_EQ(r.sigma2, 1e-8);
  // The margin is prior odds: the criterion carries it, the BIC does not.
  for (const RankedModel& m : r.ranked)
    EXPECT_DOUBLE_EQ(m.criterion - m.bic, m.fit == 0 ? 0.0 : 10.0);
}

TEST(ModelSelectionTest, ASecondEffectPaysTheMarginAgain) {
  // A pair (group 10, two effects) that gains a little over the best single effect loses to it;
  // one that gains far more than the margin and its parameters' price wins.
  ModelFit pair = Effect(10, 4, 0.97e-8);
  pair.effects = 2;
  const std::vector<ModelFit> close = {Null(1e-6), Effect(1, 2, 1e-8), pair};
  const ModelRanking r = RankModels(close, 1000, 1e-5, 10.0);
  EXPECT_EQ(r.ranked.front().fit, 1u);
  for (const RankedModel& m : r.ranked)
    EXPECT_DOUBLE_EQ(m.criterion - m.bic, m.fit == 0 ? 0.0 : m.fit == 2 ? 20.0 : 10.0);
  pair.cost = 0.2e-8;
  const ModelRanking far = RankModels({Null(1e-6), Effect(1, 2, 1e-8), pair}, 1000, 1e-5, 10.0);
  EXPECT_EQ(far.ranked.front().fit, 2u);
}

TEST(ModelSelectionTest, TheNoiseLevelScalesTheDecision) {
  // The same two fits: against a quiet recording the effect's gain is far beyond its price,
  // against a noisy one (the floor of sigma^2) it is within the noise.
  const std::vector<ModelFit> fits = {Null(2e-8), Effect(1, 1, 1e-8)};
  const ModelRanking quiet = RankModels(fits, 200, 1e-6, 10.0);
  EXPECT_EQ(quiet.ranked.front().fit, 1u);
  EXPECT_GT(quiet.ranked.front().score, 0.99);
  const ModelRanking noisy = RankModels(fits, 200, 1e-4, 10.0);
  EXPECT_EQ(noisy.ranked.front().fit, 0u);
  EXPECT_GT(noisy.ranked.front().score, 0.99);
  // The quiet recording's variance is the best fit's residual per degree of freedom.
  EXPECT_NEAR(quiet.sigma2, 2.0 * 1e-8 / (200 - 8), 1e-22);
}

TEST(ModelSelectionTest, TwoModelsThatScoreAlikeShareTheWeight) {
  const std::vector<ModelFit> fits = {Null(1e-6), Effect(1, 2, 1e-8), Effect(2, 2, 1e-8)};
  const ModelRanking r = RankModels(fits, 400, 1e-5, 10.0);
  ASSERT_EQ(r.ranked.size(), 3u);
  EXPECT_NEAR(r.ranked[0].score, 0.5, 1e-6);
  EXPECT_NEAR(r.ranked[1].score, 0.5, 1e-6);
  EXPECT_LT(ScoreOf(r, 0), 1e-6);
  // A tie keeps the catalogue's order.
  EXPECT_EQ(r.ranked[0].fit, 1u);
}

TEST(ModelSelectionTest, ScoresArePosteriorWeights) {
  const std::vector<ModelFit> fits = {Null(3e-8), Effect(1, 1, 2.6e-8), Effect(2, 2, 2.5e-8),
                                      Effect(3, 4, 2.4e-8)};
  const ModelRanking r = RankModels(fits, 300, 1e-5, 2.0);
  double sum = 0.0;
  for (std::size_t i = 0; i < r.ranked.size(); ++i) {
    sum += r.ranked[i].score;
    if (i > 0) {
      EXPECT_GE(r.ranked[i - 1].score, r.ranked[i].score);
    }
    // exp(-criterion / 2), normalised.
    EXPECT_NEAR(r.ranked[i].score / r.ranked[0].score,
                std::exp(-0.5 * (r.ranked[i].criterion - r.ranked[0].criterion)), 1e-12);
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(ModelSelectionTest, OneCandidatePerGroupTheBestOfIt) {
  // One effect at two clamps: the better clamp stands for the effect.
  const std::vector<ModelFit> fits = {Null(1e-6), Effect(1, 1, 5e-8), Effect(1, 1, 2e-8)};
  const ModelRanking r = RankModels(fits, 400, 1e-5, 10.0);
  ASSERT_EQ(r.ranked.size(), 2u);
  EXPECT_EQ(r.ranked.front().fit, 2u);
}

TEST(ModelSelectionTest, ARejectedFitWeighsNothingAndTheNextIsChosen) {
  const std::vector<ModelFit> fits = {Null(3e-8), Effect(1, 1, 1e-8), Effect(2, 1, 2e-8)};
  const ModelRanking before = RankModels(fits, 400, 1e-5, 10.0);
  EXPECT_EQ(before.ranked.front().fit, 1u);
  const ModelRanking after = RankModels(fits, 400, 1e-5, 10.0, {false, true, false});
  ASSERT_EQ(after.ranked.size(), 3u);
  EXPECT_EQ(after.ranked.front().fit, 2u);
  EXPECT_EQ(after.ranked.back().fit, 1u);
  EXPECT_EQ(after.ranked.back().score, 0.0);
  // The rejected fit still set the noise estimate.
  EXPECT_DOUBLE_EQ(after.sigma2, before.sigma2);
}

TEST(ModelSelectionTest, FitsThatFailedAreNoCandidates) {
  std::vector<ModelFit> fits = {Null(1e-6), Effect(1, 1, 1e-9)};
  fits[1].ok = false;
  const ModelRanking r = RankModels(fits, 400, 1e-5, 10.0);
  ASSERT_EQ(r.ranked.size(), 1u);
  EXPECT_EQ(r.ranked.front().fit, 0u);
  fits[0].ok = false;
  EXPECT_TRUE(RankModels(fits, 400, 1e-5, 10.0).ranked.empty());
}

TEST(ModelSelectionTest, ChiSquareQuantileMatchesTables) {
  // chi-square 99.9 % quantiles from the tables: 59.703 (30 dof), 149.449 (100 dof).
  EXPECT_NEAR(ChiSquareQuantile999(30), 59.703, 0.003 * 59.703);
  EXPECT_NEAR(ChiSquareQuantile999(100), 149.449, 0.001 * 149.449);
}

TEST(ModelSelectionTest, AdequacyComparesTheResidualWithTheAllowedNoise) {
  // 200 offsets of 1e-4 m each: chi^2 = 200 at that noise, 50 at twice the noise allowed.
  const double cost = 0.5 * 200 * 1e-8;
  const AdequacyTest at_noise = TestAdequacy(cost, 200, 1e-4, 1.0);
  EXPECT_NEAR(at_noise.chi_square, 200.0, 1e-9);
  EXPECT_TRUE(at_noise.passed);
  EXPECT_NEAR(TestAdequacy(cost, 200, 1e-4, 2.0).chi_square, 50.0, 1e-9);
  EXPECT_FALSE(TestAdequacy(cost, 200, 0.5e-4, 1.0).passed);  // chi^2 800, limit ~ 282
}

}  // namespace
}  // namespace cablefit::internal
