#include "cablefit/app/output/relax_motion_pictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cablefit/app/output/relax_file.h"
#include "cablefit/core/solver/centerline_sampling.h"
#include "cablefit/formats/apng_file.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/png_file.h"
#include "base/render_lock.h"

namespace cablefit::addin {
namespace {

constexpr double kColourScaleFloorMm = 1.0;  // as the deviation pictures: below 1 mm stays dark
constexpr int kFrameDelayMs = 200;

// Distance of each sample of `shape` to `start` at the same arc length [m] (n).
Eigen::VectorXd MovedFrom(const Polyline& start, const Polyline& shape) {
  const Polyline at = SampleCenterline(start, shape.s);
  return (shape.points - at.points).colwise().norm().transpose();
}

}  // namespace

// Long: one camera and one colour scale are fixed over all poses first, then every frame is
// drawn on them with the same scene set-up.
MotionPictures WriteMotionAnimation(const std::string& dir, const RelaxedFile& f,
                                    const HarnessConfig& config) {
  MotionPictures out;
  if (!f.motion || f.motion->cables.empty()) return out;
  const FileMotion& m = *f.motion;
  size_t poses = 0;
  for (const CableMotion& c : m.cables) poses = std::max(poses, c.poses.size());
  if (poses == 0) return out;
  std::vector<size_t> pick;
  const size_t cap = static_cast<size_t>(kMaxMotionFrames);
  for (size_t k = 0; k < std::min(poses, cap); ++k)
    pick.push_back(poses <= cap ? k : k * (poses - 1) / (cap - 1));
  // One colour scale for every frame: the farthest any swept cable moves from pose 0.
  double farthest = 0.0;
  for (const CableMotion& c : m.cables)
    for (const MotionPose& p : c.poses)
      if (!c.poses.empty())
        farthest = std::max(farthest, MovedFrom(c.poses[0].centreline, p.centreline).maxCoeff());
  ColourScale scale;
  scale.min = 0.0;
  scale.max = std::max(1e3 * farthest, kColourScaleFloorMm);
  scale.label = "moved from pose 0 [mm]";
  const bool rotation = m.config.kind == MotionConfig::Kind::kRotation;
  std::vector<Scene> frames;
  for (size_t k : pick) {
    Scene scene;
    scene.gravity = config.gravity;
    scene.colour_scale = scale;
    char caption[256];
    std::snprintf(caption, sizeof caption, "pose %zu of %zu, %g %s", k, poses - 1,
                  rotation ? m.q[k] * 180 / M_PI : m.q[k],
                  rotation ? "deg" : m.config.kind == MotionConfig::Kind::kPoses ? "(listed pose)" : "m");
    out.captions.push_back(caption);
    scene.title = f.stem + ": '" + m.config.name + "', " + caption;
    for (size_t i = 0; i < f.drawing.cables.size(); ++i) {
      const auto& r = f.cables[i];
      if (!r) continue;
      SceneTube tube;
      tube.name = f.drawing.cables[i].name;
      tube.radius = 0.5 * OutputDiameter(f, static_cast<int>(i), config);
      const CableMotion* swept = nullptr;
      for (const CableMotion& c : m.cables)
        if (c.cable == static_cast<int>(i) && k < c.poses.size()) swept = &c;
      if (swept) {
        const MotionPose& p = swept->poses[k];
        tube.centreline = p.centreline;
        tube.deviation = MovedFrom(swept->poses[0].centreline, p.centreline);
        // The start shape as the grey reference line: how far this pose has gone.
        scene.ghosts.push_back({"pose 0", swept->poses[0].centreline.points, {140, 140, 140}});
        for (size_t s = 0; s < r->setup.spec.supports.size(); ++s) {
          const SupportSpec& sp = r->setup.spec.supports[s];
          const bool moves = std::count(swept->moving.begin(), swept->moving.end(),
                                        static_cast<int>(s)) > 0;
          Vec3 where = sp.position;
          if (moves) {
            Eigen::VectorXd at(1);
            at[0] = std::clamp(sp.s, p.centreline.s[0], p.centreline.s[p.centreline.size() - 1]);
            where = SampleCenterline(p.centreline, at).points.col(0);
          }
          scene.supports.push_back({MarkerOf(sp.kind), where, " "});
        }
      } else {
        tube.centreline = r->relaxed;  // does not move: drawn grey
      }
      scene.tubes.push_back(std::move(tube));
    }
    // The tracked points' whole paths, so a frame shows where the point has been and goes.
    for (const MotionTrack& t : m.tracks)
      scene.ghosts.push_back({"path of " + t.cable + " s=" + std::to_string(static_cast<int>(
                                                                std::lround(1e3 * t.s))) + " mm",
                              t.points, {214, 95, 14}});
    for (size_t j = 0; j < f.drawing.solids.size(); ++j) {
      const DrawnSolid& solid = f.drawing.solids[j];
      scene.solids.push_back({solid.name, solid.mesh});
      if (std::count(m.moving_solids.begin(), m.moving_solids.end(), static_cast<int>(j)) > 0) {
        const Eigen::Isometry3d t = m.config.At(m.q[k]);  // where the motion has it now
        Eigen::Matrix3Xd& v = scene.solids.back().mesh.vertices;
        v = (t.linear() * v).colwise() + t.translation();
      }
    }
    frames.push_back(std::move(scene));
  }
  RenderOptions options;
  options.width = 1000;
  options.height = 640;
  options.supersample = 2;
  options.colour_scale = scale;
  std::vector<Image> images;
  {
    std::lock_guard lock(RenderMutex());
    images = RenderDeviationSequence(frames, options);
  }
  const std::filesystem::path folder(dir);
  // Each frame encoded once: written as a still, then wrapped into the animation.
  std::vector<std::vector<std::uint8_t>> pngs;
  for (size_t i = 0; i < images.size(); ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "/pose-%03zu.png", pick[i]);
    out.frames.push_back(MotionFramesFolder(f.stem) + name);
    pngs.push_back(EncodePng(images[i]));
    WriteFileAtomically((folder / out.frames.back()).string(),
                        std::string(pngs.back().begin(), pngs.back().end()));
  }
  out.animation = f.stem + "-motion.png";
  const std::vector<std::uint8_t> apng = AssembleApng(pngs, {kFrameDelayMs, 0});
  WriteFileAtomically((folder / out.animation).string(), std::string(apng.begin(), apng.end()));
  return out;
}

}  // namespace cablefit::addin
