//! What the calendar reports: a collision of two balls, a ball reaching a wall or an object
//! of the table, or a ball's path starting a new segment.

use super::walls::Side;
use crate::geometry::ObjectKind;

/// Balls `i < j` touch at `time` (absolute).
///
/// ```
/// use ballcollide::schedule::Collision;
/// let c = Collision { time: 0.5, i: 0, j: 3 };
/// assert!(c.i < c.j);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Collision {
    /// When the balls touch.
    pub time: f64,
    /// The lower ball index.
    pub i: usize,
    /// The higher ball index.
    pub j: usize,
}

/// Ball `ball` reaches the `side` wall of `axis` at `time` (its centre a radius from it).
///
/// ```
/// use ballcollide::schedule::{Side, WallContact};
/// let w = WallContact { time: 1.0, ball: 2, axis: 1, side: Side::High };
/// assert_eq!(w.side, Side::High);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WallContact {
    /// When the ball touches the wall.
    pub time: f64,
    /// The ball.
    pub ball: usize,
    /// The wall's axis (0 for x).
    pub axis: usize,
    /// Which of the axis's two walls.
    pub side: Side,
}

/// Ball `ball` reaches object `index` of `kind` of the calendar's table at `time` (see
/// [`path_table_contact`](crate::geometry::path_table_contact)).
///
/// ```
/// use ballcollide::geometry::ObjectKind;
/// use ballcollide::schedule::ObjectEvent;
/// let e = ObjectEvent { time: 1.0, ball: 2, kind: ObjectKind::Target, index: 4 };
/// assert_eq!(e.kind, ObjectKind::Target);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectEvent {
    /// When the ball touches the object (for a target: its centre enters it).
    pub time: f64,
    /// The ball.
    pub ball: usize,
    /// The object's kind.
    pub kind: ObjectKind,
    /// The object's index among the table's objects of its kind.
    pub index: usize,
}

/// Ball `ball`'s path starts its segment `segment` (`≥ 1`) at `time`: a change of state
/// (sliding to rolling, rolling to rest, a landing), reported when the calendar is asked for
/// transitions ([`ScheduleOptions::transitions`](super::ScheduleOptions::transitions)).
///
/// ```
/// use ballcollide::schedule::Transition;
/// let t = Transition { time: 0.5, ball: 0, segment: 1 };
/// assert_eq!(t.segment, 1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transition {
    /// When the segment starts.
    pub time: f64,
    /// The ball.
    pub ball: usize,
    /// The segment's index in the ball's path.
    pub segment: usize,
}

/// The calendar's next event.
///
/// Events are ordered by time, then by the (lower) ball index, then a ball's transition, its
/// wall contact, its object contact (by kind, then index) and its collisions (by the other
/// ball), in that order.
///
/// ```
/// use ballcollide::schedule::{Collision, Event};
/// let e = Event::Collision(Collision { time: 2.0, i: 0, j: 1 });
/// assert_eq!((e.time(), e.ball()), (2.0, 0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// Two balls touch.
    Collision(Collision),
    /// A ball touches a wall.
    Wall(WallContact),
    /// A ball touches an object of the table.
    Object(ObjectEvent),
    /// A ball's path starts a new segment.
    Transition(Transition),
}

impl Event {
    /// When the event happens.
    pub fn time(&self) -> f64 {
        self.order().0
    }

    /// The ball the event is ordered by: the lower of a collision's two, else its one ball.
    pub fn ball(&self) -> usize {
        self.order().1
    }

    /// The event's place in the order: time, ball, class, and two numbers within the class.
    fn order(&self) -> (f64, usize, u8, usize, usize) {
        match *self {
            Self::Transition(t) => (t.time, t.ball, 0, t.segment, 0),
            Self::Wall(w) => (w.time, w.ball, 1, w.axis, w.side as usize),
            Self::Object(o) => (o.time, o.ball, 2, o.kind.code() as usize, o.index),
            Self::Collision(c) => (c.time, c.i, 3, c.j, 0),
        }
    }

    /// Whether `self` comes before `other` in the order above.
    pub(crate) fn before(&self, other: &Self) -> bool {
        let (a, b) = (self.order(), other.order());
        a.0.total_cmp(&b.0)
            .then((a.1, a.2, a.3, a.4).cmp(&(b.1, b.2, b.3, b.4)))
            .is_lt()
    }

    /// The first of some events, in the order above.
    pub(crate) fn first_of(events: impl IntoIterator<Item = Option<Self>>) -> Option<Self> {
        events
            .into_iter()
            .flatten()
            .reduce(|a, b| if b.before(&a) { b } else { a })
    }
}
