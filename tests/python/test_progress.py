"""``progress=`` on the long calls: the batches (``collision_times``,
``path_collision_times``, ``path_geometry_times``) and the calendar's construction
(``CollisionSchedule``, ``CollisionSchedule.from_balls``: balls) count the items of each chunk
they finish, and a bar, a tqdm bar or a callable is moved on to that count while they run; the
answers do not depend on it. (``simulate``'s bar: test_simulate_progress.py; Ctrl-C with a bar:
test_interrupt.py.)"""

import sys

import numpy as np
import pytest

import ballcollide as bc

RNG = np.random.default_rng(7)


def pairs(n):
    pa, pb = RNG.uniform(-1, 1, (n, 2)), RNG.uniform(-1, 1, (n, 2))
    va, vb = RNG.normal(size=(n, 2)), RNG.normal(size=(n, 2))
    return pa, va, 0.5, pb, vb, 0.3, 0.05


def path_pairs(n):
    start = np.zeros((n, 1))
    pa, pb = RNG.uniform(-1, 1, (n, 1, 2)), RNG.uniform(-1, 1, (n, 1, 2))
    va, vb = RNG.normal(size=(n, 1, 2)), RNG.normal(size=(n, 1, 2))
    acc = RNG.normal(size=(n, 1, 2)) * 0.5
    return start, pa, va, acc, start, pb, vb, -acc, 0.05


def table_paths(n):
    start = np.zeros((n, 1))
    pos, vel = RNG.uniform(0, 1, (n, 1, 2)), RNG.normal(size=(n, 1, 2))
    acc = RNG.normal(size=(n, 1, 2)) * 0.5
    return start, pos, vel, acc, 0.01


OBJECTS = {
    "segments": RNG.uniform(0, 1, (5, 2, 2)),
    "circles": np.c_[RNG.uniform(0, 1, (3, 2)), np.full(3, 0.02)],
    "targets": np.c_[RNG.uniform(0, 1, (3, 2)), np.full(3, 0.02)],
}

CALLS = {
    "collision_times": (bc.collision_times, pairs, {}),
    "path_collision_times": (bc.path_collision_times, path_pairs, {}),
    "path_geometry_times": (bc.path_geometry_times, table_paths, OBJECTS),
}


class Bar:
    """A tqdm-like bar that records what it is shown."""

    def __init__(self):
        self.n, self.updates, self.closed = 0, 0, False

    def update(self, n):
        assert n > 0
        self.n += n
        self.updates += 1

    def close(self):
        self.closed = True


def same(a, b):
    for x, y in zip(a if isinstance(a, tuple) else (a,), b if isinstance(b, tuple) else (b,)):
        np.testing.assert_array_equal(x, y)


@pytest.mark.parametrize("name", list(CALLS))
# Inline (a few pairs), released, and watched (chunks on threads) without a bar.
@pytest.mark.parametrize("n", [0, 5, 3000, 200_000])
@pytest.mark.parametrize("threads", [1, None])
def test_a_callable_is_shown_every_item_once_and_changes_nothing(name, n, threads):
    call, data, kwargs = CALLS[name]
    args = data(n)
    plain = call(*args, **kwargs, num_threads=threads)
    shown = []
    counted = call(*args, **kwargs, num_threads=threads, progress=shown.append)
    same(plain, counted)
    assert sum(shown) == n
    assert all(k > 0 for k in shown)


@pytest.mark.parametrize("name", list(CALLS))
def test_a_bar_is_moved_on_to_the_end_and_closed(name):
    call, data, kwargs = CALLS[name]
    args = data(100_000)
    bar = Bar()
    same(call(*args, **kwargs, progress=bar), call(*args, **kwargs))
    assert bar.closed and bar.n == 100_000 and bar.updates >= 1


@pytest.mark.parametrize("name", list(CALLS))
def test_progress_true_uses_tqdm(name, capsys):
    # tqdm is one of the development tools (requirements-dev.txt): no skip.
    import tqdm  # noqa: F401

    call, data, kwargs = CALLS[name]
    args = data(5000)
    same(call(*args, **kwargs, progress=True), call(*args, **kwargs))
    assert "5000/5000" in capsys.readouterr().err


def test_progress_true_without_tqdm_is_an_import_error_naming_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm", None)  # `import tqdm` raises ImportError
    for call, data, kwargs in CALLS.values():
        with pytest.raises(ImportError, match=r"^progress: progress=True needs tqdm"):
            call(*data(10), **kwargs, progress=True)
    with pytest.raises(ImportError, match=r"^progress: "):
        bc.simulate(
            [[0.5, 0.5]], [[1, 0]], 0.0, 0.1, box=([0, 0], [1, 1]), t_end=1.0, progress=True
        )
    # False and None need no tqdm.
    for call, data, kwargs in CALLS.values():
        call(*data(10), **kwargs, progress=False)


