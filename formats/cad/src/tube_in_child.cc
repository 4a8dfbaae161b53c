#include "tube_in_child.h"

#include <BinTools.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "crash_probe.h"
#include "occt_tube.h"

namespace cablefit {
namespace {

// Sweeps a helper takes at least before another one is started (each costs ~0.03 s of CPU to
// start, and a batch file to write and read).
constexpr size_t kSweepsPerHelper = 8;

}  // namespace

TopoDS_Shape MakeCableSolid(const CableSweep& sweep) {
  return sweep.flat ? MakeFlatStripSolid(sweep.spine, sweep.guide, *sweep.flat)
                    : MakeTubeSolid(sweep.spine, sweep.diameter);
}

namespace {

// One batch file: per item a header line, then (for a shape) its binary BRep (BinTools) of the
// stated size. Binary, not BRep text: printing and parsing every pole of the swept surfaces as
// text took a fifth of the sweep helpers' time; the doubles come back bit for bit either way.
//   sweeps: "SPINE <diameter> <bytes>\n<brep of the spine>" (a round tube) or
//           "STRIP <width> <thickness> <0|1 rounded edges> <bytes>\n<brep of a compound of the
//           spine and the guide>" (a flat strip)
//   solids: "TUBE <bytes>\n<brep>" or "ERROR <message without newlines>\n"
std::string ShapeBytes(const TopoDS_Shape& shape) {
  std::ostringstream out(std::ios::binary);
  BinTools::Write(shape, out, /*theWithTriangles=*/false, /*theWithNormals=*/false,
                  BinTools_FormatVersion_CURRENT);
  return out.str();
}

bool ReadShapeBytes(std::istream& in, std::size_t bytes, TopoDS_Shape* shape) {
  std::string data(bytes, '\0');
  if (!in.read(data.data(), static_cast<std::streamsize>(bytes))) return false;
  std::istringstream shape_in(data, std::ios::binary);
  try {
    BinTools::Read(*shape, shape_in);
  } catch (const Standard_Failure&) {
    return false;
  }
  return !shape->IsNull();
}

std::string SingleLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

void WriteSweep(const CableSweep& sweep, std::ostream& out) {
  char header[160];
  if (sweep.flat) {
    TopoDS_Compound both;
    BRep_Builder builder;
    builder.MakeCompound(both);
    builder.Add(both, sweep.spine);
    builder.Add(both, sweep.guide);
    const std::string bytes = ShapeBytes(both);
    std::snprintf(header, sizeof header, "STRIP %.17g %.17g %d %zu\n", sweep.flat->width,
                  sweep.flat->thickness, sweep.flat->rounded_edges ? 1 : 0, bytes.size());
    out << header << bytes;
  } else {
    const std::string bytes = ShapeBytes(sweep.spine);
    std::snprintf(header, sizeof header, "SPINE %.17g %zu\n", sweep.diameter, bytes.size());
    out << header << bytes;
  }
}

// The next sweep of a batch file; false at its end or when it is malformed.
bool ReadSweep(std::istream& in, CableSweep* sweep) {
  std::string kind;
  if (!(in >> kind)) return false;
  std::size_t bytes = 0;
  TopoDS_Shape shape;
  if (kind == "SPINE") {
    if (!(in >> sweep->diameter >> bytes) || in.get() != '\n' || !ReadShapeBytes(in, bytes, &shape) ||
        shape.ShapeType() != TopAbs_WIRE)
      return false;
    sweep->spine = TopoDS::Wire(shape);
    return true;
  }
  FlatProfile profile;
  int rounded = 0;
  if (kind != "STRIP" || !(in >> profile.width >> profile.thickness >> rounded >> bytes) ||
      in.get() != '\n' || !ReadShapeBytes(in, bytes, &shape) || shape.ShapeType() != TopAbs_COMPOUND)
    return false;
  TopoDS_Iterator it(shape);
  if (!it.More() || it.Value().ShapeType() != TopAbs_WIRE) return false;
  sweep->spine = TopoDS::Wire(it.Value());
  it.Next();
  if (!it.More() || it.Value().ShapeType() != TopAbs_WIRE) return false;
  sweep->guide = TopoDS::Wire(it.Value());
  profile.rounded_edges = rounded != 0;
  sweep->flat = profile;
  return true;
}

TubeSweepResult SweepHere(const CableSweep& sweep) {
  TubeSweepResult r;
  try {
    r.tube = MakeCableSolid(sweep);
  } catch (const InvalidInput& e) {
    r.error = e.what();
  } catch (const Standard_Failure& e) {
    r.error = e.GetMessageString();
  }
  return r;
}

// A sweep helper started ahead (PrestartTubeSweepHelpers) with the files it will read and write.
struct WaitingSweeper {
  MemoryFile spines{"cablefit-spines"};
  MemoryFile tubes{"cablefit-tubes"};
  std::unique_ptr<WaitingHelper> helper;
};

std::mutex& PoolMutex() {
  static std::mutex mutex;
  return mutex;
}

std::vector<std::unique_ptr<WaitingSweeper>>& Pool() {
  static std::vector<std::unique_ptr<WaitingSweeper>> pool;
  return pool;
}

std::unique_ptr<WaitingSweeper> TakeWaitingSweeper() {
  const std::lock_guard lock(PoolMutex());
  if (Pool().empty()) return nullptr;
  std::unique_ptr<WaitingSweeper> taken = std::move(Pool().back());
  Pool().pop_back();
  return taken;
}

// How many helpers MakeTubeSolidsInChild uses for `sweeps` sweeps (0: in this process or one
// per sweep after a failure).
int HelpersFor(std::size_t sweeps) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int many = std::min(cores, static_cast<int>(sweeps / kSweepsPerHelper));
  return many > 1 ? many : sweeps > 1 ? 1 : 0;
}

// The sweeps in one helper: the results, or (when it died, hung or wrote nonsense) nullopt with
// `why` said. `started` is false when no helper could be started at all. A waiting helper of
// the pool is used when there is one: it has loaded already.
std::optional<std::vector<TubeSweepResult>> SweepBatch(const std::vector<CableSweep>& sweeps,
                                                       double max_seconds, std::string* why,
                                                       bool* started) {
  *started = false;
  std::unique_ptr<WaitingSweeper> waiting = TakeWaitingSweeper();
  std::optional<MemoryFile> own_spines, own_tubes;
  if (!waiting) {
    own_spines.emplace("cablefit-spines");
    own_tubes.emplace("cablefit-tubes");
  }
  const MemoryFile& spines_file = waiting ? waiting->spines : *own_spines;
  const MemoryFile& tubes_file = waiting ? waiting->tubes : *own_tubes;
  if (!spines_file.ok() || !tubes_file.ok()) return std::nullopt;
  {
    std::ofstream out(spines_file.path(), std::ios::binary | std::ios::trunc);
    for (const CableSweep& sweep : sweeps) WriteSweep(sweep, out);
    if (!out.flush()) return std::nullopt;
  }
  const auto outcome =
      waiting ? waiting->helper->Run(max_seconds)
              : RunHelper(kSweepHelper, {"sweeps", "3", "4"}, max_seconds,
                          {{spines_file.fd(), 3}, {tubes_file.fd(), 4}});
  if (!outcome) return std::nullopt;
  *started = true;
  if (outcome->timed_out) {
    *why = "the tube sweep did not finish within " + std::to_string(static_cast<int>(max_seconds)) + " s";
    return std::nullopt;
  }
  if (outcome->signal != 0) {
    *why = "the tube sweep crashed in OpenCASCADE (signal " + std::to_string(outcome->signal) +
           ": " + ::strsignal(outcome->signal) + ")";
    return std::nullopt;
  }
  *why = "the tube sweep failed (exit status " + std::to_string(outcome->exit_code) + ")";
  if (outcome->exit_code != 0) return std::nullopt;
  std::vector<TubeSweepResult> results(sweeps.size());
  std::ifstream in(tubes_file.path(), std::ios::binary);
  for (TubeSweepResult& r : results) {
    std::string kind;
    if (!(in >> kind)) return std::nullopt;
    if (kind == "ERROR") {
      in.get();  // the space
      std::getline(in, r.error);
      continue;
    }
    std::size_t bytes = 0;
    if (kind != "TUBE" || !(in >> bytes) || in.get() != '\n' || !ReadShapeBytes(in, bytes, &r.tube))
      return std::nullopt;
  }
  return results;
}

}  // namespace

