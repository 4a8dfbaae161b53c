// The user-editable description of a rod network: a harness tree of branches joined at
// junctions (breakouts), each branch with its own material, supports and loads, plus the solid
// surfaces the cable may rest on. Plain data; CompileNetworkModel() validates it.
#pragma once

#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

/// One branch: a rod from its start (s = 0) to its end (s = length), each end free or attached
/// to a junction. `route` is the drawn centreline (start shape, and the junction angles the
/// breakout holds); it is mapped onto [0, length].
struct BranchSpec {
  std::string name;
  double length = 0.0;  // [m]
  MaterialSpec material;
  std::vector<SleeveSpec> sleeves;    // s along this branch
  std::vector<SupportSpec> supports;  // s along this branch, increasing
  std::vector<NaturalCurvatureSpec> natural_curvature;
  std::vector<PointLoadSpec> point_loads;
  Polyline route;
  /// Pre-formed (a coiled cable, a moulded hose): the drawn route is its rest shape, so that
  /// it only sags from it under its loads. Otherwise the rest shape is straight (plus
  /// `natural_curvature`) and the drawing is only where the solve starts.
  bool preformed = false;
  int start_junction = -1;  // index into NetworkSpec::junctions, -1 = free end
  int end_junction = -1;
};

/// A breakout: a rigid body joining two or more branch ends, each held at the relative angle
/// it is drawn with, either rigidly or through a rotational spring.
struct JunctionSpec {
  std::string name;
  /// Rotational compliance of every branch attachment [rad/(N m)], 0 = rigid.
  double compliance = 0.0;
  double mass = 0.0;  // [kg] tape, sleeve, clip body
};

/// A solid the cable surface must stay out of (one-sided, frictionless contact).
struct ObstacleSpec {
  std::string name;
  TriangleMesh mesh;  // closed or open; faces counter-clockwise seen from outside
};

struct NetworkSpec {
  std::string name;
  Vec3 gravity = Vec3(0, 0, -9.81);  // [m/s^2]
  std::vector<BranchSpec> branches;
  std::vector<JunctionSpec> junctions;
  std::vector<ObstacleSpec> obstacles;
};

}  // namespace cablefit
