//! [`CollisionSchedule`]: N balls on paths, a current time, and their next collision, kept up
//! to date as paths change.

use super::event::{Collision, Event, ObjectEvent, Transition, WallContact};
use super::grid::{CellRange, Grid};
use super::objects::{ObjectCounts, Objects};
use super::queue::{Key, Queue};
use super::reach::{Reach, reach};
use super::walls::{Side, Walls, first_wall_contact};
use crate::collision::path_bounds::PathBounds;
use crate::collision::path_contact::{first_contact_bounded_fma, first_contact_of_paths};
use crate::error::{InputError, InputErrorKind, check_ball_radius, check_horizon, finite};
use crate::geometry::{ObjectKind, Table};
use crate::interrupt::Interrupt;
use crate::motion::{Ball, row_error};
use crate::path::{FrictionPath, Path, Segment};
use crate::prefetch::prefetch;

/// Options of a [`CollisionSchedule`].
///
/// ```
/// use ballcollide::schedule::{ScheduleOptions, Walls};
/// let options = ScheduleOptions { walls: Some(Walls::new([0.0, 0.0], [1.0, 1.0])?), ..Default::default() };
/// assert_eq!(options.t_max, f64::INFINITY);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ScheduleOptions<const D: usize> {
    /// The walls of an axis-aligned box, if ball–wall contacts are wanted.
    pub walls: Option<Walls<D>>,
    /// Static objects (cushions, jaws, pockets, planes), if ball–object contacts are wanted.
    /// Default none.
    pub table: Table<D>,
    /// Whether [`next_event`](CollisionSchedule::next_event) reports each ball's segment
    /// starts ([`Transition`]). Default `false`.
    pub transitions: bool,
    /// The horizon: a contact at `t ≥ t_max` is none. Default `∞`.
    pub t_max: f64,
}

impl<const D: usize> Default for ScheduleOptions<D> {
    fn default() -> Self {
        Self {
            walls: None,
            table: Table::default(),
            transitions: false,
            t_max: f64::INFINITY,
        }
    }
}

/// The heap memory a calendar holds, in bytes (see [`CollisionSchedule::heap_bytes`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HeapBytes {
    /// The paths (up to two segments each held in place, more on the heap) and the spare
    /// buffers an update writes new segments into.
    pub paths: usize,
    /// Everything kept per ball besides its path: radius, version, box, horizon, cells,
    /// pending events, queues.
    pub per_ball: usize,
    /// The grid's cells and their lists.
    pub grid: usize,
}

/// The balls an update gives new paths to between two looks at the interrupt flag
/// ([`CollisionSchedule::update`]): some 20 ms of work.
pub const UPDATE_CHUNK: usize = 4096;

/// An event calendar: N balls (paths and radii), a current time, and the earliest collision
/// among them from that time on, kept up to date as the paths of a few balls change.
///
/// - [`next_collision`](Self::next_collision) is the earliest `(t, i, j)`, `i < j`, over all
///   pairs whose first contact ([`path_collision_time`](crate::path_collision_time) on paths
///   `i` and `j` at contact distance `r_i + r_j`, searched from the later of their first
///   starts) is at or after the current time, ties to the lowest `i`, then `j`: bit for bit
///   what recomputing every pair gives. A pair whose first contact came before the current
///   time (an event the caller went past without resolving it) is not reported again.
/// - [`update`](Self::update) replaces the paths of some balls, all from one time `t ≥` the
///   current time, which becomes the current time; only their pairs are recomputed.
/// - With walls ([`ScheduleOptions::walls`]), [`next_event`](Self::next_event) also reports a
///   ball's first contact with the walls of its path (searched from its first start, kept if
///   at or after the current time).
///
/// ## How
/// Each ball keeps one pending key in a tournament tree (`Queue`): its earliest collision
/// with the balls whose boxes meet its own, found through a uniform grid of boxes (the box a
/// ball covers, grown by its radius and a rounding margin, over the span from the current
/// time to its *horizon*: for ever for a path that comes to rest, a little further ahead for
/// one that keeps moving). A key's partner's version is stored with it: after the partner's
/// path changes, the key is a lower bound of the ball's true next collision, and it is
/// recomputed when it reaches the root (lazy invalidation). At its horizon a moving ball's box
/// is moved on (a *re-check*, internal).
///
/// ```
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::schedule::{Collision, CollisionSchedule, ScheduleOptions};
/// use nalgebra::Vector2;
///
/// let line = |x: f64, v: f64| Path2::new(vec![Segment2::new(0.0, Vector2::new(x, 0.0), Vector2::new(v, 0.0), Vector2::zeros())]);
/// let paths = vec![line(0.0, 1.0)?, line(2.0, 0.0)?, line(5.0, 0.0)?];
/// let mut s = CollisionSchedule::new(paths, &[0.5; 3], ScheduleOptions::default())?;
/// assert_eq!(s.next_collision(), Some(Collision { time: 1.0, i: 0, j: 1 }));
/// // Ball 0 stops at the contact; ball 1 goes on at 1 m/s.
/// let stop = Path2::new(vec![Segment2::at_rest(1.0, Vector2::new(1.0, 0.0))])?;
/// let go = Path2::new(vec![Segment2::new(1.0, Vector2::new(2.0, 0.0), Vector2::new(1.0, 0.0), Vector2::zeros())])?;
/// s.update(&[0, 1], vec![stop, go])?;
/// assert_eq!(s.time(), 1.0);
/// assert_eq!(s.next_collision(), Some(Collision { time: 3.0, i: 1, j: 2 }));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Debug)]
pub struct CollisionSchedule<const D: usize> {
    paths: Vec<Path<D>>,
    /// Per ball, with a grid of one cell (else empty): its path's bounds, for the pair search
    /// (formed once per path, not per pair; with many balls, forming them again from the
    /// segments the search reads anyway costs less than reading them from memory). Without
    /// segment boxes (`0`): the calendar keeps them for long, and its paths are short.
    bounds: Vec<PathBounds<D, 0>>,
    radii: Vec<f64>,
    walls: Option<Walls<D>>,
    t_max: f64,
    time: f64,
    /// Per ball: how many times its path has been replaced (wrapping).
    versions: Vec<u32>,
    /// Per ball: the box it covers up to its horizon, and the box's cells.
    boxes: Vec<Reach<D>>,
    /// (Empty with a grid of one cell: no cell lists.)
    ranges: Vec<CellRange<D>>,
    /// Per ball: when its box must be moved on (`∞`: it covers the rest of the path, or up
    /// to `t_max`).
    horizons: Vec<f64>,
    grid: Grid<D>,
    /// About one cell: how far a horizon looks ahead.
    cell: f64,
    pairs: Queue<PairKey>,
    wall_contacts: Queue<WallKey>,
    /// The table's objects, and each ball's pending object contact (or its re-check; empty
    /// without objects).
    objects: Objects<D>,
    object_contacts: Queue<ObjectKey>,
    /// Each ball's next segment start (empty unless transitions are asked for).
    transitions: Option<Queue<TransitionKey>>,
    /// Per ball, whether it is out of play ([`retire`](Self::retire)); empty until a ball is.
    retired: Vec<bool>,
    /// Per ball, with a grid of one cell (else empty, as re-checks search every pair): the
    /// stamps of its path's last change and of its key's last refresh (from `clock`,
    /// counting path changes), and the balls that were candidates at that refresh (bit `k`
    /// for ball `k`).
    updated: Vec<u32>,
    refreshed: Vec<u32>,
    clock: u32,
    searched: Vec<u64>,
    /// Per ball, with a grid of one cell (else empty): the time of the best collision found
    /// at its last refresh, which a re-check key's partner stands for.
    best_times: Vec<f64>,
    candidates: Vec<u32>,
    /// Scratch, within an update of two balls: the ball whose pair with the one refreshed
    /// first is wanted (`u32::MAX`: none), and that pair's answer once searched.
    want: u32,
    pair_answer: Option<Option<f64>>,
    /// Scratch: segment buffers for [`update_balls`](Self::update_balls)'s new paths.
    spare: Scratch<Vec<Vec<Segment<D>>>>,
    /// Whether the caller resolves every wall contact by updating the ball before the time
    /// moves past it, as [`simulate`](super::simulate) does: each ball's pair searches then
    /// stop at its next wall contact (see [`first_contact`](Self::first_contact)).
    walls_resolved: bool,
}

