# Generates drape_over_edge.step and drape_long.step here (run with freecadcmd): a straight
# cable, 5 mm diameter, lying on a block's top (z = 0) from x = 0 and running past its edge at
# x = 200 mm, 0.5 m and 15 m long; clamped at x = 0 and free at the far end, it drapes over the
# edge (the long one hangs 14.8 m down from it).
import FreeCAD, Part, Import
from FreeCAD import Vector
for name, length in (("drape_over_edge", 500), ("drape_long", 15000)):
    doc = FreeCAD.newDocument(name)
    path = Part.makeLine(Vector(0, 0, 2.5), Vector(length, 0, 2.5))
    circle = Part.makeCircle(2.5, Vector(0, 0, 2.5), Vector(1, 0, 0))
    cable = doc.addObject("Part::Feature", "cable")
    cable.Shape = Part.Wire(path).makePipeShell([Part.Wire(circle)], True, False)
    block = doc.addObject("Part::Feature", "block")
    block.Shape = Part.makeBox(300, 200, 100, Vector(-100, -100, -100))
    Import.export([cable, block], name + ".step")
