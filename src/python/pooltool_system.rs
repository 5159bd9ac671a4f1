//! `_PooltoolBuilder`: one shot of [`simulate_shots`](super::shots::simulate_shots)'
//! results (with history) written into a pooltool `System` as pooltool 0.6.0's `simulate`
//! leaves it: each ball's history (its state at every event), its state, the events with
//! their agents' `initial` and `final` copies, the pockets' contents, `t`.
//!
//! Built here rather than in Python because a shot's `System` holds thousands of objects (a
//! break: ~800 `BallState`s, each with its own `(3, 3)` array, and ~170 history-free ball
//! copies with two `BallHistory`s each): pooltool's attrs constructors cost about a
//! microsecond an object, and even setting the slots from Python bytecode costs most of
//! that. Each object is made as `object.__new__(cls)` with its fields set as
//! `object.__setattr__` sets them (past attrs' converters and validators, which these
//! values, pooltool's own types, pass already), so the objects are instances of pooltool's
//! classes with the values its own `simulate` gives them. ballcollide.pooltool's `_build`
//! calls it.

use std::ffi::c_int;
use std::ptr;

use numpy::npyffi::{
    NPY_ARRAY_CARRAY, NPY_TYPES, NpyTypes, PY_ARRAY_API, get_type_object, npy_intp,
};
use numpy::{Element, PyArray1, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn};
use pyo3::exceptions::{PyKeyError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple, PyType};
use pyo3::{ffi, intern};

use crate::billiards::ShotEventKind;

/// Builds pooltool's objects from [`simulate_shots`](super::shots::simulate_shots)'
/// results: ``_PooltoolBuilder(types)``, where ``types`` maps ``BallState``,
/// ``BallHistory``, ``Ball``, ``Agent``, ``Event``, ``AgentType``, ``EventType`` and
/// ``null_event`` to pooltool's own (made once: it looks up how to fill each class's
/// fields); ``build`` writes one shot into a ``System``. Private: for
/// ``ballcollide.pooltool``.
#[pyclass(frozen, name = "_PooltoolBuilder", module = "ballcollide._core")]
pub(super) struct PooltoolBuilder {
    ball_state: Class,
    ball_history: Class,
    /// `Ball`: its fields other than `state`, `history` and `history_cts` (which a copy takes
    /// from its ball, as pooltool's `Ball.copy` does), then those three.
    ball: Class,
    agent: Class,
    event: Class,
    agent_types: AgentTypes,
    /// pooltool's `EventType` of each of [`ShotEventKind::NAMES`].
    event_types: Vec<Py<PyAny>>,
    null_event: Py<PyAny>,
}

#[pymethods]
impl PooltoolBuilder {
    #[new]
    fn new(types: &Bound<'_, PyDict>) -> PyResult<Self> {
        let ball_type = types_item(types, "Ball")?.cast_into::<PyType>()?;
        let own = ["state", "history", "history_cts"];
        let mut ball_fields = Vec::new();
        for field in ball_type.getattr("__attrs_attrs__")?.try_iter()? {
            let name: String = field?.getattr("name")?.extract()?;
            if !own.contains(&name.as_str()) {
                ball_fields.push(name);
            }
        }
        ball_fields.extend(own.map(String::from));
        let ball_fields: Vec<&str> = ball_fields.iter().map(String::as_str).collect();
        let agent_type = types_item(types, "AgentType")?;
        let event_type = types_item(types, "EventType")?;
        let agent = |name: &str| agent_type.getattr(name).map(Bound::unbind);
        Ok(Self {
            ball_state: Class::of(types, "BallState", &["rvw", "s", "t"])?,
            ball_history: Class::of(types, "BallHistory", &["states"])?,
            ball: Class::of(types, "Ball", &ball_fields)?,
            agent: Class::of(types, "Agent", &["id", "agent_type", "initial", "final"])?,
            event: Class::of(types, "Event", &["event_type", "agents", "time"])?,
            agent_types: AgentTypes {
                ball: agent("BALL")?,
                cue: agent("CUE")?,
                linear: agent("LINEAR_CUSHION_SEGMENT")?,
                circular: agent("CIRCULAR_CUSHION_SEGMENT")?,
                pocket: agent("POCKET")?,
            },
            event_types: ShotEventKind::NAMES
                .iter()
                .map(|name| event_type.call1((*name,)).map(Bound::unbind))
                .collect::<PyResult<_>>()?,
            null_event: types_item(types, "null_event")?.unbind(),
        })
    }

