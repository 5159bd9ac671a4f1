//! `simulate_shots`: many billiard shots at once ([`crate::billiards::simulate_shots`]), from
//! arrays in pooltool's layout, to arrays.

use nalgebra::{Vector2, Vector3};
use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use super::input_error::{input_error, kind, located_error};
use super::long_call::{Kernel, run};
use super::read::{Floats, count, flag, shape_text, shaped, threads};
use crate::billiards::{
    BallParams, BallState, BilliardTable, CircularCushion, ContactRule, Cue, CueSpecs,
    LinearCushion, MotionState, Pocket, Shot, ShotEventKind, ShotOptions, ShotSetup, shot_history,
    side_of_direction, simulate_shots_then,
};

/// Shots up to this many run on the calling thread holding the GIL (one shot is tens of µs
/// to a millisecond).
const INLINE_SHOTS: usize = 1;

/// Many billiard shots with pooltool 0.6.0's physics and events, on up to ``num_threads``
/// threads (``ballcollide.billiards`` in Rust; :func:`ballcollide.pooltool.simulate_many`
/// builds these arrays from pooltool ``System`` s and reads the results back).
///
/// Parameters
/// ----------
/// tables
///     A sequence of tables, each a tuple ``(linear, circular, pockets)``: ``linear`` shape
///     ``(L, 6)``, rows ``(p1x, p1y, p2x, p2y, height, direction)`` (``direction``
///     pooltool's ``CushionDirection``: 0, 1 or 2); ``circular`` shape ``(C, 4)``, rows
///     ``(cx, cy, radius, height)``; ``pockets`` shape ``(P, 4)``, rows ``(cx, cy, radius,
///     depth)``. Shape ``(0,)`` is none.
/// shot_table
///     Shape ``(S,)``: each shot's table, an index into ``tables``.
/// ball_start
///     Shape ``(S + 1,)``: shot ``k``'s balls are rows ``ball_start[k]:ball_start[k + 1]``
///     of the ball arrays (starting at 0, not decreasing).
/// rvw, s, params
///     The balls: shape ``(B, 3, 3)`` (pooltool's ``rvw``: position, velocity, angular
///     velocity; the heights ``rvw[:, 0, 2]`` are kept, the vertical velocities ignored),
///     ``(B,)`` motion states (0–4), ``(B, 10)`` rows ``(m, R, u_s, u_r,
///     u_sp_proportionality, u_b, e_b, e_c, f_c, g)``.
/// strike
///     Shape ``(S,)``: the ball the cue strikes at time 0, by its index within its shot, or
///     ``-1`` for no strike.
/// cue
///     Shape ``(S, 8)``: the strokes, rows ``(V0, phi, theta, a, b, M, end_mass,
///     tip_radius)`` (read where ``strike >= 0``).
/// contact_rule
///     ``"pooltool"`` (the default, also ``None``: pooltool 0.6.0's collisions at once of overlapping balls
///     and of balls with equal accelerations) or ``"approaching"`` (balls collide only when
///     they come into contact).
/// max_events
///     ``None`` (default) or an int ``≥ 0``: each shot ends after this many events.
/// history
///     ``True`` (default ``None``, ``False``: not): also every ball's state at every event (``history_*``, ``before_*``).
/// num_threads
///     ``None`` (default): all cores; an int ``n ≥ 1``: at most ``n`` threads. The results
///     do not depend on it, bit for bit.
///
/// Returns
/// -------
/// dict
///     ``event_start`` ``(S + 1,)`` (shot ``k``'s events are ``event_start[k]:event_start[k
///     + 1]``), ``time`` ``(E,)``, ``type`` ``(E,)`` (codes: indices into ``type_names``,
///     pooltool's ``EventType`` values), ``ball`` ``(E, 2)`` (the balls within the shot,
///     ``-1`` in the second column for one ball), ``object`` ``(E,)`` (the cushion's or
///     pocket's index in its table list, or ``-1``), ``rvw`` ``(E, 2, 3, 3)`` and ``s``
///     ``(E, 2)`` (each ball's state just after the event; NaN and ``-1`` where there is no
///     second ball), ``final_rvw`` ``(B, 3, 3)`` and ``final_s`` ``(B,)``, ``end`` ``(S,)``
///     (the last event's time), ``stopped`` ``(S,)`` (ended by ``max_events``),
///     ``type_names``; with ``history``: ``history_rvw`` ``(H, 3, 3)`` and ``history_s``
///     ``(H,)``, shot ``k``'s ``(events + 2) × balls`` states in rows
///     ``history_start[k]:history_start[k + 1]`` (row-major: before the strike, after each
///     event, at the end), and ``before_rvw`` ``(E, 2, 3, 3)``, ``before_s`` ``(E, 2)``:
///     each event's balls just before it.
///
/// Raises
/// ------
/// InputError
///     A wrong shape or offset; for a shot that cannot be simulated, the first such shot's
///     error, its argument prefixed by the shot (``shots[3].position``).
/// KeyboardInterrupt
///     Ctrl-C, looked for between shots.
///
/// Examples
/// --------
/// >>> import numpy as np
/// >>> import ballcollide as bc
/// >>> rvw = np.zeros((2, 3, 3)); rvw[:, 0] = [[0.5, 0.5, 0.028575], [0.5, 1.0, 0.028575]]
/// >>> params = [[0.170097, 0.028575, 0.2, 0.01, 4 / 9, 0.05, 0.95, 0.85, 0.2, 9.81]] * 2
/// >>> cue = [[2.0, 90.0, 0.0, 0.0, 0.2, 0.567, 0.170097 / 30, 0.0106045]]
/// >>> r = bc.simulate_shots([([], [], [])], [0], [0, 2], rvw, [0, 0], params, [0], cue)
/// >>> [r["type_names"][t] for t in r["type"][:3]]
/// ['stick_ball', 'ball_ball', 'sliding_rolling']
#[pyfunction]
#[pyo3(signature = (
    tables, shot_table, ball_start, rvw, s, params, strike, cue, *,
    contact_rule=None, max_events=None, history=None, num_threads=None
))]
#[allow(clippy::too_many_arguments)]
pub(super) fn simulate_shots<'py>(
    py: Python<'py>,
    tables: &Bound<'py, PyAny>,
    shot_table: &Bound<'py, PyAny>,
    ball_start: &Bound<'py, PyAny>,
    rvw: &Bound<'py, PyAny>,
    s: &Bound<'py, PyAny>,
    params: &Bound<'py, PyAny>,
    strike: &Bound<'py, PyAny>,
    cue: &Bound<'py, PyAny>,
    contact_rule: Option<&Bound<'py, PyAny>>,
    max_events: Option<&Bound<'py, PyAny>>,
    history: Option<&Bound<'py, PyAny>>,
    num_threads: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let tables = read_tables(py, tables)?;
    let shot_table = ints(py, "shot_table", shot_table, None)?;
    let n_shots = shot_table.len();
    if tables.is_empty() && n_shots > 0 {
        // Every shot names a table, so an empty `tables` is the argument at fault.
        let reason = if n_shots == 1 {
            "holds no table, but 1 shot needs one".to_string()
        } else {
            format!("holds no table, but {n_shots} shots need one")
        };
        return Err(input_error(py, "tables", None, kind::SHAPE, &reason));
    }
    let ball_start = ints(py, "ball_start", ball_start, Some(n_shots + 1))?;
    if ball_start.first().is_some_and(|&f| f != 0) {
        let reason = format!("offsets must start at 0, got {}", ball_start[0]);
        return Err(input_error(
            py,
            "ball_start",
            Some(0),
            kind::OUT_OF_RANGE,
            &reason,
        ));
    }
    let (rvw_values, rvw_shape) = shaped("rvw", rvw)?;
    let n_balls = ball_start.last().copied().unwrap_or(0).max(0) as usize;
    expect_shape(py, "rvw", &rvw_shape, &[n_balls, 3, 3], "(B, 3, 3)")?;
    let s = ints(py, "s", s, Some(n_balls))?;
    let (param_values, param_shape) = shaped("params", params)?;
    expect_shape(py, "params", &param_shape, &[n_balls, 10], "(B, 10)")?;
    let strike = ints(py, "strike", strike, Some(n_shots))?;
    let (cue_values, cue_shape) = shaped("cue", cue)?;
    expect_shape(py, "cue", &cue_shape, &[n_shots, 8], "(S, 8)")?;
    let contact_rule = match contact_rule.filter(|c| !c.is_none()) {
        None => ContactRule::Pooltool,
        Some(c) => match c.extract::<String>().ok().as_deref() {
            Some("pooltool") => ContactRule::Pooltool,
            Some("approaching") => ContactRule::Approaching,
            _ => {
                return Err(PyTypeError::new_err(format!(
                    "contact_rule: expected \"pooltool\" or \"approaching\", got {}",
                    c.repr()?
                )));
            }
        },
    };
    let options = ShotOptions {
        max_events: count("max_events", max_events)?,
        contact_rule,
        ..Default::default()
    };
    let history = match history.filter(|h| !h.is_none()) {
        Some(h) => flag("history", h)?,
        None => false,
    };
    let threads = threads(num_threads)?;

    // The balls.
    let rvw_rows = rvw_values.values();
    let param_rows = param_values.values();
    let mut balls = Vec::with_capacity(n_balls);
    let mut heights = Vec::with_capacity(n_balls);
    let mut ball_params = Vec::with_capacity(n_balls);
    for b in 0..n_balls {
        let r = &rvw_rows[9 * b..9 * b + 9];
        let Some(motion) = MotionState::from_code(s[b]) else {
            let reason = format!("a motion state must be 0 to 4, got {}", s[b]);
            return Err(input_error(py, "s", Some(b), kind::OUT_OF_RANGE, &reason));
        };
        balls.push(BallState::new(
            Vector2::new(r[0], r[1]),
            Vector2::new(r[3], r[4]),
            Vector3::new(r[6], r[7], r[8]),
            motion,
        ));
        heights.push(r[2]);
        let p = &param_rows[10 * b..10 * b + 10];
        ball_params.push(BallParams {
            mass: p[0],
            radius: p[1],
            u_s: p[2],
            u_r: p[3],
            u_sp_proportionality: p[4],
            u_b: p[5],
            e_b: p[6],
            e_c: p[7],
            f_c: p[8],
            g: p[9],
        });
    }
    // The shots.
    let cues = cue_values.values();
    let mut setups = Vec::with_capacity(n_shots);
    for k in 0..n_shots {
        let table = usize::try_from(shot_table[k])
            .ok()
            .and_then(|t| tables.get(t))
            .ok_or_else(|| {
                let reason = format!("must be in 0..{}, got {}", tables.len(), shot_table[k]);
                input_error(py, "shot_table", Some(k), kind::OUT_OF_RANGE, &reason)
            })?;
        let (first, last) = (ball_start[k], ball_start[k + 1]);
        if first < 0 || last < first {
            let reason =
                format!("offsets must start at 0 and not decrease, got {last} after {first}");
            return Err(input_error(
                py,
                "ball_start",
                Some(k + 1),
                kind::OUT_OF_RANGE,
                &reason,
            ));
        }
        let range = first as usize..last as usize;
        let stroke = match strike[k] {
            -1 => None,
            i if i >= 0 && (i as usize) < range.len() => {
                let c = &cues[8 * k..8 * k + 8];
                let cue = Cue {
                    v0: c[0],
                    phi: c[1],
                    theta: c[2],
                    a: c[3],
                    b: c[4],
                    specs: CueSpecs {
                        mass: c[5],
                        end_mass: c[6],
                        tip_radius: c[7],
                    },
                };
                Some((i as usize, cue))
            }
            i => {
                let reason = format!(
                    "must be -1 or a ball of the shot (0..{}), got {i}",
                    range.len()
                );
                return Err(input_error(
                    py,
                    "strike",
                    Some(k),
                    kind::OUT_OF_RANGE,
                    &reason,
                ));
            }
        };
        setups.push(ShotSetup {
            table,
            balls: &balls[range.clone()],
            params: &ball_params[range],
            strike: stroke,
        });
    }
    let how = if n_shots <= INLINE_SHOTS {
        Kernel::Inline
    } else {
        Kernel::Watched
    };
    let results = run(py, how, || {
        // Each shot's rows of the results (and its history) built on its thread, off the
        // GIL: what is left for the calling thread is to join them.
        simulate_shots_then(&setups, &options, threads, |k, setup, shot| {
            let h = history.then(|| shot_history(setup.balls, setup.params, &shot));
            let first = usize::try_from(ball_start[k]).unwrap_or(0);
            let heights = &heights[first..first + setup.balls.len()];
            ShotRows::of(setup, heights, &shot, h.as_ref())
        })
    })?;
    let mut shots = Vec::with_capacity(n_shots);
    for (k, r) in results.into_iter().enumerate() {
        match r {
            Ok(rows) => shots.push(rows),
            Err(e) => {
                let argument = format!("shots[{k}].{}", e.argument());
                return Err(located_error(
                    py,
                    &argument,
                    [e.index(), e.segment()],
                    (e.kind().code(), e.kind().value()),
                    &e.kind().to_string(),
                ));
            }
        }
    }
    // No shot: no history arrays either (as no shot had one).
    arrays(py, &shots, history && !shots.is_empty())
}

