// One-sided frictionless contact of a network with solids: a cable lying on a plane carries its
// weight through the contacts, and a cable pressed onto a box edge matches beam theory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cablefit/core/network/network_simulation.h"
#include "cablefit/core/rod/initial_shape.h"
#include "network_test_util.h"

namespace cablefit {
namespace {

using testing::Clamp;
using testing::StraightRoute;
using testing::TestMaterial;

// Axis-aligned box as 12 outward-facing triangles.
TriangleMesh Box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  m.vertices.resize(3, 8);
  for (int i = 0; i < 8; ++i)
    m.vertices.col(i) = Vec3(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  m.faces.resize(3, 12);
  const int f[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (int k = 0; k < 12; ++k) m.faces.col(k) = Eigen::Vector3i(f[k][0], f[k][1], f[k][2]);
  return m;
}

BranchSpec Cable(double length, const MaterialSpec& material, const Polyline& route) {
  BranchSpec b;
  b.name = "cable";
  b.length = length;
  b.material = material;
  b.route = route;
  return b;
}

TEST(NetworkContact, CableOnAPlaneRestsOnItsContacts) {
  const double length = 0.5, d = 0.01, rho = 0.1;
  const MaterialSpec mat = TestMaterial(0.01, rho, d);
  NetworkSpec spec;
  const Vec3 start(0, 0, d / 2);  // clamped level, touching the floor z = 0
  BranchSpec b = Cable(length, mat, StraightRoute(start, start + Vec3(length, 0, 0)));
  b.supports = {Clamp(0.0, start, Vec3::UnitX())};
  spec.branches = {b};
  spec.obstacles.push_back({"floor", Box(Vec3(-1, -1, -0.1), Vec3(1, 1, 0))});
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable);
  ASSERT_FALSE(sol.contacts.empty());
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  // Lying flat: no bending, every node carries its own weight through its contact.
  const double weight = rho * length * 9.81;
  Vec3 total = sol.reactions[0].force;
  double worst_node = 0.0;
  const double node_weight = rho * opt.element_length * 9.81;
  for (const ContactLoad& c : sol.contacts) {
    total += c.force;
    EXPECT_GE(c.force.z(), 0.0);
    EXPECT_NEAR(c.force.x(), 0.0, 1e-12);
    const bool end = c.s > length - 1e-9;
    worst_node = std::max(worst_node, std::abs(c.force.z() - (end ? 0.5 : 1.0) * node_weight));
  }
  EXPECT_NEAR(total.z(), weight, 1e-9 * weight);
  EXPECT_LT(worst_node, 1e-6 * node_weight);
  const Polyline& p = sol.branches[0];
  EXPECT_NEAR(p.points.row(2).minCoeff(), d / 2, 0.01 * d);
  EXPECT_NEAR(p.points.row(2).maxCoeff(), d / 2, 0.01 * d);
  std::printf("plane: %zu contacts, %d rounds, penetration %.3g m, node force error %.3g N\n",
              sol.contacts.size(), sol.contact_rounds, sol.max_penetration, worst_node);
}

// Clamped at x = 0, clamped and free to slide along x at x = L, sagging onto a thin box at
// mid-span whose top holds the centreline `lift` above the free sag. Linear beam theory:
// w_free = q L^4 / (384 EI), a mid-span point force R deflects it by R L^3 / (192 EI), so
// R = 192 EI (w_free - w_box) / L^3 and each clamp carries (q L - R) / 2.
TEST(NetworkContact, CablePressedOntoABoxEdgeMatchesBeamTheory) {
  const double length = 1.0, d = 0.005, rho = 0.1, ei = 0.5, q = rho * 9.81;
  const double w_free = q * std::pow(length, 4) / (384 * ei);  // ~5.1 mm, slopes ~1 %
  const double w_box = 0.5 * w_free;
  const MaterialSpec mat = TestMaterial(ei, rho, d);
  NetworkSpec spec;
  BranchSpec b = Cable(length, mat, StraightRoute(Vec3::Zero(), Vec3(length, 0, 0)));
  SupportSpec far = Clamp(length, Vec3(length, 0, 0), Vec3::UnitX());
  far.sliding = true;
  b.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()), far};
  spec.branches = {b};
  const double top = -w_box - d / 2, width = 0.002;
  spec.obstacles.push_back(
      {"box", Box(Vec3(0.5 * length - width / 2, -0.05, top - 0.1), Vec3(0.5 * length + width / 2, 0.05, top))});
  NetworkOptions opt;
  opt.element_length = 0.005;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  ASSERT_FALSE(sol.contacts.empty());
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  Vec3 contact = Vec3::Zero();
  for (const ContactLoad& c : sol.contacts) contact += c.force;
  const double r_beam = 192 * ei * (w_free - w_box) / std::pow(length, 3);
  EXPECT_NEAR(contact.z(), r_beam, 0.01 * r_beam);
  EXPECT_NEAR(sol.reactions[0].force.z(), 0.5 * (q * length - r_beam), 0.01 * r_beam);
  // The cable rests on the box: its lowest point is the box top plus its radius.
  const Polyline& p = sol.branches[0];
  EXPECT_NEAR(p.points.row(2).minCoeff(), top + d / 2, 0.01 * d);
  std::printf("box edge: contact %.6f N vs beam %.6f N (%zu contacts, %d rounds, penetration %.3g m)\n",
              contact.z(), r_beam, sol.contacts.size(), sol.contact_rounds, sol.max_penetration);
}