/// Memory kept between calls only to be reused: no part of the calendar's state, so not
/// shown (a refused update may leave other contents in it).
#[derive(Clone, Default)]
struct Scratch<T>(T);

impl<T> std::fmt::Debug for Scratch<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Scratch")
    }
}

/// What a refresh of a ball's key may take as known.
#[derive(Clone, Copy, Debug)]
enum Known {
    /// Nothing: every candidate's pair is searched.
    Nothing,
    /// Its pair with ball `.0` (whose path changed with its own) was found to be `.1` (if
    /// found at all: `None` inside is no contact).
    Pair(usize, Option<Option<f64>>),
    /// At a re-check: its last refresh (stamped `stamp`) searched the balls of `searched`,
    /// and its best collision was with `partner` (`u32::MAX`: none), unchanged since.
    Since {
        searched: u64,
        stamp: u32,
        partner: u32,
        partner_time: f64,
    },
}

/// What a ball's pending pair key is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    /// Its box must be moved on (comes first at equal times: it may reveal a collision).
    Recheck,
    /// A collision of the pair `(lo, hi)`.
    Collision,
    /// Nothing pending.
    Nothing,
}

/// A ball's pending pair key: `(time, kind, lo, hi)` in that order, with its partner's
/// version when the key was formed.
#[derive(Clone, Copy, Debug)]
struct PairKey {
    time: f64,
    kind: Kind,
    lo: u32,
    hi: u32,
    partner_version: u32,
}

impl PairKey {
    const NOTHING: Self = Self {
        time: f64::INFINITY,
        kind: Kind::Nothing,
        lo: u32::MAX,
        hi: u32::MAX,
        partner_version: 0,
    };
}

impl Key for PairKey {
    fn before(&self, other: &Self) -> bool {
        // Times that `<` or `>` tell apart decide at once (`total_cmp` agrees there); equal
        // ones, `±0` and NaN go on to the full order: the same order, fewer steps. One branch,
        // on whether the times differ (nearly always), not on which comes first (hard to
        // predict).
        let (earlier, later) = (self.time < other.time, self.time > other.time);
        if earlier | later {
            return earlier;
        }
        self.time
            .total_cmp(&other.time)
            .then(self.kind.cmp(&other.kind))
            .then(self.lo.cmp(&other.lo))
            .then(self.hi.cmp(&other.hi))
            .is_lt()
    }

    fn time(&self) -> f64 {
        self.time
    }
}

/// A ball's pending wall contact (`time = ∞` for none).
#[derive(Clone, Copy, Debug)]
struct WallKey {
    time: f64,
    axis: u8,
    side: Side,
}

impl WallKey {
    const NOTHING: Self = Self {
        time: f64::INFINITY,
        axis: 0,
        side: Side::Low,
    };
}

impl Key for WallKey {
    fn before(&self, other: &Self) -> bool {
        // Equal times go to the lower ball: the queue breaks ties to the left.
        self.time < other.time
    }

    fn time(&self) -> f64 {
        self.time
    }
}

/// A ball's pending object key: its earliest object contact among the objects its box
/// meets, or its re-check (at its horizon, when that comes first: an object beyond its box
/// may come before the contact found), or nothing.
#[derive(Clone, Copy, Debug)]
struct ObjectKey {
    time: f64,
    kind: ObjectKeyKind,
    index: u32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum ObjectKeyKind {
    /// Its box must be moved on (comes first at equal times: it may reveal a contact).
    Recheck,
    Contact(ObjectKind),
    Nothing,
}

impl ObjectKey {
    const NOTHING: Self = Self {
        time: f64::INFINITY,
        kind: ObjectKeyKind::Nothing,
        index: 0,
    };
}

impl Key for ObjectKey {
    fn before(&self, other: &Self) -> bool {
        // Equal times: re-checks first; then (contacts) the lower ball, as the queue breaks
        // ties to the left, and each ball holds one key.
        let (earlier, later) = (self.time < other.time, self.time > other.time);
        if earlier | later {
            return earlier;
        }
        (self.kind == ObjectKeyKind::Recheck) & (other.kind != ObjectKeyKind::Recheck)
    }

    fn time(&self) -> f64 {
        self.time
    }
}

/// A ball's next segment start (`time = ∞` for none).
#[derive(Clone, Copy, Debug)]
struct TransitionKey {
    time: f64,
    segment: u32,
}

impl TransitionKey {
    const NOTHING: Self = Self {
        time: f64::INFINITY,
        segment: 0,
    };
}

impl Key for TransitionKey {
    fn before(&self, other: &Self) -> bool {
        self.time < other.time
    }

    fn time(&self) -> f64 {
        self.time
    }
}

impl<const D: usize> CollisionSchedule<D> {
    /// The calendar of balls on `paths` with `radii` (one per ball), at the earliest first
    /// start of the paths (`0` without balls).
    ///
    /// # Errors
    /// An [`InputError`]: `radius` of another length than `paths`, or a radius at an index
    /// that is not finite and positive, or as wide as the box (`2r ≥` its width on an axis:
    /// [`InputErrorKind::WiderThanBox`]); `t_max` negative or NaN; more than `2³² − 2` balls
    /// (`paths`, as a length); [`InputErrorKind::Interrupted`] inside an
    /// [`interruptible`](crate::interrupt::interruptible) call whose flag is set.
    pub fn new(
        paths: Vec<Path<D>>,
        radii: &[f64],
        options: ScheduleOptions<D>,
    ) -> Result<Self, InputError> {
        Self::build(paths, radii, options, false)
    }

