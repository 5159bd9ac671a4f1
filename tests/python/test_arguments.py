"""Every argument of every public call, given what does not belong there (contract §6).

A bool, a negative or huge int, a float where an int belongs, a string, ``None``: each is
either a valid input (and gives an answer) or an ``InputError`` / ``TypeError`` whose
``.argument`` (or message) names that argument, never an ``OverflowError``, a
``SystemError``, a panic or a silent reading as another number. The expectations are listed
per argument below; the list of arguments is checked against the signatures, so that a new
argument cannot go untested.
"""

from __future__ import annotations

import inspect
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ballcollide as bc

# The values tried on every argument, by label.
BAD: dict[str, object] = {
    "bool": True,
    "numpy bool": np.bool_(False),
    "negative": -1,
    "huge": 2**64,
    "negative huge": -(2**64),
    "beyond float": 10**400,
    "float": 1.5,
    "string": "1",
    "None": None,
}

# What an argument of each kind accepts among BAD (everything else must raise).
NUMBER = {"float", "huge"}  # a number with a lower bound (≥ 0 or > 0)
ANY_NUMBER = {"float", "huge", "negative", "negative huge"}  # a time, of any sign
THREADS = {"huge", "beyond float", "None"}  # at most the cores there are
COUNT = {"huge", "beyond float", "None"}  # max_events: beyond 64 bits is no limit
OPTIONAL = {"None"}  # out=, box= of the calendar
FLAG = {"bool", "None"}  # progress=: True, False or None (or a tqdm-like bar or a callable)
NOTHING: set[str] = set()  # arrays, paths, indices, restitution (in [0, 1])
SIDES = {"negative", "None"}  # segment_sides: one int for every segment, -1 among them


def schedule() -> bc.CollisionSchedule:
    """Two balls at rest at time 0, 2 m apart, in a box."""
    return bc.CollisionSchedule.from_balls(
        [[0, 0], [2, 0]], [[0, 0], [0, 0]], 0.0, 0.25, box=([-4, -4], [4, 4])
    )


ONE_PATH = {  # one ball's path, as one side of a batch (N = 1, K = 1, D = 2)
    "start": [[0.0]],
    "pos": [[[0.0, 0.0]]],
    "vel": [[[1.0, 0.0]]],
    "acc": [[[0.0, 0.0]]],
}
TWO_PATHS = {
    "start": [[0.0], [0.0]],
    "pos": [[[0.0, 0.0]], [[2.0, 0.0]]],
    "vel": [[[1.0, 0.0]], [[0.0, 0.0]]],
    "acc": [[[0.0, 0.0]], [[0.0, 0.0]]],
}
PAIR = {
    "pos_a": [[0.0, 0.0]] * 3,
    "vel_a": [[1.0, 0.0]] * 3,
    "friction_a": 0.0,
    "pos_b": [[1.0, 0.0]] * 3,
    "vel_b": [[0.0, 0.0]] * 3,
    "friction_b": 0.0,
    "contact_distance": 0.5,
}
SCENE = {
    "pos": [[0.0, 0.0], [2.0, 0.0]],
    "vel": [[1.0, 0.0], [0.0, 0.0]],
    "friction": 0.1,
    "radius": 0.25,
}
PATHS_AB = {
    **{f"{k}_a": v for k, v in ONE_PATH.items()},
    **{f"{k}_b": [[0.0]] if k == "start" else [[[2.0, 0.0]]] for k in ONE_PATH},
    "contact_distance": 0.5,
}
BOX = ([-4.0, -4.0], [4.0, 4.0])
# The objects of the calendar and simulate (2-D): as OBJECTS, clear of SCENE's balls and
# inside BOX, and what each argument accepts among BAD.
OBJECTS_2D = {
    "segments": [[[-1.0, -1.0], [-1.0, 1.0]]],
    "segment_sides": 1,
    "circles": [[3.0, 2.0, 0.1]],
    "targets": [[3.0, -2.0, 0.5]],
    "planes": [[[3.9, 0.0], [-1.0, 0.0]]],
}
TABLE_ACCEPTS = {
    **dict.fromkeys(["segments", "circles", "targets", "planes"], OPTIONAL),
    "segment_sides": SIDES,
}
TRANSITIONS = {"bool", "numpy bool", "None"}  # transitions=: True, False or None (off)

# One object of each kind, none of them in ONE_PATH's way but the plane.
OBJECTS = {
    "segments": [[[-1.0, -1.0], [-1.0, 1.0]]],
    "segment_sides": 1,
    "circles": [[3.0, 2.0, 0.1]],
    "targets": [[5.0, -2.0, 0.5]],
    "planes": [[[9.0, 0.0], [-1.0, 0.0]]],
}

