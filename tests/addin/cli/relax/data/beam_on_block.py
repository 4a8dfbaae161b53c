# Generates tests/addin/cli/relax/data/beam_on_block.step (run with freecadcmd): a straight 0.5 m
# cable, 5 mm diameter, along x at z = 50 mm, over a 2 mm wide block under its mid-span whose
# top lies half the free clamped-clamped sag (EI 0.05 N m^2, 0.05 kg/m) below the cable.
import FreeCAD, Part, Import
from FreeCAD import Vector
L, d, ei, q = 0.5, 0.005, 0.05, 0.05 * 9.81
w_free = q * L ** 4 / (384 * ei)
top = 50.0 - d / 2 * 1000 - 0.5 * w_free * 1000
doc = FreeCAD.newDocument("beam_on_block")
path = Part.makeLine(Vector(100, 200, 50), Vector(600, 200, 50))
circle = Part.makeCircle(d / 2 * 1000, Vector(100, 200, 50), Vector(1, 0, 0))
cable = doc.addObject("Part::Feature", "cable")
cable.Shape = Part.Wire(path).makePipeShell([Part.Wire(circle)], True, False)
block = doc.addObject("Part::Feature", "block")
block.Shape = Part.makeBox(2, 100, 20, Vector(349, 150, top - 20))
Import.export([cable, block], "beam_on_block.step")