    /// [`new`](Self::new); with `walls_resolved`, for a caller that resolves every wall contact
    /// (updates the ball) before the time moves past it, as [`simulate`](super::simulate)
    /// does: each ball's pair searches then stop at its next wall contact, since a collision
    /// after it never comes (the ball's path changes there, and its pairs are searched
    /// again). A friction ball's path runs to rest, far beyond the walls: its later windows
    /// are not formed.
    pub(crate) fn build(
        paths: Vec<Path<D>>,
        radii: &[f64],
        options: ScheduleOptions<D>,
        walls_resolved: bool,
    ) -> Result<Self, InputError> {
        let n = paths.len();
        if radii.len() != n {
            let kind = InputErrorKind::LengthMismatch {
                expected: n,
                found: radii.len(),
            };
            return Err(InputError::new("radius", kind));
        }
        if n >= u32::MAX as usize - 1 {
            let kind = InputErrorKind::LengthMismatch {
                expected: u32::MAX as usize - 2,
                found: n,
            };
            return Err(InputError::new("paths", kind));
        }
        for (i, &r) in radii.iter().enumerate() {
            check_ball_radius("radius", r).map_err(|e| e.at(i))?;
            // A ball as wide as the box would touch two walls at once at every instant.
            if let Some(kind) = options.walls.as_ref().and_then(|w| w.wider_than(r, 1.0)) {
                return Err(InputError::new("radius", kind).at(i));
            }
        }
        let t_max = check_horizon("t_max", options.t_max)?;
        // `+ 0.0`: times are taken in with −0 made +0 (the calendar's time and the
        // friction paths' starts), so that a start of −0 never shows as the time.
        let time = paths
            .iter()
            .map(Path::first_start)
            .reduce(f64::min)
            .unwrap_or(0.0)
            + 0.0;
        let cell = cell_size(&paths, radii, options.walls.as_ref());
        let no_objects = options.table.is_empty();
        let objects = Objects::new(options.table, cell);
        let object_keys = if no_objects { 0 } else { n };
        let transitions = options
            .transitions
            .then(|| Queue::new(vec![TransitionKey::NOTHING; n]));
        let (lo, hi) = region(&paths, options.walls.as_ref(), cell);
        let grid = Grid::new(lo, hi, cell, n);
        let mut schedule = Self {
            grid,
            cell,
            versions: vec![0; n],
            boxes: Vec::with_capacity(n),
            ranges: Vec::new(),
            horizons: Vec::with_capacity(n),
            pairs: Queue::new(vec![PairKey::NOTHING; n]),
            wall_contacts: Queue::new(vec![WallKey::NOTHING; n]),
            objects,
            object_contacts: Queue::new(vec![ObjectKey::NOTHING; object_keys]),
            transitions,
            retired: Vec::new(),
            updated: Vec::new(),
            refreshed: Vec::new(),
            clock: 0,
            searched: Vec::new(),
            best_times: Vec::new(),
            candidates: Vec::new(),
            want: u32::MAX,
            pair_answer: None,
            spare: Scratch::default(),
            walls_resolved,
            bounds: Vec::new(),
            radii: radii.to_vec(),
            walls: options.walls,
            t_max,
            time,
            paths,
        };
        let one_cell = schedule.grid.is_one_cell();
        if !one_cell {
            schedule.ranges.reserve_exact(n);
        }
        // The caller's flag (see `interrupt`) is looked at every 1,024 balls, here and below.
        let interrupt = Interrupt::current();
        for i in 0..n {
            if i % 1024 == 0 {
                interrupt.check()?;
            }
            let (reach, horizon) = schedule.span_box(i, None);
            // One cell: no cell lists (every box is compared with every other).
            if !one_cell {
                let range = schedule.grid.range(&reach);
                schedule.grid.insert(i as u32, &range);
                schedule.ranges.push(range);
            }
            schedule.boxes.push(reach);
            schedule.horizons.push(horizon);
        }
        if one_cell {
            schedule.best_times = vec![f64::INFINITY; n];
            schedule.bounds = schedule
                .paths
                .iter()
                .map(|p| PathBounds::of(p.segments()))
                .collect();
            schedule.updated = vec![0; n];
            schedule.refreshed = vec![0; n];
            schedule.searched = vec![0; n];
        }
        // Each ball's first searches, the build's cost: counted by the caller's counter (a
        // progress bar) a chunk at a time.
        for chunk in (0..n).step_by(1024) {
            interrupt.check()?;
            let end = (chunk + 1024).min(n);
            for i in chunk..end {
                // The wall first: the pair searches may stop at it (`walls_resolved`).
                schedule.refresh_wall(i);
                schedule.refresh(i, None);
                schedule.refresh_object(i);
                schedule.refresh_transition(i);
            }
            interrupt.done(end - chunk);
        }
        Ok(schedule)
    }

    /// The calendar of friction balls ([`Ball`], their model: slowed along their velocity
    /// until they stop) given at time `t`: ball `i`'s path is [`Ball::path`] from `t`.
    ///
    /// # Errors
    /// As [`CollisionSchedule::new`]; a `t` that is not finite; a ball whose path overflows
    /// (see [`Ball::path`]), at its index.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use ballcollide::schedule::{Collision, CollisionSchedule, ScheduleOptions};
    /// use nalgebra::Vector2;
    ///
    /// // A ball slowed at 0.5 m/s² from 2 m/s rolls 4 m; the other rests 3 m away.
    /// let balls = [Ball::new(Vector2::zeros(), Vector2::new(2.0, 0.0), 0.5)?, Ball::at_rest(Vector2::new(3.0, 0.0))?];
    /// let mut s = CollisionSchedule::from_balls(&balls, &[0.5, 0.5], 10.0, ScheduleOptions::default())?;
    /// let c = s.next_collision().expect("a collision");
    /// // 2 m covered: 2·t − t²/4 = 2, t = 4 − 2√2 after the start at 10 s.
    /// assert!((c.time - (14.0 - 8f64.sqrt())).abs() < 1e-12);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn from_balls(
        balls: &[Ball],
        radii: &[f64],
        t: f64,
        options: ScheduleOptions<D>,
    ) -> Result<Self, InputError>
    where
        Ball: FrictionPath<D>,
    {
        let paths = friction_paths(balls, t)?;
        Self::new(paths, radii, options)
    }

    /// The number of balls.
    pub fn len(&self) -> usize {
        self.paths.len()
    }

    /// Whether there is no ball.
    pub fn is_empty(&self) -> bool {
        self.paths.is_empty()
    }

    /// The current time: the start of the last update (at first, the earliest first start).
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Ball `i`'s path.
    ///
    /// # Panics
    /// If `i` is out of range.
    pub fn path(&self, i: usize) -> &Path<D> {
        &self.paths[i]
    }

    /// Whether ball `i` is in play: not taken out by [`retire`](Self::retire) since its last
    /// update.
    ///
    /// # Panics
    /// If `i` is out of range.
    pub fn in_play(&self, i: usize) -> bool {
        !self.retired.get(i).is_some_and(|&r| r)
    }

    /// Ball `i`'s radius.
    ///
    /// # Panics
    /// If `i` is out of range.
    pub fn radius(&self, i: usize) -> f64 {
        self.radii[i]
    }

    /// The walls, if any.
    pub fn walls(&self) -> Option<&Walls<D>> {
        self.walls.as_ref()
    }

    /// The table's objects (empty without any).
    pub fn table(&self) -> &Table<D> {
        self.objects.table()
    }

    /// How many ball–object pairs the object searches have left out and asked so far (all
    /// zero without objects): what the object grid saves.
    pub fn object_counts(&self) -> ObjectCounts {
        self.objects.counts
    }

    /// Whether [`next_event`](Self::next_event) reports transitions
    /// ([`ScheduleOptions::transitions`]).
    pub fn transitions(&self) -> bool {
        self.transitions.is_some()
    }

    /// The horizon.
    pub fn t_max(&self) -> f64 {
        self.t_max
    }

    /// The earliest collision from the current time on (see [`CollisionSchedule`]), `None` if
    /// there is none before `t_max`. It takes `&mut self` for the calendar's internal upkeep
    /// (stale keys recomputed, boxes moved on); the answer is what recomputing every pair
    /// gives.
    pub fn next_collision(&mut self) -> Option<Collision> {
        self.next_collision_until(f64::INFINITY)
    }

    /// [`next_collision`](Self::next_collision) if it comes at or before `limit`, else
    /// `None`: the upkeep stops at `limit` (boxes are not moved on past it), so that a
    /// calendar asked for its next event when a wall contact comes first does not look
    /// further ahead for collisions.
    fn next_collision_until(&mut self, limit: f64) -> Option<Collision> {
        loop {
            let owner = self.pairs.first()?;
            let key = *self.pairs.key(owner);
            // Every key is a lower bound of its ball's next collision (a stale one, or a
            // re-check, of a later one).
            if key.time > limit {
                return None;
            }
            match key.kind {
                Kind::Nothing => return None,
                Kind::Recheck => self.recheck(owner),
                Kind::Collision => {
                    let partner = if key.lo as usize == owner {
                        key.hi
                    } else {
                        key.lo
                    } as usize;
                    if key.time < self.time || self.versions[partner] != key.partner_version {
                        self.refresh(owner, None);
                    } else {
                        return Some(Collision {
                            time: key.time,
                            i: key.lo as usize,
                            j: key.hi as usize,
                        });
                    }
                }
            }
        }
    }