# Each call: how to make it from keyword arguments, its valid arguments, and what each
# argument accepts among BAD.
CALLS: dict[str, tuple[Callable[..., Any], dict[str, object], dict[str, set[str]]]] = {
    "collision_time": (
        bc.collision_time,
        {k: v[0] if k.startswith(("pos", "vel")) else v for k, v in PAIR.items()}
        | {"t_max": math.inf},
        {
            **dict.fromkeys(["pos_a", "vel_a", "pos_b", "vel_b"], NOTHING),
            **dict.fromkeys(["friction_a", "friction_b", "contact_distance", "t_max"], NUMBER),
        },
    ),
    "collision_times": (
        bc.collision_times,
        PAIR | {"t_max": math.inf, "num_threads": None, "out": None, "progress": None},
        {
            **dict.fromkeys(["pos_a", "vel_a", "pos_b", "vel_b"], NOTHING),
            **dict.fromkeys(["friction_a", "friction_b", "contact_distance", "t_max"], NUMBER),
            "num_threads": THREADS,
            "out": OPTIONAL,
            "progress": FLAG,
        },
    ),
    "positions_at": (
        bc.positions_at,
        {
            "pos": SCENE["pos"],
            "vel": SCENE["vel"],
            "friction": 0.1,
            "t": 1.0,
            "num_threads": None,
            "out": None,
        },
        {
            "pos": NOTHING,
            "vel": NOTHING,
            "friction": NUMBER,
            "t": ANY_NUMBER,  # times below 0 count as 0
            "num_threads": THREADS,
            "out": OPTIONAL,
        },
    ),
    "path_collision_times": (
        bc.path_collision_times,
        PATHS_AB | {"t_max": math.inf, "num_threads": None, "out": None, "progress": None},
        {
            **{name: NOTHING for name in PATHS_AB if name != "contact_distance"},
            "contact_distance": NUMBER,
            "t_max": NUMBER,
            "num_threads": THREADS,
            "out": OPTIONAL,
            "progress": FLAG,
        },
    ),
    "path_collision_time": (
        bc.path_collision_time,
        {
            "path_a": ([0.0], [[0.0, 0.0]], [[1.0, 0.0]], [[0.0, 0.0]]),
            "path_b": ([0.0], [[2.0, 0.0]], [[0.0, 0.0]], [[0.0, 0.0]]),
            "contact_distance": 0.5,
            "t_max": math.inf,
        },
        {"path_a": NOTHING, "path_b": NOTHING, "contact_distance": NUMBER, "t_max": NUMBER},
    ),
    "path_positions_at": (
        bc.path_positions_at,
        ONE_PATH | {"t": 1.0, "num_threads": None, "out": None},
        {
            **dict.fromkeys(ONE_PATH, NOTHING),
            "t": ANY_NUMBER,  # before the first start: the first position
            "num_threads": THREADS,
            "out": OPTIONAL,
        },
    ),
    "path_geometry_times": (
        bc.path_geometry_times,
        ONE_PATH
        | {"radius": 0.5}
        | OBJECTS
        | {"t_max": math.inf, "num_threads": None, "out": None, "progress": None},
        {
            **dict.fromkeys(ONE_PATH, NOTHING),
            "radius": NUMBER,
            **dict.fromkeys(["segments", "circles", "targets", "planes"], OPTIONAL),
            "segment_sides": SIDES,
            "t_max": NUMBER,
            "num_threads": THREADS,
            "out": OPTIONAL,
            "progress": FLAG,
        },
    ),
    "real_roots": (bc.real_roots, {"coeffs": [1.0, -3.0, 2.0]}, {"coeffs": NOTHING}),
    **{
        name: (
            getattr(bc, name),
            SCENE | {"t_max": math.inf, "num_threads": None},
            {
                "pos": NOTHING,
                "vel": NOTHING,
                "friction": NUMBER,
                "radius": NUMBER,
                "t_max": NUMBER,
                "num_threads": THREADS,
            },
        )
        for name in ("pairwise_collision_times", "earliest_collision", "first_contacts")
    },
    "simulate": (
        bc.simulate,
        SCENE
        | {
            "box": BOX,
            "mass": 1.0,
            "restitution": 1.0,
            "t_end": math.inf,
            "max_events": 5,
            "progress": False,
            "table_restitution": 1.0,
        }
        | OBJECTS_2D,
        {
            "pos": NOTHING,
            "vel": NOTHING,
            "friction": NUMBER,
            "radius": NUMBER,
            "box": NOTHING,
            "mass": NUMBER,
            "restitution": NOTHING,
            "t_end": NUMBER,
            "max_events": COUNT,
            "progress": FLAG,
            "table_restitution": NOTHING,
            **TABLE_ACCEPTS,
        },
    ),
    "CollisionSchedule": (
        bc.CollisionSchedule,
        TWO_PATHS
        | {"radius": 0.25, "box": BOX, "t_max": math.inf, "transitions": False, "progress": None}
        | OBJECTS_2D,
        {
            **dict.fromkeys(TWO_PATHS, NOTHING),
            "radius": NUMBER,
            "box": OPTIONAL,
            "t_max": NUMBER,
            "transitions": TRANSITIONS,
            "progress": FLAG,
            **TABLE_ACCEPTS,
        },
    ),
    "CollisionSchedule.from_balls": (
        bc.CollisionSchedule.from_balls,
        SCENE
        | {"t": 0.0, "box": BOX, "t_max": math.inf, "transitions": False, "progress": None}
        | OBJECTS_2D,
        {
            "pos": NOTHING,
            "vel": NOTHING,
            "friction": NUMBER,
            "radius": NUMBER,
            "t": ANY_NUMBER,  # the calendar's time, any finite number
            "box": OPTIONAL,
            "t_max": NUMBER,
            "transitions": TRANSITIONS,
            "progress": FLAG,
            **TABLE_ACCEPTS,
        },
    ),
    **{
        f"CollisionSchedule.{name}": (
            lambda name=name, **kw: getattr(schedule(), name)(**kw),
            {"i": 1},
            {"i": NOTHING},
        )
        for name in ("retire", "in_play")
    },
    "pool_table": (
        bc.pool_table,
        {
            "width": 1.27,
            "length": 2.54,
            "corner_mouth": 0.1168,
            "side_mouth": 0.1295,
            "jaw_length": 0.04,
            "jaw_radius": 0.005,
            "corner_jaw_angle": 7.0,
            "side_jaw_angle": 14.0,
            "pocket_radius": 0.045,
        },
        {
            # A wider or longer table (not 2**64 m: its mouths round away), longer jaws,
            # bigger pockets: fine.
            "width": {"float"},
            "length": {"float"},
            **dict.fromkeys(["jaw_length", "pocket_radius"], NUMBER),
            # Mouths or tips of 1.5 m (or 2**64) leave no rail; angles below 45 degrees.
            "corner_mouth": NOTHING,
            "side_mouth": {"float"},
            "jaw_radius": NOTHING,
            "corner_jaw_angle": {"float"},
            "side_jaw_angle": {"float"},
        },
    ),
    "simulate_shots": (
        bc.simulate_shots,
        {
            # One ball on a table of one rail, struck at it.
            "tables": [([[0.0, 1.0, 1.0, 1.0, 0.036576, 0.0]], [], [])],
            "shot_table": [0],
            "ball_start": [0, 1],
            "rvw": [[[0.5, 0.5, 0.028575], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]],
            "s": [0],
            "params": [[0.170097, 0.028575, 0.2, 0.01, 4 / 9, 0.05, 0.95, 0.85, 0.2, 9.81]],
            "strike": [0],
            "cue": [[1.5, 90.0, 0.0, 0.0, 0.25, 0.567, 0.0056699, 0.0106045]],
            "contact_rule": "pooltool",
            "max_events": None,
            "history": False,
            "num_threads": 1,
        },
        {
            **dict.fromkeys(
                ["tables", "shot_table", "ball_start", "rvw", "s", "params", "strike", "cue"],
                NOTHING,
            ),
            "contact_rule": OPTIONAL,
            "max_events": COUNT,
            "history": {"bool", "numpy bool", "None"},
            "num_threads": THREADS,
        },
    ),
    "CollisionSchedule.update": (
        lambda **kw: schedule().update(**kw),
        {"indices": [0]} | ONE_PATH,
        {"indices": NOTHING, **dict.fromkeys(ONE_PATH, NOTHING)},
    ),
    "CollisionSchedule.update_balls": (
        lambda **kw: schedule().update_balls(**kw),
        {"indices": [0], "t": 0.5, "pos": [[0.0, 0.0]], "vel": [[1.0, 0.0]], "friction": 0.1},
        {
            "indices": NOTHING,
            "t": NUMBER,  # not before the calendar's time, 0
            "pos": NOTHING,
            "vel": NOTHING,
            "friction": NUMBER,
        },
    ),
}

