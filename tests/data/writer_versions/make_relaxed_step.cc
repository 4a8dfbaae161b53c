// Writes relaxed cables to STEP with the STEP writer of the cablefit checkout it is compiled
// against: make_relaxed_step OUT.step CENTRELINES.txt. CENTRELINES.txt holds per cable a line
// "<name> <diameter [m]> <n>" and then n lines "x y z" [m], the relaxed centreline (the
// `relaxed_centreline` of a `cablefit relax` JSON). Uses only what every writer since the first
// has: WriteRelaxedStep, HarnessDrawing, DrawnCable, RelaxedCable.
//
// Built against an old checkout: `git archive COMMIT core formats | tar -x -C OLD`, then compile
// this file with OLD's formats/cad/src/*.cc, formats/base/src/*.cc (where it exists) and the
// core sources those need (errors, geometry_types, cubic_spline_fit, parallel_for, cancellation),
// include paths OLD/*/include, OLD/*/*/include and OLD/formats/cad/src, linking OpenCASCADE
// (TKernel ... TKXDESTEP TKXDEIGES TKBin); writers from 8d79804 on sweep in a helper process, so
// OLD/formats/cad/tools/{occt,sweep}_child_main.cc are built beside it as cablefit-occt-child and
// cablefit-sweep-child.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "cablefit/formats/cad_file.h"

using namespace cablefit;

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  HarnessDrawing drawing;
  std::vector<RelaxedCable> relaxed;
  std::ifstream in(argv[2]);
  std::string name;
  double diameter = 0;
  int n = 0;
  while (in >> name >> diameter >> n) {
    Polyline p;
    p.points.resize(3, n);
    for (int i = 0; i < n; ++i) in >> p.points(0, i) >> p.points(1, i) >> p.points(2, i);
    p.ParameteriseByChords(0.0);
    DrawnCable cable;
    cable.name = name;
    cable.centreline = p;
    cable.diameter = diameter;
    drawing.cables.push_back(cable);
    RelaxedCable r;
    r.source_cable = static_cast<int>(relaxed.size());
    r.centreline = p;
    r.diameter = diameter;
    relaxed.push_back(r);
  }
  WriteRelaxedStep(argv[1], drawing, relaxed);
  std::printf("wrote %s: %zu cables\n", argv[1], relaxed.size());
  return 0;
}
