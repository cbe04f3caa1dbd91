"""argus.parallel_env against PettingZoo's ParallelEnv contract, checked here (PettingZoo is not
a dependency): agents, keys, spaces, shapes and dtypes, the end of a run, crashes, and the same
seed with the same actions giving the same trajectory."""

import unittest

import numpy as np

import argus
from common import EMULATED, SOURCE

REPLAY_FAULTS = f"{SOURCE}/scenarios/replay_faults.yaml"
NO_RANDOM_CRASH = {"network.node_failure_probability": 0}


def sweep(env, agent, tick):
    """A scripted policy: pan back and forth within the camera's limits."""
    space = env.action_space(agent)["ptz"]
    low, high = space.low, space.high
    phase = (tick % 60) / 60.0
    return {"ptz": (low + (high - low) * np.array([phase, 0.5, 0.5])).astype(np.float32)}


def trajectory(env, seed, steps):
    obs, _ = env.reset(seed=seed)
    out = [obs]
    for tick in range(steps):
        # Camera 7 holds its pose: the operator picks her in its view at 10 s.
        obs, rewards, *_ = env.step({a: sweep(env, a, tick) for a in env.agents
                                     if a != "camera_7"})
        out.append((obs, rewards))
    return out


class ParallelEnvTest(unittest.TestCase):
    def test_contract(self):
        env = argus.parallel_env(EMULATED, duration=2, set=NO_RANDOM_CRASH)
        self.assertEqual(len(env.possible_agents), 16)
        self.assertEqual(env.possible_agents[:3], ["camera_1", "camera_2", "camera_3"])
        obs, infos = env.reset(seed=3)
        self.assertEqual(sorted(env.agents), sorted(env.possible_agents))
        self.assertEqual(obs.keys(), set(env.agents))
        self.assertEqual(infos.keys(), set(env.agents))
        for agent in env.agents:
            space = env.observation_space(agent)
            self.assertEqual(set(obs[agent]), {"pose", "boxes"})
            self.assertEqual(obs[agent]["pose"].dtype, np.float32)
            self.assertEqual(obs[agent]["boxes"].shape, (8, 7))
            self.assertTrue(space.contains(obs[agent]), agent)
            self.assertTrue(env.action_space(agent).contains(env.action_space(agent).sample()))
        steps = 0
        while env.agents:
            agents = list(env.agents)
            actions = {a: env.action_space(a).sample() for a in agents}
            obs, rewards, terminations, truncations, infos = env.step(actions)
            steps += 1
            for d in (obs, rewards, terminations, truncations, infos):
                self.assertEqual(d.keys(), set(agents))
            for a in agents:
                self.assertIsInstance(rewards[a], float)
                self.assertIsInstance(terminations[a], bool)
                self.assertTrue(env.observation_space(a).contains(obs[a]))
        self.assertEqual(steps, 30)  # 2 s at 15 frames a second, the first tick in reset
        self.assertTrue(all(truncations.values()))
        self.assertFalse(any(terminations.values()))
        env.close()

    def test_actions_move_the_heads(self):
        env = argus.parallel_env(EMULATED, duration=3, set=NO_RANDOM_CRASH)
        obs, _ = env.reset(seed=1)
        target = env.action_space("camera_1")["ptz"].low + 10.0
        for _ in range(40):
            obs, *_ = env.step({"camera_1": {"ptz": target}})
        np.testing.assert_allclose(obs["camera_1"]["pose"], target, atol=1e-3)
        env.close()

    def test_same_seed_same_trajectory_and_reset_abandons_a_run(self):
        env = argus.parallel_env(EMULATED, duration=20, set=NO_RANDOM_CRASH)
        env.reset(seed=5)
        for tick in range(10):  # abandoned by the next reset
            env.step({a: sweep(env, a, tick) for a in env.agents})
        a = trajectory(env, 1, 200)  # the task starts at 10 s (tick 150) at camera 7
        b = trajectory(env, 1, 200)
        self.assertGreater(sum(r["camera_7"] for _, r in a[1:]), 0.0)  # the sensor found her
        for x, y in zip(a, b):
            x_obs, y_obs = (x, y) if isinstance(x, dict) else (x[0], y[0])
            for agent in x_obs:
                for key in x_obs[agent]:
                    np.testing.assert_array_equal(x_obs[agent][key], y_obs[agent][key])
            if not isinstance(x, dict):
                self.assertEqual(x[1], y[1])
        env.close()

    def test_pixels_observe_the_frame(self):
        env = argus.parallel_env(REPLAY_FAULTS, duration=1)
        obs, _ = env.reset(seed=17)
        self.assertEqual(env.observation_space("camera_1")["image"].shape, (120, 160, 3))
        obs, *_ = env.step({})
        image = obs["camera_1"]["image"]
        self.assertEqual(image.dtype, np.uint8)
        self.assertEqual(image.shape, (120, 160, 3))
        self.assertGreater(image.std(), 5.0)  # a rendered station, not a blank
        env.close()

    def test_a_crashed_camera_is_terminated(self):
        # replay_faults.yaml crashes camera 2 at 5 s for 3 s, and camera 4 at 9 s for 20 s.
        env = argus.parallel_env(REPLAY_FAULTS, duration=10)
        env.reset(seed=17)
        terminated_at, back_at = {}, {}
        tick = 0
        while env.agents:
            _, _, terminations, _, _ = env.step({})
            tick += 1
            for agent, done in terminations.items():
                if done:
                    terminated_at.setdefault(agent, tick)
            if "camera_2" in terminated_at and "camera_2" in env.agents:
                back_at.setdefault("camera_2", tick)
        self.assertEqual(set(terminated_at), {"camera_2", "camera_4"})
        self.assertAlmostEqual(terminated_at["camera_2"] / 15.0, 5.0, delta=0.2)
        self.assertAlmostEqual(back_at["camera_2"] / 15.0, 8.0, delta=0.2)
        self.assertAlmostEqual(terminated_at["camera_4"] / 15.0, 9.0, delta=0.2)
        env.close()


if __name__ == "__main__":
    unittest.main()