# Valid values that may yet be refused with an InputError (naming any argument): balls of
# radius 1.5 or 2**64 in this box overlap each other and the walls, an impossible start; in a
# calendar's box, a ball of radius 2**64 is wider than the box.
MAY_REFUSE = {
    ("simulate", "radius"),
    ("CollisionSchedule", "radius"),
    ("CollisionSchedule.from_balls", "radius"),
}

CASES = [
    (call, argument, label)
    for call, (_, _, accepts) in CALLS.items()
    for argument in accepts
    for label in BAD
]


def takes_nothing(f: Any) -> bool:
    """Whether `f` is a function without parameters (`simd_level`): nothing to walk."""
    return inspect.isbuiltin(f) and not inspect.signature(f).parameters


def test_every_public_call_and_argument_is_walked() -> None:
    public = {
        name
        for name in bc.__all__
        if callable(getattr(bc, name))
        and name not in {"InputError", "Event", "Simulation"}
        and not takes_nothing(getattr(bc, name))
    }
    methods = {
        f"CollisionSchedule.{name}"
        for name, member in vars(bc.CollisionSchedule).items()
        if not name.startswith("_") and callable(member)
    }
    with_arguments = {
        name
        for name in methods
        if len(inspect.signature(getattr(schedule(), name.split(".")[1])).parameters) > 0
    }
    assert set(CALLS) == public | with_arguments
    for name, (call, valid, accepts) in CALLS.items():
        target: Any = bc
        for part in name.split("."):
            target = getattr(target, part)
        if name.startswith("CollisionSchedule.") and name != "CollisionSchedule.from_balls":
            target = getattr(schedule(), name.split(".")[1])
        parameters = set(inspect.signature(target).parameters)
        assert set(valid) == parameters == set(accepts), name
        call(**valid)  # the baseline is valid


