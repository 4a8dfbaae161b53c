"""Cablefit FreeCAD workbench: drawn cables made physical by the cablefit C++ code.

Non-GUI API (also used by the headless tests):
  cable.make_cable(route_obj, subelements=(), doc=None) -> Cable object
  cable.add_support(cable, kind="clip", point=None, solid=None)
  cable.relax_harness(doc, progress=None) -> cablefit_native.Relaxation
  colours.colour_cables(cables) -> [DeviationMap objects]
  diagnose.diagnose_recording(case_file, doc=None, report_dir="", progress=None) -> group
  engine.export_report(cables, folder, pictures=True, progress=None) -> report.html path
  engine.export_step(objects, path)
  motion.sweep_file(path, config, doc, progress=None) -> motion.Sweep (show(pose), describe(pose))
"""
