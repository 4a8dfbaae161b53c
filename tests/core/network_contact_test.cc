// One-sided frictionless contact of a network with solids: a cable lying on a plane carries its
// weight through the contacts, and a cable pressed onto a box edge matches beam theory.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cablefit/core/network_simulation.h"
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

}  // namespace
}  // namespace cablefit