def documented_kinds() -> set[str]:
    """The kinds of `InputError` that docs/contract.md (section 6) lists."""
    contract = (Path(__file__).parents[2] / "docs" / "contract.md").read_text()
    listed = re.search(r"^- The kinds, from the core: (.*?)\.(?: New|$)", contract, re.M | re.S)
    assert listed is not None
    return set(re.findall(r"`(\w+)`", listed.group(1)))


KINDS = documented_kinds()


def names_argument(error: BaseException, argument: str) -> bool:
    """Whether `error` names `argument` (as `.argument`, or at the start of its message),
    and, for an `InputError`, gives a documented kind and a float or `None` as its value."""
    if isinstance(error, bc.InputError):
        assert error.kind in KINDS, error.kind
        assert error.value is None or isinstance(error.value, float), error.value
        return error.argument == argument and str(error).startswith(argument)
    text = str(error)
    return text.startswith((f"{argument}:", f"{argument}["))


def outcome(call: str, argument: str, value: object) -> BaseException | None:
    """The error of `call` with `argument` = `value` (the other arguments valid), or None."""
    function, valid, _ = CALLS[call]
    try:
        function(**{**valid, argument: value})
    except Exception as error:
        return error
    return None


@pytest.mark.parametrize(("call", "argument", "label"), CASES)
def test_a_bad_argument_is_named_or_a_valid_one_answers(
    call: str, argument: str, label: str
) -> None:
    error = outcome(call, argument, BAD[label])
    if label in CALLS[call][2][argument]:
        if (call, argument) in MAY_REFUSE and isinstance(error, bc.InputError):
            return
        assert error is None, f"{call}({argument}={label}) is valid, got {error!r}"
        return
    assert error is not None, f"{call}({argument}={label}) was accepted"
    assert type(error) in (bc.InputError, TypeError), repr(error)
    if label in {"bool", "numpy bool", "string", "None"}:
        # Not a number, whatever the argument (bools are flags, not numbers).
        assert type(error) is TypeError, repr(error)
    assert names_argument(error, argument), repr(error)


# Argument values of every kind, for the property below: numbers of any size and sign,
# floats of any kind, bools, strings, None, short lists of them.
SCALARS = st.one_of(
    st.integers(),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.floats(),
    st.booleans(),
    st.text(max_size=3),
    st.none(),
    st.sampled_from([np.bool_(True), np.int64(-1), np.uint64(2**64 - 1), np.float32(1.5)]),
)
VALUES = st.one_of(SCALARS, st.lists(SCALARS, max_size=3))


