// WriteRelaxedStep: relaxed centrelines as swept tubes (flat strips for flat cables), input
// solids copied, STEP AP242.
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/parallel_for.h"
#include "cablefit/formats/cad_file.h"
#include "cad_shape_handle.h"
#include "occt_session.h"
#include "occt_tube.h"
#include "tube_in_child.h"
#include "xde_document.h"

namespace cablefit {
namespace {

// The rows of a centreline to write: 3 x n points [m], and for a flat strip 3 more rows with
// its guide (the points moved half the width along the wide axis), filtered and filled together.
using CentrelineRows = Eigen::MatrixXd;

// Drops points within `min_gap` [m] of the previous kept one (the last point replaces a kept
// one too close to it): repeated points from chained edges or a stalled solver give zero-length
// spline parameter steps, and a median gap of zero would make FillLongGaps divide by zero.
CentrelineRows DropNearDuplicates(const CentrelineRows& rows, double min_gap) {
  const auto points = rows.topRows<3>();
  std::vector<Eigen::Index> keep{0};
  for (Eigen::Index i = 1; i < points.cols(); ++i) {
    if ((points.col(i) - points.col(keep.back())).norm() > min_gap) keep.push_back(i);
  }
  const Eigen::Index last = points.cols() - 1;
  if (keep.back() != last) {
    if (keep.size() > 1) {
      keep.back() = last;
    } else {
      keep.push_back(last);
    }
  }
  CentrelineRows result(rows.rows(), static_cast<Eigen::Index>(keep.size()));
  for (size_t k = 0; k < keep.size(); ++k) {
    result.col(static_cast<Eigen::Index>(k)) = rows.col(keep[k]);
  }
  return result;
}

// Adds points along segments longer than twice the median spacing: a B-spline fitted to
// unevenly spaced points (a long straight stretch given by its two ends next to a densely
// sampled bend) swings between them. Other points are kept as they are.
CentrelineRows FillLongGaps(const CentrelineRows& rows) {
  const auto points = rows.topRows<3>();
  const Eigen::Index n = points.cols();
  std::vector<double> gaps(n - 1);
  for (Eigen::Index i = 0; i + 1 < n; ++i) gaps[i] = (points.col(i + 1) - points.col(i)).norm();
  std::vector<double> sorted = gaps;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::vector<Eigen::VectorXd> out{rows.col(0)};
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const int pieces = gaps[i] > 2 * median ? static_cast<int>(std::ceil(gaps[i] / median)) : 1;
    for (int k = 1; k <= pieces; ++k) {
      const double w = static_cast<double>(k) / pieces;
      out.push_back((1 - w) * rows.col(i) + w * rows.col(i + 1));
    }
  }
  CentrelineRows result(rows.rows(), static_cast<Eigen::Index>(out.size()));
  for (size_t i = 0; i < out.size(); ++i) result.col(static_cast<Eigen::Index>(i)) = out[i];
  return result;
}

// The rows of `relaxed` as CentrelineRows: its points, and a flat strip's guide.
CentrelineRows RowsOf(const RelaxedCable& relaxed) {
  const Eigen::Matrix3Xd& points = relaxed.centreline.points;  // 3 x n [m]
  if (!relaxed.flat) return points;
  const FlatSection& flat = *relaxed.flat;
  if (flat.wide_axes.cols() != points.cols() || !flat.wide_axes.allFinite()) {
    throw InvalidInput("a flat cable needs a wide axis at every centreline point");
  }
  if (!(flat.thickness > 0) || !(flat.width >= flat.thickness)) {
    throw InvalidInput("a flat cable needs a positive thickness and a width at least that");
  }
  CentrelineRows rows(6, points.cols());
  rows.topRows<3>() = points;
  // Half the width beside the spine: close enough that each plane square to the spine meets it
  // once even in a bend of a few widths' radius (MakeFlatStripSolid).
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const double norm = flat.wide_axes.col(i).norm();
    if (!(norm > 0)) throw InvalidInput("a flat cable has a zero wide axis");
    rows.block<3, 1>(3, i) = points.col(i) + 0.5 * flat.width / norm * flat.wide_axes.col(i);
  }
  return rows;
}

}  // namespace

