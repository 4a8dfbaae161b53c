# The task panel of "Sweep motion" (GUI only): a slider over the motion's poses puts the swept
# cables at that pose (motion.Sweep.show) and a label says what the pose is; Play steps through
# the poses on a timer. Closing the panel puts the relaxed shapes back.
import FreeCADGui
from PySide import QtCore, QtGui

PLAY_INTERVAL_MS = 150  # per pose: a 31-pose sweep plays in under 5 s


class MotionPanel:
    def __init__(self, sweep):
        self.sweep = sweep
        self.form = QtGui.QWidget()
        self.form.setWindowTitle("Sweep motion")
        layout = QtGui.QVBoxLayout(self.form)
        self.slider = QtGui.QSlider(QtCore.Qt.Horizontal)
        self.slider.setRange(0, sweep.pose_count - 1)
        self.slider.setTickPosition(QtGui.QSlider.TicksBelow)
        self.slider.setTickInterval(1)
        self.label = QtGui.QLabel()
        self.label.setWordWrap(True)
        self.label.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        self.play_button = QtGui.QPushButton("Play")
        layout.addWidget(self.slider)
        layout.addWidget(self.label)
        layout.addWidget(self.play_button)
        layout.addStretch()
        self.timer = QtCore.QTimer(self.form)
        self.timer.setInterval(PLAY_INTERVAL_MS)
        self.timer.timeout.connect(self.step)
        self.slider.valueChanged.connect(self.show_pose)
        self.play_button.clicked.connect(self.toggle_play)
        self.show_pose(0)

    def show_pose(self, k):
        self.sweep.show(k)
        self.label.setText(self.sweep.describe(k))
        FreeCADGui.updateGui()

    def step(self):
        k = self.slider.value() + 1
        if k >= self.sweep.pose_count:
            self.stop()
        else:
            self.slider.setValue(k)

    def toggle_play(self):
        if self.timer.isActive():
            self.stop()
            return
        if self.slider.value() >= self.sweep.pose_count - 1:
            self.slider.setValue(0)
        self.play_button.setText("Stop")
        self.timer.start()

    def stop(self):
        self.timer.stop()
        self.play_button.setText("Play")

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def reject(self):
        self.stop()
        self.sweep.restore()
        FreeCADGui.Control.closeDialog()
        return True

    def accept(self):
        return self.reject()
