#include "motion/motion_pose.h"

#include <limits>

#include "cablefit/core/solver/centerline_sampling.h"

namespace cablefit::addin {

double BackToStart(const CableMotion& cm, bool there_and_back) {
  if (!there_and_back || !cm.completed || cm.poses.size() < 2)
    return std::numeric_limits<double>::quiet_NaN();
  return (cm.poses.front().centreline.points - cm.poses.back().centreline.points)
      .colwise()
      .norm()
      .maxCoeff();
}

MotionPose MeasurePose(const CableRelaxation& relaxed, const SweepPose& p, double factor) {
  CableRelaxation r;
  r.setup = relaxed.setup;
  r.result = p.result;
  MeasureBendAndTension(factor, &r);
  MotionPose m;
  m.q = p.q;
  m.converged = p.converged;
  m.stable = p.stable;
  m.escaped_unstable = p.escaped_unstable;
  m.jumped = p.jumped;
  m.step = p.step;
  m.min_bend_radius = r.min_bend_radius;
  m.min_bend_radius_s = r.min_bend_radius_s;
  m.bend_flag = r.bend_flag;
  m.max_tension = r.max_tension;
  m.max_tension_s = r.max_tension_s;
  m.reactions = p.result.solution.reactions;
  m.newton_iterations = p.result.newton_iterations;
  const double length = relaxed.setup.spec.length;
  m.centreline = SampleCenterline(p.result.solution.centerline,
                                  UniformArcLengths(length, OutputSamples(length)));
  return m;
}

}  // namespace cablefit::addin
