"""lone_tracker.cpp in Python: the camera the operator tasks follows her alone, centring her in
its frame, and gives up after GIVE_UP_S without a find. No messages.

    PYTHONPATH=examples/strategies argus run scenarios/penn_station_emulated.yaml \\
      --set controller.strategy=python:lone_tracker:LoneTracker

Its event log is the C++ plug-in's, byte for byte (tests/python).
"""

import argus

GIVE_UP_S = 10.0


class LoneTracker(argus.Strategy):
    """The tasked camera follows her alone, centring her (an example in Python)."""

    def __init__(self, context):
        super().__init__(context)
        self.task = None  # (task id, her signature)
        self.last_found = 0

    def step(self, inp):
        out = argus.Output()
        for cancelled in inp.cancels:
            if self.task and self.task[0] == cancelled:
                self.leave("cancelled", out)
        for q in inp.queries:
            if not self.task:
                self.task = (q.task.task, q.task.target)
                self.last_found = inp.tick
                out.event("lone_tracker_started", task=q.task.task)
        for look in inp.looks:
            if not self.task or look.task != self.task[0]:
                continue
            if look.model is not None:  # her colours at this camera's zoom
                self.task = (self.task[0], look.model)
            if look.found:
                self.last_found = inp.tick
                out.command = argus.centring_pose(inp.pose, look.box, self.me.frame, 0.4)
        if self.task and (inp.tick - self.last_found) * self.context.tick_s > GIVE_UP_S:
            self.leave("lost", out)
        if self.task:
            out.look(*self.task)
        return out

    def status(self):
        if not self.task:
            return argus.Status()
        return argus.Status(argus.NodeState.performing_task, self.task[0])

    def leave(self, why, out):
        out.event("lone_tracker_left", task=self.task[0], reason=why)
        self.task = None
        out.command = self.me.home
