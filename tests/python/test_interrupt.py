"""Ctrl-C stops every long Rust call within a fraction of a second (``KeyboardInterrupt``):
batches, path batches, scenes, a calendar's construction and updates, ``simulate`` (also
with a progress bar) and ``simulate_shots`` (between shots).

Each call runs in a child process that sends itself SIGINT half a second in; uninterrupted,
each would run for seconds to minutes here (measured on this project's 2-core machine: the
scene over 12,000 clustered balls about 17 s, the calendar of 10⁶ friction balls 3 s, the
batches 2–3 s; the parallel calls on two threads, as here, whatever the cores), so a
``KeyboardInterrupt`` that comes soon after the signal comes from the call stopping, not
from its end."""

import os
import subprocess
import sys
import textwrap

import pytest

SETUP = """
import numpy as np
import ballcollide as bc
rng = np.random.default_rng(1)
"""

# Each: the data (built before the timer starts), then the call.
CALLS = {
    "collision_times": (
        # Pairs at 5e118 with friction: each costs about 2 µs (long windows).
        "n = 2_000_000\n"
        "pa, pb = rng.uniform(-1, 1, (n, 2)), rng.uniform(-1, 1, (n, 2))\n"
        "va, vb = rng.normal(size=(n, 2)) * 5e118, rng.normal(size=(n, 2)) * 5e118",
        "bc.collision_times(pa, va, 1409.0, pb, vb, 1409.0, 0.03, num_threads=2)",
    ),
    "path_collision_times": (
        "n = 2_000_000\n"
        "start = np.zeros((n, 1))\n"
        "pa, pb = rng.uniform(-1, 1, (n, 1, 2)), rng.uniform(-1, 1, (n, 1, 2))\n"
        "va, vb = rng.normal(size=(n, 1, 2)) * 5e118, rng.normal(size=(n, 1, 2)) * 5e118\n"
        "acc = rng.normal(size=(n, 1, 2)) * 1409.0",
        "bc.path_collision_times(start, pa, va, acc, start, pb, vb, -acc, 0.03, num_threads=2)",
    ),
    "path_geometry_times": (
        # 300,000 balls moving for ever among 120 objects: about 5 s on two threads.
        "n, m = 300_000, 40\n"
        "start = np.zeros((n, 1))\n"
        "pos, vel = rng.uniform(0, 1, (n, 1, 2)), rng.normal(size=(n, 1, 2))\n"
        "acc = rng.normal(size=(n, 1, 2)) * 0.5\n"
        "segments = rng.uniform(0, 1, (m, 2, 2))\n"
        "discs = np.c_[rng.uniform(0, 1, (m, 2)), np.full(m, 0.01)]",
        "bc.path_geometry_times(start, pos, vel, acc, 0.03, segments=segments, circles=discs,"
        " targets=discs, num_threads=2)",
    ),
    "first_contacts": (
        "pos = rng.uniform(0, 1e-3, (12_000, 2))\nvel = rng.normal(size=(12_000, 2))",
        "bc.first_contacts(pos, vel, 0.0, 1e-6, num_threads=2)",
    ),
    "CollisionSchedule.from_balls": (
        "pos = rng.uniform(0, 1, (1_000_000, 2))\nvel = rng.normal(size=(1_000_000, 2))",
        "bc.CollisionSchedule.from_balls(pos, vel, 0.1, 1e-4)",
    ),
    "CollisionSchedule.update_balls": (
        # Every ball of a 10⁶-ball calendar given a new velocity: about 5 s (it looked at no
        # signal before, and held the GIL).
        "pos = rng.uniform(0, 1, (1_000_000, 2))\nvel = rng.normal(size=(1_000_000, 2))\n"
        "s = bc.CollisionSchedule.from_balls(pos, vel, 0.1, 1e-4)\n"
        "indices = np.arange(1_000_000)",
        "s.update_balls(indices, 0.0, pos, -vel, 0.1)",
    ),
    "CollisionSchedule.update": (
        "n = 1_000_000\nstart = np.zeros((n, 1))\npos = rng.uniform(0, 1, (n, 1, 2))\n"
        "vel = rng.normal(size=(n, 1, 2))\nacc = np.zeros((n, 1, 2))\n"
        "s = bc.CollisionSchedule(start, pos, vel, acc, 1e-4)\nindices = np.arange(n)",
        "s.update(indices, start, pos, -vel, acc)",
    ),
    "simulate_shots": (
        # 300,000 billiard shots, each a ball struck at a rail: about 15 µs a shot.
        "n = 300_000\n"
        "rail = [[0.0, 1.0, 1.0, 1.0, 0.036576, 0.0]]\n"
        "rvw = np.zeros((n, 3, 3)); rvw[:, 0] = [0.5, 0.5, 0.028575]\n"
        "params = [[0.170097, 0.028575, 0.2, 0.01, 4 / 9, 0.05, 0.95, 0.85, 0.2, 9.81]] * n\n"
        "cue = [[1.5, 90.0, 0.0, 0.0, 0.25, 0.567, 0.0056699, 0.0106045]] * n",
        "bc.simulate_shots([(rail, [], [])], np.zeros(n), np.arange(n + 1), rvw, np.zeros(n),"
        " params, np.zeros(n), cue, num_threads=2)",
    ),
    "simulate": (
        "pass",
        "bc.simulate([[0.5, 0.5]], [[1, 0.3]], 0.0, 0.1, box=([0, 0], [1, 2]), t_end=1e12)",
    ),
}


# With a progress bar (a callable here), moved on from the same looks as the signals.
CALLS.update(
    {
        f"{name} with progress": (data, call[:-1] + ", progress=lambda n: None)")
        for name, (data, call) in list(CALLS.items())
        if name in ("collision_times", "path_collision_times", "path_geometry_times", "simulate")
    }
)


@pytest.mark.parametrize("name", list(CALLS))
def test_ctrl_c_stops_a_long_call_within_a_fraction_of_a_second(name):
    data, call = CALLS[name]
    code = (
        SETUP
        + data
        + "\n"
        + textwrap.dedent(
            f"""
        import os, signal, threading, time
        # Python's own Ctrl-C handler, whatever the parent left: a shell runs background
        # jobs with SIGINT ignored, and Python then installs none.
        signal.signal(signal.SIGINT, signal.default_int_handler)
        sent = []
        def interrupt():
            sent.append(time.perf_counter())
            os.kill(os.getpid(), signal.SIGINT)
        threading.Timer(0.5, interrupt).start()
        began = time.perf_counter()
        try:
            {call}
            print("ended")
        except KeyboardInterrupt:
            # How late the signal came (a call holding the GIL delays the timer's thread
            # until it ends), and from it to the exception.
            print(f"interrupted {{sent[0] - began:.3f}} {{time.perf_counter() - sent[0]:.3f}}")
        """
        )
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=300, env=os.environ
    )
    assert out.returncode == 0, out.stderr
    kind, *seconds = out.stdout.split()
    assert kind == "interrupted", f"{name} ended before the signal"
    # The signal sent about 0.5 s into the call (not held back until its end), and from it to
    # the exception: the call looks for it every 0.05 s (a loaded machine may take longer to
    # schedule the process).
    late, after = map(float, seconds)
    assert late < 2.0 and after < 2.0, seconds
