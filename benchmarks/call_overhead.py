"""What one call of ballcollide costs from Python, on the small inputs of an event loop.

An event-driven simulator asks after every event, often about one pair or a handful. This
measures each public function on such inputs with ``timeit`` (the best and the median of
``--repeats`` short rounds of ``--number`` calls: on shared, loaded cores the best of many
short rounds is the one least disturbed), as a ratio to ``np.hypot(1.0, 2.0)`` on Python
floats timed in the same run: numpy's own cost of one call, which moves with the machine's
load as these do.

- ``collision_time`` on plain Python floats (tuples and lists of floats);
- ``collision_times`` on 16 pairs (float64 arrays, per-pair frictions), with and without
  ``out=``; ``positions_at`` on 16 balls; ``real_roots`` on 16 quartics;
- the scene functions on a pool break (a rack of 15 at rest, the cue ball shot at it).

With Rust available (``cargo``), the same 16 pairs and the same scene are timed from Rust
(``examples/kernel_timing.rs``, ``examples/scene_timing.rs``: the fastest of many single
calls), so that each Python call can be set beside its Rust time.

    python benchmarks/call_overhead.py [--repeats 201] [--number 200] [--no-rust]
"""

from __future__ import annotations

import argparse
import shlex
import subprocess
import tempfile
import timeit
from collections.abc import Callable
from pathlib import Path

import numpy as np

import ballcollide as bc

ROOT = Path(__file__).resolve().parents[1]
R = 0.028575  # pool ball radius, m


def pairs16(seed: int = 1) -> dict[str, np.ndarray]:
    """16 table pairs: A rolling at up to 3 m/s at B near its path, half of the Bs rolling."""
    rng = np.random.default_rng(seed)
    n = 16
    pos_a = rng.uniform(0, 2.5, (n, 2))
    vel_a = rng.uniform(-3, 3, (n, 2))
    pos_b = pos_a + vel_a * rng.uniform(0, 1, (n, 1)) + rng.normal(0, 0.1, (n, 2))
    vel_b = rng.uniform(-1, 1, (n, 2)) * (np.arange(n) % 2)[:, None]
    return {
        "pos_a": pos_a,
        "vel_a": vel_a,
        "friction_a": rng.uniform(0.09, 0.11, n),
        "pos_b": pos_b,
        "vel_b": vel_b,
        "friction_b": rng.uniform(0.09, 0.11, n),
    }


def pool_break() -> dict[str, np.ndarray]:
    """A rack of 15 balls at rest and the cue ball at 3 m/s towards it (16 balls)."""
    d = 2 * R
    rack = [
        (1.9 + row * d * np.sqrt(3) / 2, 0.635 + (k - row / 2) * d)
        for row in range(5)
        for k in range(row + 1)
    ]
    pos = np.array([*rack, (0.635, 0.64)])
    vel = np.zeros_like(pos)
    vel[-1] = (3.0, 0.0)
    return {"pos": pos, "vel": vel, "friction": np.full(16, 0.2), "radius": np.full(16, R)}


def timed(call: Callable[[], object], number: int, repeats: int) -> tuple[float, float]:
    """The best and the median µs per call over ``repeats`` rounds of ``number`` calls."""
    rounds = np.array(timeit.repeat(call, number=number, repeat=repeats)) / number * 1e6
    return float(rounds.min()), float(np.median(rounds))


def rust(example: str, path: Path, *tail: str) -> dict[str, str] | None:
    """Run a Rust timing example; its ``key=value`` fields, or ``None`` (with a message)."""
    cmd = ["cargo", "run", "-q", "--release", "--example", example, "--", str(path), *tail]
    print(f"$ {shlex.join(cmd)}")
    try:
        done = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"# skipped the Rust timing: {e}")
        return None
    print(done.stdout.strip())
    return dict(field.split("=", 1) for field in done.stdout.split())