/// One shot's rows of [`simulate_shots`]' result arrays (the names of its dictionary).
struct ShotRows {
    time: Vec<f64>,
    types: Vec<i64>,
    ball: Vec<i64>,
    object: Vec<i64>,
    rvw: Vec<f64>,
    s: Vec<i64>,
    before_rvw: Vec<f64>,
    before_s: Vec<i64>,
    final_rvw: Vec<f64>,
    final_s: Vec<i64>,
    history_rvw: Vec<f64>,
    history_s: Vec<i64>,
    end: f64,
    stopped: bool,
}

impl ShotRows {
    /// The rows of `shot`, played from `setup` with its balls at `heights`, and of its
    /// history `h` if given.
    fn of(
        setup: &ShotSetup<'_>,
        heights: &[f64],
        shot: &Shot,
        h: Option<&crate::billiards::ShotHistory>,
    ) -> Self {
        let n_events = shot.events.len();
        let n = setup.balls.len();
        // Room for the history's rows only when there is one.
        let with_h = usize::from(h.is_some());
        let mut out = Self {
            time: Vec::with_capacity(n_events),
            types: Vec::with_capacity(n_events),
            ball: Vec::with_capacity(2 * n_events),
            object: Vec::with_capacity(n_events),
            rvw: Vec::with_capacity(18 * n_events),
            s: Vec::with_capacity(2 * n_events),
            before_rvw: Vec::with_capacity(with_h * 18 * n_events),
            before_s: Vec::with_capacity(with_h * 2 * n_events),
            final_rvw: Vec::with_capacity(9 * n),
            final_s: Vec::with_capacity(n),
            history_rvw: Vec::with_capacity(with_h * 9 * n * (n_events + 2)),
            history_s: Vec::with_capacity(with_h * n * (n_events + 2)),
            end: shot.end,
            stopped: shot.stopped,
        };
        let table = setup.table;
        // Each ball's height: as given, until it drops into a pocket (its bottom).
        let mut z: Vec<f64> = heights.to_vec();
        let mut before_at = 0;
        for (e, event) in shot.events.iter().enumerate() {
            out.time.push(event.time);
            out.types.push(event.kind.code());
            out.object
                .push(event.kind.object().map_or(-1, super::index_i64));
            if let (ShotEventKind::Pocket(p), Some(&b)) = (event.kind, event.balls.first())
                && let (Some(pocket), Some(zb)) = (table.pockets.get(p), z.get_mut(b))
            {
                *zb = pocket.bottom();
            }
            for slot in 0..2 {
                match (event.balls.get(slot), event.states.get(slot)) {
                    (Some(&b), Some(state)) => {
                        out.ball.push(super::index_i64(b));
                        push_state(&mut out.rvw, &mut out.s, state, z[b]);
                        if let Some(h) = h {
                            let zb = match event.kind {
                                ShotEventKind::Pocket(_) => heights[b],
                                _ => z[b],
                            };
                            push_state(
                                &mut out.before_rvw,
                                &mut out.before_s,
                                &h.before[before_at],
                                zb,
                            );
                            before_at += 1;
                        }
                    }
                    _ => {
                        out.ball.push(-1);
                        push_missing(&mut out.rvw, &mut out.s);
                        if h.is_some() {
                            push_missing(&mut out.before_rvw, &mut out.before_s);
                        }
                    }
                }
            }
            if let Some(h) = h {
                let row = &h.rows[(e + 1) * n..(e + 2) * n];
                // Row 0 (before the strike) is written with the first event below.
                if e == 0 {
                    for (b, state) in h.rows[..n].iter().enumerate() {
                        push_state(&mut out.history_rvw, &mut out.history_s, state, heights[b]);
                    }
                }
                for (b, state) in row.iter().enumerate() {
                    push_state(&mut out.history_rvw, &mut out.history_s, state, z[b]);
                }
            }
        }
        for (b, state) in shot.states.iter().enumerate() {
            push_state(&mut out.final_rvw, &mut out.final_s, state, z[b]);
        }
        if let Some(h) = h {
            if shot.events.is_empty() {
                for (b, state) in h.rows[..n].iter().enumerate() {
                    push_state(&mut out.history_rvw, &mut out.history_s, state, heights[b]);
                }
            }
            for (b, state) in shot.states.iter().enumerate() {
                push_state(&mut out.history_rvw, &mut out.history_s, state, z[b]);
            }
        }
        out
    }
}

