//! `_pooltool_inputs`: pooltool `System`s read into [`simulate_shots`]' arguments, for
//! ballcollide.pooltool's `simulate` and `simulate_many` (its serial part): each shot's
//! balls, cue and table, a few hundred attribute reads, about 45 µs a shot in Python on the
//! benchmark's shots and 24 µs here.
//!
//! [`simulate_shots`]: super::shots::simulate_shots

use std::collections::HashMap;

use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};

use super::read::{number, shaped};

/// A ball's parameters in [`simulate_shots`](super::shots::simulate_shots)' order (its
/// `params` rows).
const PARAM_FIELDS: [&str; 10] = [
    "m",
    "R",
    "u_s",
    "u_r",
    "u_sp_proportionality",
    "u_b",
    "e_b",
    "e_c",
    "f_c",
    "g",
];

/// ``_core.simulate_shots``' arguments (a dict: ``tables``, ``shot_table``, ``ball_start``,
/// ``rvw``, ``s``, ``params``, ``strike``, ``cue``) for a sequence of pooltool ``System`` s:
/// each shot's balls (in ``balls`` order: ``state.rvw``, ``state.s``, ``params``), its cue's
/// stroke, struck at time 0 only when ``V0 > 0`` and no ball moves or spins (as pooltool's
/// loop strikes), and its table (tables shared by identity are read once). Raises
/// ``ValueError`` for a cue to strike whose ``cue_ball_id`` is not among the balls (where
/// pooltool's loop raises a ``KeyError``). Private: for ``ballcollide.pooltool``.
#[pyfunction]
#[pyo3(name = "_pooltool_inputs")]
pub(super) fn pooltool_inputs<'py>(shots: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let py = shots.py();
    let shots: Vec<Bound<'py, PyAny>> = shots.try_iter()?.collect::<PyResult<_>>()?;
    let mut tables = Vec::new();
    // Each table read so far, by identity (the tables are held meanwhile, by their shots).
    let mut table_of: HashMap<usize, usize> = HashMap::new();
    // Each parameter set's row, read once (balls often share one: a rack's, a game's).
    let mut param_rows: HashMap<usize, [f64; 10]> = HashMap::new();
    let mut shot_table = Vec::with_capacity(shots.len());
    let mut ball_start = vec![0.0];
    let (mut rvw, mut s, mut params) = (Vec::new(), Vec::new(), Vec::new());
    let mut strike = Vec::with_capacity(shots.len());
    let mut cue = Vec::with_capacity(8 * shots.len());
    for (k, system) in shots.iter().enumerate() {
        let table = system.getattr(intern!(py, "table"))?;
        let next = table_of.len();
        let t = *table_of.entry(table.as_ptr() as usize).or_insert(next);
        if t == next {
            tables.push(table_arrays(&table)?);
        }
        shot_table.push(t as f64);

        let balls = dict_values(&system.getattr(intern!(py, "balls"))?)?;
        let mut moving = false;
        for ball in &balls {
            let state = ball.getattr(intern!(py, "state"))?;
            let (values, _) = shaped("rvw", &state.getattr(intern!(py, "rvw"))?)?;
            let values = values.values();
            if values.len() != 9 {
                return Err(PyValueError::new_err(format!(
                    "shots[{k}]: ball {}'s state.rvw holds {} numbers, not 3 × 3",
                    ball.getattr(intern!(py, "id"))?.repr()?,
                    values.len()
                )));
            }
            // pooltool strikes only a table at rest: no velocity, no spin (NaN counts).
            moving |= values[3..].iter().any(|&x| x != 0.0);
            rvw.extend_from_slice(values);
            s.push(field(&state, intern!(py, "s"))?);
            let p = ball.getattr(intern!(py, "params"))?;
            let row = match param_rows.get(&(p.as_ptr() as usize)) {
                Some(row) => *row,
                None => {
                    let mut row = [0.0; 10];
                    for (x, name) in row.iter_mut().zip(PARAM_FIELDS) {
                        *x = number(name, &p.getattr(name)?)?;
                    }
                    // The parameter sets are held meanwhile, by their balls.
                    param_rows.insert(p.as_ptr() as usize, row);
                    row
                }
            };
            params.extend_from_slice(&row);
        }
        ball_start.push(ball_start[k] + balls.len() as f64);

        let c = system.getattr(intern!(py, "cue"))?;
        let v0 = field(&c, intern!(py, "V0"))?;
        if v0 > 0.0 && !moving {
            let id = c.getattr(intern!(py, "cue_ball_id"))?;
            let mut at = None;
            for (i, ball) in balls.iter().enumerate() {
                if ball.getattr(intern!(py, "id"))?.eq(&id)? {
                    at = Some(i);
                    break;
                }
            }
            let Some(i) = at else {
                // pooltool's own loop raises a KeyError here.
                return Err(PyValueError::new_err(format!(
                    "shots[{k}]: the cue's ball {} is not among the balls",
                    id.repr()?
                )));
            };
            strike.push(i as f64);
        } else {
            strike.push(-1.0);
        }
        let specs = c.getattr(intern!(py, "specs"))?;
        cue.extend([
            v0,
            field(&c, intern!(py, "phi"))?,
            field(&c, intern!(py, "theta"))?,
            field(&c, intern!(py, "a"))?,
            field(&c, intern!(py, "b"))?,
            field(&specs, intern!(py, "M"))?,
            field(&specs, intern!(py, "end_mass"))?,
            field(&specs, intern!(py, "tip_radius"))?,
        ]);
    }

    let n_balls = s.len();
    let dict = PyDict::new(py);
    dict.set_item("tables", PyList::new(py, tables)?)?;
    dict.set_item("shot_table", PyArray1::from_vec(py, shot_table))?;
    dict.set_item("ball_start", PyArray1::from_vec(py, ball_start))?;
    dict.set_item("rvw", PyArray1::from_vec(py, rvw).reshape([n_balls, 3, 3])?)?;
    dict.set_item("s", PyArray1::from_vec(py, s))?;
    dict.set_item(
        "params",
        PyArray1::from_vec(py, params).reshape([n_balls, 10])?,
    )?;
    dict.set_item("strike", PyArray1::from_vec(py, strike))?;
    dict.set_item(
        "cue",
        PyArray1::from_vec(py, cue).reshape([shots.len(), 8])?,
    )?;
    Ok(dict)
}

