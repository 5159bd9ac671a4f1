//! How many pairs and windows each stage of the path search settles: counters compiled in
//! only with the cargo feature `stage-counts` (off by default, so that the search pays
//! nothing for them), read by the benchmarks (in `benches/`, `cargo bench --bench paths
//! --features stage-counts`).
//!
//! See [`take`] for an example.

#[cfg(feature = "stage-counts")]
use std::sync::atomic::{AtomicU64, Ordering};

/// The counts since the last [`take`], over every thread.
///
/// ```
/// use ballcollide::collision::stage_counts::StageCounts;
/// let none = StageCounts::default();
/// assert_eq!(none.path_pairs - none.bounds_apart, 0); // the pairs that went on to windows
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StageCounts {
    /// Pairs of paths searched (valid input).
    pub path_pairs: u64,
    /// Of those, the pairs whose whole-path bounds are apart (`path_bounds`): no window.
    pub bounds_apart: u64,
    /// Of the others, the pairs apart across either path's chord (`chord_normals`): no window.
    pub chords_apart: u64,
    /// Of the others, the pairs whose every window the window screens prove apart at once
    /// (`batch/window_lanes.rs`, in batches at the SIMD levels that run the lane stages: AVX2
    /// with FMA, AVX-512; elsewhere, and in single queries, such pairs' windows are formed and
    /// counted one by one below).
    pub windows_apart: u64,
    /// Windows formed for the pairs left (`path_contact`).
    pub windows: u64,
    /// Windows whose two segments' boxes (`path_bounds`) are apart: no motion formed.
    pub windows_segments_apart: u64,
    /// Windows that the separation box proves apart (`window_box`).
    pub windows_box_apart: u64,
    /// Windows that the separation's span across its chord proves apart (`window_chord`).
    pub windows_chord_apart: u64,
    /// Windows without relative acceleration answered in closed form (`straight`).
    pub windows_straight: u64,
    /// Windows handed to the window search (`search_window`).
    pub windows_searched: u64,
    /// Of those, the windows settled on their first open eighth (`eighth_entry`), an entry
    /// or none; the others go through the search's own stages.
    pub windows_eighth: u64,
    /// Of those, the windows on which the distance grows throughout (`parting`: a pair
    /// touching and parting after its collision): no entry, without the search.
    pub windows_parting: u64,
    /// Contacts found (at the first time or in a window; one at or past the horizon, reported
    /// as none, included).
    pub contacts: u64,
}

/// One counter per field of [`StageCounts`].
#[derive(Clone, Copy)]
pub(crate) enum Stage {
    PathPair,
    BoundsApart,
    ChordsApart,
    WindowsApart,
    Window,
    WindowSegmentsApart,
    WindowBoxApart,
    WindowChordApart,
    WindowStraight,
    WindowSearched,
    WindowEighth,
    WindowParting,
    Contact,
}

#[cfg(feature = "stage-counts")]
static COUNTS: [AtomicU64; 13] = [const { AtomicU64::new(0) }; 13];

/// Counts one event of `stage` (nothing without the feature).
#[inline(always)]
pub(crate) fn count(stage: Stage) {
    #[cfg(feature = "stage-counts")]
    COUNTS[stage as usize].fetch_add(1, Ordering::Relaxed);
    #[cfg(not(feature = "stage-counts"))]
    let _ = stage;
}

/// The counts since the last call (all zero without the feature), and zero them.
///
/// ```
/// use ballcollide::collision::stage_counts;
/// use ballcollide::path::{Path2, Segment2};
/// use ballcollide::{CollisionOptions, path_collision_time};
/// use nalgebra::Vector2;
///
/// stage_counts::take();
/// // A ball rolling to rest at (0.5, 0), another at rest at (5, 0).
/// let a = Path2::new(vec![
///     Segment2::new(0.0, Vector2::zeros(), Vector2::new(1.0, 0.0), Vector2::new(-1.0, 0.0)),
///     Segment2::at_rest(1.0, Vector2::new(0.5, 0.0)),
/// ])?;
/// let b = Path2::new(vec![Segment2::at_rest(0.0, Vector2::new(5.0, 0.0))])?;
/// path_collision_time(&a, &b, 1.0, &CollisionOptions::default())?;
/// let counts = stage_counts::take();
/// if cfg!(feature = "stage-counts") {
///     // Their paths' boxes are far apart: the path bounds settle the pair.
///     assert_eq!((counts.path_pairs, counts.bounds_apart, counts.windows), (1, 1, 0));
/// } else {
///     assert_eq!(counts, Default::default());
/// }
/// # Ok::<(), ballcollide::InputError>(())
/// ```
pub fn take() -> StageCounts {
    #[cfg(feature = "stage-counts")]
    let c: [u64; 13] = std::array::from_fn(|i| COUNTS[i].swap(0, Ordering::Relaxed));
    #[cfg(not(feature = "stage-counts"))]
    let c = [0u64; 13];
    StageCounts {
        path_pairs: c[Stage::PathPair as usize],
        bounds_apart: c[Stage::BoundsApart as usize],
        chords_apart: c[Stage::ChordsApart as usize],
        windows_apart: c[Stage::WindowsApart as usize],
        windows: c[Stage::Window as usize],
        windows_segments_apart: c[Stage::WindowSegmentsApart as usize],
        windows_box_apart: c[Stage::WindowBoxApart as usize],
        windows_chord_apart: c[Stage::WindowChordApart as usize],
        windows_straight: c[Stage::WindowStraight as usize],
        windows_searched: c[Stage::WindowSearched as usize],
        windows_eighth: c[Stage::WindowEighth as usize],
        windows_parting: c[Stage::WindowParting as usize],
        contacts: c[Stage::Contact as usize],
    }
}