/// The result dictionary of [`simulate_shots`]: the shots' rows joined.
fn arrays<'py>(
    py: Python<'py>,
    shots: &[ShotRows],
    with_history: bool,
) -> PyResult<Bound<'py, PyDict>> {
    /// The rows `part` of every shot, one after the other.
    fn joined<T: Copy>(shots: &[ShotRows], part: impl Fn(&ShotRows) -> &[T]) -> Vec<T> {
        let mut all = Vec::with_capacity(shots.iter().map(|r| part(r).len()).sum());
        for rows in shots {
            all.extend_from_slice(part(rows));
        }
        all
    }
    /// 0, then where each shot's rows `part` end.
    fn starts(shots: &[ShotRows], part: impl Fn(&ShotRows) -> usize) -> Vec<i64> {
        let mut at = 0;
        let mut starts = Vec::with_capacity(shots.len() + 1);
        starts.push(0);
        for rows in shots {
            at += part(rows);
            starts.push(super::index_i64(at));
        }
        starts
    }
    let n_events: usize = shots.iter().map(|r| r.time.len()).sum();
    let dict = PyDict::new(py);
    let shaped = |v: Vec<f64>, shape: &[usize]| -> PyResult<Bound<'py, PyAny>> {
        PyArray1::from_vec(py, v).call_method1("reshape", (PyTuple::new(py, shape)?,))
    };
    let pairs = |v: Vec<i64>| PyArray1::from_vec(py, v).call_method1("reshape", ((n_events, 2),));
    dict.set_item(
        "event_start",
        PyArray1::from_vec(py, starts(shots, |r| r.time.len())),
    )?;
    dict.set_item("time", PyArray1::from_vec(py, joined(shots, |r| &r.time)))?;
    dict.set_item("type", PyArray1::from_vec(py, joined(shots, |r| &r.types)))?;
    dict.set_item("ball", pairs(joined(shots, |r| &r.ball))?)?;
    dict.set_item(
        "object",
        PyArray1::from_vec(py, joined(shots, |r| &r.object)),
    )?;
    dict.set_item(
        "rvw",
        shaped(joined(shots, |r| &r.rvw), &[n_events, 2, 3, 3])?,
    )?;
    dict.set_item("s", pairs(joined(shots, |r| &r.s))?)?;
    let final_s = joined(shots, |r| &r.final_s);
    let n_balls = final_s.len();
    dict.set_item(
        "final_rvw",
        shaped(joined(shots, |r| &r.final_rvw), &[n_balls, 3, 3])?,
    )?;
    dict.set_item("final_s", PyArray1::from_vec(py, final_s))?;
    let end: Vec<f64> = shots.iter().map(|r| r.end).collect();
    let stopped: Vec<bool> = shots.iter().map(|r| r.stopped).collect();
    dict.set_item("end", PyArray1::from_vec(py, end))?;
    dict.set_item("stopped", PyArray1::from_vec(py, stopped))?;
    dict.set_item("type_names", PyTuple::new(py, ShotEventKind::NAMES)?)?;
    if with_history {
        let history_s = joined(shots, |r| &r.history_s);
        let rows = history_s.len();
        dict.set_item(
            "history_start",
            PyArray1::from_vec(py, starts(shots, |r| r.history_s.len())),
        )?;
        dict.set_item(
            "history_rvw",
            shaped(joined(shots, |r| &r.history_rvw), &[rows, 3, 3])?,
        )?;
        dict.set_item("history_s", PyArray1::from_vec(py, history_s))?;
        dict.set_item(
            "before_rvw",
            shaped(joined(shots, |r| &r.before_rvw), &[n_events, 2, 3, 3])?,
        )?;
        dict.set_item("before_s", pairs(joined(shots, |r| &r.before_s))?)?;
    }
    Ok(dict)
}