    /// The earliest wall contact from the current time on (`None` without walls).
    pub fn next_wall_contact(&mut self) -> Option<WallContact> {
        loop {
            let ball = self.wall_contacts.first()?;
            let key = *self.wall_contacts.key(ball);
            if key.time == f64::INFINITY {
                return None;
            }
            if key.time < self.time {
                // Reached before the current time: not reported again for this path.
                self.wall_contacts.set(ball, WallKey::NOTHING);
                continue;
            }
            return Some(WallContact {
                time: key.time,
                ball,
                axis: key.axis as usize,
                side: key.side,
            });
        }
    }

    /// The earliest object contact from the current time on (`None` without objects), its
    /// upkeep stopping at `limit` as [`next_collision_until`](Self::next_collision_until)'s.
    fn next_object_until(&mut self, limit: f64) -> Option<ObjectEvent> {
        loop {
            let ball = self.object_contacts.first()?;
            let key = *self.object_contacts.key(ball);
            if key.time > limit {
                return None;
            }
            match key.kind {
                ObjectKeyKind::Nothing => return None,
                ObjectKeyKind::Recheck => self.recheck_objects(ball),
                ObjectKeyKind::Contact(_) if key.time < self.time => self.refresh_object(ball),
                ObjectKeyKind::Contact(kind) => {
                    return Some(ObjectEvent {
                        time: key.time,
                        ball,
                        kind,
                        index: key.index as usize,
                    });
                }
            }
        }
    }

    /// The earliest segment start from the current time on (`None` unless transitions are
    /// asked for).
    fn next_transition(&mut self) -> Option<Transition> {
        loop {
            let queue = self.transitions.as_ref()?;
            let ball = queue.first()?;
            let key = *queue.key(ball);
            if key.time == f64::INFINITY {
                return None;
            }
            if key.time < self.time {
                // Gone past without an update: the next start from the current time.
                self.refresh_transition(ball);
                continue;
            }
            return Some(Transition {
                time: key.time,
                ball,
                segment: key.segment as usize,
            });
        }
    }

    /// The earliest event from the current time on, in the order of [`Event`]: a collision
    /// ([`next_collision`]), a wall contact ([`next_wall_contact`]), a contact with an object
    /// of the table (each ball's first contact with each object, searched from its path's
    /// first start and kept if at or after the current time, as for a pair of balls), or, if
    /// asked for, a ball's next segment start.
    ///
    /// An event stays the next one until the calendar moves past it: update the balls it
    /// involves (for a transition, with the ball's path from then on, if nothing else
    /// changes).
    ///
    /// ```
    /// use ballcollide::geometry::{LineSegment, ObjectKind, SegmentSide, Table};
    /// use ballcollide::path::{Path2, Segment2};
    /// use ballcollide::schedule::{CollisionSchedule, Event, ObjectEvent, ScheduleOptions, Side, WallContact, Walls};
    /// use nalgebra::Vector2;
    ///
    /// let path = Path2::new(vec![Segment2::new(0.0, Vector2::new(0.5, 0.5), Vector2::new(1.0, 0.0), Vector2::zeros())])?;
    /// let options = ScheduleOptions { walls: Some(Walls::new([0.0, 0.0], [1.0, 1.0])?), ..Default::default() };
    /// let mut s = CollisionSchedule::new(vec![path.clone()], &[0.25], options)?;
    /// let wall = WallContact { time: 0.25, ball: 0, axis: 0, side: Side::High };
    /// assert_eq!(s.next_event(), Some(Event::Wall(wall)));
    ///
    /// // A cushion across the ball's way at x = 0.6, played from the ball's side.
    /// let cushion = LineSegment::new(Vector2::new(0.6, 0.0), Vector2::new(0.6, 1.0), SegmentSide::Left)?;
    /// let table = Table { segments: vec![cushion], ..Default::default() };
    /// let mut s = CollisionSchedule::new(vec![path], &[0.05], ScheduleOptions { table, ..Default::default() })?;
    /// let Some(Event::Object(hit)) = s.next_event() else { panic!("the cushion") };
    /// assert_eq!((hit.ball, hit.kind, hit.index), (0, ObjectKind::Segment, 0));
    /// assert!((hit.time - 0.05).abs() < 1e-15);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    ///
    /// [`next_collision`]: Self::next_collision
    /// [`next_wall_contact`]: Self::next_wall_contact
    pub fn next_event(&mut self) -> Option<Event> {
        let transition = self.next_transition();
        let wall = self.next_wall_contact();
        let time = |t: Option<f64>| t.unwrap_or(f64::INFINITY);
        let limit = time(transition.map(|t| t.time)).min(time(wall.map(|w| w.time)));
        let object = self.next_object_until(limit);
        let limit = limit.min(time(object.map(|o| o.time)));
        let collision = self.next_collision_until(limit);
        Event::first_of([
            transition.map(Event::Transition),
            wall.map(Event::Wall),
            object.map(Event::Object),
            collision.map(Event::Collision),
        ])
    }

    /// Takes ball `i` out of play (a ball captured by a pocket): it has no event from now on,
    /// and no ball meets it, until it is given a path again by an update.
    ///
    /// # Errors
    /// An [`InputError`] naming `i` if it is out of range; the calendar is then unchanged.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use ballcollide::schedule::{Collision, CollisionSchedule, ScheduleOptions};
    /// use nalgebra::Vector2;
    ///
    /// let balls = [Ball::new(Vector2::zeros(), Vector2::new(1.0, 0.0), 0.0)?, Ball::at_rest(Vector2::new(2.0, 0.0))?, Ball::at_rest(Vector2::new(4.0, 0.0))?];
    /// let mut s = CollisionSchedule::from_balls(&balls, &[0.5; 3], 0.0, ScheduleOptions::default())?;
    /// assert_eq!(s.next_collision(), Some(Collision { time: 1.0, i: 0, j: 1 }));
    /// s.retire(1)?;
    /// assert_eq!(s.next_collision(), Some(Collision { time: 3.0, i: 0, j: 2 }));
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn retire(&mut self, i: usize) -> Result<(), InputError> {
        if i >= self.len() {
            let kind = InputErrorKind::IndexOutOfRange {
                index: i64::try_from(i).unwrap_or(i64::MAX),
                len: self.len(),
            };
            return Err(InputError::new("i", kind));
        }
        // A box of NaN: it overlaps no other (not even an unbounded one), so no refresh
        // finds the ball (it stays listed in its cells until its next update moves it).
        self.boxes[i] = Reach {
            lo: [f64::NAN; D],
            hi: [f64::NAN; D],
        };
        if self.retired.is_empty() {
            self.retired = vec![false; self.len()];
        }
        self.retired[i] = true;
        self.horizons[i] = f64::INFINITY;
        // Its partners' keys with it are stale from now on.
        self.versions[i] = self.versions[i].wrapping_add(1);
        self.bump_clock(i);
        self.pairs.set(i, PairKey::NOTHING);
        self.wall_contacts.set(i, WallKey::NOTHING);
        if self.has_objects() {
            self.object_contacts.set(i, ObjectKey::NOTHING);
        }
        if let Some(queue) = &mut self.transitions {
            queue.set(i, TransitionKey::NOTHING);
        }
        Ok(())
    }

