#include "tube_in_child.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS.hxx>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "cablefit/core/base/errors.h"
#include "crash_probe.h"
#include "occt_tube.h"

namespace cablefit {
namespace {

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TopoDS_Shape MakeTubeSolidInChild(const TopoDS_Wire& spine, double diameter, double max_seconds) {
  const MemoryFile spine_file("cablefit-spine");
  const MemoryFile tube_file("cablefit-tube");
  if (spine_file.fd() < 0 || tube_file.fd() < 0 ||
      !BRepTools::Write(spine, spine_file.path().c_str())) {
    return MakeTubeSolid(spine, diameter);
  }
  char diameter_text[32];
  std::snprintf(diameter_text, sizeof diameter_text, "%.17g", diameter);
  const auto outcome =
      RunOcctChild({"sweep", "3", diameter_text, "4"}, max_seconds,
                   {{spine_file.fd(), 3}, {tube_file.fd(), 4}});
  if (!outcome) return MakeTubeSolid(spine, diameter);
  if (outcome->timed_out) {
    throw InvalidInput("the tube sweep did not finish within " +
                       std::to_string(static_cast<int>(max_seconds)) + " s");
  }
  if (outcome->signal != 0) {
    throw InvalidInput("the tube sweep crashed in OpenCASCADE (signal " +
                       std::to_string(outcome->signal) + ": " + ::strsignal(outcome->signal) +
                       ")");
  }
  if (outcome->exit_code == kTubeSweepFailedExit) throw InvalidInput(ReadAll(tube_file.path()));
  TopoDS_Shape tube;
  BRep_Builder builder;
  if (outcome->exit_code != 0 || !BRepTools::Read(tube, tube_file.path().c_str(), builder) ||
      tube.IsNull()) {
    throw InvalidInput("the tube sweep failed (exit status " +
                       std::to_string(outcome->exit_code) + ")");
  }
  return tube;
}

int SweepTubeInHelper(int spine_fd, double diameter, int tube_fd) {
  const std::string spine_path = "/proc/self/fd/" + std::to_string(spine_fd);
  const std::string tube_path = "/proc/self/fd/" + std::to_string(tube_fd);
  TopoDS_Shape spine;
  BRep_Builder builder;
  if (!BRepTools::Read(spine, spine_path.c_str(), builder) || spine.IsNull() ||
      spine.ShapeType() != TopAbs_WIRE) {
    return 4;
  }
  try {
    const TopoDS_Shape tube = MakeTubeSolid(TopoDS::Wire(spine), diameter);
    return BRepTools::Write(tube, tube_path.c_str()) ? 0 : 4;
  } catch (const InvalidInput& e) {
    std::ofstream(tube_path, std::ios::trunc) << e.what();
    return kTubeSweepFailedExit;
  }
}

}  // namespace cablefit