// Drawn level in the air, the cantilever sags onto a block below its far half: contacts appear
// during the solve, all push, nothing penetrates, and the lifted tip stays off the block.
TEST(NetworkContact, SaggingCantileverLandsOnABlock) {
  const double length = 0.5, d = 0.008, rho = 0.1;
  const MaterialSpec mat = TestMaterial(0.05, rho, d);  // free tip sag ~0.15 m
  NetworkSpec spec;
  const Vec3 start(0, 0, 0.03);
  BranchSpec b = Cable(length, mat, StraightRoute(start, start + Vec3(length, 0, 0)));
  b.supports = {Clamp(0.0, start, Vec3::UnitX())};
  spec.branches = {b};
  spec.obstacles.push_back({"block", Box(Vec3(0.25, -0.2, -0.5), Vec3(0.8, 0.2, 0.0))});
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable);
  ASSERT_FALSE(sol.contacts.empty());
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  Vec3 total = Vec3::Zero();
  for (const ContactLoad& c : sol.contacts) {
    EXPECT_GE(c.force.dot(Vec3::UnitZ()), -1e-12) << "contact at s=" << c.s << " pulls";
    total += c.force;
  }
  EXPECT_GT(total.z(), 0.0);
  const Polyline& p = sol.branches[0];
  EXPECT_GE(p.points.row(2).minCoeff(), d / 2 - 0.01 * d);  // on or above the block
  std::printf("landing: %zu contacts, %d rounds, penetration %.3g m, contact force %.4f N of %.4f N\n",
              sol.contacts.size(), sol.contact_rounds, sol.max_penetration, total.z(),
              rho * length * 9.81);
}

// Clamped level 2 cm above a floor, a long soft cable falls and lies along it: the contact zone
// is found by holding the deeper half of each penetrating stretch, so it fills in within a few
// rounds (about log2 of its nodes) instead of one node per round, and the lying part carries
// its own weight.
// A soft 1 m cantilever (d 6 mm, 0.1 kg/m) clamped level 2 cm above a slab whose top is z = 0.
struct FallingCable {
  static constexpr double length = 1.0, d = 0.006, rho = 0.1, lift = 0.02;
  NetworkOptions opt;
  NetworkSolution Solve(double slab_thickness) {
    NetworkSpec spec;
    const Vec3 start(0, 0, d / 2 + lift);
    BranchSpec b = Cable(length, TestMaterial(0.002, rho, d), StraightRoute(start, start + Vec3(length, 0, 0)));
    b.supports = {Clamp(0.0, start, Vec3::UnitX())};
    spec.branches = {b};
    spec.obstacles.push_back({"slab", Box(Vec3(-1, -1, -slab_thickness), Vec3(2, 1, 0))});
    opt.element_length = 0.005;
    return SolveNetwork(spec, opt);
  }
};

