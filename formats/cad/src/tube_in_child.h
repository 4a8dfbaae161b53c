// The tube sweep run in the helper process (see crash_probe.h): OCCT's sweeps have crashed on
// smooth centrelines (BRepFill_Pipe::MakeShape read a null face when its sweep failed). A crash
// or hang there becomes one cable that could not be written (InvalidInput), never the end of
// the whole process.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include <string>
#include <utility>
#include <vector>

namespace cablefit {

/// Exit status of the helper's sweep when MakeTubeSolid threw InvalidInput; the message is then
/// the content of the tube file.
inline constexpr int kTubeSweepFailedExit = 3;

/// MakeTubeSolid(spine, diameter) computed in the helper and handed back as a BRep file.
/// Throws InvalidInput with the helper's message when the sweep fails, and "the tube sweep
/// crashed in OpenCASCADE (signal ...)" / "... did not finish within N s" when the helper dies
/// or hangs. Sweeps in this process when no helper can be started.
TopoDS_Shape MakeTubeSolidInChild(const TopoDS_Wire& spine, double diameter,
                                  double max_seconds = 120.0);

/// A tube to sweep, or why it could not be swept.
struct TubeSweepResult {
  TopoDS_Shape tube;   ///< null when the sweep failed
  std::string error;   ///< the reason when it failed
};

/// MakeTubeSolid for every (spine, diameter) in one helper process: a process start costs about
/// 0.1 s, which dominated writing a harness of many cables. When the batch's helper crashes or
/// hangs, every tube is swept again in its own helper (MakeTubeSolidInChild), so one bad spine
/// costs only its own tube. Sweeps in this process when no helper can be started.
std::vector<TubeSweepResult> MakeTubeSolidsInChild(
    const std::vector<std::pair<TopoDS_Wire, double>>& spines, double max_seconds = 600.0);

/// The helper's side of MakeTubeSolidsInChild: reads the spines from descriptor `spines_fd` and
/// writes the results to `tubes_fd`. Returns the exit status: 0, or 4 when a file cannot be read
/// or written.
int SweepTubesInHelper(int spines_fd, int tubes_fd);

/// The helper's side: reads the spine (a BRep wire) from descriptor `spine_fd`, sweeps it and
/// writes the tube (BRep) or InvalidInput's message to descriptor `tube_fd`. Returns the exit
/// status: 0, kTubeSweepFailedExit, or 4 when a file cannot be read or written.
int SweepTubeInHelper(int spine_fd, double diameter, int tube_fd);

}  // namespace cablefit
