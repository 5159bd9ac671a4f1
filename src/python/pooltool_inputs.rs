//! `_pooltool_inputs`: pooltool `System`s read into [`simulate_shots`]' arguments, for
//! ballcollide.pooltool's `simulate` and `simulate_many` (its serial part): each shot's
//! balls, cue and table, a few hundred attribute reads, ~34 µs a shot on the benchmark's
//! shots (each made with a table of its own), ~6 µs on copies of one `System` (whose
//! tables share their parts).
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
/// loop strikes), and its table (each distinct table read once: see [`TableReader`]). Raises
/// ``ValueError`` for a cue to strike whose ``cue_ball_id`` is not among the balls (where
/// pooltool's loop raises a ``KeyError``). Private: for ``ballcollide.pooltool``.
#[pyfunction]
#[pyo3(name = "_pooltool_inputs")]
pub(super) fn pooltool_inputs<'py>(shots: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let py = shots.py();
    let shots: Vec<Bound<'py, PyAny>> = shots.try_iter()?.collect::<PyResult<_>>()?;
    let mut tables = TableReader::default();
    // Each parameter set's row, read once (balls often share one: a rack's, a game's).
    let mut param_rows: HashMap<usize, [f64; 10]> = HashMap::new();
    let mut shot_table = Vec::with_capacity(shots.len());
    let mut ball_start = vec![0.0];
    let (mut rvw, mut s, mut params) = (Vec::new(), Vec::new(), Vec::new());
    let mut strike = Vec::with_capacity(shots.len());
    let mut cue = Vec::with_capacity(8 * shots.len());
    for (k, system) in shots.iter().enumerate() {
        let table = system.getattr(intern!(py, "table"))?;
        shot_table.push(tables.index_of(&table, k)? as f64);

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
    dict.set_item("tables", PyList::new(py, tables.into_arrays(py)?)?)?;
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

/// A table's rows for `simulate_shots`: `(linear, circular, pockets)`, rows `(p1x, p1y, p2x,
/// p2y, height, direction)`, `(cx, cy, radius, height)` and `(cx, cy, radius, depth)`.
type TableRows = [Vec<f64>; 3];

/// The shots' tables, each distinct one read into rows once.
///
/// Every shot has a table object of its own when its `System` is a copy (`System.copy()`
/// copies the table), and reading one takes a few hundred attribute reads, most of the
/// serial part of `simulate_many` (~34 µs a shot on the benchmark's shots). But the
/// copies share their parts: pooltool's cushion segments are frozen and `copy()` returns the
/// segment itself, and a copied pocket keeps its `center` array. So the parts are read once
/// each by identity (210 copies of `System.example()`: 5.9 µs a shot, against 18.4 for 210
/// made one by one), and tables of equal rows (to the bit) share one index, so that the
/// engine also builds each distinct table once. Each part read is kept alive here for the
/// call, so that no address can be reused by another object meanwhile.
#[derive(Default)]
struct TableReader<'py> {
    /// Each table's index, by the table object's identity.
    by_object: HashMap<usize, (Bound<'py, PyAny>, usize)>,
    /// Each linear cushion's row, by the segment's identity.
    linear: HashMap<usize, (Bound<'py, PyAny>, Vec<f64>)>,
    /// Each circular cushion's row, by the segment's identity.
    circular: HashMap<usize, (Bound<'py, PyAny>, Vec<f64>)>,
    /// Each pocket centre's `(x, y)`, by the array's identity.
    centres: HashMap<usize, (Bound<'py, PyAny>, [f64; 2])>,
    /// Each distinct table's index, by its rows' bits.
    by_rows: HashMap<[Vec<u64>; 3], usize>,
    /// The distinct tables' rows, in index order.
    rows: Vec<TableRows>,
}

impl<'py> TableReader<'py> {
    /// The index of `table`'s rows, read if no table with the same rows was read before.
    /// A point that is not `(x, y, z)` is a `ValueError` naming shot `k`.
    fn index_of(&mut self, table: &Bound<'py, PyAny>, k: usize) -> PyResult<usize> {
        if let Some((_, t)) = self.by_object.get(&(table.as_ptr() as usize)) {
            return Ok(*t);
        }
        let rows = self
            .read(table)
            .map_err(|e| prefixed(table.py(), e, &format!("shots[{k}].table")))?;
        let bits = rows
            .each_ref()
            .map(|v| v.iter().map(|x| x.to_bits()).collect());
        let next = self.rows.len();
        let t = *self.by_rows.entry(bits).or_insert(next);
        if t == next {
            self.rows.push(rows);
        }
        self.by_object
            .insert(table.as_ptr() as usize, (table.clone(), t));
        Ok(t)
    }

    /// `table`'s rows, its segments and pocket centres read once by identity.
    fn read(&mut self, table: &Bound<'py, PyAny>) -> PyResult<TableRows> {
        let py = table.py();
        let segments = table.getattr(intern!(py, "cushion_segments"))?;
        let mut linear = Vec::new();
        for c in dict_values(&segments.getattr(intern!(py, "linear"))?)? {
            // `height` is pooltool's `p1[2]` (a `cached_property`: computing it on a new
            // segment costs 0.6 µs, most of a table's reading), read here from `p1`.
            linear.extend(segment(&mut self.linear, &c, |c| {
                let [x1, y1, height] = xyz(c, intern!(py, "p1"))?;
                let [x2, y2, _] = xyz(c, intern!(py, "p2"))?;
                let direction = field(c, intern!(py, "direction"))?;
                Ok(vec![x1, y1, x2, y2, height, direction])
            })?);
        }
        let mut circular = Vec::new();
        for c in dict_values(&segments.getattr(intern!(py, "circular"))?)? {
            // `height` is pooltool's `center[2]` (as for a linear cushion).
            circular.extend(segment(&mut self.circular, &c, |c| {
                let [x, y, height] = xyz(c, intern!(py, "center"))?;
                Ok(vec![x, y, field(c, intern!(py, "radius"))?, height])
            })?);
        }
        let mut pockets = Vec::new();
        for p in dict_values(&table.getattr(intern!(py, "pockets"))?)? {
            // A pocket is copied with its table (its `contains` is mutable), its centre not.
            let centre = p.getattr(intern!(py, "center"))?;
            let [x, y] = *by_identity(&mut self.centres, &centre, |centre| {
                let [x, y, _] = xyz_of("center", centre)
                    .map_err(|e| prefixed(py, e, &format!("pocket {}", id_of(&p))))?;
                Ok([x, y])
            })?;
            pockets.extend([
                x,
                y,
                field(&p, intern!(py, "radius"))?,
                field(&p, intern!(py, "depth"))?,
            ]);
        }
        Ok([linear, circular, pockets])
    }

    /// The distinct tables' `(linear, circular, pockets)` arrays, in index order.
    fn into_arrays(self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyTuple>>> {
        let array = |values: Vec<f64>, width: usize| {
            let n = values.len() / width;
            PyArray1::from_vec(py, values).reshape([n, width])
        };
        self.rows
            .into_iter()
            .map(|[linear, circular, pockets]| {
                PyTuple::new(
                    py,
                    [array(linear, 6)?, array(circular, 4)?, array(pockets, 4)?],
                )
            })
            .collect()
    }
}

/// What `read` gives for `obj`, from `cache` by `obj`'s identity, read the first time (and
/// `obj` kept, so that its address is not reused during the call).
fn by_identity<'m, 'py, T>(
    cache: &'m mut HashMap<usize, (Bound<'py, PyAny>, T)>,
    obj: &Bound<'py, PyAny>,
    read: impl FnOnce(&Bound<'py, PyAny>) -> PyResult<T>,
) -> PyResult<&'m T> {
    let entry = match cache.entry(obj.as_ptr() as usize) {
        std::collections::hash_map::Entry::Occupied(e) => e.into_mut(),
        std::collections::hash_map::Entry::Vacant(e) => e.insert((obj.clone(), read(obj)?)),
    };
    Ok(&entry.1)
}

/// The row of cushion segment `c` (frozen in pooltool) from `rows`, by `read` the first time
/// (a point that is not `(x, y, z)` named with the segment's id).
fn segment<'m, 'py>(
    rows: &'m mut HashMap<usize, (Bound<'py, PyAny>, Vec<f64>)>,
    c: &Bound<'py, PyAny>,
    read: impl FnOnce(&Bound<'py, PyAny>) -> PyResult<Vec<f64>>,
) -> PyResult<&'m [f64]> {
    let row = by_identity(rows, c, |c| {
        read(c).map_err(|err| prefixed(c.py(), err, &format!("cushion segment {}", id_of(c))))
    })?;
    Ok(row)
}

/// `obj.id`'s repr (`?` if it has none), for errors.
fn id_of(obj: &Bound<'_, PyAny>) -> String {
    obj.getattr("id")
        .and_then(|id| id.repr().map(|r| r.to_string()))
        .unwrap_or_else(|_| "?".to_string())
}

/// `error` with `context: ` before its message if it is a plain `ValueError` (the point
/// errors here); any other error (an `InputError` naming its argument) as it is.
fn prefixed(py: Python<'_>, error: PyErr, context: &str) -> PyErr {
    if error.get_type(py).is(py.get_type::<PyValueError>()) {
        PyValueError::new_err(format!("{context}: {}", error.value(py)))
    } else {
        error
    }
}

/// The number `obj.name`.
fn field(obj: &Bound<'_, PyAny>, name: &Bound<'_, PyString>) -> PyResult<f64> {
    number(&name.to_cow()?, &obj.getattr(name)?)
}

/// The coordinates of `obj.name` (a point of pooltool's, `(x, y, z)`).
fn xyz(obj: &Bound<'_, PyAny>, name: &Bound<'_, PyString>) -> PyResult<[f64; 3]> {
    xyz_of(&name.to_cow()?, &obj.getattr(name)?)
}

/// The coordinates of point `value`, named `name` in errors.
fn xyz_of(name: &str, value: &Bound<'_, PyAny>) -> PyResult<[f64; 3]> {
    let (values, _) = shaped(name, value)?;
    match values.values() {
        [x, y, z] => Ok([*x, *y, *z]),
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
