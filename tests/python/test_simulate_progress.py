"""``simulate`` always moves on, ends, and never lets balls sink into each other. The Rust
suite (tests/integration/simulation_progress.rs) has the families of cases; these are the reported
reproducers through the Python call (Ctrl-C: tests/python/test_interrupt.py)."""

import numpy as np
import pytest

import ballcollide as bc

BIG_BOX = ([-4, -4], [4, 4])


def overlap(pos, radius):
    """The deepest overlap of two balls, relative to their contact distance."""
    d = np.linalg.norm(pos[:, None, :] - pos[None, :, :], axis=-1)
    np.fill_diagonal(d, np.inf)
    return max(0.0, float((2 * radius - d.min()) / (2 * radius)))


@pytest.mark.parametrize("restitution", [0.0, 0.001, 0.01, 0.5, 1.0])
@pytest.mark.parametrize("vel", [[[1, 0], [0, 0.05]], [[1, 0.1], [0.5, 0]], [[1, 0.1], [0, 0]]])
def test_a_resting_contact_ends_without_overlap(restitution, vel):
    pos = [[0, 0], [0.5, 0]]
    run = bc.simulate(pos, vel, 1.0, 0.125, box=BIG_BOX, restitution=restitution)
    times = run[0]
    assert len(times) < 10_000
    # Every state along the way: runs cut at several times (a horizon only cuts).
    for t in np.linspace(0, times[-1] + 1, 9)[1:]:
        state = bc.simulate(pos, vel, 1.0, 0.125, box=BIG_BOX, restitution=restitution, t_end=t)
        assert overlap(state[3], 0.125) <= 1e-9, t


@pytest.mark.parametrize("k", [10, 30])
@pytest.mark.parametrize("axis", [0, 1])
def test_a_touching_train_into_a_resting_ball_is_a_newtons_cradle(k, axis):
    # Ten touching balls into a resting one were refused ("keep colliding", 1,705 events at
    # one instant): now each ball passes the motion on once.
    pos = np.zeros((k + 1, 2))
    pos[:k, axis] = 0.25 * np.arange(k)
    pos[k, axis] = 0.25 * (k - 1) + 0.75
    vel = np.zeros((k + 1, 2))
    vel[:k, axis] = 1.0
    box = ([-40, -40], [40, 40])
    run = bc.simulate(pos, vel, 0.0, 0.125, box=box, t_end=3.0)
    assert len(run.times) == k and np.all(run.times == 0.5)
    assert run.vel[0, axis] == 0.0 and np.all(run.vel[1:, axis] == 1.0)


def test_impossible_starts_are_refused_naming_the_balls():
    with pytest.raises(bc.InputError, match=r"^radius\[0\]: the ball must be narrower"):
        bc.simulate([[0.5, 0.5]], [[1, 0.3]], 0.0, 0.5, box=([0, 0], [1, 2]), t_end=1.0)
    with pytest.raises(bc.InputError, match=r"^pos\[0\]: the ball overlaps a wall") as e:
        bc.simulate([[0.2, 0.5], [0.8, 0.5]], [[1, 0], [0, 0]], 0.1, 0.3, box=([0, 0], [1, 1]))
    assert (e.value.argument, e.value.index) == ("pos", 0)
    with pytest.raises(bc.InputError, match=r"^pos\[1\]: .* outside the box"):
        bc.simulate([[0.5, 0.5], [3, 3]], [[0, 0], [0, 0]], 0.1, 0.1, box=([0, 0], [1, 1]))
    with pytest.raises(bc.InputError, match=r"^pos\[1\]: the ball overlaps ball 0"):
        bc.simulate([[0.5, 0.5], [0.6, 0.5]], [[0, 0], [0, 0]], 0.1, 0.1, box=([0, 0], [1, 1]))


@pytest.mark.parametrize("mass", [5e-324, 1e-308, 1e-300, 1.0, 1e300, 1e308])
def test_masses_over_the_float_range_move_on(mass):
    for masses in (mass, [mass, 1.0], [1.0, mass]):
        times, _i, _j, pos, vel, *_ = bc.simulate(
            [[0, 0], [0.5, 0]], [[1, 0.1], [0.5, 0]], 1.0, 0.125, box=BIG_BOX, mass=masses
        )
        assert 1 <= len(times) < 100
        assert np.isfinite(pos).all() and np.isfinite(vel).all()


class Bar:
    """A tqdm-like bar that records what it is shown."""

    def __init__(self):
        self.n, self.closed, self.postfix = 0, False, None

    def update(self, n):
        self.n += n

    def set_postfix(self, **values):
        self.postfix = values

    def close(self):
        self.closed = True


