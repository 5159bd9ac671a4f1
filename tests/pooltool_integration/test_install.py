"""``ballcollide.pooltool``'s switch: install, uninstall, the context manager, the version
check, the lazy import of pooltool, the docs' examples and the errors."""

from __future__ import annotations

import doctest
import subprocess
import sys
import textwrap

import pytest

pt = pytest.importorskip("pooltool")

import numpy as np  # noqa: E402
from pooltool.evolution.event_based import simulate as pt_simulate  # noqa: E402

import ballcollide.pooltool as bcp  # noqa: E402

STOCK = pt_simulate.get_next_ball_ball_collision


def run(code: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def test_importing_ballcollide_does_not_import_pooltool() -> None:
    result = run(
        """
        import sys
        import ballcollide
        import ballcollide.pooltool
        assert "pooltool" not in sys.modules, sorted(m for m in sys.modules if "pooltool" in m)
        print("ok")
        """
    )
    assert result.returncode == 0 and result.stdout == "ok\n", result.stderr


def test_install_swaps_the_pair_loop_and_uninstall_restores_pooltools_own() -> None:
    assert pt_simulate.get_next_ball_ball_collision is STOCK
    bcp.install()
    try:
        assert pt_simulate.get_next_ball_ball_collision is bcp.next_ball_ball_collision
        assert bcp.is_installed()
        bcp.install()  # twice is once
        assert pt_simulate.get_next_ball_ball_collision is bcp.next_ball_ball_collision
    finally:
        bcp.uninstall()
    assert pt_simulate.get_next_ball_ball_collision is STOCK
    assert not bcp.is_installed()
    bcp.uninstall()  # nothing installed: nothing happens
    assert pt_simulate.get_next_ball_ball_collision is STOCK


def test_the_context_manager_uninstalls_on_exit_even_on_error() -> None:
    with pytest.raises(KeyError), bcp.install():
        assert pt_simulate.get_next_ball_ball_collision is bcp.next_ball_ball_collision
        raise KeyError("boom")
    assert pt_simulate.get_next_ball_ball_collision is STOCK


def test_a_nested_install_leaves_the_outer_one_in_force() -> None:
    with bcp.install() as outer:
        with bcp.install() as inner:
            assert not inner.swapped
        assert bcp.is_installed() and outer.swapped
    assert pt_simulate.get_next_ball_ball_collision is STOCK


def test_uninstall_leaves_a_later_replacement_alone() -> None:
    bcp.install()

    def other(shot: object, collision_cache: object) -> object:
        raise AssertionError

    pt_simulate.get_next_ball_ball_collision = other
    try:
        with pytest.raises(RuntimeError, match="replaced by something else"):
            bcp.uninstall()
    finally:
        pt_simulate.get_next_ball_ball_collision = bcp.next_ball_ball_collision
        bcp.uninstall()
    assert pt_simulate.get_next_ball_ball_collision is STOCK


def test_install_refuses_other_pooltool_versions(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(pt, "__version__", "0.5.1")
    with pytest.raises(RuntimeError, match=r"supports pooltool-billiards 0\.6\.0, not 0\.5\.1"):
        bcp.install()
    assert pt_simulate.get_next_ball_ball_collision is STOCK


def test_install_without_pooltool_says_how_to_get_it() -> None:
    result = run(
        """
        import sys
        sys.modules["pooltool"] = None  # as if not installed
        import ballcollide.pooltool as bcp
        try:
            bcp.install()
        except ImportError as e:
            print(e)
        """
    )
    assert result.returncode == 0, result.stderr
    assert "needs pooltool-billiards 0.6.0" in result.stdout
    assert "scripts/install-pooltool" in result.stdout


def test_a_bad_ball_state_is_named_by_its_ball() -> None:
    a = pt.Ball.create("a", xy=(0.5, 0.5))
    b = pt.Ball.create("b", xy=(1.0, 0.5))
    b.state.rvw[1, 0] = np.nan
    b.state.s = 3
    with pytest.raises(ValueError, match=r"ball 'b' \(motion state 3, rvw .*must be finite"):
        bcp.collision_time(a, b)


def test_pocketed_and_resting_balls_never_touch() -> None:
    a = pt.Ball.create("a", xy=(0.5, 0.5))
    b = pt.Ball.create("b", xy=(0.5 + 0.01, 0.5))  # overlapping, both at rest
    assert bcp.collision_time(a, b) == np.inf
    b.state.rvw[1, 0] = -1.0
    b.state.s = 2
    assert bcp.collision_time(a, b) == 0.0  # overlapping and closing in
    b.state.s = 4
    assert bcp.collision_time(a, b) == np.inf


def test_the_module_examples_run() -> None:
    result = doctest.testmod(bcp, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 10 and result.failed == 0
