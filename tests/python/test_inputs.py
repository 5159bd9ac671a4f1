"""Reading arguments: numbers as Python has them, structured errors, keyword-only options."""

from __future__ import annotations

import pickle
import re
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import ballcollide as bc

PAIR = ([0, 0], [1, 0], 0.0, [1, 0], [0, 0], 0.0, 0.5)  # contact at 0.5


def batch(n: int = 3) -> dict:
    return {
        "pos_a": np.zeros((n, 2)),
        "vel_a": np.tile([1.0, 0.0], (n, 1)),
        "friction_a": 0.0,
        "pos_b": np.tile([1.0, 0.0], (n, 1)),
        "vel_b": np.zeros((n, 2)),
        "friction_b": 0.0,
        "contact_distance": 0.5,
    }


class Real:
    """Not a number type Python knows, but one `float()` accepts."""

    def __float__(self) -> float:
        return 0.5


@pytest.mark.parametrize(
    "radius", [0.5, Fraction(1, 2), Decimal("0.5"), np.float32(0.5), np.float16(0.5), Real()]
)
def test_any_real_number_where_a_number_goes(radius: object) -> None:
    args = list(PAIR)
    args[6] = radius
    assert bc.collision_time(*args) == 0.5
    assert bc.collision_times(**{**batch(), "contact_distance": radius}).tolist() == [0.5] * 3
    # Two balls of that radius, touching and approaching: at once.
    assert bc.earliest_collision([[0, 0], [1, 0]], [[1, 0], [0, 0]], 0, radius) == (0.0, 0, 1)


def test_integers_of_any_size_and_type() -> None:
    # 2**70 fits a float (rounded); numpy ints and Python ints alike.
    far = bc.collision_time([0, 0], [1, 0], 0, [2**70, 0], [0, 0], 0, 1, t_max=2**80)
    assert far == float(2**70) - 1
    assert bc.collision_time(*PAIR[:2], np.int8(0), *PAIR[3:]) == 0.5
    assert bc.collision_time(*PAIR, t_max=np.uint64(1)) == 0.5
    t = bc.collision_times(**{**batch(), "t_max": Fraction(1, 3)})
    assert np.isinf(t).all()  # contact at 0.5 ≥ 1/3


@pytest.mark.parametrize("flag", [True, np.bool_(False), np.array(True)])
def test_booleans_are_not_numbers(flag: object) -> None:
    args = list(PAIR)
    args[2] = flag
    with pytest.raises(TypeError, match=r"^friction_a: expected real numbers, got .*bool"):
        bc.collision_time(*args)
    with pytest.raises(TypeError, match=r"^contact_distance: expected real numbers, got .*bool"):
        bc.collision_times(**{**batch(), "contact_distance": flag})
    if np.ndim(flag) == 0 and not isinstance(flag, np.ndarray):
        with pytest.raises(TypeError, match=r"^num_threads: expected None or an int, got bool"):
            bc.collision_times(**batch(), num_threads=flag)


def test_a_number_too_large_for_a_float_names_its_argument() -> None:
    too_large = r"^contact_distance: must be finite, got .*float64's range"
    with pytest.raises(bc.InputError, match=too_large):
        bc.collision_time(*PAIR[:6], 10**400)


def test_num_threads_of_any_size() -> None:
    ref = bc.collision_times(**batch())
    for n in (10**30, np.int64(2**62), 1):
        np.testing.assert_array_equal(bc.collision_times(**batch(), num_threads=n), ref)
    with pytest.raises(bc.InputError, match=r"^num_threads: must be None .* got -1000000000000"):
        bc.collision_times(**batch(), num_threads=-(10**30))


def test_t_max_none_is_not_a_horizon() -> None:
    with pytest.raises(TypeError, match=r"^t_max: expected real numbers, got NoneType"):
        bc.collision_time(*PAIR, t_max=None)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"^t_max: expected real numbers"):
        bc.first_contacts([[0, 0]], [[0, 0]], 0, 1, t_max=None)  # type: ignore[arg-type]