std::vector<TubeSweepResult> MakeTubeSolidsInChild(const std::vector<CableSweep>& sweeps,
                                                   double max_seconds) {
  std::string why;
  bool started = false;
  // Many sweeps: one helper per core, each taking every n-th sweep (long and short cables
  // mixed alike); a sweep's tube does not depend on its helper, so neither does the result.
  const int helpers = HelpersFor(sweeps.size());
  if (helpers > 1) {
    std::vector<std::optional<std::vector<TubeSweepResult>>> parts(static_cast<size_t>(helpers));
    ParallelFor(helpers, helpers, [&](int h) {
      std::vector<CableSweep> mine;
      for (size_t i = static_cast<size_t>(h); i < sweeps.size(); i += static_cast<size_t>(helpers))
        mine.push_back(sweeps[i]);
      std::string part_why;
      bool part_started = false;
      parts[static_cast<size_t>(h)] = SweepBatch(mine, max_seconds, &part_why, &part_started);
    });
    if (std::all_of(parts.begin(), parts.end(), [](const auto& p) { return p.has_value(); })) {
      std::vector<TubeSweepResult> results(sweeps.size());
      for (size_t i = 0; i < sweeps.size(); ++i)
        results[i] = std::move((*parts[i % static_cast<size_t>(helpers)])[i / static_cast<size_t>(helpers)]);
      return results;
    }
    // A helper died: the slow, sure way below for all of them.
  } else if (sweeps.size() > 1) {
    if (auto all = SweepBatch(sweeps, max_seconds, &why, &started)) return *std::move(all);
  }
  // One helper each: a batch that died on one of the sweeps costs only that one. No helper at
  // all: each in this process.
  std::vector<TubeSweepResult> results(sweeps.size());
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    auto one = SweepBatch({sweeps[i]}, max_seconds, &why, &started);
    if (one) {
      results[i] = std::move(one->front());
    } else if (started) {
      results[i].error = why;
    } else {
      results[i] = SweepHere(sweeps[i]);
    }
  }
  return results;
}

