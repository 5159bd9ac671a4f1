//! What the calendar reports: a collision of two balls, or a ball reaching a wall.

use super::walls::Side;

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

/// The calendar's next event: a collision or a wall contact.
///
/// Events are ordered by time, then by the (lower) ball index, a wall contact of a ball
/// coming before its collisions at the same time (as `(t, i, j)` with `j = −1` for a wall).
///
/// ```
/// use ballcollide::schedule::{Collision, Event};
/// let e = Event::Collision(Collision { time: 2.0, i: 0, j: 1 });
/// assert_eq!(e.time(), 2.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// Two balls touch.
    Collision(Collision),
    /// A ball touches a wall.
    Wall(WallContact),
}

impl Event {
    /// When the event happens.
    pub fn time(&self) -> f64 {
        match self {
            Self::Collision(c) => c.time,
            Self::Wall(w) => w.time,
        }
    }

    /// The earlier of a collision and a wall contact, in the order above.
    pub(crate) fn first_of(
        collision: Option<Collision>,
        wall: Option<WallContact>,
    ) -> Option<Self> {
        match (collision, wall) {
            (Some(c), Some(w)) => Some(if (w.time, w.ball) <= (c.time, c.i) {
                Self::Wall(w)
            } else {
                Self::Collision(c)
            }),
            (Some(c), None) => Some(Self::Collision(c)),
            (None, Some(w)) => Some(Self::Wall(w)),
            (None, None) => None,
        }
    }
}
