#include "tube_in_child.h"

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>
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

namespace {

// One batch file: per item a header line, then (for a shape) its BRep text of the stated size.
//   spines: "SPINE <diameter> <bytes>\n<brep>"
//   tubes:  "TUBE <bytes>\n<brep>" or "ERROR <message without newlines>\n"
std::string ShapeText(const TopoDS_Shape& shape) {
  std::ostringstream out;
  BRepTools::Write(shape, out);
  return out.str();
}

bool ReadShapeText(std::istream& in, std::size_t bytes, TopoDS_Shape* shape) {
  std::string text(bytes, '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(bytes))) return false;
  std::istringstream shape_in(text);
  BRep_Builder builder;
  BRepTools::Read(*shape, shape_in, builder);
  return !shape->IsNull();
}

std::string SingleLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::vector<TubeSweepResult> SweepEachInItsOwnChild(
    const std::vector<std::pair<TopoDS_Wire, double>>& spines, double max_seconds) {
  std::vector<TubeSweepResult> results(spines.size());
  for (std::size_t i = 0; i < spines.size(); ++i) {
    try {
      results[i].tube = MakeTubeSolidInChild(spines[i].first, spines[i].second, max_seconds);
    } catch (const InvalidInput& e) {
      results[i].error = e.what();
    }
  }
  return results;
}

}  // namespace

std::vector<TubeSweepResult> MakeTubeSolidsInChild(
    const std::vector<std::pair<TopoDS_Wire, double>>& spines, double max_seconds) {
  if (spines.size() <= 1) return SweepEachInItsOwnChild(spines, max_seconds);
  const MemoryFile spines_file("cablefit-spines");
  const MemoryFile tubes_file("cablefit-tubes");
  if (!spines_file.ok() || !tubes_file.ok()) return SweepEachInItsOwnChild(spines, max_seconds);
  {
    std::ofstream out(spines_file.path(), std::ios::binary | std::ios::trunc);
    for (const auto& [spine, diameter] : spines) {
      const std::string text = ShapeText(spine);
      char header[96];
      std::snprintf(header, sizeof header, "SPINE %.17g %zu\n", diameter, text.size());
      out << header << text;
    }
    if (!out.flush()) return SweepEachInItsOwnChild(spines, max_seconds);
  }
  const auto outcome = RunOcctChild({"sweeps", "3", "4"}, max_seconds,
                                    {{spines_file.fd(), 3}, {tubes_file.fd(), 4}});
  if (!outcome || outcome->timed_out || outcome->signal != 0 || outcome->exit_code != 0) {
    // No helper (then each sweeps in this process), or the batch died on one of the spines.
    return SweepEachInItsOwnChild(spines, max_seconds);
  }
  std::vector<TubeSweepResult> results(spines.size());
  std::ifstream in(tubes_file.path(), std::ios::binary);
  for (TubeSweepResult& r : results) {
    std::string kind;
    if (!(in >> kind)) return SweepEachInItsOwnChild(spines, max_seconds);
    if (kind == "ERROR") {
      in.get();  // the space
      std::getline(in, r.error);
      continue;
    }
    std::size_t bytes = 0;
    if (kind != "TUBE" || !(in >> bytes) || in.get() != '\n' || !ReadShapeText(in, bytes, &r.tube))
      return SweepEachInItsOwnChild(spines, max_seconds);
  }
  return results;
}

int SweepTubesInHelper(int spines_fd, int tubes_fd) {
  std::ifstream in("/proc/self/fd/" + std::to_string(spines_fd), std::ios::binary);
  std::ofstream out("/proc/self/fd/" + std::to_string(tubes_fd), std::ios::binary | std::ios::trunc);
  if (!in || !out) return 4;
  std::string kind;
  while (in >> kind) {
    double diameter = 0;
    std::size_t bytes = 0;
    TopoDS_Shape spine;
    if (kind != "SPINE" || !(in >> diameter >> bytes) || in.get() != '\n' ||
        !ReadShapeText(in, bytes, &spine) || spine.ShapeType() != TopAbs_WIRE) {
      return 4;
    }
    try {
      const std::string text = ShapeText(MakeTubeSolid(TopoDS::Wire(spine), diameter));
      out << "TUBE " << text.size() << "\n" << text;
    } catch (const InvalidInput& e) {
      out << "ERROR " << SingleLine(e.what()) << "\n";
    } catch (const Standard_Failure& e) {
      out << "ERROR " << SingleLine(e.GetMessageString()) << "\n";
    }
  }
  return out.flush() ? 0 : 4;
}

}  // namespace cablefit
