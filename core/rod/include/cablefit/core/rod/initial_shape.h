// Starting shapes for the statics solver. The shape the solver starts from selects the
// equilibrium branch it converges to: a CAD route or a recorded centreline, or without one a
// smooth curve of the right length through the supports.
#pragma once

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit {

/// A smooth curve of length spec.length through every support: per span a cubic Hermite curve
/// with the supports' tangents (clamp, clip) or Catmull-Rom tangents (pin), its tangent scale
/// chosen so the span has the right arc length. Parameterised by arc length.
Polyline DefaultInitialCurve(const RodSpec& spec, int samples_per_span = 64);

/// Maps a polyline's parameter linearly onto [0, length] (by its own s, or by chord length when
/// s is empty). Throws InvalidInput for fewer than 2 points or non-finite values.
Polyline ReparameteriseToLength(const Polyline& curve, double length);

/// Point of an arc-length-parameterised polyline at s (linear between samples).
Vec3 PointAt(const Polyline& curve, double s);

/// The point at arc length `s` [m] of the C1 cubic through the curve's samples (Hermite, with
/// tangents from the neighbouring samples), straight beyond the ends as PointAt. For a finer
/// discretisation started from a coarser shape: chords of the polyline itself kink at every
/// coarse sample, and the bending energy of those kinks grows as the elements shrink.
Vec3 SmoothPointAt(const Polyline& curve, double s);

/// A state whose elements follow `curve` (chord directions), twisted by parallel transport from
/// the first frame support with the twist mismatch at each following clamp spread linearly.
/// The state's support targets are the poses the shape itself has (continuation start).
RodState MakeInitialState(const RodModel& model, const Polyline& curve);

/// Transfers a converged state to another discretisation of the same spec (warm start): each
/// element takes the interpolated frame of the source at its midpoint.
RodState TransferState(const RodModel& from_model, const RodState& from, const RodModel& to_model);

}  // namespace cablefit
