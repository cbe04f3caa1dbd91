"""Argus: smart camera networks in virtual reality, from Python.

    import argus
    result = argus.run("scenarios/penn_station_emulated.yaml", seed=3, duration="2 min")
    result["metrics"]["tasks"]

A camera strategy is a subclass of argus.Strategy (docs/strategies.md): named in a scenario as
``controller.strategy: python:MODULE:CLASS``, or passed to argus.run(strategy=Class).
argus.parallel_env steps every camera from Python, as a PettingZoo ParallelEnv does.
"""

import json
import sys

if "_argus" in sys.builtin_module_names:  # inside the argus executable
    import _argus
else:
    # C++ strategy plug-ins (plugin:PATH) take the simulator's symbols from the process, as
    # they do from the argus executable: the extension's must be global.
    import os as _os
    _flags = sys.getdlopenflags()
    sys.setdlopenflags(_flags | _os.RTLD_GLOBAL)
    try:
        from . import _argus
    finally:
        sys.setdlopenflags(_flags)

# The strategy interface's types (Input, Output, Status, Pose, Box, ...), at the package's top.
globals().update({k: getattr(_argus, k) for k in dir(_argus) if not k.startswith("_")})

__version__ = _argus.__version__


class Strategy:
    """A camera strategy: one object per camera node, stepped once per frame.

    Constructed with an argus.StrategyContext (``context.me``: the camera's id, limits, home
    pose and frame size; ``context.tick_s``; ``context.seed``). Override ``step``, and
    ``status`` when the strategy takes tasks; ``plan`` where it wants frames it is not looking
    in. Never called from two threads at once.
    """

    #: Whether operator picks reach step() with the pedestrian's signature taken by the sensor.
    takes_operator_signatures = True

    def __init__(self, context):
        self.context = context
        self.me = context.me

    def plan(self, tick, looking):
        """Whether the node takes a frame at ``tick`` (default: when it is looking)."""
        return looking

    def step(self, inp):
        """One frame: ``inp`` is an argus.Input; return an argus.Output (or None)."""
        raise NotImplementedError(f"{type(self).__name__}.step")

    def status(self):
        """The state after the last step, an argus.Status (default: idle)."""
        return _argus.Status()


class RunFailed(RuntimeError):
    """A run that a strategy ended by raising; ``result`` holds what it wrote up to then."""

    def __init__(self, message, result):
        super().__init__(message)
        self.result = result


def _yaml_value(value):
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "true" if value else "false"
    return json.dumps(value)


def _set_texts(set=None, duration=None, **fields):
    """The KEY=VALUE overrides of `set`, `duration` (seconds, or a text such as "2 min") and
    the named run fields (run.seed=..., given as seed=...) that are not None."""
    texts = [f"{key}={_yaml_value(value)}" for key, value in (set or {}).items()]
    if duration is not None:
        fields["duration"] = duration if isinstance(duration, str) else f"{duration} s"
    texts += [f"run.{key}={_yaml_value(value)}" for key, value in fields.items() if value is not None]
    return texts


def run(scenario, seed=None, set=None, duration=None, strategy=None, out=None, progress=False):
    """Runs ``scenario`` (a YAML file) and returns its metrics, summary and paths.

    seed: run.seed. set: {"network.loss_probability": 0.2, ...}, as ``--set`` does.
    duration: seconds, or a text such as "2 min". strategy: an argus.Strategy subclass for
    every camera. out: the output folder (run.output_dir). Raises ValueError naming the field
    of bad input, and argus.RunFailed when a strategy raised (the run's outputs stay complete
    up to that tick).
    """
    texts = _set_texts(set, duration, seed=None if seed is None else int(seed), output_dir=out)
    result = _argus._run(str(scenario), texts, strategy, bool(progress))
    if result["failure"]:
        raise RunFailed(result["failure"], result)
    return result


def strategies():
    """The strategies a scenario can name now: {name: summary}."""
    return dict(_argus._strategies())


from .env import parallel_env  # noqa: E402
from . import spaces  # noqa: E402,F401
