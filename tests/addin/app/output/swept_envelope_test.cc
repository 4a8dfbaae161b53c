// The swept envelope encloses the tube of every shape it is built from: the winding number of
// the mesh is >= 1 at every centreline point and at points just inside every tube's surface,
// and 0 outside a lone tube; the way back of a there-and-back motion adds nothing.
#include "cablefit/app/output/swept_envelope.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cablefit::addin {
namespace {

// A quarter circle of radius R in a plane through the z axis turned by `angle` about z.
Polyline Arc(double angle, int n = 60) {
  constexpr double kR = 0.2;
  Polyline p;
  p.points.resize(3, n);
  for (int i = 0; i < n; ++i) {
    const double t = 0.5 * M_PI * i / (n - 1);
    const double r = 0.05 + kR * std::sin(t);
    p.points.col(i) << r * std::cos(angle), r * std::sin(angle), kR * (1 - std::cos(t));
  }
  p.ParameteriseByChords();
  return p;
}

// Points at `fraction` of `radius` around every sample of `shape`, square to its tangent.
std::vector<Vec3> AroundCentreline(const Polyline& shape, double radius, double fraction) {
  std::vector<Vec3> out;
  for (int i = 1; i + 1 < shape.size(); i += 3) {
    const Vec3 t = (shape.points.col(i + 1) - shape.points.col(i - 1)).normalized();
    const Vec3 n = t.unitOrthogonal(), b = t.cross(n);
    for (int k = 0; k < 7; ++k) {
      const double a = 2 * M_PI * k / 7 + 0.3;
      out.push_back(shape.points.col(i) + fraction * radius * (std::cos(a) * n + std::sin(a) * b));
    }
  }
  return out;
}

TEST(SweptEnvelope, ALoneTubeIsClosedAndOutward) {
  const Polyline arc = Arc(0.0);
  const double r = 0.01;
  const TriangleMesh tube = TubeSurface(arc.points, r, 12);
  ASSERT_GT(tube.faces.cols(), 0);
  for (int i = 1; i + 1 < arc.size(); i += 5)
    EXPECT_NEAR(WindingNumber(tube, arc.points.col(i)), 1.0, 1e-6) << i;
  // An end of the centreline lies on its flat cap.
  EXPECT_NEAR(WindingNumber(tube, arc.points.col(0)), 0.5, 1e-6);
  // The polygon circumscribes the circle: just inside the surface is inside...
  for (const Vec3& p : AroundCentreline(arc, r, 0.98)) EXPECT_NEAR(WindingNumber(tube, p), 1.0, 1e-6);
  // ...and a little outside the circumscribed polygon is outside.
  for (const Vec3& p : AroundCentreline(arc, r, 1.1)) EXPECT_NEAR(WindingNumber(tube, p), 0.0, 1e-6);
}

TEST(SweptEnvelope, EnclosesTheTubeOfEveryPose) {
  std::vector<Polyline> poses;
  const int steps = 6;
  for (int k = 0; k <= 2 * steps; ++k) {
    const int j = k <= steps ? k : 2 * steps - k;  // there and back
    poses.push_back(Arc(0.6 * j / steps));
  }
  const double r = 0.008;
  std::vector<size_t> used;
  const TriangleMesh env = SweptEnvelope(poses, r, EnvelopeOptions{}, &used);
  ASSERT_EQ(used.size(), static_cast<size_t>(steps + 1));  // the way back repeats the way there
  for (size_t k = 0; k < used.size(); ++k) EXPECT_EQ(used[k], k);
  for (const Polyline& pose : poses) {
    for (int i = 1; i + 1 < pose.size(); i += 4)
      EXPECT_GE(WindingNumber(env, pose.points.col(i)), 1.0 - 1e-6);
    for (const Vec3& p : AroundCentreline(pose, r, 0.95))
      EXPECT_GE(WindingNumber(env, p), 1.0 - 1e-6);
  }
  // Halfway between two poses near the far end is outside: nothing is added between poses.
  const Polyline between = Arc(0.05);
  EXPECT_NEAR(WindingNumber(env, between.points.col(between.size() - 1)), 0.0, 1e-6);
}

TEST(SweptEnvelope, ManyShapesAreThinnedEvenlyKeepingTheLast) {
  std::vector<Polyline> poses;
  for (int k = 0; k < 50; ++k) poses.push_back(Arc(0.01 * k, 20));
  EnvelopeOptions options;
  options.max_shapes = 10;
  std::vector<size_t> used;
  const TriangleMesh env = SweptEnvelope(poses, 0.005, options, &used);
  ASSERT_EQ(used.size(), 10u);
  EXPECT_EQ(used.front(), 0u);               // first and last kept
  EXPECT_EQ(used.back(), poses.size() - 1);
  EXPECT_GE(WindingNumber(env, poses.back().points.col(10)), 1.0 - 1e-6);
}

}  // namespace
}  // namespace cablefit::addin
