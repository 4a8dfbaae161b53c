// The Python module `cablefit_native` the FreeCAD workbench imports: bindings of
// cablefit_facade.h only. Lengths in metres as everywhere in cablefit (the workbench converts
// from FreeCAD's millimetres); point sets are numpy arrays of shape (3, n).
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/solver_failure.h"
#include "cablefit_facade.h"

namespace py = pybind11;
using cablefit::freecad::CableSummary;
using cablefit::freecad::DiagnosisSummary;
using cablefit::freecad::HarnessRelaxation;
using cablefit::freecad::MotionPoseSummary;
using cablefit::freecad::MotionSummary;
using cablefit::freecad::SupportSummary;
using cablefit::freecad::SweptCableSummary;

namespace {

// A Python progress callable as the core's ProgressCallback: a falsy return value cancels.
// An exception raised by the callable (e.g. FreeCAD's progress indicator when the user pressed
// Esc) cancels too and is re-raised once the C++ call has returned, so no Python error crosses
// the solver.
class PythonProgress {
 public:
  explicit PythonProgress(py::object callable) : callable_(std::move(callable)) {}

  cablefit::ProgressCallback Callback() {
    if (callable_.is_none()) return {};
    return [this](double fraction, const std::string& stage) {
      if (error_) return false;
      try {
        py::object r = callable_(fraction, stage);
        return r.is_none() || r.cast<bool>();
      } catch (py::error_already_set& e) {
        error_.emplace(std::move(e));
        return false;
      }
    };
  }
  void RethrowIfFailed() {
    if (error_) {
      py::error_already_set e = std::move(*error_);
      error_.reset();
      throw e;
    }
  }

 private:
  py::object callable_;
  std::optional<py::error_already_set> error_;
};

}  // namespace