    /// Writes shot ``k`` of ``results`` (``_core.simulate_shots``' dict, computed with
    /// ``history=True``) into ``system`` (that shot's pooltool ``System``, or a copy), as
    /// pooltool's ``simulate`` leaves it: its balls' ``history``, ``history_cts`` and
    /// ``state``, its pockets' ``contains``, ``events`` and ``t``. With ``new_balls``, each
    /// ball in ``system.balls`` is replaced by a new one (a copy with these fields, sharing
    /// the others, as ``Ball.copy`` does) rather than written into.
    fn build<'py>(
        &self,
        system: &Bound<'py, PyAny>,
        results: &Bound<'py, PyDict>,
        k: usize,
        new_balls: bool,
    ) -> PyResult<()> {
        let py = system.py();
        let agent_types = &self.agent_types;
        let columns = Columns::read(results)?;
        let shot = columns.shot(k)?;
        let ball_dict = system.getattr(intern!(py, "balls"))?;
        let keys: Vec<Bound<'py, PyAny>> = ball_dict.try_iter()?.collect::<PyResult<_>>()?;
        let balls: Vec<Bound<'py, PyAny>> = keys
            .iter()
            .map(|key| ball_dict.get_item(key))
            .collect::<PyResult<_>>()?;
        // What each ball's copies (the agents', and with `new_balls` the system's own) share
        // with it.
        let copies: Vec<BallCopy<'py>> = balls
            .iter()
            .map(|ball| self.ball_copy_of(ball))
            .collect::<PyResult<_>>()?;
        let n = balls.len();
        let n_events = shot.time.len();
        if shot.history_s.len() != n * (n_events + 2) {
            return Err(PyValueError::new_err(format!(
                "results: shot {k} has {} history rows, not (events + 2) × balls = {}",
                shot.history_s.len(),
                n * (n_events + 2)
            )));
        }

        // Every state's rvw, in one new array: the history's rows, then each event's two slots
        // before it, then after it.
        let history_rows = shot.history_s.len();
        let before_at = history_rows;
        let after_at = before_at + shot.before_s.len();
        let block = RvwBlock::new(py, &[shot.history_rvw, shot.before_rvw, shot.rvw])?;

        // The event times as Python floats, shared by every state at an event as pooltool's
        // `ball.state.t = event.time` shares them; the first is the strike's 0.0.
        let mut times = Vec::with_capacity(n_events + 1);
        times.push(0.0f64.into_pyobject(py)?.into_any());
        for &t in shot.time {
            times.push(t.into_pyobject(py)?.into_any());
        }
        // The last event's (0.0 without events).
        let end = times[n_events].clone();

        // Each ball's history: its state at time 0 and after each event (rows `e * n + b`),
        // then the last again, the same object: pooltool adds the ball's state at the closing
        // null event without a copy. The ball's state is that last one.
        for (b, ((key, ball), copy)) in keys.iter().zip(&balls).zip(&copies).enumerate() {
            let mut own = Vec::with_capacity(n_events + 2);
            for (e, t) in times.iter().enumerate() {
                let row = e * n + b;
                own.push(self.state(block.row(row)?, shot.history_s[row], t)?);
            }
            let last = own[n_events].clone();
            own.push(last.clone());
            let history = self.history(PyList::new(py, own)?)?;
            let history_cts = self.history(PyList::empty(py))?;
            if new_balls {
                let own = [&last, &history, &history_cts];
                let ball = self.ball.make(py, copy.fields.iter().chain(own))?;
                ball_dict.set_item(key, ball)?;
            } else {
                put(ball, intern!(py, "history"), &history)?;
                put(ball, intern!(py, "history_cts"), &history_cts)?;
                put(ball, intern!(py, "state"), &last)?;
            }
        }

        let table = system.getattr(intern!(py, "table"))?;
        let segments = table.getattr(intern!(py, "cushion_segments"))?;
        let values = |dict: Bound<'py, PyAny>| -> PyResult<Vec<Bound<'py, PyAny>>> {
            dict.call_method0(intern!(py, "values"))?
                .try_iter()?
                .collect()
        };
        let linear = values(segments.getattr(intern!(py, "linear"))?)?;
        let circular = values(segments.getattr(intern!(py, "circular"))?)?;
        let pockets = values(table.getattr(intern!(py, "pockets"))?)?;
        let id = intern!(py, "id");
        let object_at = |list: &[Bound<'py, PyAny>], e: usize| -> PyResult<Bound<'py, PyAny>> {
            usize::try_from(shot.object[e])
                .ok()
                .and_then(|i| list.get(i))
                .cloned()
                .ok_or_else(|| {
                    PyValueError::new_err(format!(
                        "results: event {e}'s object {} is not in the table",
                        shot.object[e]
                    ))
                })
        };

        let null_event = self.null_event.bind(py);
        let mut events = Vec::with_capacity(n_events + 2);
        // pooltool starts with `null_event(time=0)`: an int.
        events.push(null_event.call1((0,))?);
        for e in 0..n_events {
            let code = shot.kind[e];
            let (Some(name), Some(kind)) = (
                usize::try_from(code)
                    .ok()
                    .and_then(|c| ShotEventKind::NAMES.get(c)),
                usize::try_from(code)
                    .ok()
                    .and_then(|c| self.event_types.get(c)),
            ) else {
                return Err(PyValueError::new_err(format!(
                    "results: event {e}'s type {code} is unknown"
                )));
            };
            let t = &times[e + 1];
            let mut agents = Vec::with_capacity(3);
            for slot in 2 * e..2 * e + 2 {
                let Ok(b) = usize::try_from(shot.ball[slot]) else {
                    continue;
                };
                let ball = copies.get(b).ok_or_else(|| {
                    PyValueError::new_err(format!(
                        "results: event {e}'s ball {b} is not in the shot"
                    ))
                })?;
                let before = self.state(block.row(before_at + slot)?, shot.before_s[slot], t)?;
                let initial = self.ball_copy(ball, before)?;
                let after = self.state(block.row(after_at + slot)?, shot.s[slot], t)?;
                let last = self.ball_copy(ball, after)?;
                agents.push(self.agent(&ball.id, &agent_types.ball, &initial, &last)?);
            }
            let none = py.None().into_bound(py);
            match *name {
                "stick_ball" => {
                    let cue = system.getattr(intern!(py, "cue"))?;
                    let initial = cue.call_method0(intern!(py, "copy"))?;
                    let agent = self.agent(&cue.getattr(id)?, &agent_types.cue, &initial, &none)?;
                    agents.insert(0, agent);
                }
                "ball_linear_cushion" | "ball_circular_cushion" => {
                    let (list, kind) = if *name == "ball_linear_cushion" {
                        (&linear, &agent_types.linear)
                    } else {
                        (&circular, &agent_types.circular)
                    };
                    let c = object_at(list, e)?;
                    agents.push(self.agent(&c.getattr(id)?, kind, &c, &none)?);
                }
                "ball_pocket" => {
                    let p = object_at(&pockets, e)?;
                    let initial = p.call_method0(intern!(py, "copy"))?;
                    let ball = usize::try_from(shot.ball[2 * e])
                        .ok()
                        .and_then(|b| copies.get(b))
                        .ok_or_else(|| PyValueError::new_err(format!("event {e}: no ball")))?;
                    p.call_method1(intern!(py, "add"), (&ball.id,))?;
                    let last = p.call_method0(intern!(py, "copy"))?;
                    agents.push(self.agent(
                        &p.getattr(id)?,
                        &agent_types.pocket,
                        &initial,
                        &last,
                    )?);
                }
                _ => {}
            }
            events.push(self.event(kind, &PyTuple::new(py, agents)?, t)?);
        }
        events.push(null_event.call1((&end,))?);
        system.setattr(intern!(py, "events"), PyList::new(py, events)?)?;
        system.setattr(intern!(py, "t"), end)?;
        Ok(())
    }
}

