# The harness.json motion in FreeCAD: a harness file relaxed and swept as `cablefit relax --config`
# does (engine.relax_file: the sweep runs inside the same native call), then every swept cable's
# object shown at any pose with the tube cablefit writes for that pose (engine.tube_shape). No GUI
# here: the task panel (motion_panel.py) and the headless tests drive a Sweep alike.
import math
import shutil
import tempfile

import FreeCAD

from . import engine

MM = engine.MM


def sweep_file(path, config, doc, progress=None):
    """Relaxes `path` with `config` (a harness.json with a "motion") into a group of `doc`, as
    engine.relax_file does, and returns the Sweep over its poses. Raises ValueError when the
    harness.json has no motion or nothing could be swept (the problems say why)."""
    relaxation, group = engine.relax_file(path, doc, config, progress)
    m = relaxation.motion
    if m is None:
        raise ValueError("%s has no \"motion\": nothing to sweep" % (config or "no harness.json"))
    for problem in m.problems:
        FreeCAD.Console.PrintWarning("cablefit: motion: %s\n" % problem)
    if not m.cables:
        raise ValueError("motion '%s' moves no cable that could be swept: %s" %
                         (m.name, "; ".join(m.problems) or "no moving support"))
    return Sweep(relaxation, group)


class Sweep:
    """The poses of a relaxed file's motion, shown on the objects of its group."""

    def __init__(self, relaxation, group):
        self.relaxation = relaxation
        self.motion = relaxation.motion
        self.group = group
        # engine.relax_file adds one object per relaxed cable, in the relaxation's order.
        self.objects = [group.Group[c.cable] for c in self.motion.cables]
        self._relaxed = [o.Shape.copy() for o in self.objects]
        self._shapes = {}  # (swept cable, pose) -> shape: each pose's tube is written once
        self._scratch = tempfile.mkdtemp(prefix="cablefit-motion-")
        self.pose = -1

    @property
    def pose_count(self):
        return len(self.motion.q)

    def pose_shape(self, i, k):
        """Swept cable `i`'s shape at pose `k` (mm); None when its sweep stopped before."""
        swept = self.motion.cables[i]
        if k >= len(swept.poses):
            return None
        if (i, k) not in self._shapes:
            try:
                shape = engine.tube_shape(self.relaxation, swept.cable, self._scratch, k)
            except ValueError:  # no tube for this cable's poses (a flat cable): its centreline
                shape = engine.polyline_shape(swept.poses[k].centreline)
            self._shapes[(i, k)] = shape
        return self._shapes[(i, k)]

    def show(self, k):
        """Puts every swept cable's object at pose `k` (one that stopped earlier stays at its
        last pose)."""
        if not 0 <= k < self.pose_count:
            raise ValueError("pose %d of %d" % (k, self.pose_count))
        for i, o in enumerate(self.objects):
            solved = len(self.motion.cables[i].poses)
            if solved:
                o.Shape = self.pose_shape(i, min(k, solved - 1))
        self.pose = k

    def restore(self):
        """The relaxed shapes back, the intermediate files gone."""
        for o, shape in zip(self.objects, self._relaxed):
            o.Shape = shape
        self.pose = -1
        shutil.rmtree(self._scratch, ignore_errors=True)

    def q_text(self, k):
        q = self.motion.q[k]
        if self.motion.unit == "rad":
            return "%.1f deg" % math.degrees(q)
        if self.motion.unit == "pose":  # a list of poses: q counts them, fractions between
            return "listed pose %g" % q
        return "%.1f mm" % (q * MM)

    def describe(self, k):
        """What pose `k` is: the parameter, then per swept cable its measures, one line each."""
        head = "pose %d of %d: %s %s" % (k + 1, self.pose_count, self.motion.name, self.q_text(k))
        return "\n".join([head] + [_pose_line(swept, k) for swept in self.motion.cables])


def _pose_line(swept, k):
    if k >= len(swept.poses):
        return "%s: not solved at this pose (%s)" % (swept.name, swept.message or "sweep stopped")
    p = swept.poses[k]
    bend = ("straight" if not math.isfinite(p.min_bend_radius)
            else "%.1f mm%s" % (p.min_bend_radius * MM, " (TOO TIGHT)" if p.bend_flag else ""))
    if swept.branch_lost_pose >= 0 and k >= swept.branch_lost_pose:
        state = "BRANCH LOST at pose %d" % (swept.branch_lost_pose + 1)
    else:
        state = "stable" if p.stable else "UNSTABLE"
    if not p.converged:
        state += ", not converged"
    line = "%s: min bend radius %s, max tension %.3g N, %s" % (swept.name, bend, p.max_tension,
                                                             state)
    if p.clearance_to:
        short = 0 < p.clearance_required and p.clearance < p.clearance_required
        line += ", least clearance %.1f mm to %s%s" % (p.clearance * MM, p.clearance_to,
                                                        " (CLEARANCE)" if short else "")
    return line
