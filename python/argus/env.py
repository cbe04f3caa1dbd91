"""argus.parallel_env: every camera of a scenario as an agent, stepped from Python.

It follows PettingZoo's ParallelEnv API by shape (reset, step, observation_space,
action_space, agents, possible_agents) without depending on PettingZoo:

    env = argus.parallel_env("scenarios/penn_station_emulated.yaml", duration=60)
    observations, infos = env.reset(seed=1)
    while env.agents:
        actions = {agent: policy(observations[agent]) for agent in env.agents}
        observations, rewards, terminations, truncations, infos = env.step(actions)

Observations, per camera: "pose" (pan, tilt, field of view in degrees), "boxes" (one row per
task the camera looks for: task, found, x, y, width, height, score; unused rows zero) and, with
pixel sensing, "image" (the degraded frame, height x width x 3, BGR). Actions: "ptz" (the pose
to slew towards; absent: hold), and optionally "looks" (the tasks to keep looking for; absent:
all the camera was given) and "messages" (a list of (destination, topic, bytes)). Rewards: the
number of the camera's tasks its sensor found in the frame. infos: tick, the operator's queries
and cancels, and the messages delivered. A crashed camera is terminated; the run's end truncates
everyone.
"""

import os
import tempfile

import numpy as np

from . import _argus
from . import spaces

MAX_LOOKS = 8
BOX_COLUMNS = 7


def _agent(camera_id):
    return f"camera_{camera_id}"


