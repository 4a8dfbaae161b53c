#include "shape_effects.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/core/solver/centerline_sampling.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "two_clamp_setup.h"

namespace cablefit {
namespace {

using testing::TwoClamps;

std::vector<EffectModel> Models(const RodSpec& nominal, const std::vector<double>& moments) {
  return testing::StraightRecordingModels(nominal, moments);
}

const EffectModel& ModelOf(const std::vector<EffectModel>& models, ShapeEffect effect,
                           int clamp = 0) {
  for (const EffectModel& m : models)
    if (m.effect == effect && (!m.clamp || *m.clamp == clamp)) return m;
  throw std::logic_error(ToString(effect));
}

Eigen::VectorXd X(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<int>(v.size()));
  int i = 0;
  for (double e : v) x[i++] = e;
  return x;
}

TEST(ShapeEffectsTest, EveryModelIsComplete) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {0.01, 0.01});
  ASSERT_FALSE(models.empty());
  EXPECT_EQ(models.front().effect, ShapeEffect::kNone);
  for (const EffectModel& m : models) {
    SCOPED_TRACE(ToString(m.effect));
    EXPECT_EQ(m.scale.size(), m.physical_parameters);
    ASSERT_FALSE(m.starts.empty());
    for (const Eigen::VectorXd& x : m.starts) EXPECT_EQ(x.size(), m.physical_parameters);
    ASSERT_TRUE(m.change && m.describe && m.base);
    const EffectDescription d = m.describe(m.starts.front(), {});
    for (const auto& [name, value] : d.parameters) EXPECT_TRUE(d.units.count(name)) << name;
    for (const auto& [name, value] : d.vectors) EXPECT_TRUE(d.units.count(name)) << name;
  }
}

TEST(ShapeEffectsTest, NoneChangesNothingAndSaysNothing) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {});
  const EffectModel& m = ModelOf(models, ShapeEffect::kNone);
  const EffectDescription d = m.describe(Eigen::VectorXd(0), {{0.2, 0.4}, nullptr});
  EXPECT_TRUE(d.parameters.empty());
  EXPECT_FALSE(d.interval.has_value());
  EXPECT_EQ(m.apply(Eigen::VectorXd(0)).supports.size(), nominal.supports.size());
}

TEST(ShapeEffectsTest, CurvatureIsDescribedWhereItIsApplied) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {});
  const EffectModel& m = ModelOf(models, ShapeEffect::kIntrinsicCurvature);
  // A span sticking out of the far end, and one narrower than the narrowest allowed.
  for (const Eigen::VectorXd& x : {X({0.95, 0.3, 3.0, 4.0}), X({0.5, 0.001, -2.0, 0.0})}) {
    const RodSpec changed = m.apply(x);
    ASSERT_EQ(changed.natural_curvature.size(), 1u);
    const NaturalCurvatureSpec& nc = changed.natural_curvature.front();
    const EffectDescription d = m.describe(x, {});
    ASSERT_TRUE(d.interval.has_value());
    EXPECT_DOUBLE_EQ(d.interval->first, nc.s_start);
    EXPECT_DOUBLE_EQ(d.interval->second, nc.s_end);
    EXPECT_LE(d.interval->second, nominal.length);
    EXPECT_GE(d.interval->second - d.interval->first, 0.01 * nominal.length - 1e-12);
    EXPECT_DOUBLE_EQ(d.parameters.at("curvature"), nc.kappa.head<2>().norm());
  }
  EXPECT_DOUBLE_EQ(m.describe(X({0.5, 0.2, 3.0, 4.0}), {}).parameters.at("total_bend_angle"),
                   5.0 * 0.2);
}

TEST(ShapeEffectsTest, ContactIsDescribedWhereItPushes) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {});
  const EffectModel& m = ModelOf(models, ShapeEffect::kSupportContact);
  // On a clamp, or beyond the cable, a contact is held off the ends.
  for (double s : {-0.3, 0.0, 0.4, 1.0, 1.7}) {
    const Eigen::VectorXd x = X({s, 0.003, -0.004});
    const RodSpec changed = m.apply(x);
    ASSERT_EQ(changed.point_loads.size(), 1u);
    const EffectDescription d = m.describe(x, {});
    EXPECT_DOUBLE_EQ(d.parameters.at("s"), changed.point_loads.front().s);
    EXPECT_GE(d.parameters.at("s"), 0.02);
    EXPECT_LE(d.parameters.at("s"), 0.98);
    EXPECT_NEAR(d.parameters.at("force"), 0.005, 1e-15);
    EXPECT_TRUE(d.vectors.at("force_vector").isApprox(changed.point_loads.front().force));
    // Normal to the cable (recorded along x), its first component against gravity.
    EXPECT_NEAR(d.vectors.at("force_vector").x(), 0.0, 1e-15);
    EXPECT_NEAR(d.vectors.at("force_vector").z(), 0.003, 1e-15);
    ASSERT_TRUE(d.interval.has_value());
    EXPECT_LE(d.interval->first, d.parameters.at("s"));
    EXPECT_GE(d.interval->second, d.parameters.at("s"));
  }
}

