// The cable sweeps run in the helper process (see crash_probe.h): OCCT's sweeps have crashed on
// smooth centrelines (BRepFill_Pipe::MakeShape read a null face when its sweep failed). A crash
// or hang there becomes one cable that could not be written, never the end of the whole process.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include <optional>
#include <string>
#include <vector>

#include "occt_flat_strip.h"

namespace cablefit {

/// One cable solid to sweep along `spine` [OCCT unit]: a round tube of `diameter`
/// (MakeTubeSolid), or with `flat` a flat strip whose wide axis points towards `guide`
/// (MakeFlatStripSolid).
struct CableSweep {
  TopoDS_Wire spine;
  double diameter = 0.0;            ///< a round tube's [OCCT unit]
  std::optional<FlatProfile> flat;  ///< a flat strip's section
  TopoDS_Wire guide;                ///< a flat strip's guide beside the spine
};

/// The sweep in this process. Throws InvalidInput when it fails.
TopoDS_Shape MakeCableSolid(const CableSweep& sweep);

/// A swept cable solid, or why it could not be swept.
struct TubeSweepResult {
  TopoDS_Shape tube;   ///< null when the sweep failed
  std::string error;   ///< the reason when it failed
};

/// MakeCableSolid for every sweep in one helper process (cablefit-sweep-child): a process start
/// costs about 0.03 s, which dominated writing a harness of many cables when each had its own.
/// When the batch's helper crashes or hangs, every sweep is run again in a helper of its own,
/// so one bad spine costs only its own solid ("the tube sweep crashed in OpenCASCADE (signal ...)", "... did not finish within N s").
/// Sweeps in this process when no helper can be started.
std::vector<TubeSweepResult> MakeTubeSolidsInChild(const std::vector<CableSweep>& sweeps,
                                                   double max_seconds = 600.0);

/// Starts the helpers MakeTubeSolidsInChild will use for `sweeps` sweeps now, waiting
/// (WaitingHelper): they load while the caller does other work, and the next calls take them
/// (each its own sweeps, results the same). Call it from a thread that outlives their use.
void PrestartTubeSweepHelpers(std::size_t sweeps);

/// The helper's side of MakeTubeSolidsInChild: reads the sweeps from descriptor `spines_fd` and
/// writes the results to `tubes_fd`. Returns the exit status: 0, or 4 when a file cannot be read
/// or written.
int SweepTubesInHelper(int spines_fd, int tubes_fd);

}  // namespace cablefit
