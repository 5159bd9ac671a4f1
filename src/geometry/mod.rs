//! Static geometry: when a ball on a path first touches a cushion, a jaw, a pocket or a
//! plane.
//!
//! ## The map
//!
//! | file | what it holds |
//! |---|---|
//! | `signed_distance.rs` | the walk behind the calendar's box walls: the first entry of a quadratic signed distance along a path, with the pair search's semantics at segment starts |

pub(crate) mod signed_distance;