    /// Replaces the paths of balls `indices` by `paths`, which must all start at one time
    /// `t ≥` [`time`](Self::time); `t` becomes the current time. Only the pairs of those
    /// balls are recomputed. An empty update changes nothing.
    ///
    /// # Errors
    /// An [`InputError`], and the calendar left exactly as it was: `paths` of another length
    /// than `indices`; an index out of range or given twice (`indices[m]`); a path `m` whose
    /// first start differs from path 0's, or is before the current time (`start[m, 0]`).
    ///
    /// Inside an [`interruptible`](crate::interrupt::interruptible) call whose flag is set,
    /// an update of more than [`UPDATE_CHUNK`] balls stops between chunks of that many
    /// ([`InputErrorKind::Interrupted`]): the calendar is then as if only the balls of the
    /// chunks done (the first of `indices`) had been updated, at `t`; consistent, equal to
    /// brute force.
    pub fn update(&mut self, indices: &[usize], paths: Vec<Path<D>>) -> Result<(), InputError> {
        self.check_update(indices, &paths)?;
        let Some(t) = paths.first().map(Path::first_start) else {
            return Ok(());
        };
        self.time = t + 0.0;
        let interrupt = Interrupt::current();
        let mut paths = paths.into_iter();
        for (k, chunk) in indices.chunks(UPDATE_CHUNK).enumerate() {
            if k > 0 {
                interrupt.check()?;
            }
            for (&i, path) in chunk.iter().zip(&mut paths) {
                self.paths[i] = path;
                self.replaced(i);
            }
            self.refresh_updated(chunk);
        }
        Ok(())
    }

    /// After ball `i`'s path was replaced: its bounds, version and box.
    fn replaced(&mut self, i: usize) {
        if let Some(bounds) = self.bounds.get_mut(i) {
            *bounds = PathBounds::of(self.paths[i].segments());
        }
        self.versions[i] = self.versions[i].wrapping_add(1);
        self.bump_clock(i);
        if let Some(retired) = self.retired.get_mut(i) {
            *retired = false;
        }
        let (reach, horizon) = self.span_box(i, None);
        self.move_box(i, reach, horizon);
    }

    /// Stamps ball `i` as changed now (for [`Known::Since`]).
    fn bump_clock(&mut self, i: usize) {
        if self.clock == u32::MAX {
            // Wrapped: every ball counts as changed since every refresh.
            self.refreshed.fill(0);
            self.updated.fill(1);
            self.clock = 1;
        }
        self.clock += 1;
        if let Some(updated) = self.updated.get_mut(i) {
            *updated = self.clock;
        }
    }

    /// After the balls `indices` were replaced: their keys.
    fn refresh_updated(&mut self, indices: &[usize]) {
        for (m, &i) in indices.iter().enumerate() {
            // A collision's two balls: the second takes their pair's answer from the first.
            let known = match (m, indices) {
                (1, &[a, b]) => Known::Pair(a, self.pair_answer.take().filter(|_| b == i)),
                _ => Known::Nothing,
            };
            if m == 0 && indices.len() == 2 {
                self.pair_answer = None;
                self.want = indices[1] as u32;
            }
            // The wall first: the pair searches may stop at it (`walls_resolved`).
            self.refresh_wall(i);
            self.refresh(i, Some(known));
            self.refresh_object(i);
            self.refresh_transition(i);
        }
        self.want = u32::MAX;
    }

    /// [`update`](Self::update) for friction balls given at time `t` (see
    /// [`from_balls`](Self::from_balls)).
    ///
    /// # Errors
    /// As [`update`](Self::update), with `balls` in place of `paths`; a `t` that is not
    /// finite; a ball whose path overflows. Interrupted as [`update`](Self::update) is.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use ballcollide::schedule::{Collision, CollisionSchedule, ScheduleOptions};
    /// use nalgebra::Vector2;
    ///
    /// let balls = [Ball::new(Vector2::zeros(), Vector2::new(1.0, 0.0), 0.0)?, Ball::at_rest(Vector2::new(2.0, 0.0))?];
    /// let mut s = CollisionSchedule::from_balls(&balls, &[0.5, 0.5], 0.0, ScheduleOptions::default())?;
    /// assert_eq!(s.next_collision(), Some(Collision { time: 1.0, i: 0, j: 1 }));
    /// // Equal masses, head on: the velocities swap.
    /// let after = [Ball::at_rest(Vector2::new(1.0, 0.0))?, Ball::new(Vector2::new(2.0, 0.0), Vector2::new(1.0, 0.0), 0.0)?];
    /// s.update_balls(&[0, 1], 1.0, &after)?;
    /// assert_eq!(s.next_collision(), None);
    /// assert!(s.update_balls(&[0], 0.5, &after[..1]).is_err()); // before the current time
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn update_balls(
        &mut self,
        indices: &[usize],
        t: f64,
        balls: &[Ball],
    ) -> Result<(), InputError>
    where
        Ball: FrictionPath<D>,
    {
        let t = finite("t", t)? + 0.0;
        if t < self.time {
            let kind = InputErrorKind::BeforeCurrentTime {
                time: t,
                current: self.time,
            };
            return Err(InputError::new("t", kind));
        }
        // The new segments in spare buffers first (the errors of `friction_paths`, in its
        // order), swapped in once all are good: no allocation once the buffers have grown.
        let mut spare = std::mem::take(&mut self.spare.0);
        if spare.len() < balls.len() {
            spare.resize_with(balls.len(), Vec::new);
        }
        let written = balls
            .iter()
            .zip(&mut spare)
            .enumerate()
            .try_for_each(|(m, (ball, out))| {
                ball.write_path_from(t, out).map_err(|e| row_error(e, m))
            })
            .and_then(|()| self.check_indices(indices, balls.len()));
        let result = written.and_then(|()| {
            if balls.is_empty() {
                return Ok(());
            }
            self.time = t;
            let interrupt = Interrupt::current();
            let mut spare = spare.iter_mut();
            for (k, chunk) in indices.chunks(UPDATE_CHUNK).enumerate() {
                if k > 0 {
                    interrupt.check()?;
                }
                for (&i, segments) in chunk.iter().zip(&mut spare) {
                    // Checked by `write_path_from` (`Ball`'s, the only one: the trait and
                    // `Ball` are this crate's).
                    self.paths[i].swap_checked(segments);
                    self.replaced(i);
                }
                self.refresh_updated(chunk);
            }
            Ok(())
        });
        self.spare.0 = spare;
        result
    }

    /// The heap memory the calendar holds.
    ///
    /// ```
    /// use ballcollide::Ball;
    /// use ballcollide::schedule::{CollisionSchedule, ScheduleOptions};
    /// use nalgebra::Vector2;
    /// let balls: Vec<Ball> = (0..100).map(|i| Ball::at_rest(Vector2::new(i as f64, 0.0))).collect::<Result<_, _>>()?;
    /// let s = CollisionSchedule::from_balls(&balls, &[0.25; 100], 0.0, ScheduleOptions::default())?;
    /// assert!(s.heap_bytes().per_ball <= 200 * 100);
    /// # Ok::<(), ballcollide::InputError>(())
    /// ```
    pub fn heap_bytes(&self) -> HeapBytes {
        use std::mem::size_of;
        let paths = self.paths.capacity() * size_of::<Path<D>>()
            + self.paths.iter().map(Path::heap_bytes).sum::<usize>()
            + self.spare.0.capacity() * size_of::<Vec<Segment<D>>>()
            + self
                .spare
                .0
                .iter()
                .map(|s| s.capacity() * size_of::<Segment<D>>())
                .sum::<usize>();
        let per_ball = self.radii.capacity() * size_of::<f64>()
            + self.bounds.capacity() * size_of::<PathBounds<D, 0>>()
            + self.versions.capacity() * size_of::<u32>()
            + self.boxes.capacity() * size_of::<Reach<D>>()
            + self.ranges.capacity() * size_of::<CellRange<D>>()
            + self.horizons.capacity() * size_of::<f64>()
            + self.retired.capacity()
            + self.updated.capacity() * size_of::<u32>()
            + self.refreshed.capacity() * size_of::<u32>()
            + self.searched.capacity() * size_of::<u64>()
            + self.best_times.capacity() * size_of::<f64>()
            + self.candidates.capacity() * size_of::<u32>()
            + self.pairs.heap_bytes()
            + self.wall_contacts.heap_bytes()
            + self.object_contacts.heap_bytes()
            + self.transitions.as_ref().map_or(0, Queue::heap_bytes);
        HeapBytes {
            paths,
            per_ball,
            grid: self.grid.heap_bytes() + self.objects.heap_bytes(),
        }
    }

