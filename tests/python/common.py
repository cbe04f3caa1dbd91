"""What the Python tests share: paths from the environment CTest sets."""

import json
import os
import shutil

ARGUS = os.environ.get("ARGUS", "argus")
SOURCE = os.environ.get("ARGUS_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
SCRATCH = os.environ.get("SCRATCH", "/tmp/argus-python-tests")
EMULATED = os.path.join(SOURCE, "scenarios", "penn_station_emulated.yaml")
MINIMAL = os.path.join(SOURCE, "scenarios", "minimal.yaml")


def scratch(name):
    path = os.path.join(SCRATCH, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def events(path):
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f]
