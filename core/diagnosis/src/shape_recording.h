// First stage of the shape diagnosis: the recording made ready for the fits. It must belong
// between its clamps (an inextensible cable cannot reach farther from a clamp than its length);
// a recording listed from the last clamp to the first is reversed, with a note; its points are
// thinned for the fits, and the recorded shape, joined to the clamps, is the nominal solve's
// starting shape (which selects the equilibrium branch).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

struct PreparedRecording {
  ShapeObservation observation;  // in cable order (reversed when listed the other way)
  Eigen::VectorXd s;             // [m] arc length of every point
  Eigen::Matrix3Xd fit_points;   // 3 x n [m] the points the fits use (thinned)
  Eigen::VectorXd fit_s;         // n [m] their arc lengths
  Polyline initial;              // the clamps' own positions plus the recorded points
  std::vector<DiagnosisNote> notes;  // what was done to the recording
};

/// Throws InvalidInput for fewer than 5 or non-finite points, RecordingMismatch for a
/// recording out of the cable's reach. At most about `max_points` points are kept for the fits.
PreparedRecording PrepareRecording(const RodSpec& nominal, const ShapeObservation& recorded,
                                   int max_points);

}  // namespace cablefit