TEST(NetworkContact, LongCableFallsOntoAFloorAndLiesAlongIt) {
  FallingCable fall;
  const NetworkSolution sol = fall.Solve(0.1);
  const NetworkOptions& opt = fall.opt;
  const double length = fall.length, d = fall.d, rho = fall.rho;
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable);
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  const int nodes = static_cast<int>(std::lround(length / opt.element_length)) + 1;
  EXPECT_GT(static_cast<int>(sol.contacts.size()), nodes / 2);  // most of it lies on the floor
  EXPECT_LE(sol.contact_rounds, 2 * static_cast<int>(std::ceil(std::log2(nodes))) + 4);
  // Beyond the touch-down zone each held node carries its own weight; a node left unheld (its
  // sag between two holds stays within the tolerance) hands its weight to its neighbours, so
  // the force on the lying stretch is checked as a whole and node by node for most of it.
  const double node_weight = rho * opt.element_length * 9.81;
  double first = length;
  for (const ContactLoad& c : sol.contacts) first = std::min(first, c.s);
  const double s0 = first + 0.1;
  double total = sol.reactions[0].force.z(), lying = 0.0;
  int inner = 0, exact = 0;
  for (const ContactLoad& c : sol.contacts) {
    total += c.force.z();
    EXPECT_GE(c.force.z(), -1e-12) << "contact at s=" << c.s << " pulls";
    if (c.s <= s0) continue;
    lying += c.force.z();
    if (c.s > length - 1e-9) continue;
    ++inner;
    exact += std::abs(c.force.z() - node_weight) < 1e-3 * node_weight;
  }
  EXPECT_NEAR(total, rho * length * 9.81, 1e-9 * rho * length * 9.81);
  EXPECT_NEAR(lying, rho * 9.81 * (length - s0), 5 * node_weight);
  EXPECT_GE(exact, 0.7 * inner);
  std::printf("floor: %zu contacts of %d nodes, %d rounds, %d iterations, penetration %.3g m\n",
              sol.contacts.size(), nodes, sol.contact_rounds, sol.summary.iterations, sol.max_penetration);
}

// The same fall with an extensible cable held by a clip before it reaches the floor: the clip's
// row is compliant (it holds the node up to the stretch between it and the clamp), so the
// contacts beyond it must not be measured from it; they were, and their stretch offset kept the
// contact set of a harness over a panel from settling (bench contact_*).
TEST(NetworkContact, ContactsBeyondACompliantClipSettleOnTheFloor) {
  const double length = 1.0, d = 0.006, rho = 0.1, lift = 0.02;
  NetworkSpec spec;
  const Vec3 start(0, 0, d / 2 + lift);
  MaterialSpec mat = TestMaterial(0.002, rho, d);
  mat.axial_stiffness = 2e3;  // [N] soft, so that the stretch is not round-off
  BranchSpec b = Cable(length, mat, StraightRoute(start, start + Vec3(length, 0, 0)));
  SupportSpec clip = Clamp(0.2, start + Vec3(0.2, 0, 0), Vec3::UnitX());
  clip.kind = SupportKind::kClip;
  b.supports = {Clamp(0.0, start, Vec3::UnitX()), clip};
  spec.branches = {b};
  spec.obstacles.push_back({"slab", Box(Vec3(-1, -1, -0.1), Vec3(2, 1, 0))});
  NetworkOptions opt;
  opt.element_length = 0.005;
  const NetworkSolution sol = SolveNetwork(spec, opt);
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  EXPECT_GT(sol.contacts.size(), 50u);
  double total = 0.0;
  for (const SupportReaction& r : sol.reactions) total += r.force.z();
  for (const ContactLoad& c : sol.contacts) {
    total += c.force.z();
    EXPECT_GE(c.force.z(), -1e-12) << "contact at s=" << c.s << " pulls";
  }
  EXPECT_NEAR(total, rho * length * 9.81, 1e-9 * rho * length * 9.81);
  // Lying on the floor: the held nodes' centres are a radius above it.
  const Polyline& p = sol.branches[0];
  for (const ContactLoad& c : sol.contacts) {
    const Vec3 at = PointAt(p, c.s);
    EXPECT_NEAR(at.z(), d / 2, 0.01 * d) << "contact at s=" << c.s;
  }
  std::printf("compliant clip: %zu contacts, %d rounds, %d iterations, penetration %.3g m\n",
              sol.contacts.size(), sol.contact_rounds, sol.summary.iterations, sol.max_penetration);
}

// A droop between two clamps (0.3 m apart, drawn 4 mm deep) over a panel whose top lies
// `clearance` below the drawn cable surface (negative: the drawing runs into the panel); the far
// clamp may slide along the cable's axis.
NetworkSolution DroopOverPanel(double clearance, bool sliding, double* top) {
  const double span = 0.3, d = 0.006, droop = 0.004;
  Polyline route;
  const int n = 61;
  route.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1);
    route.points.col(i) = Vec3(span * u, 0, -droop * std::sin(M_PI * u));
  }
  route.ParameteriseByChords();
  const double length = route.s[n - 1];
  NetworkSpec spec;
  BranchSpec b = Cable(length, TestMaterial(0.05, 0.05, d), route);
  b.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX()), Clamp(length, Vec3(span, 0, 0), Vec3::UnitX())};
  b.supports[1].sliding = sliding;
  spec.branches = {b};
  *top = -droop - d / 2 - clearance;
  spec.obstacles.push_back({"panel", Box(Vec3(-0.1, -0.1, *top - 0.01), Vec3(span + 0.1, 0.1, *top))});
  NetworkOptions opt;
  opt.element_length = 0.003;
  return SolveNetwork(spec, opt);
}

