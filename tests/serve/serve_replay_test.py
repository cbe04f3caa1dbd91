"""A scripted live run, replayed: the operator's commands of `argus serve` (DIR/commands.yaml),
given to `argus run --commands`, give a byte-identical event log.

  python3 serve_replay_test.py ARGUS SCENARIO OUT
"""
import filecmp
import os
import shutil
import subprocess
import sys

from serve_session import Serve


def main(argus, scenario, out, *serve_options, while_tasked=None):
    """The scripted live run and its replay; `serve_options` go to `argus serve`, and
    `while_tasked(serve, camera)`, when given, runs once the clicked task is issued."""
    shutil.rmtree(out, ignore_errors=True)
    live = os.path.join(out, "live")
    serve = Serve(argus, scenario, live, "--speed", "2", "--duration", "16s", "--threads", "2",
                  *serve_options)
    try:
        serve.wait_tick(20)
        camera, x, y = serve.pause_on_someone()
        known = {t["task"] for t in serve.state()["tasks"]}
        assert serve.command(command="task", camera=camera, pixel=[x, y])[0] == 202
        victim = 4 if camera != 4 else 3
        assert serve.command(command="crash", camera=victim)[0] == 202
        assert serve.command(command="cut", camera=1, peer=2)[0] == 202
        serve.pace(paused=False)
        tick = serve.state()["tick"]
        task = serve.new_task(known)
        if while_tasked:
            while_tasked(serve, camera)
        serve.wait_tick(tick + 30)
        assert serve.command(command="cancel", task=task)[0] == 202
        assert serve.command(command="cancel", task=7)[0] == 202  # refused at its tick
        assert serve.command(command="heal", camera=1, peer=2)[0] == 202
        serve.wait_tick(tick + 45)
        assert serve.command(command="recover", camera=victim)[0] == 202
        serve.finish()
    finally:
        serve.kill()
    commands = open(os.path.join(live, "commands.yaml")).read()
    print(commands)
    for wanted in ("command: task", "command: crash", "command: cut",
                   "command: cancel, task: %d" % task,
                   "command: heal", "command: recover"):
        assert wanted in commands, "commands.yaml lacks " + wanted
    assert "task: 7" not in commands, "a refused cancellation was recorded"
    events = open(os.path.join(live, "events.jsonl")).read()
    for wanted in ('"kind":"task_issued","task":%d,"by":"pixel"' % task,
                   '"kind":"task_cancelled","task":%d' % task,
                   '"fault":"link_cut","camera":1,"peer":2', '"kind":"node_recovered","camera":'):
        assert wanted in events, "events.jsonl lacks " + wanted
    replay = os.path.join(out, "replay")
    subprocess.run([argus, "run", os.path.join(live, "scenario.yaml"), "--commands",
                    os.path.join(live, "commands.yaml"), "--out", replay, "--threads", "1",
                    "--no-progress"], check=True, stdout=subprocess.DEVNULL)
    same = filecmp.cmp(os.path.join(live, "events.jsonl"), os.path.join(replay, "events.jsonl"),
                       shallow=False)
    assert same, "the replay's events.jsonl differs from the live run's"
    print("replay: events.jsonl byte-identical (%d events)" % events.count("\n"))


if __name__ == "__main__":
    main(*sys.argv[1:4])
