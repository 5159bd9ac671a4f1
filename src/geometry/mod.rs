//! Static geometry: when a ball on a path first touches a cushion, a jaw, a pocket or a
//! plane.
//!
//! ## The map
//!
//! | file | what it holds |
//! |---|---|
//! | `shapes.rs` | the objects, checked when made: [`LineSegment`] (2-D, with its [`SegmentSide`]), [`Circle`], [`Target`], [`Plane`] |
//! | `signed_distance.rs` | the walk behind the segment and plane queries (and the calendar's box walls): the first entry of a quadratic signed distance along a path, with the pair search's semantics at segment starts |
//! | `path_segment_contact.rs` | [`path_segment_contact`]: the band of half-width `r` about the segment's line, each entry kept if its foot lies on the segment and its side counts |
//! | `path_plane_contact.rs` | [`path_plane_contact`]: the height above the plane coming down to `r` |
//! | `path_circle_contact.rs` | [`path_circle_contact`]: the pair search of two paths against the circle's centre at rest, at contact distance `ρ + r` |
//! | `path_target_contact.rs` | [`path_target_contact`]: the same at contact distance `ρ` (the centre enters the disc) |
//! | `table.rs` | [`Table`]: a scene's objects together; [`ObjectKind`], [`ObjectContact`] |
//! | `pool_table.rs` | [`PoolTable`]: a pool table's rails, jaws, jaw tips and pockets as a [`Table`] |
//! | `path_table_contact.rs` | [`path_table_contact`]: the earliest contact with any object of a table (each by its own query); the calendar asks the same function per object |
//!
//! Every query answers with the first contact's absolute time, as
//! [`path_collision_time`](crate::path_collision_time) does, with the same semantics
//! (`docs/contract.md` §3 and §4.7): touching at the first start counts only when
//! approaching, exact tangency is no contact, a horizon only cuts. A segment's rounded ends
//! are not part of it: a table gives them as circles of radius 0.
//!
//! ```
//! use ballcollide::geometry::{Circle, LineSegment, SegmentSide, path_circle_contact, path_segment_contact};
//! use ballcollide::path::{Path2, Segment2};
//! use ballcollide::CollisionOptions;
//! use nalgebra::Vector2;
//!
//! // A cushion from (0, 0) to (1, 0) played from above, with its rounded ends.
//! let (p, q) = (Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.0));
//! let cushion = LineSegment::new(p, q, SegmentSide::Left)?;
//! let ends = [Circle::new(p, 0.0)?, Circle::new(q, 0.0)?];
//! // A ball of radius 0.1 rolls down at x = 1.05, past the end at Q.
//! let path = Path2::new(vec![Segment2::new(0.0, Vector2::new(1.05, 1.0), Vector2::new(0.0, -1.0), Vector2::zeros())])?;
//! let options = CollisionOptions::default();
//! assert_eq!(path_segment_contact(&path, &cushion, 0.1, &options)?, None);
//! let t = path_circle_contact(&path, &ends[1], 0.1, &options)?.expect("the end");
//! assert!((t - (1.0 - 0.0075f64.sqrt())).abs() < 1e-15); // 0.05² + y² = 0.1²
//! # Ok::<(), ballcollide::InputError>(())
//! ```

mod path_circle_contact;
mod path_plane_contact;
mod path_segment_contact;
mod path_table_contact;
mod path_target_contact;
mod pool_table;
mod shapes;
pub(crate) mod signed_distance;
mod table;

pub use path_circle_contact::path_circle_contact;
pub use path_plane_contact::path_plane_contact;
pub use path_segment_contact::path_segment_contact;
pub(crate) use path_table_contact::first_table_contact;
pub use path_table_contact::path_table_contact;
pub(crate) use path_table_contact::{TablePath, object_contact};
pub use path_target_contact::path_target_contact;
pub use pool_table::PoolTable;
pub use shapes::{Circle, LineSegment, Plane, SegmentSide, Target};
pub use table::{ObjectContact, ObjectKind, Table};