TEST(ShapeEffectsTest, MaterialEffectsAreDescribedAsApplied) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {});
  const EffectDescriptionContext where{{0.3, 0.6}, nullptr};
  {
    const EffectModel& m = ModelOf(models, ShapeEffect::kWeightStiffnessRatio);
    const Eigen::VectorXd x = X({0.4});
    EXPECT_NEAR(m.describe(x, where).parameters.at("ratio"),
                m.apply(x).material.linear_density / nominal.material.linear_density, 1e-12);
    EXPECT_EQ(m.describe(x, where).interval, where.mismatch);
  }
  {
    const EffectModel& m = ModelOf(models, ShapeEffect::kAnisotropicBending);
    for (const Eigen::VectorXd& x : {X({0.2, 0.1}), X({-0.3, -0.05})}) {
      const RodSpec changed = m.apply(x);
      const EffectDescription d = m.describe(x, where);
      EXPECT_DOUBLE_EQ(d.parameters.at("ratio"), changed.material.bending_ratio);
      const double angle = d.parameters.at("principal_angle");
      EXPECT_GE(angle, 0.0);
      EXPECT_LT(angle, M_PI);
      // The same axis: the principal angle is a direction, defined up to a half-turn.
      EXPECT_NEAR(std::remainder(angle - changed.material.principal_angle, M_PI), 0.0, 1e-12);
    }
  }
}

TEST(ShapeEffectsTest, ClampEffectsAreDescribedAsApplied) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {0.01, 0.02});
  {
    const EffectModel& m = ModelOf(models, ShapeEffect::kClampCompliance, 1);
    const Eigen::VectorXd x = X({std::log(4.0)});
    const RodSpec changed = m.apply(x);
    ASSERT_TRUE(changed.supports[1].compliance.has_value());
    EXPECT_NEAR(m.describe(x, {}).parameters.at("stiffness") * (*changed.supports[1].compliance)(0, 0),
                1.0, 1e-12);
  }
  {
    const EffectModel& m = ModelOf(models, ShapeEffect::kClampOrientation, 0);
    const Eigen::VectorXd x = X({0.03, -0.04});
    const RodSpec changed = m.apply(x);
    const EffectDescription d = m.describe(x, {});
    EXPECT_NEAR(d.parameters.at("angle"), 0.05, 1e-15);
    const double turned = std::acos(changed.supports[0].tangent.normalized().dot(Vec3::UnitX()));
    EXPECT_NEAR(turned, 0.05, 1e-9);
    // The axis is perpendicular to both the nominal and the turned direction.
    EXPECT_NEAR(d.vectors.at("axis").dot(Vec3::UnitX()), 0.0, 1e-12);
    EXPECT_NEAR(d.vectors.at("axis").dot(changed.supports[0].tangent), 0.0, 1e-12);
  }
  {
    // Two clamps, isotropic, straight: turning the other clamp back gives the same shape.
    const EffectModel& m = ModelOf(models, ShapeEffect::kTwistPreload, 0);
    const EffectDescription d = m.describe(X({0.5 + 2 * M_PI}), {});
    EXPECT_NEAR(d.parameters.at("angle"), 0.5, 1e-12);
    EXPECT_EQ(d.parameters.at("alternative_clamp"), 1.0);
    EXPECT_NEAR(d.parameters.at("alternative_angle"), -0.5, 1e-12);
    EXPECT_FALSE(d.parameters.count("torque"));  // no solution to read it from
  }
}

// The largest distance between two solved centrelines at the same arc lengths [m] (a point
// load is an element boundary: the two may have different nodes).
double Distance(const SimulationResult& a, const SimulationResult& b, double length) {
  const Eigen::VectorXd s = UniformArcLengths(length, 201);
  return (SampleCenterline(a.solution.centerline, s).points -
          SampleCenterline(b.solution.centerline, s).points)
      .colwise().norm().maxCoeff();
}