/// The results' arrays, borrowed (read in place: the GIL is held throughout, and the
/// arrays are referenced, so nothing frees or moves their memory meanwhile).
struct Columns<'py> {
    event_start: PyReadonlyArrayDyn<'py, i64>,
    history_start: PyReadonlyArrayDyn<'py, i64>,
    time: PyReadonlyArrayDyn<'py, f64>,
    kind: PyReadonlyArrayDyn<'py, i64>,
    ball: PyReadonlyArrayDyn<'py, i64>,
    object: PyReadonlyArrayDyn<'py, i64>,
    rvw: PyReadonlyArrayDyn<'py, f64>,
    s: PyReadonlyArrayDyn<'py, i64>,
    before_rvw: PyReadonlyArrayDyn<'py, f64>,
    before_s: PyReadonlyArrayDyn<'py, i64>,
    history_rvw: PyReadonlyArrayDyn<'py, f64>,
    history_s: PyReadonlyArrayDyn<'py, i64>,
}

/// Shot `k`'s rows of the [`Columns`].
struct ShotRows<'a> {
    time: &'a [f64],
    kind: &'a [i64],
    /// Two slots an event (`-1`: none), as `s`, `rvw` (9 values a slot), `before_*`.
    ball: &'a [i64],
    object: &'a [i64],
    rvw: &'a [f64],
    s: &'a [i64],
    before_rvw: &'a [f64],
    before_s: &'a [i64],
    /// `(events + 2) × balls` rows, row-major by event.
    history_rvw: &'a [f64],
    history_s: &'a [i64],
}