/// Appends `state` as pooltool's `rvw` (height `z`, no vertical velocity) and `s`.
fn push_state(rvw: &mut Vec<f64>, s: &mut Vec<i64>, state: &BallState, z: f64) {
    let (r, v, w) = (state.position, state.velocity, state.angular_velocity);
    rvw.extend_from_slice(&[r.x, r.y, z, v.x, v.y, 0.0, w.x, w.y, w.z]);
    s.push(state.motion.code());
}

/// Appends an absent ball: NaN and `-1`.
fn push_missing(rvw: &mut Vec<f64>, s: &mut Vec<i64>) {
    rvw.extend_from_slice(&[f64::NAN; 9]);
    s.push(-1);
}

/// Checks an array's shape.
fn expect_shape(
    py: Python<'_>,
    name: &str,
    shape: &[usize],
    expected: &[usize],
    text: &str,
) -> PyResult<()> {
    if shape == expected {
        return Ok(());
    }
    let reason = format!(
        "expected shape {text} = {}, got {}",
        shape_text(expected),
        shape_text(shape)
    );
    Err(input_error(py, name, None, kind::SHAPE, &reason))
}

/// A one-dimensional array of integers (any real dtype holding whole numbers), of `len` if
/// given.
fn ints(
    py: Python<'_>,
    name: &str,
    obj: &Bound<'_, PyAny>,
    len: Option<usize>,
) -> PyResult<Vec<i64>> {
    let (values, shape) = shaped(name, obj)?;
    let n = len.unwrap_or(shape.first().copied().unwrap_or(0));
    expect_shape(py, name, &shape, &[n], "(N,)")?;
    values
        .values()
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            if x.fract() == 0.0 && x.abs() < 9.0e15 {
                Ok(x as i64)
            } else {
                let reason = format!("expected a whole number, got {x}");
                Err(input_error(py, name, Some(i), kind::OUT_OF_RANGE, &reason))
            }
        })
        .collect()
}