    /// The checks of [`update`](Self::update), before anything changes.
    fn check_update(&self, indices: &[usize], paths: &[Path<D>]) -> Result<(), InputError> {
        self.check_indices(indices, paths.len())?;
        let Some(first) = paths.first().map(Path::first_start) else {
            return Ok(());
        };
        for (m, path) in paths.iter().enumerate() {
            let start = path.first_start();
            if start != first {
                let kind = InputErrorKind::StartsDiffer { first, start };
                return Err(InputError::new("start", kind).at(0).in_pair(m));
            }
        }
        if first < self.time {
            let kind = InputErrorKind::BeforeCurrentTime {
                time: first,
                current: self.time,
            };
            return Err(InputError::new("start", kind).at(0).in_pair(0));
        }
        Ok(())
    }

    /// The checks of an update's `indices`, for `count` new paths.
    fn check_indices(&self, indices: &[usize], count: usize) -> Result<(), InputError> {
        if count != indices.len() {
            let kind = InputErrorKind::LengthMismatch {
                expected: indices.len(),
                found: count,
            };
            return Err(InputError::new("paths", kind));
        }
        let n = self.len();
        for (m, &i) in indices.iter().enumerate() {
            if i >= n {
                let kind = InputErrorKind::IndexOutOfRange {
                    index: i64::try_from(i).unwrap_or(i64::MAX),
                    len: n,
                };
                return Err(InputError::new("indices", kind).at(m));
            }
        }
        // A repeat is reported at its second occurrence, the earliest such position: by
        // looking back for a few indices (an event's update, no allocation), else in order.
        let repeat = if indices.len() <= 8 {
            (1..indices.len()).find(|&m| indices[..m].contains(&indices[m]))
        } else {
            let mut order: Vec<(usize, usize)> = indices.iter().copied().zip(0..).collect();
            order.sort_unstable();
            order
                .windows(2)
                .filter(|w| w[0].0 == w[1].0)
                .map(|w| w[1].1)
                .min()
        };
        if let Some(m) = repeat {
            let kind = InputErrorKind::RepeatedIndex(indices[m]);
            return Err(InputError::new("indices", kind).at(m));
        }
        Ok(())
    }

    /// The first contact of balls `i` and `j` (`i ≠ j`) for ball `i`'s key: the pair search
    /// on `(lo, hi)`, with the paths' bounds (stored, or formed here: the same either way).
    fn first_contact(&self, i: usize, j: usize, t_max: f64) -> Option<f64> {
        let (a, b) = (i.min(j), i.max(j));
        let (pa, pb) = (self.paths[a].segments(), self.paths[b].segments());
        let radii = [self.radii[a] + self.radii[b], 0.0];
        // Without the window chord (see `first_contact_bounded_fma`).
        match (self.bounds.get(a), self.bounds.get(b)) {
            (Some(ba), Some(bb)) => {
                first_contact_bounded_fma((pa, ba), (pb, bb), radii, t_max, false)
            }
            _ => first_contact_of_paths(pa, pb, radii, t_max, false),
        }
    }

    /// How far ball `i`'s pair searches go: the horizon, or, where the caller resolves wall
    /// contacts, up to ball `i`'s next one.
    fn pair_horizon(&self, i: usize) -> f64 {
        // Where the caller resolves wall contacts, up to ball `i`'s next one (a collision at
        // that very time included: it may come first in the order of events). The search
        // skips the windows that start beyond it and reports none beyond it; the contacts
        // before it are the same bits (the windows keep their lengths). A collision's second
        // ball takes the pair's answer as the first ball's search found it (`Known::Pair`),
        // cut at the first ball's wall: a contact it misses comes after that wall, where the
        // first ball's path changes and the pair is searched again.
        let wall = self.wall_contacts.key(i).time;
        if self.walls_resolved && wall < self.t_max {
            wall.next_up()
        } else {
            self.t_max
        }
    }

    /// Ball `i`'s box from the current time, and its horizon (`∞` if the box covers the
    /// rest of its path, or up to `t_max`); `previous`: the horizon being moved on.
    fn span_box(&self, i: usize, previous: Option<f64>) -> (Reach<D>, f64) {
        let segments = self.paths[i].segments();
        let from = self.time;
        let horizon = self.next_horizon(segments, from, previous);
        let end = horizon.min(self.t_max);
        let horizon = if horizon < self.t_max {
            horizon
        } else {
            f64::INFINITY
        };
        (reach(segments, self.radii[i], from, end), horizon)
    }

    /// How far ahead a box reaches: far enough to cross a quarter of a cell at the path's
    /// fastest from `from` on (of about two ball spacings: measured on the benchmark's
    /// frictionless disks, shorter boxes in coarser cells ask the pair search less often
    /// than boxes of a whole cell), and at least twice as far from `from` as the `previous`
    /// horizon (so that a calendar whose time does not advance moves boxes on in ever larger
    /// steps). For ever (`∞`: the box covers the rest of the path) once the path is at rest
    /// within that reach, or once the boxes have grown [`LONGEST_STEPS`] times a step without
    /// the time moving on: balls that never meet (moving apart, alone in open space) are then
    /// settled by one search of their whole paths instead of doubling their reach a thousand
    /// times up to the float range.
    ///
    /// A friction ball is thus covered a quarter cell at a time while it rolls, not over its
    /// whole run to rest (which may cross the table and meet every ball).
    fn next_horizon(&self, segments: &[Segment<D>], from: f64, previous: Option<f64>) -> f64 {
        let Some(last) = segments.last() else {
            return f64::INFINITY;
        };
        let resting = last.velocity.amax() == 0.0 && last.acceleration.amax() == 0.0;
        if resting && from >= last.start {
            return f64::INFINITY;
        }
        // The fastest the path moves over the next quarter cell from `from`: each segment
        // still to come (or under way) at its speed at `from`, or at its start, bounded for
        // a quarter cell of acceleration; or, on a segment that ends, by its speed at `from`
        // and at its end, whichever is larger (each component's magnitude is convex in time):
        // a ball slowing to rest is not credited with a speed it never reaches, so its box
        // steps are not cut short as it slows (16 balls at friction 5 were re-checked four
        // times per event).
        let mut speed = 0.0f64;
        for (k, segment) in segments.iter().enumerate() {
            let end = segments.get(k + 1).map_or(f64::INFINITY, |next| next.start);
            if end <= from {
                continue;
            }
            let (v, a) = (segment.velocity.amax(), segment.acceleration.amax());
            let ahead = (from - segment.start).max(0.0);
            // (No acceleration: the same sum without the square root of 0.)
            let here = if a == 0.0 {
                v
            } else {
                let near = v + a * ahead + (a * self.cell).sqrt();
                let at = |s: f64| (segment.velocity + segment.acceleration * s).amax();
                if end < f64::INFINITY {
                    near.min(at(ahead).max(at(end - segment.start)))
                } else {
                    near
                }
            };
            speed = speed.max(here);
        }
        let step = 0.25 * self.cell / speed;
        let base = previous.map_or(from, |h| h.max(from));
        let span = previous.map_or(0.0, |h| h - from);
        if span >= LONGEST_STEPS * step {
            return f64::INFINITY;
        }
        let horizon = base + step.max(span);
        // At rest within reach; or no progress (rounding, or a NaN from an overflow): cover
        // the rest.
        let at_rest_within = resting && horizon >= last.start;
        if horizon > base && !at_rest_within {
            horizon
        } else {
            f64::INFINITY
        }
    }

