//! [`BilliardTable`]: the cushions, jaws and pockets a shot is played on, as pooltool's table
//! holds them, and the calendar's [`Table`] made from them.

use nalgebra::Vector2;

use super::{CircularCushion, LinearCushion, Pocket};
use crate::error::{InputError, InputErrorKind, finite};
use crate::geometry::{Circle, LineSegment, SegmentSide, Table, Target};

/// A billiard table as pooltool's `Table` holds it: straight cushions (each with the side a
/// ball meets it from), rounded cushions (the jaws' tips) and pockets. The index of each in
/// its list is its id in a shot's events ([`simulate_shot`](super::simulate_shot)).
///
/// ```
/// use ballcollide::billiards::{BilliardTable, LinearCushion, Pocket};
/// use ballcollide::geometry::SegmentSide;
/// use nalgebra::Vector2;
///
/// // One rail along y = 0, played from above, and a pocket beyond its right end.
/// let rail = LinearCushion::new(Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0), 0.036576);
/// let table = BilliardTable {
///     linear: vec![(rail, SegmentSide::Left)],
///     pockets: vec![Pocket::new(Vector2::new(1.05, -0.02), 0.062, 0.08)],
///     ..Default::default()
/// };
/// let geometry = table.geometry()?;
/// assert_eq!((geometry.segments.len(), geometry.targets.len()), (1, 1));
/// # Ok::<(), ballcollide::InputError>(())
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BilliardTable {
    /// Straight cushions, each with the side of `p1 → p2` a ball meets it from
    /// ([`SegmentSide::Left`]: from the left; pooltool's `direction`:
    /// [`side_of_direction`]).
    pub linear: Vec<(LinearCushion, SegmentSide)>,
    /// Rounded cushions (the jaws' tips), met from outside.
    pub circular: Vec<CircularCushion>,
    /// Pockets: a ball whose centre enters one drops in.
    pub pockets: Vec<Pocket>,
}

impl BilliardTable {
    /// The table as the calendar's static objects: each straight cushion a [`LineSegment`]
    /// (a ball touches its flat part, `R` from the line between the ends, from its side),
    /// each rounded one a [`Circle`] (the centre `R` beyond the cushion's radius), each
    /// pocket a [`Target`] (the centre enters its radius), in the same order, so that an
    /// object's index is its index here. These are pooltool's detectors' conditions
    /// (`solve.py`): a straight cushion's contact counts where the centre's foot lies on the
    /// segment.
    ///
    /// # Errors
    /// An [`InputError`] naming `linear`, `circular` or `pockets` at the object's index: a
    /// number that is not finite, a straight cushion whose ends coincide, a negative
    /// rounded-cushion radius, a pocket that fails [`Pocket::check`].
    pub fn geometry(&self) -> Result<Table<2>, InputError> {
        let mut table = Table::default();
        for (i, (cushion, side)) in self.linear.iter().enumerate() {
            finite("linear", cushion.height).map_err(|e| e.at(i))?;
            let segment = LineSegment::new(cushion.p1, cushion.p2, *side)
                .map_err(|e| e.renamed("linear").at(i))?;
            table.segments.push(segment);
        }
        for (i, cushion) in self.circular.iter().enumerate() {
            finite("circular", cushion.height).map_err(|e| e.at(i))?;
            let circle = Circle::new(cushion.center, cushion.radius)
                .map_err(|e| e.renamed("circular").at(i))?;
            table.circles.push(circle);
        }
        for (i, pocket) in self.pockets.iter().enumerate() {
            pocket.check().map_err(|e| e.renamed("pockets").at(i))?;
            let target = Target::new(pocket.center, pocket.radius)
                .map_err(|e| e.renamed("pockets").at(i))?;
            table.targets.push(target);
        }
        Ok(table)
    }
}

/// The side a ball meets `cushion` from, for pooltool's `direction` of it
/// (`CushionDirection`: `0` SIDE1, `1` SIDE2, `2` BOTH).
///
/// pooltool writes the cushion's line as `lx·x + ly·y + l0 = 0` with `(lx, ly) = (−dy/dx, 1)`,
/// or `(1, 0)` for a vertical one (`d = p2 − p1`), and its detector for SIDE1 looks for the
/// centre at `−R` from it (the side where `lx·x + ly·y + l0 < 0`), for SIDE2 at `+R`. That
/// form is the signed distance from the line `p1 → p2` (positive on its left) times
/// `1/dx`, or times `−1/dy` for a vertical line, so SIDE1 is the right of `p1 → p2` where
/// `dx > 0`, or where `dx = 0` and `dy < 0`, and the left otherwise.
///
/// # Errors
/// An [`InputError`] naming `direction` for another number
/// ([`InputErrorKind::InvalidSide`]).
///
/// ```
/// use ballcollide::billiards::{LinearCushion, side_of_direction};
/// use ballcollide::geometry::SegmentSide;
/// use nalgebra::Vector2;
/// // pooltool's bottom rail of its default table: (0.09, 0) → (0.9, 0), SIDE2, played from y > 0.
/// let rail = LinearCushion::new(Vector2::new(0.09, 0.0), Vector2::new(0.9, 0.0), 0.036576);
/// assert_eq!(side_of_direction(&rail, 1)?, SegmentSide::Left);
/// assert_eq!(side_of_direction(&rail, 0)?, SegmentSide::Right);
/// assert_eq!(side_of_direction(&rail, 2)?, SegmentSide::Both);
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn side_of_direction(
    cushion: &LinearCushion,
    direction: i64,
) -> Result<SegmentSide, InputError> {
    let d: Vector2<f64> = cushion.p2 - cushion.p1;
    // Whether pooltool's form has the sign of the signed distance (left positive).
    let same_sign = if d.x == 0.0 { d.y < 0.0 } else { d.x > 0.0 };
    let side1 = if same_sign {
        SegmentSide::Right
    } else {
        SegmentSide::Left
    };
    match direction {
        0 => Ok(side1),
        1 => Ok(side1.flipped()),
        2 => Ok(SegmentSide::Both),
        _ => Err(InputError::new(
            "direction",
            InputErrorKind::InvalidSide(direction),
        )),
    }
}