class parallel_env:  # noqa: N801  (PettingZoo's name for the constructor)
    metadata = {"name": "argus_parallel_v0", "render_modes": []}

    def __init__(self, scenario, set=None, duration=None, out=None, max_looks=MAX_LOOKS):
        from . import _set_texts
        self._session = _argus.EnvSession(str(scenario), _set_texts(set, duration))
        self._cameras = {c.id: c for c in self._session.cameras()}
        self._out = out
        self._tmp = None
        self.max_looks = max_looks
        self.possible_agents = [_agent(i) for i in sorted(self._cameras)]
        self._by_agent = {_agent(i): i for i in self._cameras}
        self.agents = []
        self.render_mode = None
        self._observation_spaces = {a: self._observation_space(i) for a, i in self._by_agent.items()}
        self._action_spaces = {a: self._action_space(i) for a, i in self._by_agent.items()}

    # --- spaces -----------------------------------------------------------------------------

    def _observation_space(self, camera_id):
        me = self._cameras[camera_id]
        d = {
            "pose": spaces.Box(-360.0, 360.0, (3,), np.float32),
            "boxes": spaces.Box(-1e6, 1e6, (self.max_looks, BOX_COLUMNS), np.float32),
        }
        if self._session.pixels:
            d["image"] = spaces.Box(0, 255, (me.frame.height_px, me.frame.width_px, 3), np.uint8)
        return spaces.Dict(d)

    def _action_space(self, camera_id):
        lim = self._cameras[camera_id].limits
        low = [lim.pan.min_deg, lim.tilt.min_deg, lim.field_of_view.min_deg]
        high = [lim.pan.max_deg, lim.tilt.max_deg, lim.field_of_view.max_deg]
        return spaces.Dict({"ptz": spaces.Box(low, high, (3,), np.float32)})

    def observation_space(self, agent):
        return self._observation_spaces[agent]

    def action_space(self, agent):
        return self._action_spaces[agent]

    # --- stepping ---------------------------------------------------------------------------

    def reset(self, seed=None, options=None):
        out = (options or {}).get("out", self._out)
        if out is None:
            if self._tmp is None:
                self._tmp = tempfile.TemporaryDirectory(prefix="argus-env-")
            out = self._tmp.name
        os.makedirs(out, exist_ok=True)
        self.output_dir = out
        for space in self._action_spaces.values():
            space.seed(seed)
        c = self._session.reset(seed, out)
        self._raise_on_error(c)
        self.agents = [_agent(i) for i in sorted(c["inputs"])]
        observations, infos = {}, {}
        for camera_id, inp in c["inputs"].items():
            observations[_agent(camera_id)], infos[_agent(camera_id)] = self._observe(camera_id, inp)
        return observations, infos

    def step(self, actions):
        native = {}
        for agent, action in (actions or {}).items():
            if agent not in self._by_agent:
                raise KeyError(f"no agent named {agent!r} (agents: {', '.join(self.possible_agents)})")
            native[self._by_agent[agent]] = self._action(action)
        before = list(self.agents)
        c = self._session.step(native)
        self._raise_on_error(c)
        observations, rewards, terminations, truncations, infos = {}, {}, {}, {}, {}
        stepped = {_agent(i): inp for i, inp in c["inputs"].items()}
        for agent, inp in stepped.items():
            observations[agent], infos[agent] = self._observe(self._by_agent[agent], inp)
            rewards[agent] = float(sum(1 for look in inp.looks if look.found))
            terminations[agent] = False
            truncations[agent] = False
        # At the run's end every node goes: that is a truncation, not a crash.
        for camera_id in [] if c["finished"] else c["gone"]:
            agent = _agent(camera_id)
            if agent in before and agent not in stepped:
                observations[agent] = self._empty_observation(camera_id)
                rewards[agent], terminations[agent], truncations[agent] = 0.0, True, False
                infos[agent] = {"tick": c["tick"], "crashed": True}
        if c["finished"]:
            for agent in before:
                if agent not in observations:
                    observations[agent] = self._empty_observation(self._by_agent[agent])
                    rewards[agent], infos[agent] = 0.0, {"tick": c["tick"]}
                terminations.setdefault(agent, False)
                truncations[agent] = not terminations[agent]
            self.agents = []
        else:
            self.agents = sorted(stepped, key=lambda a: self._by_agent[a])
        return observations, rewards, terminations, truncations, infos

    def close(self):
        self._session.close()
        self.agents = []
        if self._tmp is not None:
            self._tmp.cleanup()
            self._tmp = None

    def __del__(self):
        try:
            self.close()
        except Exception:  # noqa: BLE001  (interpreter shutdown)
            pass

    # --- conversions ------------------------------------------------------------------------

    def _raise_on_error(self, c):
        if c["finished"] and c["error"]:
            raise RuntimeError(f"the run failed: {c['error']}")

    def _empty_observation(self, camera_id):
        space = self._observation_spaces[_agent(camera_id)]
        return {k: np.zeros(s.shape, s.dtype) for k, s in space.spaces.items()}

    def _observe(self, camera_id, inp):
        pose = inp.pose
        obs = {
            "pose": np.array([pose.pan_deg, pose.tilt_deg, pose.field_of_view_deg], np.float32),
            "boxes": np.zeros((self.max_looks, BOX_COLUMNS), np.float32),
        }
        for row, look in enumerate(inp.looks[: self.max_looks]):
            b = look.box
            obs["boxes"][row] = (look.task, float(look.found), b.x, b.y, b.width, b.height,
                                 look.score)
        if self._session.pixels:
            image = inp.image
            if image is None:  # no frame this tick (a failed rendering)
                frame = self._cameras[camera_id].frame
                image = np.zeros((frame.height_px, frame.width_px, 3), np.uint8)
            obs["image"] = image
        info = {
            "tick": inp.tick,
            "sensed": inp.sensed,
            "queries": [(q.task.task, (q.box.x, q.box.y, q.box.width, q.box.height))
                        for q in inp.queries],
            "cancels": list(inp.cancels),
            "messages": [(m.origin, m.kind, m.task, m.topic, m.body) for m in inp.messages],
        }
        return obs, info

    @staticmethod
    def _action(action):
        a = _argus.EnvAction()
        if action is None:
            return a
        ptz = action.get("ptz")
        if ptz is not None:
            pan, tilt, fov = (float(v) for v in np.asarray(ptz).reshape(3))
            a.command = _argus.Pose(pan, tilt, fov)
        if action.get("looks") is not None:
            a.looks = [int(t) for t in action["looks"]]
        for destination, topic, body in action.get("messages", ()):
            a.send(int(destination), str(topic), bytes(body))
        return a