    /// Moves ball `i`'s box in the grid.
    fn move_box(&mut self, i: usize, reach: Reach<D>, horizon: f64) {
        if let Some(old) = self.ranges.get(i).copied() {
            let range = self.grid.range(&reach);
            if range != old {
                self.grid.remove(i as u32, &old);
                self.grid.insert(i as u32, &range);
                self.ranges[i] = range;
            }
        }
        self.boxes[i] = reach;
        self.horizons[i] = horizon;
    }

    /// At ball `i`'s horizon: its box moved on, its key recomputed.
    ///
    /// With a grid of one cell, its pairs with the balls that were candidates at its last
    /// refresh, paths unchanged since, are known to come no earlier than the best of that
    /// refresh, whose partner the re-check key holds: only the other pairs are searched, and
    /// the partner's, if the partner is still a candidate and its contact not past.
    fn recheck(&mut self, i: usize) {
        let key = *self.pairs.key(i);
        let partner_unchanged =
            key.hi == u32::MAX || self.versions[key.hi as usize] == key.partner_version;
        let known = self
            .searched
            .get(i)
            .filter(|_| partner_unchanged)
            .map(|&searched| Known::Since {
                searched,
                stamp: self.refreshed[i],
                partner: key.hi,
                partner_time: self.best_times[i],
            });
        let (reach, horizon) = self.span_box(i, Some(self.horizons[i]));
        self.move_box(i, reach, horizon);
        if !self.refresh(i, known) {
            self.refresh(i, None);
        }
        // An object contact found before the old horizon stands (the new box holds the old
        // one's span from now on); a re-check is done now.
        if self.has_objects() && self.object_contacts.key(i).kind == ObjectKeyKind::Recheck {
            self.refresh_object(i);
        }
    }

    /// At ball `i`'s horizon, reached first by its object key: as [`recheck`](Self::recheck)
    /// if its pair key is a re-check too, else its box moved on and its object key
    /// recomputed. Its pair key stands: a collision found before the old horizon is still its
    /// earliest (every ball it meets before then was a candidate), and a stale one, a lower
    /// bound, is recomputed with the new box when it comes first; the other balls meet the
    /// larger box at their own refreshes.
    fn recheck_objects(&mut self, i: usize) {
        if self.pairs.key(i).kind == Kind::Recheck {
            self.recheck(i);
            return;
        }
        let (reach, horizon) = self.span_box(i, Some(self.horizons[i]));
        self.move_box(i, reach, horizon);
        self.refresh_object(i);
    }

    /// Recomputes ball `i`'s pair key: its earliest collision at or after the current time
    /// with a ball whose box meets its own, or its re-check if that comes first. With
    /// `known` ([`Known`]), some pairs are not searched again; `false` (nothing changed) if
    /// what was known turned out not to settle the key.
    fn refresh(&mut self, i: usize, known: Option<Known>) -> bool {
        let mut candidates = std::mem::take(&mut self.candidates);
        candidates.clear();
        let boxes = &self.boxes;
        let own = &boxes[i];
        if self.grid.is_one_cell() {
            // Every ball is listed once, in order: no cell lists, no marks; each written in
            // the next slot and kept if its box overlaps (no branch to mispredict).
            candidates.resize(boxes.len(), 0);
            let mut kept = 0;
            for (b, k) in boxes.iter().zip(0u32..) {
                candidates[kept] = k;
                kept += usize::from((k as usize != i) & b.overlaps(own));
            }
            candidates.truncate(kept);
        } else {
            // Each overlapping ball once (see `Grid::for_each_overlapping`).
            self.grid
                .for_each_overlapping(&self.ranges[i], own, boxes, |k| {
                    if k as usize != i {
                        candidates.push(k);
                    }
                });
        }
        // Each candidate's path is one or two lines (up to two segments held in place), or
        // one and then its segments on the heap: cache misses in a large scene, asked for
        // all at once, before the searches, so that they overlap rather than come one after
        // another. A path's second line (a friction ball's second segment) is asked for
        // with its first, not after a read of the first tells what the path holds.
        if candidates.len() > 1 && self.grid.asks_ahead() {
            for &k in &candidates {
                let path = &self.paths[k as usize];
                prefetch(path);
                if size_of::<Path<D>>() > 64 {
                    prefetch(std::ptr::from_ref(path).cast::<u8>().wrapping_add(64));
                }
            }
            for &k in &candidates {
                if let Some(heap) = self.paths[k as usize].heap_segments() {
                    prefetch(heap.as_ptr());
                }
            }
        }
        let mut best = PairKey::NOTHING;
        let t_max = self.pair_horizon(i);
        // Whether the re-check's partner was searched and its contact is not past.
        let mut partner_valid = false;
        for &k in &candidates {
            let ku = k as usize;
            let t = match known {
                Some(Known::Since {
                    searched,
                    stamp,
                    partner,
                    ..
                }) if k != partner => {
                    if was_searched(searched, k) && self.updated[ku] <= stamp {
                        continue;
                    }
                    self.first_contact(i, ku, t_max)
                }
                Some(Known::Since { partner_time, .. }) => {
                    // The same pair on the same paths: its answer as found then.
                    partner_valid = partner_time >= self.time;
                    Some(partner_time)
                }
                Some(Known::Pair(other, Some(answer))) if other == ku => answer,
                _ => self.first_contact(i, ku, t_max),
            };
            if k == self.want {
                self.pair_answer = Some(t);
            }
            if let Some(t) = t.filter(|&t| t >= self.time) {
                let key = PairKey {
                    time: t,
                    kind: Kind::Collision,
                    lo: i.min(ku) as u32,
                    hi: i.max(ku) as u32,
                    partner_version: self.versions[ku],
                };
                if key.before(&best) {
                    best = key;
                }
            }
        }
        self.candidates = candidates;
        if let Some(Known::Since { partner, .. }) = known {
            // The skipped pairs come no earlier than the partner's, which must be among
            // those searched.
            if partner != u32::MAX && !partner_valid {
                return false;
            }
        }
        let found_time = best.time;
        let horizon = self.horizons[i];
        if horizon < best.time || (horizon == best.time && horizon.is_finite()) {
            // The best collision's partner stays in the key, for the re-check.
            let (partner, partner_version) = match best.kind {
                Kind::Collision => {
                    let other = if best.lo as usize == i {
                        best.hi
                    } else {
                        best.lo
                    };
                    (other, best.partner_version)
                }
                _ => (u32::MAX, 0),
            };
            best = PairKey {
                time: horizon,
                kind: Kind::Recheck,
                lo: i as u32,
                hi: partner,
                partner_version,
            };
        }
        if let (Some(refreshed), Some(searched), Some(best_time)) = (
            self.refreshed.get_mut(i),
            self.searched.get_mut(i),
            self.best_times.get_mut(i),
        ) {
            *refreshed = self.clock;
            *searched = searched_mask(&self.candidates);
            *best_time = found_time;
        }
        self.pairs.set(i, best);
        true
    }