void PrestartTubeSweepHelpers(std::size_t sweeps) {
  const std::lock_guard lock(PoolMutex());
  for (int k = static_cast<int>(Pool().size()); k < HelpersFor(sweeps); ++k) {
    auto sweeper = std::make_unique<WaitingSweeper>();
    if (!sweeper->spines.ok() || !sweeper->tubes.ok()) return;
    sweeper->helper = WaitingHelper::Start(kSweepHelper, {"sweeps-when-told", "3", "4"},
                                           {{sweeper->spines.fd(), 3}, {sweeper->tubes.fd(), 4}});
    if (!sweeper->helper) return;
    Pool().push_back(std::move(sweeper));
  }
}

int SweepTubesInHelper(int spines_fd, int tubes_fd) {
  std::ifstream in("/proc/self/fd/" + std::to_string(spines_fd), std::ios::binary);
  std::ofstream out("/proc/self/fd/" + std::to_string(tubes_fd), std::ios::binary | std::ios::trunc);
  if (!in || !out) return 4;
  while (in >> std::ws && in.peek() != EOF) {
    CableSweep sweep;
    if (!ReadSweep(in, &sweep)) return 4;
    const TubeSweepResult r = SweepHere(sweep);
    if (r.tube.IsNull()) {
      out << "ERROR " << SingleLine(r.error) << "\n";
    } else {
      const std::string bytes = ShapeBytes(r.tube);
      out << "TUBE " << bytes.size() << "\n" << bytes;
    }
  }
  return out.flush() ? 0 : 4;
}

}  // namespace cablefit
