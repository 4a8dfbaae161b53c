# Cablefit workbench (GUI): cables as physics inside FreeCAD. The commands live in
# cablefit_workbench.commands; this file only declares the workbench, its toolbar and menu.
import os

import FreeCADGui


class CablefitWorkbench(FreeCADGui.Workbench):
    MenuText = "Cablefit"
    ToolTip = "Cables and hoses relaxed under gravity (Kirchhoff rods), deviation colours, " \
              "recording diagnosis"

    def __init__(self):
        import cablefit_workbench
        self.__class__.Icon = os.path.join(os.path.dirname(cablefit_workbench.__file__), "..",
                                           "Resources", "icons", "cablefit_workbench.svg")

    def Initialize(self):
        from cablefit_workbench import commands
        names = commands.register()
        self.appendToolbar("Cablefit", names)
        self.appendMenu("Cablefit", names)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(CablefitWorkbench())