    /// Recomputes ball `i`'s wall key.
    fn refresh_wall(&mut self, i: usize) {
        let Some(walls) = &self.walls else {
            return;
        };
        let hit = first_wall_contact(self.paths[i].segments(), self.radii[i], walls, self.t_max);
        let key = match hit {
            Some((time, axis, side)) if time >= self.time => WallKey {
                time,
                axis: axis as u8,
                side,
            },
            _ => WallKey::NOTHING,
        };
        self.wall_contacts.set(i, key);
    }

    /// Whether the calendar has objects (else it keeps no object keys).
    fn has_objects(&self) -> bool {
        !self.objects.table().is_empty()
    }

    /// Recomputes ball `i`'s object key: its earliest object contact at or after the current
    /// time among the objects its box meets, or its re-check if that may come first.
    fn refresh_object(&mut self, i: usize) {
        if !self.has_objects() {
            return;
        }
        let best = self.objects.first_contact(
            self.paths[i].segments(),
            self.radii[i],
            &self.boxes[i],
            self.time,
            self.t_max,
        );
        let horizon = self.horizons[i];
        let key = match best {
            // Before the horizon: every object touched by then meets the box.
            Some(c) if c.time < horizon => ObjectKey {
                time: c.time,
                kind: ObjectKeyKind::Contact(c.kind),
                index: c.index as u32,
            },
            _ if horizon.is_finite() => ObjectKey {
                time: horizon,
                kind: ObjectKeyKind::Recheck,
                index: 0,
            },
            _ => ObjectKey::NOTHING,
        };
        self.object_contacts.set(i, key);
    }

    /// Recomputes ball `i`'s transition key: its path's first segment start after its first
    /// at or after the current time (and before `t_max`).
    fn refresh_transition(&mut self, i: usize) {
        let Some(queue) = &mut self.transitions else {
            return;
        };
        let (time, t_max) = (self.time, self.t_max);
        let next = self.paths[i]
            .segments()
            .iter()
            .enumerate()
            .skip(1)
            .find(|(_, s)| s.start >= time);
        let key = match next {
            Some((k, s)) if s.start < t_max => TransitionKey {
                time: s.start,
                segment: k as u32,
            },
            _ => TransitionKey::NOTHING,
        };
        queue.set(i, key);
    }
}

/// The paths of friction balls from time `t` (errors at the ball's index).
pub(crate) fn friction_paths<const D: usize>(
    balls: &[Ball],
    t: f64,
) -> Result<Vec<Path<D>>, InputError>
where
    Ball: FrictionPath<D>,
{
    let t = finite("t", t)? + 0.0;
    // The caller's flag (see `interrupt`) looked at every 1,024 balls, as in the build.
    let interrupt = Interrupt::current();
    // Each ball's segments written over one buffer (checked there), then copied into its
    // path: no allocation for the paths of up to two segments, held in place.
    // (Made at their final size: a `Result` collected grows its vector by doubling.)
    let mut buffer = Vec::new();
    let mut paths = Vec::with_capacity(balls.len());
    for (i, b) in balls.iter().enumerate() {
        if i % 1024 == 0 {
            interrupt.check()?;
        }
        b.write_path_from(t, &mut buffer)
            .map_err(|e| row_error(e, i))?;
        paths.push(Path::from_checked_slice(&buffer));
    }
    Ok(paths)
}

/// The grid's cell size: about twice the spacing of the balls (the region's volume per
/// ball), and at least eight typical radii.
fn cell_size<const D: usize>(paths: &[Path<D>], radii: &[f64], walls: Option<&Walls<D>>) -> f64 {
    // The median radius (selected, not sorted: linear in the balls).
    let mut radii = radii.to_vec();
    let middle = radii.len() / 2;
    let typical = match radii.is_empty() {
        true => 1.0,
        false => *radii.select_nth_unstable_by(middle, f64::total_cmp).1,
    };
    let (lo, hi) = match walls {
        Some(w) => (w.lo(), w.hi()),
        None => first_positions_box(paths),
    };
    let mut volume = 1.0;
    for k in 0..D {
        volume *= (hi[k] - lo[k]).max(4.0 * typical);
    }
    let spacing = (volume / paths.len().max(1) as f64).powf(1.0 / D as f64);
    let size = 2.0 * spacing.max(4.0 * typical);
    if size.is_finite() && size > 0.0 {
        size
    } else {
        1.0
    }
}

/// How many steps ahead (a quarter cell each) a ball's box may grow while the calendar's
/// time stands still, before it covers the rest of the path (see
/// [`CollisionSchedule::next_horizon`]).
const LONGEST_STEPS: f64 = 64.0;

/// The bit mask of the candidates a refresh searched, for [`Known::Since`]: bit `k` for ball
/// `k < 64`. Balls from 64 on have no bit (a grid of one cell may hold any number of balls
/// when its region is too wide to divide) and count as not searched: searched again.
fn searched_mask(candidates: &[u32]) -> u64 {
    candidates
        .iter()
        .filter(|&&k| k < u64::BITS)
        .fold(0, |m, &k| m | 1 << k)
}

/// Whether ball `k` has its bit in a [`searched_mask`].
fn was_searched(mask: u64, k: u32) -> bool {
    k < u64::BITS && mask >> k & 1 == 1
}

/// The box of the paths' first positions (`[0, 1]` without balls).
fn first_positions_box<const D: usize>(paths: &[Path<D>]) -> ([f64; D], [f64; D]) {
    let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for p in paths {
        let x = p.segments()[0].position;
        for k in 0..D {
            lo[k] = lo[k].min(x[k]);
            hi[k] = hi[k].max(x[k]);
        }
    }
    if paths.is_empty() {
        return ([0.0; D], [1.0; D]);
    }
    (lo, hi)
}

/// The grid's region: the walls' box, or the box of the first positions, grown by a cell.
fn region<const D: usize>(
    paths: &[Path<D>],
    walls: Option<&Walls<D>>,
    cell: f64,
) -> ([f64; D], [f64; D]) {
    let (lo, hi) = match walls {
        Some(w) => (w.lo(), w.hi()),
        None => first_positions_box(paths),
    };
    (lo.map(|x| x - cell), hi.map(|x| x + cell))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;

    #[test]
    fn pair_keys_order_by_time_then_kind_then_balls() {
        let times = [
            f64::NEG_INFINITY,
            -1.0,
            -0.0,
            0.0,
            f64::MIN_POSITIVE,
            1.0,
            1.0 + f64::EPSILON,
            f64::INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        let kinds = [Kind::Recheck, Kind::Collision, Kind::Nothing];
        let balls = [0, 1, 7, u32::MAX - 1, u32::MAX];
        let mut rng = Rng(5);
        let mut pick = |n: usize| rng.below(n as u64) as usize;
        let mut draw = || PairKey {
            time: times[pick(times.len())],
            kind: kinds[pick(kinds.len())],
            lo: balls[pick(balls.len())],
            hi: balls[pick(balls.len())],
            partner_version: 0,
        };
        let (mut before, mut after) = (0, 0);
        for _ in 0..20_000 {
            let (a, b) = (draw(), draw());
            let order = a
                .time
                .total_cmp(&b.time)
                .then(a.kind.cmp(&b.kind))
                .then(a.lo.cmp(&b.lo))
                .then(a.hi.cmp(&b.hi));
            assert_eq!(a.before(&b), order.is_lt(), "{a:?} {b:?}");
            before += usize::from(order.is_lt());
            after += usize::from(order.is_gt());
        }
        assert!(before > 5_000 && after > 5_000);
    }
}