def test_options_are_keyword_only() -> None:
    with pytest.raises(TypeError, match="positional"):
        bc.collision_time(*PAIR, 1.0)  # type: ignore[misc]
    with pytest.raises(TypeError, match="positional"):
        bc.earliest_collision([[0, 0]], [[0, 0]], 0, 1, 1.0)  # type: ignore[misc]


def test_messages_print_floats_briefly() -> None:
    with pytest.raises(bc.InputError) as e:
        bc.collision_times(**{**batch(), "friction_b": [0, 0, -1e300]})
    assert str(e.value) == "friction_b[2]: friction must be ≥ 0, got -1e+300"
    with pytest.raises(bc.InputError, match=re.escape("got -1.5e-07")):
        bc.collision_time(*PAIR[:6], -1.5e-7)
    with pytest.raises(bc.InputError, match=re.escape("got -0.25")):
        bc.collision_time(*PAIR[:6], -0.25)


def test_input_errors_carry_their_parts() -> None:
    with pytest.raises(ValueError) as e:
        bc.collision_times(**{**batch(12346), "friction_b": np.r_[np.zeros(12345), -0.5]})
    err = e.value
    assert isinstance(err, bc.InputError)
    assert (err.argument, err.index, err.reason) == (
        "friction_b",
        12345,
        "friction must be ≥ 0, got -0.5",
    )
    assert str(err) == "friction_b[12345]: friction must be ≥ 0, got -0.5"
    with pytest.raises(bc.InputError) as e:
        bc.collision_time(*PAIR[:6], -1.0)
    assert (e.value.argument, e.value.index) == ("contact_distance", None)
    assert str(e.value) == f"contact_distance: {e.value.reason}"
    # Shapes, lengths and out= too.
    cases = [
        ({"pos_b": np.zeros((2, 2))}, "pos_b", "has 2 rows, expected 3"),
        ({"vel_a": np.zeros(3)}, "vel_a", "expected shape (N, 2), got (3,)"),
        ({"out": np.empty(2)}, "out", "expected shape (3,), got (2,)"),
    ]
    for change, argument, reason in cases:
        with pytest.raises(bc.InputError) as e:
            bc.collision_times(**{**batch(), **change})
        assert (e.value.argument, e.value.index, e.value.reason) == (argument, None, reason)


def test_input_errors_pickle_with_their_parts() -> None:
    with pytest.raises(bc.InputError) as e:
        bc.positions_at([[0, 0]] * 3, [[0, 0]] * 3, 0.1, [0, np.nan, 0])
    back = pickle.loads(pickle.dumps(e.value))
    assert type(back) is bc.InputError
    assert (back.argument, back.index, back.reason, str(back)) == (
        "t",
        1,
        "must be finite, got NaN",
        "t[1]: must be finite, got NaN",
    )


def test_reading_any_layout_of_any_real_dtype() -> None:
    ref = bc.real_roots(np.array([[1.0, -3.0, 2.0]] * 4))
    c = np.array([[1, -3, 2]] * 4, dtype=">i2")
    for variant in (c, np.asfortranarray(c), c.astype(np.float32)[::-1], tuple(map(tuple, c))):
        np.testing.assert_array_equal(bc.real_roots(variant), ref)


@pytest.mark.parametrize("n", [3, 5000])  # on the calling thread; with the GIL released
def test_out_sharing_memory_with_an_input_is_refused_at_any_size(n: int) -> None:
    args = {**batch(n), "friction_a": np.zeros(n), "contact_distance": np.full(n, 0.5)}
    for shared in (args["friction_a"], args["contact_distance"], args["pos_b"].reshape(-1)[:n]):
        with pytest.raises(
            bc.InputError, match=r"^out: the array shares memory with an input"
        ) as e:
            bc.collision_times(**args, out=shared)
        assert e.value.kind == "shared_memory"
    out = np.empty(n)
    assert bc.collision_times(**args, out=out) is out
    np.testing.assert_array_equal(out, 0.5)