# Rules that relate arguments: a value of one can break the rule, and the error names the
# argument that the rule is stated on (a mouth too wide for the table names the mouth). Each
# rule with the arguments it links: the argument varied and the one named must both be among
# them.
RELATIONS: dict[str, set[str]] = {
    "leaves no rail between the pockets": {
        "width", "length", "corner_mouth", "side_mouth", "jaw_radius",
    },
    "must be below half the narrower mouth": {"jaw_radius", "corner_mouth", "side_mouth"},
    "is too large for the pockets' mouths": {"width", "length", "corner_mouth", "side_mouth"},
    "the ball overlaps ball": {"pos", "radius"},
    "overlaps a wall of the box": {"pos", "radius", "box"},
    "expected shape (N,)": {"shot_table", "ball_start", "strike", "cue"},
    # A friction ball's path beyond the float range (path_overflow): its deceleration −v/τ
    # (named friction), its resting point p + ½·v·τ (vel), its stop time moved on by t (t).
    "so its path cannot be represented": {"pos", "vel", "friction", "t"},
}  # fmt: skip


def relates(error: BaseException, argument: str) -> bool:
    """Whether `error` names an argument that one of the RELATIONS links to `argument`."""
    if not isinstance(error, bc.InputError):
        return False
    named = error.argument.split("[")[0]
    return any(
        rule in error.reason and {named, argument} <= linked for rule, linked in RELATIONS.items()
    )


@given(
    target=st.sampled_from([(call, argument) for call, argument, _ in CASES[:: len(BAD)]]),
    value=VALUES,
)
def test_any_value_of_any_argument_answers_or_is_named(
    target: tuple[str, str], value: object
) -> None:
    call, argument = target
    error = outcome(call, argument, value)
    if error is not None:
        assert type(error) in (bc.InputError, TypeError), repr(error)
        # Lengths that differ between two arguments: either may be named.
        mismatch = isinstance(error, bc.InputError) and re.fullmatch(
            r"has \d+ rows, expected \d+", error.reason
        )
        named = names_argument(error, argument) or relates(error, argument)
        assert mismatch or named, repr(error)


# The reproducers of issue 39.


@pytest.mark.parametrize("flag", [True, np.bool_(False), np.array(True)])
def test_a_bool_inside_an_array_argument_is_a_type_error_naming_it(flag: object) -> None:
    # numpy reads [True, 0.0] as numbers; a bool is no real number, in a list as alone.
    calls = {
        "radius": lambda: bc.simulate(
            [[0, 0], [1, 0]], [[1, 0], [0, 0]], 0.0, [flag, 0.1], box=([-2, -2], [2, 2])
        ),
        "pos": lambda: bc.earliest_collision([[flag, 0.0], [0.5, 0]], [[1, 0], [0, 0]], 0.0, 0.1),
        "box": lambda: bc.CollisionSchedule.from_balls(
            [[0.5, 0.5]], [[1, 0]], 0.0, 0.1, box=([flag, 0.0], [1, 1])
        ),
        "vel_a": lambda: bc.collision_times(
            [[0, 0]], [[flag, 0.5]], 0.0, [[1, 0]], [[0, 0]], 0.0, 0.5
        ),
    }
    calls["pos "] = lambda: bc.earliest_collision(
        [np.array([True, False]), [0.5, 0]], [[1, 0], [0, 0]], 0.0, 0.1
    )
    for argument, call in calls.items():
        with pytest.raises(TypeError, match=rf"^{argument.strip()}: expected real numbers"):
            call()


def test_a_friction_balls_path_beyond_the_float_range_names_the_balls_inputs() -> None:
    # Finite inputs whose path is not: the deceleration −v/τ (τ = |v|/μ subnormal) named
    # `friction`, the resting point p + ½·v·τ named `vel`, never the path's own fields.
    box = ([-1.5e308, -4], [1.5e308, 4])
    calls = {
        "friction": lambda: bc.simulate(
            [[0, 0], [1, 0]], [[1, 0], [0, 0]], 1.7976931348623157e308, 0.25, box=box
        ),
        "vel": lambda: bc.simulate(
            [[1e308, 0], [-1e308, 0]], [[1e308, 0], [0, 0]], 1.0, 0.25, box=box
        ),
    }
    for argument, call in calls.items():
        with pytest.raises(bc.InputError) as error:
            call()
        got = (error.value.argument, error.value.index, error.value.kind)
        assert got == (argument, 0, "path_overflow")
        assert "beyond the range of float64" in error.value.reason
    with pytest.raises(bc.InputError, match=r"^friction\[0\]: the ball's deceleration"):
        bc.CollisionSchedule.from_balls([[0, 0]], [[1, 0]], 1.7976931348623157e308, 0.25)