impl<'py> Columns<'py> {
    fn read(results: &Bound<'py, PyDict>) -> PyResult<Self> {
        Ok(Self {
            event_start: column(results, "event_start")?,
            history_start: column(results, "history_start")?,
            time: column(results, "time")?,
            kind: column(results, "type")?,
            ball: column(results, "ball")?,
            object: column(results, "object")?,
            rvw: column(results, "rvw")?,
            s: column(results, "s")?,
            before_rvw: column(results, "before_rvw")?,
            before_s: column(results, "before_s")?,
            history_rvw: column(results, "history_rvw")?,
            history_s: column(results, "history_s")?,
        })
    }

    fn shot(&self, k: usize) -> PyResult<ShotRows<'_>> {
        let offsets =
            |key: &str, column: &PyReadonlyArrayDyn<'py, i64>| -> PyResult<(usize, usize)> {
                let v = part(key, column, k..k + 2)?;
                match (usize::try_from(v[0]), usize::try_from(v[1])) {
                    (Ok(a), Ok(b)) if a <= b => Ok((a, b)),
                    _ => Err(PyValueError::new_err(format!(
                        "results[{key:?}]: shot {k}'s offsets {} and {} are not a range",
                        v[0], v[1]
                    ))),
                }
            };
        let (e0, e1) = offsets("event_start", &self.event_start)?;
        let (h0, h1) = offsets("history_start", &self.history_start)?;
        Ok(ShotRows {
            time: part("time", &self.time, e0..e1)?,
            kind: part("type", &self.kind, e0..e1)?,
            ball: part("ball", &self.ball, 2 * e0..2 * e1)?,
            object: part("object", &self.object, e0..e1)?,
            rvw: part("rvw", &self.rvw, 18 * e0..18 * e1)?,
            s: part("s", &self.s, 2 * e0..2 * e1)?,
            before_rvw: part("before_rvw", &self.before_rvw, 18 * e0..18 * e1)?,
            before_s: part("before_s", &self.before_s, 2 * e0..2 * e1)?,
            history_rvw: part("history_rvw", &self.history_rvw, 9 * h0..9 * h1)?,
            history_s: part("history_s", &self.history_s, h0..h1)?,
        })
    }
}

/// `results[key]`, an array of `T`, borrowed for reading.
fn column<'py, T: Element>(
    results: &Bound<'py, PyDict>,
    key: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, T>> {
    let item = results
        .get_item(key)?
        .ok_or_else(|| PyKeyError::new_err(format!("results: no {key:?}")))?;
    Ok(item.cast::<PyArrayDyn<T>>()?.try_readonly()?)
}

