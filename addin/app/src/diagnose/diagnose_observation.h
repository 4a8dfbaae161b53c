// What the shape diagnosis is given: a ShapeObservation built from a laser scan's extracted
// centreline or from a measured centreline CSV, with the centre-point noise it needs for model
// selection.
#pragma once

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/diagnosis/scan_centerline.h"
#include "cablefit/core/diagnosis/shape_diagnosis.h"

namespace cablefit::addin {

/// The smallest centre-point noise ever assumed [m]: below it the model-selection criterion
/// would treat solver and sampling errors as significant.
inline constexpr double kMinCentreNoise = 1e-5;
/// Noise assumed for a centreline too short to estimate its own [m].
inline constexpr double kDefaultCentreNoise = 5e-5;

/// From a scan: the centres, their s, the seen stretches, and the centre noise = surface noise /
/// sqrt(mean surface points per centre) (a least-squares circle centre averages its points),
/// floored at kMinCentreNoise.
ShapeObservation ObservationFromScan(const ScanCenterline& scan);

/// From a measured centreline of a cable of `length`: its points and s (chord length when the
/// file had none), coverage = the whole cable, noise from EstimateCenterlineNoise.
ShapeObservation ObservationFromCenterline(const Polyline& line, double length);

/// Robust per-coordinate noise of an evenly sampled centreline [m]: the fourth difference
/// p[i-2] - 4p[i-1] + 6p[i] - 4p[i+1] + p[i+2] removes a smooth curve up to cubic terms and has
/// variance 70 sigma^2 for white noise; sigma = 1.4826 MAD / sqrt(70). Floored at
/// kMinCentreNoise; kDefaultCentreNoise for fewer than 8 points.
double EstimateCenterlineNoise(const Polyline& line);

}  // namespace cablefit::addin
