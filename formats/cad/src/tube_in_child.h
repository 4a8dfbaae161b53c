// The tube sweep run in the helper process (see crash_probe.h): OCCT's sweeps have crashed on
// smooth centrelines (BRepFill_Pipe::MakeShape read a null face when its sweep failed). A crash
// or hang there becomes one cable that could not be written (InvalidInput), never the end of
// the whole process.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

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

/// The helper's side: reads the spine (a BRep wire) from descriptor `spine_fd`, sweeps it and
/// writes the tube (BRep) or InvalidInput's message to descriptor `tube_fd`. Returns the exit
/// status: 0, kTubeSweepFailedExit, or 4 when a file cannot be read or written.
int SweepTubeInHelper(int spine_fd, double diameter, int tube_fd);

}  // namespace cablefit