/// Values `range` of a column (C-ordered, read flat).
fn part<'a, T: Element>(
    key: &str,
    column: &'a PyReadonlyArrayDyn<'_, T>,
    range: std::ops::Range<usize>,
) -> PyResult<&'a [T]> {
    let values = column
        .as_slice()
        .map_err(|e| PyValueError::new_err(format!("results[{key:?}]: {e}")))?;
    values.get(range.clone()).ok_or_else(|| {
        PyValueError::new_err(format!(
            "results[{key:?}]: {} values, not the {}..{} of the shot",
            values.len(),
            range.start,
            range.end
        ))
    })
}

fn types_item<'py>(types: &Bound<'py, PyDict>, key: &str) -> PyResult<Bound<'py, PyAny>> {
    types
        .get_item(key)?
        .ok_or_else(|| PyKeyError::new_err(format!("types: no {key:?}")))
}

/// `AgentType`'s members the agents use.
struct AgentTypes {
    ball: Py<PyAny>,
    cue: Py<PyAny>,
    linear: Py<PyAny>,
    circular: Py<PyAny>,
    pocket: Py<PyAny>,
}

/// The fields a ball's copies share with it (all but the last three of
/// `PooltoolBuilder::ball`'s).
struct BallCopy<'py> {
    id: Bound<'py, PyAny>,
    fields: Vec<Bound<'py, PyAny>>,
}

impl PooltoolBuilder {
    /// `BallState(rvw, s, t)`.
    fn state<'py>(
        &self,
        rvw: Bound<'py, PyAny>,
        s: i64,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = rvw.py();
        self.ball_state
            .make(py, [&rvw, s.into_pyobject(py)?.as_any(), t])
    }

    /// `BallHistory(states)`.
    fn history<'py>(&self, states: Bound<'py, PyList>) -> PyResult<Bound<'py, PyAny>> {
        self.ball_history.make(states.py(), [states.as_any()])
    }

    /// What the copies of `ball` share with it.
    fn ball_copy_of<'py>(&self, ball: &Bound<'py, PyAny>) -> PyResult<BallCopy<'py>> {
        let py = ball.py();
        let shared = self.ball.fields.len().saturating_sub(3);
        Ok(BallCopy {
            id: ball.getattr(intern!(py, "id"))?,
            fields: self.ball.fields[..shared]
                .iter()
                .map(|(name, _)| ball.getattr(name.bind(py)))
                .collect::<PyResult<_>>()?,
        })
    }

    /// `ball.copy(drop_history=True)` with state `state`, for the ball `copy` is of.
    fn ball_copy<'py>(
        &self,
        copy: &BallCopy<'py>,
        state: Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = state.py();
        let history = self.history(PyList::empty(py))?;
        let history_cts = self.history(PyList::empty(py))?;
        let own = [&state, &history, &history_cts];
        self.ball.make(py, copy.fields.iter().chain(own))
    }

    /// `Agent(id, agent_type, initial, final)`.
    fn agent<'py>(
        &self,
        id: &Bound<'py, PyAny>,
        agent_type: &Py<PyAny>,
        initial: &Bound<'py, PyAny>,
        last: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = id.py();
        self.agent
            .make(py, [id, agent_type.bind(py), initial, last])
    }

    /// `Event(event_type, agents, time)`.
    fn event<'py>(
        &self,
        event_type: &Py<PyAny>,
        agents: &Bound<'py, PyTuple>,
        time: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = time.py();
        self.event
            .make(py, [event_type.bind(py), agents.as_any(), time])
    }
}

/// One of pooltool's (attrs, slotted) classes, made without its `__init__`.
struct Class {
    ty: Py<PyType>,
    /// The fields `make` sets, in its order: each name and, for a `__slots__` member, the
    /// offset in an instance where its value is kept.
    fields: Vec<(Py<PyString>, Option<usize>)>,
}

