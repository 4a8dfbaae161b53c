// Reading harness CAD (STEP AP203/214/242, IGES) and writing relaxed cables back as STEP AP242.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cablefit/formats/harness_drawing.h"

namespace cablefit {

struct CadReadOptions {
  /// Spacing of centreline samples along a curve [m]; routes get at least 16 samples.
  double sample_spacing = 0.002;
  /// Relative chordal deflection for tessellating other solids (fraction of their size).
  double mesh_relative_deflection = 0.01;
  /// A solid counts as a tube when its lateral (circular cross-section) faces are this fraction
  /// of its area or more (or all of it but its two end caps: a tube under two diameters long),
  /// and a cable when it is at least `min_tube_aspect` diameters long. Ten diameters:
  /// a rod model (bending, no shear, section shape kept) describes a piece only when it is
  /// slender, and below that a piece barely bends under its own weight anyway. Shorter tubes
  /// (end stubs, ferrules, screw shanks, sleeves) are kept as solids.
  double min_tube_area_fraction = 0.8;
  double min_tube_aspect = 10.0;
  /// Cable ends closer than this [m] are recorded as one junction.
  double junction_tolerance = 1e-4;
  /// [s] Longest the crash probe of a STEP/IGES read (a helper process reading the file first,
  /// since OCCT segfaults on some corrupt files) may take before the file is reported as failed:
  /// `probe_seconds` plus `probe_seconds_per_megabyte` for each MB (10^6 bytes) of the file;
  /// probe_seconds = 0 reads in this process only, without the probe. Healthy files read at about
  /// 1 MB/s here (third-party assemblies included), so the default leaves a margin of 30x and
  /// more; a hostile file can keep OCCT's shape healing busy for many minutes (a mutated IGES of
  /// 97 kB ran for over 10 minutes), and this limit is what ends it.
  double probe_seconds = 30.0;
  double probe_seconds_per_megabyte = 30.0;

  bool IsValid(std::string* why) const;
  /// The probe's limit [s] for a file of `bytes`.
  double ProbeSecondsFor(std::uintmax_t bytes) const;
};

/// Reads a STEP (.step/.stp) or IGES (.iges/.igs) file with its assembly structure, names and
/// colours. Edges and wires become cables (routes split at branch points), tube solids/shells
/// become cables with a recovered centreline and diameter, other solids are kept as solids.
/// Throws FileError(path, problem) for a missing, unreadable, empty or cable-less file;
/// UsageError for invalid options.
HarnessDrawing ReadCadFile(const std::string& path, const CadReadOptions& options = {});

/// Writes `cables` as tubes (a circle swept along a B-spline through each relaxed centreline;
/// a cable with `flat` its rectangle or stadium, turned by its wide axes) with the names and
/// colours of their source cables, plus every solid of `input` unchanged, as
/// a STEP AP242 file in millimetres. Written atomically (temp file + rename). A cable without a
/// usable centreline or diameter, or whose tube OCCT cannot sweep, throws InvalidInput; with
/// `skipped` it is left out instead and its one-line problem appended there, so that one bad
/// cable does not cost its neighbours their output (when every cable is left out and there is no
/// solid, no file is written). FileError on I/O failure.
void WriteRelaxedStep(const std::string& path, const HarnessDrawing& input,
                      const std::vector<RelaxedCable>& cables,
                      std::vector<std::string>* skipped = nullptr);

/// Starts, ahead of time, the sweep helpers the next WriteRelaxedStep of `cables` cables will
/// use: each loads OpenCASCADE (~0.1 s) while the caller relaxes. Unused ones exit when the
/// process ends. Call it from a thread that lives until then (the main thread).
void PrepareRelaxedStep(std::size_t cables);

}  // namespace cablefit
