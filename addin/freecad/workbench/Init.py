# Cablefit workbench, loaded by FreeCAD at start-up also headless (freecadcmd): nothing to set up
# here. The Cable objects' code (cablefit_workbench) is imported from this folder, which FreeCAD
# puts on sys.path, when a document holding them is opened.