impl Class {
    /// `types[key]`, with `fields`.
    fn of(types: &Bound<'_, PyDict>, key: &str, fields: &[&str]) -> PyResult<Self> {
        let py = types.py();
        let ty = types_item(types, key)?.cast_into::<PyType>()?;
        // `make` allocates as `object.__new__` does: only for classes that it makes.
        let object_new = py.get_type::<PyAny>().getattr(intern!(py, "__new__"))?;
        if !ty.getattr(intern!(py, "__new__"))?.is(&object_new) {
            return Err(PyTypeError::new_err(format!(
                "types[{key:?}]: {} has a __new__ of its own",
                ty.name()?
            )));
        }
        let mut class = Self {
            ty: ty.unbind(),
            fields: Vec::with_capacity(fields.len()),
        };
        for &name in fields {
            let name = PyString::intern(py, name);
            let offset = class.slot_offset(&name)?;
            class.fields.push((name.unbind(), offset));
        }
        Ok(class)
    }

    /// `object.__new__(cls)`: an instance with no field set.
    fn blank<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let no_args = PyTuple::empty(py);
        // SAFETY: the class's `__new__` is `object.__new__` (checked in `of`), which makes
        // an instance by the class's `tp_alloc`, as `PyType_GenericNew` does; the arguments
        // are not read.
        unsafe {
            Bound::from_owned_ptr_or_err(
                py,
                ffi::PyType_GenericNew(self.ty.as_ptr().cast(), no_args.as_ptr(), ptr::null_mut()),
            )
        }
    }

    /// A new instance with `values` in its fields, as `object.__new__(cls)` followed by
    /// `object.__setattr__(obj, field, value)` for each: what attrs' `__init__` leaves, for
    /// values it would neither convert nor reject.
    fn make<'a, 'py: 'a>(
        &self,
        py: Python<'py>,
        values: impl IntoIterator<Item = &'a Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let o = self.blank(py)?;
        let mut set = 0;
        for ((name, offset), value) in self.fields.iter().zip(values) {
            match offset {
                // SAFETY: `offset` is where instances of this class keep this slot (found by
                // `slot_offset`), word-aligned inside the instance; `o` is one, and alive.
                // What the slot's descriptor does: take a reference to the new value, drop
                // the old one (none in a new instance).
                Some(offset) => unsafe {
                    let slot = o
                        .as_ptr()
                        .cast::<u8>()
                        .add(*offset)
                        .cast::<*mut ffi::PyObject>();
                    ffi::Py_XDECREF(slot.replace(value.clone().into_ptr()));
                },
                None => put(&o, name.bind(py), value)?,
            }
            set += 1;
        }
        if set != self.fields.len() {
            return Err(PyValueError::new_err(format!(
                "{}: {set} of its {} fields given",
                self.ty.bind(py).name()?,
                self.fields.len()
            )));
        }
        Ok(o)
    }

    /// Where an instance keeps field `name` (a byte offset), if it is a `__slots__` member:
    /// found by setting it on a new instance to an object of our own and looking for that
    /// object's address among the instance's words (`__basicsize__` bytes), then checked by
    /// deleting it (the word becomes null). A slot's descriptor keeps its value at a fixed
    /// offset in every instance of the class; the stable ABI only hides where, and setting
    /// it through the descriptor costs a lookup and two calls for each of a shot's thousands
    /// of fields. Anything else (a property, a field in `__dict__`) is set through
    /// `object.__setattr__` (`None`).
    fn slot_offset(&self, name: &Bound<'_, PyString>) -> PyResult<Option<usize>> {
        let py = name.py();
        let ty = self.ty.bind(py);
        let member = py
            .import(intern!(py, "types"))?
            .getattr(intern!(py, "MemberDescriptorType"))?;
        let Ok(descriptor) = ty.getattr(name) else {
            return Ok(None);
        };
        if !descriptor.get_type().is(&member) {
            return Ok(None);
        }
        let size: usize = ty.getattr(intern!(py, "__basicsize__"))?.extract()?;
        let word = size_of::<*mut ffi::PyObject>();
        let probe = self.blank(py)?;
        let marker = PyList::empty(py);
        if put(&probe, name, marker.as_any()).is_err() {
            return Ok(None);
        }
        let words = probe.as_ptr().cast::<*mut ffi::PyObject>();
        // SAFETY: an instance spans `__basicsize__` bytes from its address, all initialised
        // (the allocation zeroes them), and is word-aligned.
        let read = |w: usize| unsafe { words.add(w).read() };
        let header = size_of::<ffi::PyObject>() / word;
        let mut found = (header..size / word).filter(|&w| read(w) == marker.as_ptr());
        let (Some(at), None) = (found.next(), found.next()) else {
            return Ok(None);
        };
        // SAFETY: live objects; a null value deletes the field through its descriptor.
        let deleted =
            unsafe { ffi::PyObject_GenericSetAttr(probe.as_ptr(), name.as_ptr(), ptr::null_mut()) };
        if deleted < 0 {
            drop(PyErr::fetch(py));
            return Ok(None);
        }
        Ok(read(at).is_null().then_some(at * word))
    }
}