def write(path: Path, n: int, *arrays: np.ndarray) -> None:
    """``n`` as a little-endian u64, then the arrays as little-endian float64."""
    with path.open("wb") as f:
        f.write(np.uint64(n).astype("<u8").tobytes())
        for a in arrays:
            f.write(np.ascontiguousarray(a, dtype="<f8").tobytes())


def rust_times(p: dict[str, np.ndarray], s: dict[str, np.ndarray]) -> dict[str, float]:
    """µs per call from Rust (the fastest single call) on the same pairs and scene."""
    out: dict[str, float] = {}
    with tempfile.TemporaryDirectory() as tmp:
        pairs_file, scene_file = Path(tmp) / "pairs.bin", Path(tmp) / "scene.bin"
        write(pairs_file, 16, *(p[k] for k in p), np.array([2 * R]))
        write(scene_file, 16, s["pos"], s["vel"], s["friction"], s["radius"])
        kernel = rust("kernel_timing", pairs_file, "1", "20000")
        if kernel is not None:
            out["collision_times (16 pairs)"] = float(kernel["min_ns_per_pair"]) * 16 / 1e3
        scene = rust("scene_timing", scene_file, "20000")
        if scene is not None:
            for name in ("earliest_collision", "first_contacts", "pairwise_collision_times"):
                out[f"{name} (16 balls)"] = float(scene[f"{name}_min_ns"]) / 1e3
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=201, help="timeit rounds (default 201)")
    parser.add_argument("--number", type=int, default=200, help="calls a round (default 200)")
    parser.add_argument("--no-rust", action="store_true", help="skip the Rust timings")
    args = parser.parse_args()

    p, s = pairs16(), pool_break()
    out, centres = np.empty(16), np.empty((16, 2))
    coeffs = np.poly1d([1.0, -10.0, 35.0, -50.0, 24.0]).coeffs[np.newaxis, :].repeat(16, axis=0)
    scene = (s["pos"], s["vel"], s["friction"], s["radius"])
    pairs = tuple(p.values())  # positionally, as a simulator calls it
    calls: dict[str, Callable[[], object]] = {
        "np.hypot(1.0, 2.0)": lambda: np.hypot(1.0, 2.0),
        "collision_time (tuples of floats)": lambda: bc.collision_time(
            (0.0, 0.0), (2.0, 0.0), 0.2, (1.0, 0.0), (0.0, 0.0), 0.2, 0.05715
        ),
        "collision_time (lists of floats)": lambda: bc.collision_time(
            [0.0, 0.0], [2.0, 0.0], 0.2, [1.0, 0.0], [0.0, 0.0], 0.2, 0.05715
        ),
        "collision_times (16 pairs)": lambda: bc.collision_times(*pairs, 2 * R),
        "collision_times (16 pairs, out=)": lambda: bc.collision_times(*pairs, 2 * R, out=out),
        "positions_at (16 balls, out=)": lambda: bc.positions_at(
            p["pos_a"], p["vel_a"], p["friction_a"], 0.5, out=centres
        ),
        "real_roots (16 quartics)": lambda: bc.real_roots(coeffs),
        "earliest_collision (16 balls)": lambda: bc.earliest_collision(*scene),
        "first_contacts (16 balls)": lambda: bc.first_contacts(*scene),
        "pairwise_collision_times (16 balls)": lambda: bc.pairwise_collision_times(*scene),
    }
    print(f"# best and median of {args.repeats} rounds of {args.number} calls, µs per call")
    results = {name: timed(call, args.number, args.repeats) for name, call in calls.items()}
    hypot = results["np.hypot(1.0, 2.0)"][0]
    from_rust = {} if args.no_rust else rust_times(p, s)
    print(f"\n{'call':<38} {'best':>8} {'median':>8} {'× hypot':>8} {'Rust':>8}")
    for name, (best, median) in results.items():
        r = from_rust.get(name)
        rust_text = f"{r:8.3f}" if r is not None else f"{'':>8}"
        print(f"{name:<38} {best:8.3f} {median:8.3f} {best / hypot:8.2f} {rust_text}")
    print("(× hypot: best against best; Rust: the fastest single call on the same data)")


if __name__ == "__main__":
    main()