def grid(n=400):
    side = int(np.sqrt(n))
    k = np.arange(n)
    pos = np.stack([(k % side + 0.5) / side, (k // side + 0.5) / side], 1)
    return pos, np.random.default_rng(1).normal(size=(n, 2)), 0.25 / side


def test_a_progress_bar_counts_every_event_and_changes_nothing():
    pos, vel, r = grid()
    plain = bc.simulate(pos, vel, 0.5, r, box=([0, 0], [1, 1]), max_events=20_000)
    bar = Bar()
    shown = bc.simulate(pos, vel, 0.5, r, box=([0, 0], [1, 1]), max_events=20_000, progress=bar)
    assert bar.closed and bar.n == len(plain[0])
    assert bar.postfix["t"] >= plain[0][-1]  # the end of the run
    for a, b in zip(plain, shown):
        np.testing.assert_array_equal(a, b)


def test_progress_true_uses_tqdm():
    # tqdm is one of the development tools (requirements-dev.txt): no skip.
    import tqdm  # noqa: F401

    pos, vel, r = grid(16)
    run = bc.simulate(pos, vel, 0.5, r, box=([0, 0], [1, 1]), max_events=100, progress=True)
    assert len(run[0]) == 100


@pytest.mark.parametrize("progress", [3, "yes", object()])
def test_a_progress_that_is_not_a_bar_is_refused_naming_it(progress):
    pos, vel, r = grid(16)
    with pytest.raises(TypeError, match=r"^progress: "):
        bc.simulate(pos, vel, 0.5, r, box=([0, 0], [1, 1]), max_events=10, progress=progress)


def gas(seed, side=10):
    """side² balls on a grid in the unit box, 0.01 apart, with normal random velocities."""
    k = np.arange(side * side)
    pos = np.stack([(k % side + 0.5) / side, (k // side + 0.5) / side], 1)
    return pos, np.random.default_rng(seed).normal(size=(side * side, 2)), 0.5 / side - 0.005


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("friction", [0.0, 0.2])
def test_a_dense_gas_at_restitution_0_moves_on(seed, friction):
    # Issue 39 audit: 34 of 108 such runs (seeds 0-5, restitution 0, 0.01, 0.1) stopped with
    # "pos[21]: the ball and ball 31 keep colliding at t = 0.0374...: 7401 events at that
    # instant": a pair parted at the least parting speed was parted again by an ulp at each
    # follow-up of the instant, without end.
    pos, vel, r = gas(seed)
    run = bc.simulate(pos, vel, friction, r, box=([0, 0], [1, 1]), restitution=0.0, t_end=1.0)
    times = run[0]
    assert len(times) > 1000 and times[-1] <= 1.0
    assert overlap(run[3], r) <= 1e-9


@pytest.mark.parametrize("e", [-1000, -600, -538, -528, -300, 300, 512, 600, 1000])
@pytest.mark.parametrize(
    "scene",
    [
        # The reported resting contact (restitution 0 with friction), a pressed pair, and
        # two elastic balls: each run at 2^e is the run at 1, every length times 2^e.
        ([[0, 0], [0.5, 0]], [[1, 0.1], [0.5, 0]], 1.0, 0.125, BIG_BOX, 0.0),
        ([[0, 0], [0.5, 0]], [[1, 0], [0, 0.05]], 1.0, 0.125, BIG_BOX, 0.0),
        ([[0, 0], [1, 0.3]], [[1, 0], [0, 0]], 0.0, 0.25, ([-2, -2], [3, 3]), 1.0),
    ],
)
def test_a_run_scaled_by_a_power_of_two_is_the_same_run(e, scene):
    pos, vel, friction, radius, (lo, hi), restitution = scene
    s = 2.0**e

    def run(s):
        box = ([x * s for x in lo], [x * s for x in hi])
        return bc.simulate(
            np.array(pos, float) * s,
            np.array(vel, float) * s,
            friction * s,
            radius * s,
            box=box,
            restitution=restitution,
            t_end=20.0,
            max_events=5_000,
        )

    ref, got = run(1.0), run(s)
    np.testing.assert_array_equal(got.times, ref.times)
    np.testing.assert_array_equal(got.i, ref.i)
    np.testing.assert_array_equal(got.j, ref.j)
    np.testing.assert_array_equal(got.pos, ref.pos * s)
    np.testing.assert_array_equal(got.vel, ref.vel * s)
