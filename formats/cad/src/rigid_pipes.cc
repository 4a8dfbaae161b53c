#include "rigid_pipes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace cablefit::internal {
namespace {

// A straight tube: no route point farther from the chord than this fraction of its radius.
constexpr double kStraightness = 0.1;
// A flange is at least this many times as wide as the tube (a DN 300 pipe's flange is 1.37
// times its diameter, smaller pipes' relatively wider; a hose clamp's band adds less), no longer
// along it than its own radius, and round: its outline in each of kSectors sectors about the
// axis reaches within kRoundness of its widest.
constexpr double kFlangeWidth = 1.3;
constexpr int kSectors = 8;
constexpr double kRoundness = 0.8;
// A pipe elbow turns through at least this much [rad] at a bend radius under this many of its
// diameters.
constexpr double kElbowTurn = M_PI / 6;
constexpr double kElbowBendRadius = 3.0;
// Ends meet, and diameters agree, within this fraction of the radius.
constexpr double kMeet = 0.05;

bool Straight(const Eigen::Matrix3Xd& p, double radius) {  // 3 x n [m]
  const Vec3 a = p.col(0), b = p.col(p.cols() - 1);
  const double length = (b - a).norm();
  if (!(length > 0)) return false;
  const Vec3 t = (b - a) / length;
  for (Eigen::Index k = 0; k < p.cols(); ++k) {
    const Vec3 d = p.col(k) - a;
    if ((d - d.dot(t) * t).norm() > kStraightness * radius) return false;
  }
  return true;
}

// Whether `solid` is a flange on the tube end at `end`, axis `out` (unit, pointing out of the
// tube), tube radius `radius`.
bool IsFlangeAt(const DrawnSolid& solid, const Vec3& end, const Vec3& out, double radius) {
  const Eigen::Matrix3Xd& v = solid.mesh.vertices;  // 3 x m [m]
  if (v.cols() == 0) return false;
  const Vec3 e1 = out.unitOrthogonal(), e2 = out.cross(e1);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, widest = 0;
  std::array<double, kSectors> reach{};
  for (Eigen::Index k = 0; k < v.cols(); ++k) {
    const Vec3 d = v.col(k) - end;
    const double along = d.dot(out);
    const Vec3 across = d - along * out;
    const double r = across.norm();
    lo = std::min(lo, along);
    hi = std::max(hi, along);
    widest = std::max(widest, r);
    const double angle = std::atan2(across.dot(e2), across.dot(e1)) + M_PI;  // [0, 2 pi]
    const int sector = std::min(kSectors - 1, static_cast<int>(angle / (2 * M_PI) * kSectors));
    reach[static_cast<size_t>(sector)] = std::max(reach[static_cast<size_t>(sector)], r);
  }
  if (widest < kFlangeWidth * radius || hi - lo > widest) return false;
  // Around the end: the end inside its extent along the axis (a slip-on flange's hub over the
  // pipe, a weld-neck's face at the pipe's end), within a tube radius.
  if (lo > radius || hi < -radius) return false;
  return std::all_of(reach.begin(), reach.end(),
                     [&](double r) { return r >= kRoundness * widest; });
}

// The turn [rad] and bend radius [m] of a route (3 x n [m]): the angle between its end tangents
// and its length over that angle.
std::pair<double, double> Bend(const Eigen::Matrix3Xd& p) {
  const Eigen::Index n = p.cols();
  const Eigen::Index k = std::min<Eigen::Index>(2, n - 1);
  const Vec3 t0 = (p.col(k) - p.col(0)).normalized();
  const Vec3 t1 = (p.col(n - 1) - p.col(n - 1 - k)).normalized();
  const double turn = std::acos(std::clamp(t0.dot(t1), -1.0, 1.0));
  double length = 0;
  for (Eigen::Index i = 1; i < n; ++i) length += (p.col(i) - p.col(i - 1)).norm();
  return {turn, turn > 0 ? length / turn : std::numeric_limits<double>::infinity()};
}

std::string Mm(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g mm", 1e3 * metres);
  return text;
}

}  // namespace

std::vector<RigidPipe> FindRigidPipes(const std::vector<DrawnTube>& tubes,
                                      const AbsorbedTubes& absorbed,
                                      const HarnessDrawing& drawing) {
  // Pipe elbows: stout hollow tube parts bent tightly.
  std::vector<const DrawnTube*> elbows;
  for (const DrawnTube& t : tubes) {
    if (t.is_cable || t.skipped_note < 0 || absorbed.Marked(t) || !(t.inner_radius > 0) ||
        t.centres.cols() < 3)
      continue;
    const auto [turn, bend_radius] = Bend(t.centres);
    if (turn >= kElbowTurn && bend_radius < kElbowBendRadius * 2 * t.radius) elbows.push_back(&t);
  }
  std::vector<RigidPipe> pipes;
  for (size_t c = 0; c < drawing.cables.size(); ++c) {
    const DrawnCable& cable = drawing.cables[c];
    if ((c < absorbed.CableCount() && absorbed.CableMarked(c)) ||
        cable.source != CableSourceKind::kTube || cable.flat || !(cable.inner_diameter > 0) ||
        cable.centreline.size() < 2)
      continue;
    const double radius = 0.5 * cable.diameter;
    const Eigen::Matrix3Xd& p = cable.centreline.points;
    if (!Straight(p, radius)) continue;
    const Eigen::Index n = p.cols();
    const Vec3 ends[2] = {p.col(0), p.col(n - 1)};
    const Vec3 axis = (ends[1] - ends[0]).normalized();
    std::string fitting;
    for (int side = 0; side < 2 && fitting.empty(); ++side) {
      const Vec3 out = side == 0 ? Vec3(-axis) : axis;
      for (const DrawnSolid& solid : drawing.solids) {
        if (IsFlangeAt(solid, ends[side], out, radius)) {
          fitting = "flanged at an end by '" +
                    (solid.name.empty() ? std::string("unnamed") : solid.name) + "'";
          break;
        }
      }
      if (!fitting.empty()) continue;
      for (const DrawnTube* elbow : elbows) {
        const Eigen::Matrix3Xd& q = elbow->centres;
        const bool meets = (q.col(0) - ends[side]).norm() <= kMeet * radius ||
                           (q.col(q.cols() - 1) - ends[side]).norm() <= kMeet * radius;
        if (meets && std::abs(elbow->radius - radius) <= kMeet * radius) {
          const std::string& name = drawing.solids[static_cast<size_t>(elbow->index)].name;
          fitting = "joined at an end to the pipe elbow '" +
                    (name.empty() ? std::string("unnamed") : name) + "'";
          break;
        }
      }
    }
    if (fitting.empty()) continue;
    pipes.push_back(
        {static_cast<int>(c), "'" + (cable.name.empty() ? std::string("unnamed") : cable.name) +
                                  "': a straight tube (" + Mm(cable.diameter) + " across, " +
                                  Mm((ends[1] - ends[0]).norm()) + " long) " + fitting +
                                  ": a rigid pipe, kept as a solid part"});
  }
  return pipes;
}

}  // namespace cablefit::internal