def test_huge_and_tiny_masses_are_valid_and_bounce() -> None:
    pos, vel = [[0.0, 0.0], [1.0, 0.0]], [[2.0, 0.0], [0.0, 0.0]]
    ref = bc.simulate(pos, vel, 0.1, 0.25, box=BOX, max_events=6)
    for mass in (1e308, 5e-324, 1e-308, 2.2250738585072014e-308, 1.7976931348623157e308):
        run = bc.simulate(pos, vel, 0.1, 0.25, box=BOX, mass=mass, max_events=6)
        # Only the mass ratio matters: the same run as with unit masses, to the bit.
        for got, want in zip(run, ref, strict=True):
            np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize(
    "masses",
    [(5e-324, 1e308), (1e308, 5e-324), (1e-308, 1e308), (1.0, 1e308), (1e-300, 1.0)],
)
def test_mass_ratios_beyond_the_float_range_give_finite_velocities(
    masses: tuple[float, float],
) -> None:
    # Ball 0 runs into ball 1 at rest: the light one bounces off the heavy one as off a
    # wall, or is sent off by it, the heavy one barely changes; every velocity stays finite,
    # and the run goes on.
    pos, vel = [[0.0, 0.0], [1.0, 0.0]], [[2.0, 0.0], [0.0, 0.0]]
    times, i, j, _, v, *_ = bc.simulate(
        pos, vel, 0.0, 0.25, box=BOX, mass=list(masses), restitution=1.0, max_events=1
    )
    assert (times.tolist(), i.tolist(), j.tolist()) == ([0.25], [0], [1])
    assert np.isfinite(v).all()
    light = 0 if masses[0] < masses[1] else 1
    heavy = 1 - light
    if masses[heavy] / masses[light] == math.inf:
        # The ratio overflows: the light ball takes the whole change, the heavy none (a
        # light ball bounces back; one at rest, hit, leaves at twice the heavy one's speed).
        expected = [[-2.0, 0.0], [0.0, 0.0]] if light == 0 else [[2.0, 0.0], [4.0, 0.0]]
        assert v.tolist() == expected
    times, *_ = bc.simulate(pos, vel, 0.0, 0.25, box=BOX, mass=list(masses), max_events=20)
    assert len(times) == 20 and np.all(np.diff(times) > 0)  # no collision repeated at once


@pytest.mark.parametrize("value", [-1, -(2**64)])
def test_a_negative_event_count_is_an_input_error(value: int) -> None:
    with pytest.raises(bc.InputError, match=rf"^max_events: must be None or ≥ 0, got {value}$"):
        bc.simulate(**{**CALLS["simulate"][1], "max_events": value})


def test_a_huge_event_count_is_no_limit() -> None:
    baseline = {**CALLS["simulate"][1], "max_events": None, "friction": 0.5}
    ref = bc.simulate(**baseline)
    for count in (2**63, 2**64, 10**100):
        for got, want in zip(bc.simulate(**{**baseline, "max_events": count}), ref, strict=True):
            np.testing.assert_array_equal(got, want)
    assert len(bc.simulate(**{**baseline, "max_events": 0})[0]) == 0


@pytest.mark.parametrize("value", [1.5, 1.0, True, "1", np.float64(2.0)])
def test_an_event_count_that_is_not_an_int_is_a_type_error(value: object) -> None:
    with pytest.raises(TypeError, match=r"^max_events: expected None or an int, got "):
        bc.simulate(**{**CALLS["simulate"][1], "max_events": value})


@pytest.mark.parametrize("value", ["1", True, np.bool_(True), None])
def test_restitution_is_a_number(value: object) -> None:
    with pytest.raises(TypeError, match=r"^restitution: expected real numbers, got "):
        bc.simulate(**{**CALLS["simulate"][1], "restitution": value})


INT = "expected an int (a ball index), got"
INTS = "expected an int or a sequence of ints (ball indices), got"
RANGE = "ball index must be in 0..2, got"
SHAPE = "expected an int or shape (M,), got shape"
ARRAY = "expected ints (ball indices), got an array of dtype"