void WriteRelaxedStep(const std::string& path, const HarnessDrawing& input,
                      const std::vector<RelaxedCable>& cables, std::vector<std::string>* skipped) {
  Handle(TDocStd_Document) doc = NewXcafDocument();
  int shapes = 0;
  // The spines of every cable first, then all sweeps in helper processes, then the document in
  // the order of `cables`.
  struct Pending {
    const DrawnCable* drawn = nullptr;
    std::vector<std::size_t> spines;  // indices into `sweeps`; two for a closed loop
    std::string problem;              // why it cannot be written, when it cannot
  };
  // The spines (a B-spline fit each, a few ms) on every core: OCCT's curve fitting keeps no
  // shared state. Sweeps are what crash on bad geometry, and they run in helper processes.
  const int n = static_cast<int>(cables.size());
  std::vector<Pending> pending(static_cast<std::size_t>(n));
  std::vector<std::vector<CableSweep>> spines(static_cast<std::size_t>(n));  // [mm]
  const auto diameter_of = [&](const RelaxedCable& relaxed) {  // [m]
    return relaxed.diameter > 0 ? relaxed.diameter : input.cables[relaxed.source_cable].diameter;
  };
  for (const RelaxedCable& relaxed : cables) {
    if (relaxed.source_cable < 0 || relaxed.source_cable >= static_cast<int>(input.cables.size())) {
      throw InvalidInput("relaxed cable refers to input cable " +
                         std::to_string(relaxed.source_cable) + " of " +
                         std::to_string(input.cables.size()));
    }
    const DrawnCable& drawn = input.cables[relaxed.source_cable];
    if (!(diameter_of(relaxed) > 0)) {
      throw InvalidInput("cable '" + drawn.name + "': no diameter (drawn as a curve; set one)");
    }
  }
  const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  ParallelFor(n, std::min(threads, n), [&](int c) {
    const RelaxedCable& relaxed = cables[static_cast<std::size_t>(c)];
    const DrawnCable& drawn = input.cables[relaxed.source_cable];
    const double diameter = diameter_of(relaxed);  // [m]
    Pending& p = pending[static_cast<std::size_t>(c)];
    std::vector<CableSweep>& mine = spines[static_cast<std::size_t>(c)];
    p.drawn = &drawn;
    try {
      if (relaxed.centreline.size() < 2 || !relaxed.centreline.points.allFinite()) {
        throw InvalidInput("the relaxed centreline needs at least 2 finite points");
      }
      // A thousandth of the diameter: well below the spline tolerance below.
      const CentrelineRows distinct = DropNearDuplicates(RowsOf(relaxed), 1e-3 * diameter);
      // Arc length, not end-to-end distance: a closed loop ends where it starts.
      double length = 0.0;  // [m]
      for (Eigen::Index k = 1; k < distinct.cols(); ++k)
        length += (distinct.block<3, 1>(0, k) - distinct.block<3, 1>(0, k - 1)).norm();
      if (distinct.cols() < 2 || length <= 1e-3 * diameter) {
        throw InvalidInput("the relaxed centreline has no length");
      }
      const CentrelineRows rows = FillLongGaps(distinct) / kMetresPerOcctUnit;  // [mm]
      // Approximation tolerance well below the 1 %-of-diameter accuracy promised for read-back
      // (of the thickness for a flat strip: its thinnest measure).
      const double size = relaxed.flat ? relaxed.flat->thickness : diameter;  // [m]
      const double tolerance = std::min(0.01, 1e-3 * size / kMetresPerOcctUnit);  // [mm]
      const auto add = [&](const CentrelineRows& along) {
        CableSweep sweep;
        // A round tube's surface is built on its spine's poles (occt_pipe_surface.h), so its
        // spine is our fit with few poles (MakeTubeSpineEdge); a flat strip is swept by OCCT's
        // pipe shell, whose surfaces stay small only along OCCT's own fit (MakeSplineEdge).
        sweep.spine = BRepBuilderAPI_MakeWire(relaxed.flat ? MakeSplineEdge(along.topRows<3>(), tolerance)
                                                           : MakeTubeSpineEdge(along.topRows<3>(), tolerance))
                          .Wire();
        sweep.diameter = diameter / kMetresPerOcctUnit;
        if (relaxed.flat) {
          sweep.guide = BRepBuilderAPI_MakeWire(MakeSplineEdge(along.bottomRows<3>(), tolerance)).Wire();
          sweep.flat = FlatProfile{relaxed.flat->width / kMetresPerOcctUnit,
                                   relaxed.flat->thickness / kMetresPerOcctUnit,
                                   relaxed.flat->rounded_edges};
        }
        mine.push_back(std::move(sweep));
      };
      const Eigen::Index m = rows.cols();
      const double gap = (rows.block<3, 1>(0, m - 1) - rows.block<3, 1>(0, 0)).norm();  // [mm]
      // A closed loop: a spline through coinciding ends cannot be swept, two halves can. Ends
      // closer than the diameter on a cable many gaps long are a loop; a stub shorter than its
      // diameter (a segment between two nodes of a harness network) is not, and written as one
      // tube it reads back as one.
      if (m >= 4 && gap < diameter / kMetresPerOcctUnit &&
          gap < 0.1 * length / kMetresPerOcctUnit) {
        add(rows.leftCols(m / 2 + 1));
        add(rows.rightCols(m - m / 2));
      } else {
        add(rows);
      }
    } catch (const InvalidInput& e) {
      p.problem = e.what();
      mine.clear();
    } catch (const Standard_Failure& e) {
      p.problem = e.GetMessageString();
      mine.clear();
    }
  });
  std::vector<CableSweep> sweeps;  // [mm], in the order of `cables`
  for (int c = 0; c < n; ++c) {
    for (CableSweep& sweep : spines[static_cast<std::size_t>(c)]) {
      pending[static_cast<std::size_t>(c)].spines.push_back(sweeps.size());
      sweeps.push_back(std::move(sweep));
    }
  }
  const std::vector<TubeSweepResult> tubes = MakeTubeSolidsInChild(sweeps);
  for (const Pending& p : pending) {
    std::string problem = p.problem;
    for (const std::size_t k : p.spines)
      if (problem.empty() && tubes[k].tube.IsNull()) problem = tubes[k].error;
    if (!problem.empty()) {
      problem = "cable '" + p.drawn->name + "': " + problem;
      if (skipped == nullptr) throw InvalidInput(problem);
      skipped->push_back(problem);
      continue;
    }
    TopoDS_Shape tube;
    if (p.spines.size() == 1) {
      tube = tubes[p.spines.front()].tube;
    } else {
      TopoDS_Compound halves;
      BRep_Builder builder;
      builder.MakeCompound(halves);
      for (const std::size_t k : p.spines) builder.Add(halves, tubes[k].tube);
      tube = halves;
    }
    AddNamedShape(doc, tube, p.drawn->name,
                  p.drawn->has_color ? std::optional<SrgbColor>(p.drawn->color) : std::nullopt);
    ++shapes;
  }
  for (const DrawnSolid& solid : input.solids) {
    if (!solid.shape) continue;  // not from CAD (e.g. a mesh input): nothing to copy
    AddNamedShape(doc, solid.shape->shape, solid.name,
                  solid.has_color ? std::optional<SrgbColor>(solid.color) : std::nullopt);
    ++shapes;
  }
  if (shapes == 0) {
    // OCCT refuses an empty model with a message that blames the folder; say what happened.
    if (skipped != nullptr && !skipped->empty()) return;
    throw InvalidInput("nothing to write: no cable and no solid");
  }
  WriteStepAtomically(doc, path, "AP242DIS");
}

void PrepareRelaxedStep(std::size_t cables) { PrestartTubeSweepHelpers(cables); }

}  // namespace cablefit
