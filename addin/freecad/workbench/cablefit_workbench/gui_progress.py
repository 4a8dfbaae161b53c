# FreeCAD's progress indicator as the C++ solve's progress callback: the status bar shows the
# stage, Esc cancels (FreeCAD's sequencer raises on next(True) once the user aborted), and the
# event loop runs between steps so the window repaints during a long solve.
import FreeCAD

from . import engine

STEPS = 1000


class ProgressBar:
    def __init__(self, title):
        self._bar = FreeCAD.Base.ProgressIndicator()
        self._bar.start(title, STEPS)
        self._done = 0
        self._open = True

    def __call__(self, fraction, stage):
        if not self._open:
            return False
        target = min(STEPS, int(fraction * STEPS))
        try:
            while self._done < target:
                self._bar.next(True)
                self._done += 1
            if FreeCAD.GuiUp:
                import FreeCADGui
                FreeCADGui.updateGui()
        except Exception:  # the sequencer's abort (Esc)
            self.close()
            raise engine.Cancelled(stage)
        if fraction >= 1.0:
            self.close()
        return True

    def close(self):
        if self._open:
            self._open = False
            self._bar.stop()

    def __del__(self):
        self.close()
