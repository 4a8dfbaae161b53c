// A finer level's start from a coarser level's equilibrium of the same network, frame by frame.
#include <Eigen/Geometry>
#include <algorithm>

#include "network_parts.h"
#include "cablefit/core/rod/internal/support_targets.h"

namespace cablefit {
namespace {

Eigen::Quaterniond AsQuaternion(const Eigen::Vector4d& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

}  // namespace

bool TransferNetworkState(const NetworkModel& from, const RodState& from_state,
                          const NetworkModel& to, RodState* state) {
  const RodModel& fm = from.rod;
  const RodModel& tm = to.rod;
  if (from.branches.size() != to.branches.size() || from.junctions.size() != to.junctions.size() ||
      from.num_spec_supports != to.num_spec_supports ||
      from_state.q.size() != fm.items.size() ||
      static_cast<int>(from_state.support_position.size()) < from.num_spec_supports ||
      fm.num_constraints != tm.num_constraints || from_state.lambda.size() < fm.num_constraints)
    return false;
  RodState st;
  st.q.assign(tm.items.size(), Eigen::Vector4d(1, 0, 0, 0));
  // Elements: slerped by arc length between the coarser level's frame samples of the same branch
  // (element midpoints and the support frames at their nodes). A coarse element's tangent is its
  // chord, so the finer chain passes through the coarse nodes up to the curvature's second-order
  // term. Beyond the outermost samples (towards a junction) the frames are extrapolated from the
  // two nearest ones: the branch's end turns as the coarse level has it turning there. Holding
  // the nearest frame instead puts the turn over half a coarse element into a finer element's
  // joint (a twisted Y junction's start: 2.8e-3 of the energy above the equilibrium, now 2.5e-5).
  struct Sample {
    double s;
    Eigen::Quaterniond q;
  };
  std::vector<Sample> samples;
  for (size_t b = 0; b < to.branches.size(); ++b) {
    const internal::BranchLayout& fl = from.branches[b];
    const internal::BranchLayout& tl = to.branches[b];
    if (fl.elements.empty() || tl.elements.empty()) return false;
    const double scale = tl.node_s[tl.node_s.size() - 1] /
                         std::max(1e-300, fl.node_s[fl.node_s.size() - 1]);
    samples.clear();
    for (int e : fl.elements) {
      const int item = fm.element_item[e];
      samples.push_back({fm.items[item].s * scale, AsQuaternion(from_state.q[item])});
    }
    for (int k : fl.supports) {
      const int item = fm.supports[k].item;
      if (item >= 0)
        samples.push_back({fm.items[item].s * scale, AsQuaternion(from_state.q[item])});
    }
    std::stable_sort(samples.begin(), samples.end(),
                     [](const Sample& a, const Sample& b) { return a.s < b.s; });
    const int n = static_cast<int>(samples.size());
    for (size_t k = 0; k < tl.elements.size(); ++k) {
      const double s = 0.5 * (tl.node_s[k] + tl.node_s[k + 1]);
      const auto up = std::upper_bound(samples.begin(), samples.end(), s,
                                       [](double v, const Sample& a) { return v < a.s; });
      const int before = static_cast<int>(up - samples.begin()) - 1;
      Eigen::Quaterniond q = samples[std::clamp(before, 0, n - 1)].q;
      const int j = std::clamp(before, 0, std::max(0, n - 2));
      if (j + 1 < n && samples[j + 1].s > samples[j].s) {
        // At most half a sample spacing beyond the outermost samples: a bounded extrapolation.
        const double w =
            std::clamp((s - samples[j].s) / (samples[j + 1].s - samples[j].s), -0.5, 1.5);
        Eigen::Quaterniond qb = samples[j + 1].q;
        if (samples[j].q.dot(qb) < 0) qb.coeffs() = -qb.coeffs();
        q = samples[j].q.slerp(w, qb);
      }
      st.q[tm.element_item[tl.elements[k]]] = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
    }
  }
  // Support and junction frames: the same ones as in the coarser equilibrium.
  for (size_t i = 0; i < tm.items.size(); ++i) {
    const RodItem& it = tm.items[i];
    if (it.is_element || it.junction >= 0) continue;
    if (it.support >= from.num_spec_supports) return false;
    const int item = fm.supports[it.support].item;
    if (item < 0) return false;
    st.q[i] = from_state.q[item];
  }
  for (size_t j = 0; j < to.junctions.size(); ++j) {
    if (to.junctions[j].item < 0) continue;
    if (from.junctions[j].item < 0) return false;
    st.q[to.junctions[j].item] = from_state.q[from.junctions[j].item];
  }
  internal::AlignQuaternionSigns(tm, &st);
  // The spec's supports keep their poses and multipliers (contact rows are not carried: the
  // finer level finds its own contact set).
  st.lambda = from_state.lambda.head(tm.num_constraints);
  st.support_position.assign(from_state.support_position.begin(),
                             from_state.support_position.begin() + to.num_spec_supports);
  st.support_q.assign(from_state.support_q.begin(),
                      from_state.support_q.begin() + to.num_spec_supports);
  st.load_factor = from_state.load_factor;
  st.natural_factor = from_state.natural_factor;
  *state = std::move(st);
  return true;
}

}  // namespace cablefit