void ExpectRestingOnOrAbove(const NetworkSolution& sol, double top, double d) {
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_TRUE(sol.summary.stable);
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  EXPECT_GE(sol.branches[0].points.row(2).minCoeff() - d / 2, top - 0.01 * d);
  for (const ContactLoad& c : sol.contacts)
    EXPECT_GE(c.force.z(), -1e-12) << "contact at s=" << c.s << " pulls";
}

// Drawn 0.3 mm (a twentieth of the diameter) clear of the panel, with clamps too close for
// gravity to bring it lower: it must not be pulled flat onto the panel (that needs more length
// than the inextensible cable has, and used to make the KKT system singular).
TEST(NetworkContact, DroopDrawnJustClearOfAPanelIsNotPulledOntoIt) {
  double top = 0.0;
  const NetworkSolution sol = DroopOverPanel(0.0003, false, &top);
  ExpectRestingOnOrAbove(sol, top, 0.006);
  EXPECT_TRUE(sol.contacts.empty());
}

// Drawn 1 mm into the panel (CAD that ignored the cable's radius), the far clamp sliding so the
// length pushing out frees can leave (with both clamps fixed it buckles sideways on the panel,
// a saddle this planar start cannot leave). It starts with its 46 drawn-inside nodes held on
// the panel; relaxed, its droop is shallower than drawn and it lifts off. The holds of the
// flattened stretch pull at its edges and are peeled off by widening releases, not two a round.
TEST(NetworkContact, DroopDrawnIntoAPanelIsPushedOutOntoIt) {
  double top = 0.0;
  const NetworkSolution sol = DroopOverPanel(-0.001, true, &top);
  ExpectRestingOnOrAbove(sol, top, 0.006);
  EXPECT_LE(sol.contact_rounds, 12);
  std::printf("droop into panel: %zu contacts, %d rounds, %d iterations\n", sol.contacts.size(),
              sol.contact_rounds, sol.summary.iterations);
}

// A pipe drawn with its clamped end 15 mm inside a flange block (radius 10 mm): it is fitted
// there. Pushing it out would fight the clamp (the KKT system was singular on OCCT's exhaust
// model); the block is reported as attached and the pipe relaxes as if the block were not there.
TEST(NetworkContact, ACableDrawnIntoAPartAtItsClampIsFittedThereNotPushedOut) {
  const double length = 0.4, d = 0.02;
  const MaterialSpec mat = TestMaterial(0.5, 0.5, d);
  NetworkSpec spec;
  BranchSpec b = Cable(length, mat, StraightRoute(Vec3::Zero(), Vec3(length, 0, 0)));
  b.supports = {Clamp(0.0, Vec3::Zero(), Vec3::UnitX())};
  spec.branches = {b};
  NetworkOptions opt;
  opt.element_length = 0.01;
  const NetworkSolution free = SolveNetwork(spec, opt);
  spec.obstacles.push_back({"flange", Box(Vec3(-0.05, -0.05, -0.05), Vec3(0.015, 0.05, 0.05))});
  const NetworkSolution fitted = SolveNetwork(spec, opt);
  ASSERT_TRUE(free.converged()) << free.summary.BriefReport();
  ASSERT_TRUE(fitted.converged()) << fitted.summary.BriefReport();
  EXPECT_EQ(fitted.attached_obstacles, std::vector<int>{0});
  EXPECT_TRUE(fitted.contacts.empty());
  EXPECT_LT((fitted.branches[0].points - free.branches[0].points).cwiseAbs().maxCoeff(), 1e-12);
  // The same block 1 m along, where the drawing does not enter it, stays an obstacle.
  spec.obstacles[0].mesh.vertices.row(0).array() += 1.0;
  EXPECT_TRUE(SolveNetwork(spec, opt).attached_obstacles.empty());
}

// The same fall onto sheet metal half a millimetre thick: within one solve the free hanging
// cable would pass right through it, so the crossing must be caught on each node's path.
TEST(NetworkContact, FallThroughAThinSheetIsCaught) {
  FallingCable fall;
  const NetworkSolution sol = fall.Solve(0.0005);
  const double d = fall.d;
  ASSERT_TRUE(sol.converged()) << sol.summary.BriefReport();
  EXPECT_LE(sol.max_penetration, 0.01 * d);
  EXPECT_GE(sol.branches[0].points.row(2).minCoeff(), d / 2 - 0.01 * d);  // on top, not below
  EXPECT_GT(sol.contacts.size(), 50u);
}

}  // namespace
}  // namespace cablefit
