#include "effect_combination.h"

#include <utility>

namespace cablefit {
namespace {

// The clamps that hold the twist (kClamp supports).
int TwistHoldingClamps(const RodSpec& spec) {
  int n = 0;
  for (const SupportSpec& s : spec.supports) n += s.kind == SupportKind::kClamp;
  return n;
}

}  // namespace

bool CanCombine(const EffectModel& a, const EffectModel& b, const RodSpec& nominal) {
  if (a.effect == ShapeEffect::kNone || b.effect == ShapeEffect::kNone) return false;
  if (a.is_combination() || b.is_combination()) return false;
  if (a.effect != b.effect) return true;
  switch (a.effect) {
    case ShapeEffect::kIntrinsicCurvature:
    case ShapeEffect::kSupportContact:
      return true;
    case ShapeEffect::kClampOrientation:
    case ShapeEffect::kClampCompliance:
      return a.clamp != b.clamp;
    case ShapeEffect::kTwistPreload: {
      if (a.clamp == b.clamp) return false;
      const bool only_difference_seen = TwistHoldingClamps(nominal) == 2 &&
                                        nominal.material.bending_ratio == 1.0 &&
                                        nominal.natural_curvature.empty();
      return !only_difference_seen;
    }
    default:
      return false;
  }
}

EffectModel CombineEffects(const std::vector<EffectModel>& singles, int a, int b) {
  const EffectModel& ma = singles[static_cast<size_t>(a)];
  const EffectModel& mb = singles[static_cast<size_t>(b)];
  const int na = static_cast<int>(ma.scale.size()), nb = static_cast<int>(mb.scale.size());
  EffectModel m;
  m.effect = ma.effect;
  m.clamp = ma.clamp;
  m.physical_parameters = ma.physical_parameters + mb.physical_parameters;
  m.scale.resize(na + nb);
  m.scale << ma.scale, mb.scale;
  m.base = ma.base;
  m.parts = {a, b};
  m.part_offsets = {0, na};
  m.change = [ca = ma.change, cb = mb.change, na, nb](const Eigen::VectorXd& x, RodSpec* s) {
    ca(x.head(na), s);
    cb(x.segment(na, nb), s);
  };
  // A combination is described part by part (shape_diagnosis); as one model it reads as its
  // first part.
  m.describe = [da = ma.describe, na](const Eigen::VectorXd& x, const EffectDescriptionContext& c) {
    return da(x.head(na), c);
  };
  return m;
}

EffectModel WithoutPart(const EffectModel& combined, const std::vector<EffectModel>& singles,
                        int part) {
  EffectModel m = combined;
  std::vector<std::pair<std::function<void(const Eigen::VectorXd&, RodSpec*)>, std::pair<int, int>>>
      kept;
  for (size_t i = 0; i < combined.parts.size(); ++i) {
    if (static_cast<int>(i) == part) continue;
    const EffectModel& single = singles[static_cast<size_t>(combined.parts[i])];
    kept.push_back({single.change,
                    {combined.part_offsets[i], static_cast<int>(single.scale.size())}});
  }
  m.change = [kept](const Eigen::VectorXd& x, RodSpec* s) {
    for (const auto& [change, span] : kept) change(x.segment(span.first, span.second), s);
  };
  return m;
}

Eigen::VectorXd PartParameters(const EffectModel& combined, const std::vector<EffectModel>& singles,
                               int part, const Eigen::VectorXd& x) {
  const EffectModel& single = singles[static_cast<size_t>(combined.parts[static_cast<size_t>(part)])];
  return x.segment(combined.part_offsets[static_cast<size_t>(part)],
                   static_cast<int>(single.scale.size()));
}

}  // namespace cablefit