class NoClose:
    def update(self, n):
        pass


@pytest.mark.parametrize("name", list(CALLS))
@pytest.mark.parametrize("progress", [3, "yes", object(), np.bool_(True), NoClose()])
def test_a_progress_that_is_not_a_bar_is_refused_naming_it(name, progress):
    call, data, kwargs = CALLS[name]
    with pytest.raises(TypeError, match=r"^progress: "):
        call(*data(10), **kwargs, progress=progress)


@pytest.mark.parametrize("name", list(CALLS))
def test_an_error_of_the_callable_stops_the_call_and_is_raised(name):
    call, data, kwargs = CALLS[name]

    def fails(n):
        raise RuntimeError("no more")

    with pytest.raises(RuntimeError, match="no more"):
        call(*data(20_000), **kwargs, progress=fails)


def test_a_bar_is_closed_when_the_call_fails():
    pa, va, fa, pb, vb, fb, r = pairs(50_000)
    va[30_000, 0] = np.nan
    bar = Bar()
    with pytest.raises(bc.InputError, match=r"^vel_a\[30000"):
        bc.collision_times(pa, va, fa, pb, vb, fb, r, progress=bar)
    assert bar.closed and bar.n < 50_000


def test_a_bad_out_is_reported_before_the_bar_is_made():
    pa, va, fa, pb, vb, fb, r = pairs(10)
    bar = Bar()
    with pytest.raises(bc.InputError, match=r"^out"):
        bc.collision_times(pa, va, fa, pb, vb, fb, r, out=np.empty(3), progress=bar)
    assert bar.n == 0 and not bar.closed


def friction_balls(n):
    side = max(1, int(np.ceil(np.sqrt(n))))
    grid = np.stack(np.meshgrid(np.arange(side), np.arange(side)), -1).reshape(-1, 2)[:n]
    pos = (grid + 0.5) / side
    return pos, RNG.normal(size=(n, 2)), 0.1, 0.25 / side


def calendar_paths(n):
    pos, vel, _friction, radius = friction_balls(n)
    start = np.zeros((n, 1))
    return start, pos[:, None, :], vel[:, None, :], np.zeros((n, 1, 2)), radius


CALENDARS = {
    "from_balls": (bc.CollisionSchedule.from_balls, friction_balls),
    "CollisionSchedule": (bc.CollisionSchedule, calendar_paths),
}
BOX = ([0, 0], [1, 1])


def first_events(schedule):
    return schedule.next_event(), schedule.next_collision(), len(schedule)


@pytest.mark.parametrize("name", list(CALENDARS))
# Inline (a few balls), released, and watched.
@pytest.mark.parametrize("n", [0, 5, 3000, 20_000])
def test_a_calendar_counts_every_ball_once_and_is_the_same(name, n):
    make, data = CALENDARS[name]
    args = data(n)
    shown = []
    counted = make(*args, box=BOX, progress=shown.append)
    assert first_events(counted) == first_events(make(*args, box=BOX))
    assert sum(shown) == n
    assert all(k > 0 for k in shown)


@pytest.mark.parametrize("name", list(CALENDARS))
def test_a_calendars_bar_is_moved_on_to_the_end_and_closed(name, capsys):
    make, data = CALENDARS[name]
    bar = Bar()
    make(*data(5000), box=BOX, progress=bar)
    assert bar.closed and bar.n == 5000 and bar.updates >= 1
    make(*data(3000), box=BOX, progress=True)  # tqdm: a development tool, no skip
    assert "3000/3000" in capsys.readouterr().err


@pytest.mark.parametrize("name", list(CALENDARS))
@pytest.mark.parametrize("progress", [3, "yes", np.bool_(True), NoClose()])
def test_a_calendars_progress_that_is_not_a_bar_is_refused_naming_it(name, progress):
    make, data = CALENDARS[name]
    with pytest.raises(TypeError, match=r"^progress: "):
        make(*data(10), progress=progress)


@pytest.mark.parametrize("name", list(CALENDARS))
def test_an_error_of_the_callable_stops_the_calendar_and_is_raised(name):
    make, data = CALENDARS[name]

    def fails(n):
        raise RuntimeError("no more")

    with pytest.raises(RuntimeError, match="no more"):
        make(*data(20_000), progress=fails)