/// `tables`: a list or tuple of `(linear, circular, pockets)` (each a list or tuple); the
/// errors name `tables` at the table's index.
fn read_tables(py: Python<'_>, tables: &Bound<'_, PyAny>) -> PyResult<Vec<BilliardTable>> {
    let sequence =
        |o: &Bound<'_, PyAny>| o.is_instance_of::<PyList>() || o.is_instance_of::<PyTuple>();
    let not_tables = |what: &Bound<'_, PyAny>| -> PyResult<PyErr> {
        Ok(PyTypeError::new_err(format!(
            "tables: expected a list of (linear, circular, pockets), got {}",
            what.get_type().name()?
        )))
    };
    if !sequence(tables) {
        return Err(not_tables(tables)?);
    }
    let mut out = Vec::new();
    for (t, item) in tables.try_iter()?.enumerate() {
        let item = item?;
        if !sequence(&item) {
            return Err(not_tables(&item)?);
        }
        let parts: Vec<Bound<'_, PyAny>> = item.try_iter()?.collect::<PyResult<_>>()?;
        let [linear, circular, pockets] = parts.as_slice() else {
            let reason = format!(
                "expected (linear, circular, pockets), got {} items",
                parts.len()
            );
            return Err(input_error(py, "tables", Some(t), kind::SHAPE, &reason));
        };
        let located = |e: crate::InputError| {
            let reason = e.to_string();
            located_error(
                py,
                "tables",
                [Some(t), None],
                (e.kind().code(), e.kind().value()),
                &reason,
            )
        };
        let mut table = BilliardTable::default();
        for (m, r) in table_rows(py, t, "linear", linear, 6)?.iter().enumerate() {
            let cushion =
                LinearCushion::new(Vector2::new(r[0], r[1]), Vector2::new(r[2], r[3]), r[4]);
            let direction = if r[5].fract() == 0.0 { r[5] as i64 } else { -1 };
            let side = side_of_direction(&cushion, direction)
                .map_err(|e| located(e.renamed("linear direction").at(m)))?;
            table.linear.push((cushion, side));
        }
        for r in table_rows(py, t, "circular", circular, 4)? {
            table
                .circular
                .push(CircularCushion::new(Vector2::new(r[0], r[1]), r[2], r[3]));
        }
        for r in table_rows(py, t, "pockets", pockets, 4)? {
            table
                .pockets
                .push(Pocket::new(Vector2::new(r[0], r[1]), r[2], r[3]));
        }
        // The core's checks.
        table.geometry().map_err(located)?;
        out.push(table);
    }
    Ok(out)
}

/// Rows of `width` numbers (shape `(M, width)`, or `(0,)` for none): part `part` of table
/// `t`.
fn table_rows(
    py: Python<'_>,
    t: usize,
    part: &str,
    obj: &Bound<'_, PyAny>,
    width: usize,
) -> PyResult<Vec<Vec<f64>>> {
    let (values, shape): (Floats<'_>, Vec<usize>) = shaped("tables", obj)?;
    match shape.as_slice() {
        [0] => Ok(Vec::new()),
        [_, w] if *w == width => Ok(values
            .values()
            .chunks_exact(width)
            .map(<[f64]>::to_vec)
            .collect()),
        _ => {
            let reason = format!(
                "{part}: expected shape (M, {width}), got {}",
                shape_text(&shape)
            );
            Err(input_error(py, "tables", Some(t), kind::SHAPE, &reason))
        }
    }
}