// The whole Python API in one place, as pybind11 declares it: a list of bindings, not logic.
PYBIND11_MODULE(cablefit_native, m) {
  m.doc() = "cablefit relax and diagnose for the FreeCAD workbench (lengths in metres)";
  static py::exception<cablefit::InvalidInput> error(m, "Error", PyExc_ValueError);
  // A stopped run (progress returned False, or a time limit) is not bad input: its own type.
  static py::exception<cablefit::Cancelled> cancelled(m, "Cancelled", PyExc_RuntimeError);
  static py::exception<cablefit::SolverFailure> solver_failure(m, "SolverFailure",
                                                               PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const cablefit::InvalidInput& e) {
      error(e.what());  // FileError's what() already names the file
    } catch (const cablefit::Cancelled& e) {
      cancelled(e.what());
    } catch (const cablefit::SolverFailure& e) {
      solver_failure(e.what());
    }
  });

  py::class_<SupportSummary>(m, "Support")
      .def_readonly("kind", &SupportSummary::kind)
      .def_readonly("origin", &SupportSummary::origin)
      .def_readonly("s", &SupportSummary::s)
      .def_readonly("position", &SupportSummary::position)
      .def_readonly("sliding", &SupportSummary::sliding);

  py::class_<CableSummary>(m, "Cable")
      .def_readonly("name", &CableSummary::name)
      .def_readonly("ok", &CableSummary::ok)
      .def_readonly("error", &CableSummary::error)
      .def_readonly("length", &CableSummary::length)
      .def_readonly("diameter", &CableSummary::diameter)
      .def_readonly("drawn", &CableSummary::drawn)
      .def_readonly("s", &CableSummary::s)
      .def_readonly("relaxed", &CableSummary::relaxed)
      .def_readonly("deviation", &CableSummary::deviation)
      .def_readonly("max_deviation", &CableSummary::max_deviation)
      .def_readonly("rms_deviation", &CableSummary::rms_deviation)
      .def_readonly("max_deviation_s", &CableSummary::max_deviation_s)
      .def_readonly("min_bend_radius", &CableSummary::min_bend_radius)
      .def_readonly("bend_limit", &CableSummary::bend_limit)
      .def_readonly("bend_flag", &CableSummary::bend_flag)
      .def_readonly("stable", &CableSummary::stable)
      .def_readonly("material_source", &CableSummary::material_source)
      .def_readonly("material_defaulted", &CableSummary::material_defaulted)
      .def_readonly("bending_stiffness", &CableSummary::bending_stiffness)
      .def_readonly("linear_density", &CableSummary::linear_density)
      .def_readonly("gravity", &CableSummary::gravity)
      .def_readonly("supports", &CableSummary::supports)
      .def_readonly("notes", &CableSummary::notes)
      .def_readonly("iterations", &CableSummary::iterations)
      .def_readonly("seconds", &CableSummary::seconds);

  py::class_<MotionPoseSummary>(m, "MotionPose")
      .def_readonly("q", &MotionPoseSummary::q)
      .def_readonly("converged", &MotionPoseSummary::converged)
      .def_readonly("stable", &MotionPoseSummary::stable)
      .def_readonly("escaped_unstable", &MotionPoseSummary::escaped_unstable)
      .def_readonly("jumped", &MotionPoseSummary::jumped)
      .def_property_readonly(
          "branch_lost", [](const MotionPoseSummary& p) { return p.escaped_unstable || p.jumped; })
      .def_readonly("min_bend_radius", &MotionPoseSummary::min_bend_radius)
      .def_readonly("min_bend_radius_s", &MotionPoseSummary::min_bend_radius_s)
      .def_readonly("bend_flag", &MotionPoseSummary::bend_flag)
      .def_readonly("max_tension", &MotionPoseSummary::max_tension)
      .def_readonly("max_tension_s", &MotionPoseSummary::max_tension_s)
      .def_readonly("clearance", &MotionPoseSummary::clearance)
      .def_readonly("clearance_s", &MotionPoseSummary::clearance_s)
      .def_readonly("clearance_required", &MotionPoseSummary::clearance_required)
      .def_readonly("clearance_to", &MotionPoseSummary::clearance_to)
      .def_readonly("s", &MotionPoseSummary::s)
      .def_readonly("centreline", &MotionPoseSummary::centreline);

  py::class_<SweptCableSummary>(m, "SweptCable")
      .def_readonly("cable", &SweptCableSummary::cable)
      .def_readonly("name", &SweptCableSummary::name)
      .def_readonly("poses", &SweptCableSummary::poses)
      .def_readonly("branch_lost_pose", &SweptCableSummary::branch_lost_pose)
      .def_readonly("completed", &SweptCableSummary::completed)
      .def_readonly("message", &SweptCableSummary::message)
      .def_readonly("back_to_start", &SweptCableSummary::back_to_start)
      .def_readonly("seconds", &SweptCableSummary::seconds);

  py::class_<MotionSummary>(m, "Motion")
      .def_readonly("name", &MotionSummary::name)
      .def_readonly("kind", &MotionSummary::kind)
      .def_readonly("unit", &MotionSummary::unit)
      .def_readonly("q", &MotionSummary::q)
      .def_readonly("problems", &MotionSummary::problems)
      .def_readonly("cables", &MotionSummary::cables)
      .def_readonly("seconds", &MotionSummary::seconds);

  py::class_<HarnessRelaxation>(m, "Relaxation")
      .def_property_readonly("cables", &HarnessRelaxation::cables)
      .def_property_readonly("motion", &HarnessRelaxation::motion,
                             "The harness.json motion as swept (None without one)")
      .def_property_readonly("solid_names", &HarnessRelaxation::solid_names)
      .def_property_readonly("read_seconds", &HarnessRelaxation::read_seconds)
      .def("write_step", &HarnessRelaxation::WriteStep, py::arg("path"),
           py::arg("with_solids") = true, py::arg("cable") = -1, py::arg("pose") = -1,
           "Relaxed tubes (all, or only number `cable`, at pose `pose` of the motion when >= 0) "
           "and the input's other solids (unless with_solids is False) as STEP AP242 in mm")
      .def("write_report", &HarnessRelaxation::WriteReport, py::arg("dir"),
           py::arg("pictures") = true,
           "What `cablefit relax --out DIR` writes for this input; returns report.html's path");

  m.def(
      "relax",
      [](const std::string& input, const std::string& config, double accuracy,
         const std::string& mesh_unit, py::object progress, double timeout) {
        PythonProgress p(std::move(progress));
        HarnessRelaxation r =
            HarnessRelaxation::Run(input, config, accuracy, mesh_unit, timeout, p.Callback());
        p.RethrowIfFailed();
        return r;
      },
      py::arg("input"), py::arg("config") = "", py::arg("accuracy") = 0.0,
      py::arg("mesh_unit") = "mm", py::arg("progress") = py::none(), py::arg("timeout") = 0.0,
      "Relax every cable of a STEP/IGES/KBL/mesh file like `cablefit relax INPUT --config CONFIG "
      "--timeout T` (accuracy 0: the command line's default for the input). progress(fraction, stage) returning False (or raising) cancels.");

  m.def("deviation_colour", &cablefit::freecad::DeviationColour, py::arg("value"), py::arg("lo"),
        py::arg("hi"), "sRGB (r, g, b) in [0, 1] of value on the relax pictures' colour scale");

  py::class_<DiagnosisSummary>(m, "Diagnosis")
      .def_readonly("name", &DiagnosisSummary::name)
      .def_readonly("kind", &DiagnosisSummary::kind)
      .def_readonly("effect", &DiagnosisSummary::effect)
      .def_readonly("confidence", &DiagnosisSummary::confidence)
      .def_readonly("interval", &DiagnosisSummary::interval)
      .def_readonly("parameters", &DiagnosisSummary::parameters)
      .def_readonly("candidates", &DiagnosisSummary::candidates)
      .def_readonly("effects", &DiagnosisSummary::effects)
      .def_readonly("baseline_max", &DiagnosisSummary::baseline_max)
      .def_readonly("fitted_max", &DiagnosisSummary::fitted_max)
      .def_readonly("deviation_unit", &DiagnosisSummary::deviation_unit)
      .def_readonly("explanation", &DiagnosisSummary::explanation)
      .def_readonly("observation_source", &DiagnosisSummary::observation_source)
      .def_readonly("scan_points", &DiagnosisSummary::scan_points)
      .def_readonly("observation", &DiagnosisSummary::observation)
      .def_readonly("nominal", &DiagnosisSummary::nominal)
      .def_readonly("fitted", &DiagnosisSummary::fitted)
      .def_readonly("notes", &DiagnosisSummary::notes)
      .def_readonly("seconds", &DiagnosisSummary::seconds)
      .def_readonly("report", &DiagnosisSummary::report);

  m.def(
      "diagnose",
      [](const std::string& case_file, const std::string& report_dir, py::object progress) {
        PythonProgress p(std::move(progress));
        try {
          DiagnosisSummary d =
              cablefit::freecad::DiagnoseRecording(case_file, report_dir, p.Callback());
          p.RethrowIfFailed();
          return d;
        } catch (const cablefit::Cancelled&) {
          p.RethrowIfFailed();  // a cancel from Python surfaces as the Python error
          throw;
        }
      },
      py::arg("case_file"), py::arg("report_dir") = "", py::arg("progress") = py::none(),
      "Diagnose a recording case.json like `cablefit diagnose`; with report_dir also write "
      "diagnosis.json, model curves and report.html there.");
}