/// `object.__setattr__(obj, name, value)`: through the class's descriptor, past its own
/// `__setattr__` (attrs' converters and validators).
fn put(
    obj: &Bound<'_, PyAny>,
    name: &Bound<'_, PyString>,
    value: &Bound<'_, PyAny>,
) -> PyResult<()> {
    // SAFETY: three live objects; the call borrows them.
    let status =
        unsafe { ffi::PyObject_GenericSetAttr(obj.as_ptr(), name.as_ptr(), value.as_ptr()) };
    if status < 0 {
        Err(PyErr::fetch(obj.py()))
    } else {
        Ok(())
    }
}

/// The `rvw` of a shot's states: one new float64 array of their rows (9 values each), whose
/// rows are handed out as `(3, 3)` views. One allocation for the shot instead of one a state;
/// each state still has its own memory (its row), as pooltool's own `rvw`s, which are mostly
/// views too.
struct RvwBlock<'py> {
    array: Bound<'py, PyArray1<f64>>,
    rows: usize,
}

impl<'py> RvwBlock<'py> {
    /// The rows of `parts` (each a multiple of 9 values long), one after the other.
    fn new(py: Python<'py>, parts: &[&[f64]]) -> PyResult<Self> {
        let len: usize = parts.iter().map(|p| p.len()).sum();
        // SAFETY: every value of the new (uninitialised) array is written below, before the
        // array is read or handed out.
        let array = unsafe { PyArray1::<f64>::new(py, len, false) };
        let mut at = 0;
        for part in parts {
            // SAFETY: `at + part.len() <= len`, the array's length; `part` is other memory.
            unsafe { ptr::copy_nonoverlapping(part.as_ptr(), array.data().add(at), part.len()) };
            at += part.len();
        }
        Ok(Self {
            array,
            rows: len / 9,
        })
    }

    /// Row `i` as a C-ordered, writeable `(3, 3)` view, based on the block (which its memory
    /// is part of).
    fn row(&self, i: usize) -> PyResult<Bound<'py, PyAny>> {
        let py = self.array.py();
        if i >= self.rows {
            return Err(PyValueError::new_err(format!(
                "results: rvw row {i} of {}",
                self.rows
            )));
        }
        let mut dims: [npy_intp; 2] = [3, 3];
        // SAFETY: numpy's C API, loaded at import (`core_module`). `PyArray_DescrFromType`
        // gives a new reference that `PyArray_NewFromDescr` takes over; the data pointer is
        // row `i` of the block (9 float64s, inside it: `i < rows`), and the view holds a
        // reference to the block from `PyArray_SetBaseObject` (which takes over the one
        // given, also when it fails), so the memory lives as long as the view.
        unsafe {
            let descr = PY_ARRAY_API.PyArray_DescrFromType(py, NPY_TYPES::NPY_DOUBLE as c_int);
            if descr.is_null() {
                return Err(PyErr::fetch(py));
            }
            let view = PY_ARRAY_API.PyArray_NewFromDescr(
                py,
                get_type_object(py, NpyTypes::PyArray_Type),
                descr,
                2,
                dims.as_mut_ptr(),
                ptr::null_mut(),
                self.array.data().add(9 * i).cast(),
                NPY_ARRAY_CARRAY,
                ptr::null_mut(),
            );
            let view = Bound::from_owned_ptr_or_err(py, view)?;
            let base = self.array.clone().into_ptr();
            if PY_ARRAY_API.PyArray_SetBaseObject(py, view.as_ptr().cast(), base) < 0 {
                return Err(PyErr::fetch(py));
            }
            Ok(view)
        }
    }
}