// A pair's start beside a single fit takes the single fit's solve as its own when the other
// effect is neutral: with every amplitude zero the model must be the spec it changes, whatever
// its other parameters (up to the discretisation, which a contact's place changes), and a
// non-zero amplitude must change it.
TEST(ShapeEffectsTest, NeutralParametersChangeNothing) {
  const RodSpec nominal = TwoClamps();
  const std::vector<EffectModel> models = Models(nominal, {0.01, 0.01});
  RodSimulator sim;
  const SimulationResult base = sim.Simulate(nominal);
  ASSERT_TRUE(base.converged);
  const double accuracy = sim.options().accuracy;
  int with_amplitudes = 0;
  for (const EffectModel& m : models) {
    if (m.amplitudes.empty()) continue;
    SCOPED_TRACE(ToString(m.effect));
    ++with_amplitudes;
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(m.scale.size(), 0.3, 0.7);  // somewhere
    for (int i : m.amplitudes) x[i] = 0.0;
    ASSERT_TRUE(m.is_neutral(x));
    RodSimulator neutral = sim;
    const SimulationResult same = neutral.Resimulate(m.apply(x));
    ASSERT_TRUE(same.converged);
    EXPECT_LT(Distance(same, base, nominal.length), accuracy);
    x[m.amplitudes.front()] = m.scale[m.amplitudes.front()];
    EXPECT_FALSE(m.is_neutral(x));
    RodSimulator changed = sim;
    const SimulationResult other = changed.Resimulate(m.apply(x));
    ASSERT_TRUE(other.converged);
    EXPECT_GT(Distance(other, base, nominal.length), 10 * accuracy);
  }
  EXPECT_GE(with_amplitudes, 5);  // curvature, both clamp orientations, weight, contact, twists
}

// A placed effect starts at each bend of a residual, where the bend is and with no strength
// (the other effect's fit is the start's shape); an effect without a place has no such starts.
TEST(ShapeEffectsTest, PlacedEffectsStartAtResidualBends) {
  const RodSpec nominal = TwoClamps();
  const double L = nominal.length;
  const std::vector<EffectModel> models = Models(nominal, {0.01, 0.01});
  const std::vector<ResidualBend> bends = {{0.3 * L, 0.01 * L, 2.0}, {0.7 * L, 0.9 * L, 1.0}};
  for (ShapeEffect e : {ShapeEffect::kIntrinsicCurvature, ShapeEffect::kSupportContact}) {
    SCOPED_TRACE(ToString(e));
    const EffectModel& m = ModelOf(models, e);
    ASSERT_TRUE(m.starts_at_bends);
    const std::vector<Eigen::VectorXd> starts = m.starts_at_bends(bends);
    ASSERT_EQ(starts.size(), bends.size());
    for (size_t i = 0; i < bends.size(); ++i) {
      EXPECT_EQ(starts[i].size(), m.physical_parameters);
      EXPECT_DOUBLE_EQ(starts[i][0], bends[i].s);
      EXPECT_TRUE(m.is_neutral(starts[i]));
    }
  }
  // A curvature span as wide as its bend, but neither a point nor the whole cable.
  const std::vector<Eigen::VectorXd> spans =
      ModelOf(models, ShapeEffect::kIntrinsicCurvature).starts_at_bends(bends);
  EXPECT_GT(spans[0][1], 0.01 * L);
  EXPECT_LT(spans[1][1], 0.9 * L);
  EXPECT_FALSE(ModelOf(models, ShapeEffect::kClampCompliance).starts_at_bends);
}

// A contact's scan places: at zero force, in order along the cable, off the clamps' own ends and
// finer than its grid of starts; an effect without a place has none.
TEST(ShapeEffectsTest, ContactScansPlacesAlongTheCable) {
  const RodSpec nominal = TwoClamps();
  const double L = nominal.length;
  const std::vector<EffectModel> models = Models(nominal, {0.01, 0.01});
  const EffectModel& m = ModelOf(models, ShapeEffect::kSupportContact);
  ASSERT_GT(m.scan_places.size(), 2 * m.starts.size());
  for (size_t i = 0; i < m.scan_places.size(); ++i) {
    EXPECT_TRUE(m.is_neutral(m.scan_places[i]));
    EXPECT_GE(m.scan_places[i][0], 0.02 * L);
    EXPECT_LE(m.scan_places[i][0], 0.98 * L);
    if (i > 0) {
      EXPECT_GT(m.scan_places[i][0], m.scan_places[i - 1][0]);
    }
  }
  EXPECT_TRUE(ModelOf(models, ShapeEffect::kClampCompliance).scan_places.empty());
}

}  // namespace
}  // namespace cablefit