@pytest.mark.parametrize(
    ("indices", "error", "message"),
    [
        ([True, False], TypeError, f"indices[0]: {INT} bool"),
        ([0, np.bool_(True)], TypeError, f"indices[1]: {INT} bool"),
        (True, TypeError, f"indices: {INTS} bool"),
        ([0, 1.0], TypeError, f"indices[1]: {INT} float"),
        (np.array([True, False]), TypeError, f"indices: {ARRAY} bool"),
        (np.array([0.0, 1.0]), TypeError, f"indices: {ARRAY} float64"),
        ("01", TypeError, f"indices: {INTS} str"),
        ([0, 2**64], bc.InputError, f"indices[1]: {RANGE} 18446744073709551616"),
        (2**64, bc.InputError, f"indices: {RANGE} 18446744073709551616"),
        ([0, -(2**64)], bc.InputError, f"indices[1]: {RANGE} -18446744073709551616"),
        ([-1, 0], bc.InputError, f"indices[0]: {RANGE} -1"),
        ([0, 2], bc.InputError, f"indices[1]: {RANGE} 2"),
        (np.array([[0, 1]]), bc.InputError, f"indices: {SHAPE} (1, 2)"),
    ],
)  # fmt: skip
def test_update_indices_are_ints_in_range(indices: object, error: type, message: str) -> None:
    s = schedule()
    before = (s.time, s.next_event())
    m = 1 if np.ndim(indices) == 0 and not isinstance(indices, str) else 2
    with pytest.raises(error) as raised:
        s.update_balls(indices, 1.0, [[0.0, 0.0]] * m, [[1.0, 0.0]] * m, 0.0)
    assert str(raised.value) == message
    if error is bc.InputError:
        assert raised.value.argument == "indices"
    assert (s.time, s.next_event()) == before  # refused: nothing changed


@pytest.mark.parametrize(
    "indices", [[1, 0], (1, 0), np.array([1, 0]), np.array([1, 0], dtype=np.uint8)]
)
def test_update_indices_of_any_int_type(indices: object) -> None:
    s = schedule()
    s.update_balls(indices, 1.0, [[-1.0, 0.0], [2.0, 0.0]], [[1.0, 0.0], [0.0, 0.0]], 0.0)
    assert s.next_collision() == (3.5, 0, 1)  # ball 1 from -1 at 1 m/s, ball 0 at rest at 2
    s.update_balls(np.int64(0), 2.0, [[1.0, 0.0]], [[0.0, 0.0]], 0.0)
    assert s.time == 2.0


def out_aliasing_cases(n: int) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """(argument, input, out): inputs converted to a copy, and an out over their memory."""
    cases = []
    fortran = np.asfortranarray(np.zeros((n, 2)))
    cases.append(("pos_a", fortran, fortran[:, 0]))  # a column of an F-order array
    big = np.zeros(n, dtype=">f8")
    cases.append(("friction_a", big, big.view(np.float64)))  # big-endian, viewed as native
    strided = np.zeros(2 * n)
    cases.append(("friction_b", strided[::2], strided[:n]))  # a strided view
    ints = np.zeros(n, dtype=np.int64)
    cases.append(("friction_a", ints, ints.view(np.float64)))  # ints, viewed as floats
    return cases


@pytest.mark.parametrize("n", [3, 5000])  # on the calling thread; with the GIL released
@pytest.mark.parametrize("case", range(4))
def test_out_sharing_memory_with_an_input_that_is_converted_is_refused(n: int, case: int) -> None:
    argument, value, out = out_aliasing_cases(n)[case]
    kept = value.copy()
    with pytest.raises(bc.InputError, match=r"^out: the array shares memory with an input$") as e:
        bc.collision_times(**{**pair_batch(n), argument: value}, out=out)
    assert (e.value.argument, e.value.kind) == ("out", "shared_memory")  # contract § 6
    np.testing.assert_array_equal(value, kept)  # the caller's input untouched


def pair_batch(n: int) -> dict:
    return {
        k: np.array(v[:1] * n, dtype=float) if isinstance(v, list) else v for k, v in PAIR.items()
    }


def test_out_next_to_a_converted_input_is_accepted() -> None:
    n = 4
    memory = np.zeros(3 * n)
    out = memory[:n]
    strided = memory[n + 1 :: 2]  # after out's last element: no overlap
    got = bc.collision_times(**{**pair_batch(n), "friction_a": strided[:n]}, out=out)
    assert got is out
    np.testing.assert_array_equal(out, 0.5)
    # Within a strided input's span, between its elements: no element in common.
    memory = np.zeros(5 * n)
    out = memory[1:5]
    got = bc.collision_times(**{**pair_batch(n), "friction_a": memory[::5]}, out=out)
    assert got is out
    np.testing.assert_array_equal(out, 0.5)
    np.testing.assert_array_equal(memory[::5], 0.0)
    # The whole memory read by a path batch, converted, and out elsewhere.
    times = np.empty(1)
    fortran = np.asfortranarray(np.zeros((1, 1, 2)))
    paths = {**PATHS_AB, "pos_a": fortran}
    assert bc.path_collision_times(**paths, out=times) is times


