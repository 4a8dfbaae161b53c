// The tube sweep run in a forked child: OCCT's sweeps have crashed on smooth centrelines
// (BRepFill_Pipe::MakeShape read a null face when its sweep failed). A crash or hang there becomes
// one cable that could not be written (InvalidInput), never the end of the whole process.
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace cablefit {

/// MakeTubeSolid(spine, diameter) computed in a forked child and handed back as a BRep file.
/// Throws InvalidInput with the child's message when the sweep fails, and "the tube sweep
/// crashed in OpenCASCADE (signal ...)" / "... did not finish within N s" when the child dies or
/// hangs. Sweeps in this process when no child can be started.
TopoDS_Shape MakeTubeSolidInChild(const TopoDS_Wire& spine, double diameter,
                                  double max_seconds = 120.0);

}  // namespace cablefit