/// A pooltool table as `simulate_shots`' `(linear, circular, pockets)`: rows `(p1x, p1y,
/// p2x, p2y, height, direction)`, `(cx, cy, radius, height)` and `(cx, cy, radius, depth)`.
fn table_arrays<'py>(table: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyTuple>> {
    let py = table.py();
    let segments = table.getattr(intern!(py, "cushion_segments"))?;
    let mut linear = Vec::new();
    for c in dict_values(&segments.getattr(intern!(py, "linear"))?)? {
        let [x1, y1] = xy(&c, intern!(py, "p1"))?;
        let [x2, y2] = xy(&c, intern!(py, "p2"))?;
        let height = field(&c, intern!(py, "height"))?;
        let direction = field(&c, intern!(py, "direction"))?;
        linear.extend([x1, y1, x2, y2, height, direction]);
    }
    // Rows `(cx, cy, radius, last)`: a circular cushion's height, a pocket's depth.
    let discs = |items: Vec<Bound<'py, PyAny>>, last: &Bound<'py, PyString>| {
        let mut rows = Vec::with_capacity(4 * items.len());
        for c in items {
            let [x, y] = xy(&c, intern!(py, "center"))?;
            let radius = field(&c, intern!(py, "radius"))?;
            rows.extend([x, y, radius, field(&c, last)?]);
        }
        PyResult::Ok(rows)
    };
    let circular = discs(
        dict_values(&segments.getattr(intern!(py, "circular"))?)?,
        intern!(py, "height"),
    )?;
    let pockets = discs(
        dict_values(&table.getattr(intern!(py, "pockets"))?)?,
        intern!(py, "depth"),
    )?;
    let rows = |values: Vec<f64>, width: usize| {
        let n = values.len() / width;
        PyArray1::from_vec(py, values).reshape([n, width])
    };
    PyTuple::new(
        py,
        [rows(linear, 6)?, rows(circular, 4)?, rows(pockets, 4)?],
    )
}

/// The number `obj.name`.
fn field(obj: &Bound<'_, PyAny>, name: &Bound<'_, PyString>) -> PyResult<f64> {
    number(&name.to_cow()?, &obj.getattr(name)?)
}

/// The first two coordinates of `obj.name` (a point of pooltool's, `(x, y, z)`).
fn xy(obj: &Bound<'_, PyAny>, name: &Bound<'_, PyString>) -> PyResult<[f64; 2]> {
    let (values, _) = shaped(&name.to_cow()?, &obj.getattr(name)?)?;
    match values.values() {
        [x, y, ..] => Ok([*x, *y]),
        _ => Err(PyValueError::new_err(format!(
            "{name}: expected a point (x, y, z), got {} numbers",
            values.values().len()
        ))),
    }
}

/// A dict's values, in order.
fn dict_values<'py>(dict: &Bound<'py, PyAny>) -> PyResult<Vec<Bound<'py, PyAny>>> {
    dict.call_method0(intern!(dict.py(), "values"))?
        .try_iter()?
        .collect()
}