def test_a_ball_radius_is_not_a_sum_of_two() -> None:
    calls = [
        lambda: bc.earliest_collision(**{**SCENE, "radius": [0.25, -1.0]}),
        lambda: bc.pairwise_collision_times(**{**SCENE, "radius": [0.25, -1.0]}),
        lambda: bc.first_contacts(**{**SCENE, "radius": [0.25, -1.0]}),
        lambda: bc.CollisionSchedule.from_balls(**{**SCENE, "radius": [0.25, -1.0]}),
        lambda: bc.CollisionSchedule(**TWO_PATHS, radius=[0.25, -1.0]),
        lambda: bc.simulate(**{**SCENE, "radius": [0.25, -1.0]}, box=BOX, max_events=1),
    ]
    for call in calls:
        with pytest.raises(bc.InputError) as raised:
            call()
        assert str(raised.value) == "radius[1]: a ball's radius must be > 0, got -1"
    # A contact distance still is one.
    contact = r"^contact_distance: the contact distance \(sum of the two radii\) must be"
    with pytest.raises(bc.InputError, match=contact):
        bc.collision_time([0, 0], [1, 0], 0, [1, 0], [0, 0], 0, -1.0)


@pytest.mark.parametrize("t_end", [-1.0, math.nan, -math.inf])
def test_t_end_errors_name_t_end(t_end: float) -> None:
    with pytest.raises(bc.InputError) as raised:
        bc.simulate(**{**CALLS["simulate"][1], "t_end": t_end})
    assert raised.value.argument == "t_end"
    assert "t_max" not in str(raised.value)
    assert str(raised.value).startswith("t_end: must be ≥ 0 (∞ for none), got ")


@pytest.mark.parametrize("t", [-1e300, 1e300, -1.5, 0.1, 1e-310, 2.0**70, -0.0, 0.0])
def test_repr_prints_the_time_as_python_does(t: float) -> None:
    s = bc.CollisionSchedule.from_balls([[0, 0]], [[0, 0]], 0.0, 0.25, t=t)
    assert repr(s) == f"CollisionSchedule(1 balls in 2-D, time={s.time!r})"
    assert len(repr(s)) < 70
    assert s.time == t


def positive_zero(x: float) -> bool:
    return x == 0 and math.copysign(1.0, x) == 1.0


def test_a_time_of_minus_zero_is_taken_in_as_zero() -> None:
    s = bc.CollisionSchedule.from_balls([[0, 0]], [[0, 0]], 0.0, 0.25, t=-0.0)
    assert positive_zero(s.time) and repr(s).endswith("time=0.0)")
    s = bc.CollisionSchedule.from_balls([[0, 0], [2, 0]], [[1, 0], [0, 0]], 0.0, 0.5, t=-1.0)
    s.update_balls([0], -0.0, [[0.5, 0]], [[1, 0]], 0.0)
    assert positive_zero(s.time)
    assert s.next_collision() == (0.5, 0, 1)
    start = [[-0.0], [-0.0]]
    touching = [[[0.0, 0.0]], [[0.5, 0.0]]]
    vel = [[[1.0, 0.0]], [[0.0, 0.0]]]
    s = bc.CollisionSchedule(start, touching, vel, np.zeros((2, 1, 2)), 0.25)
    assert positive_zero(s.time)
    t, i, j = s.next_collision()
    assert (t, i, j) == (0.0, 0, 1) and positive_zero(t)
    s = bc.CollisionSchedule([[-1.0], [-1.0]], touching, vel, np.zeros((2, 1, 2)), 0.25)
    s.update([0, 1], start, touching, vel, np.zeros((2, 1, 2)))
    assert positive_zero(s.time)
    assert positive_zero(s.next_event().time)


def test_a_box_of_another_type_is_named_with_what_it_got() -> None:
    pos, vel = [[0.5, 0.5]], [[0.0, 0.0]]
    with pytest.raises(TypeError, match=r"^box: expected a tuple \(lo, hi\), got str$"):
        bc.simulate(pos, vel, 0.0, 0.1, box="box")
    with pytest.raises(TypeError, match=r"^box: expected a tuple \(lo, hi\), got NoneType$"):
        bc.simulate(pos, vel, 0.0, 0.1, box=None)
    with pytest.raises(TypeError, match=r"^box: expected None or a tuple \(lo, hi\), got int$"):
        bc.CollisionSchedule.from_balls(pos, vel, 0.0, 0.1, box=3)
