//! The pending-event queue: a tournament tree over one key per ball.
//!
//! Each ball holds exactly one pending key (its earliest event, or none); the tree's inner
//! nodes hold the ball whose key comes first below them, so the earliest key of all is at the
//! root. Changing a ball's key replays its path to the root: `log₂ N` comparisons, no
//! allocation, and no stale copies (a heap would hold one per change). Stale keys, whose
//! partner has since changed, are found when they reach the root (lazy invalidation: see the
//! calendar).

/// A key that orders events: `before` is a strict total order on keys, in which of two keys
/// whose times `<` tells apart the earlier comes first.
pub(crate) trait Key: Copy {
    /// Whether `self` comes strictly before `other`.
    fn before(&self, other: &Self) -> bool;

    /// The event's time.
    fn time(&self) -> f64;
}

/// The tournament tree over `keys` (one per ball).
#[derive(Clone, Debug)]
pub(crate) struct Queue<K> {
    keys: Vec<K>,
    /// Inner node `n`'s winner and its time (`1 ≤ n < leaves`; node 0 unused), two siblings
    /// (`2k`, `2k + 1`) to an entry. Leaf `leaves + i` is ball `i` (none past the last
    /// ball), its time its key's.
    nodes: Vec<Siblings>,
    leaves: usize,
}

/// An inner node: the ball whose key comes first below it (`u32::MAX` for none) and that
/// key's time (not read where the winner is none). The time is what a replay compares with,
/// kept beside the winner rather than read through its key, a random read in a large tree
/// (measured at N = 10⁶: the replay's reads of the siblings' keys were 55 % of its time);
/// the two side by side.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    time: f64,
    winner: u32,
}

/// Two sibling nodes, aligned so that they never straddle two cache lines: a level of a
/// replay reads one line.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(32))]
struct Siblings([Node; 2]);

const NONE: u32 = u32::MAX;

/// The most leaves of a tree whose winners are chosen by selects ([`Queue::set`]).
const SMALL_TREE: usize = 4096;

impl<K: Key> Queue<K> {
    /// The queue holding `keys` (fewer than `u32::MAX`).
    pub(crate) fn new(keys: Vec<K>) -> Self {
        let leaves = keys.len().next_power_of_two().max(1);
        let none = Node {
            time: f64::INFINITY,
            winner: NONE,
        };
        let mut queue = Self {
            keys,
            nodes: vec![Siblings([none; 2]); leaves.div_ceil(2)],
            leaves,
        };
        for node in (1..leaves).rev() {
            let winner = queue.winner(2 * node, 2 * node + 1);
            if winner != NONE {
                *queue.node_mut(node) = Node {
                    time: queue.keys[winner as usize].time(),
                    winner,
                };
            }
        }
        queue
    }

    /// Inner node `n`.
    fn node(&self, n: usize) -> Node {
        self.nodes[n / 2].0[n % 2]
    }

    fn node_mut(&mut self, n: usize) -> &mut Node {
        &mut self.nodes[n / 2].0[n % 2]
    }

    /// Node `n`'s winner (a leaf's: its ball, if there is one).
    fn winner_at(&self, n: usize) -> u32 {
        if n >= self.leaves {
            let i = n - self.leaves;
            if i < self.keys.len() { i as u32 } else { NONE }
        } else {
            self.node(n).winner
        }
    }

    /// The ball whose key comes first (`None` without balls).
    pub(crate) fn first(&self) -> Option<usize> {
        let top = self.winner_at(1);
        (top != NONE).then_some(top as usize)
    }

    /// Ball `i`'s key.
    pub(crate) fn key(&self, i: usize) -> &K {
        &self.keys[i]
    }

    /// Sets ball `i`'s key.
    pub(crate) fn set(&mut self, i: usize, key: K) {
        self.keys[i] = key;
        // Up from the leaf, each node's winner from the one coming up and its sibling's
        // (the only child that did not change). The time coming up is carried along, not read
        // again through the winner just chosen: each level reads only its sibling's, whose
        // place does not wait for the level below, so that a level costs a comparison and a
        // select rather than a dependent load as well (measured: the calendar 7 % faster at
        // N = 16, 8 % at 1,000, 11 % at 100,000). Equal times (rare) go to the keys' whole
        // order.
        //
        // A small tree's keys are in the cache: each level's winner as a select (which side
        // wins is hard to predict), and every level replayed, so that the loop always runs
        // the same number of turns (where it could stop is as hard to predict: measured, 5 %
        // faster at N = 16, 3 % at 1,000). A large tree's are not: a branch, so that the CPU
        // goes on to the next level's loads without waiting for this level's (measured: N = 16
        // and 1,000 faster with selects, 100,000 slower), and a stop at the first node that
        // keeps a winner other than `i` (from there up nothing changes), which saves loads.
        let mut node = self.leaves + i;
        let mut up = i as u32;
        let small = self.leaves <= SMALL_TREE;
        let mut up_time = key.time();
        while node > 1 {
            // A leaf's time is its key's (beside the key just set); an inner node's is kept
            // beside its winner.
            let (sibling, sibling_time) = if node >= self.leaves {
                let sibling = self.winner_at(node ^ 1);
                let time = match sibling {
                    NONE => f64::INFINITY,
                    b => self.keys[b as usize].time(),
                };
                (sibling, time)
            } else {
                let n = self.node(node ^ 1);
                (n.winner, n.time)
            };
            if sibling != NONE {
                let (earlier, later) = (sibling_time < up_time, sibling_time > up_time);
                let sibling_first = if earlier | later {
                    earlier
                } else {
                    // Equal times (or NaN): ties go left, to the lower ball.
                    let (left, right) = if node & 1 == 0 {
                        (up, sibling)
                    } else {
                        (sibling, up)
                    };
                    let right_first = self.keys[right as usize].before(&self.keys[left as usize]);
                    right_first == (right == sibling)
                };
                if small {
                    up = std::hint::select_unpredictable(sibling_first, sibling, up);
                    // (On the bits: a select of two `f64`s compiles to a branch.)
                    up_time = f64::from_bits(std::hint::select_unpredictable(
                        sibling_first,
                        sibling_time.to_bits(),
                        up_time.to_bits(),
                    ));
                } else if sibling_first {
                    (up, up_time) = (sibling, sibling_time);
                }
            }
            node /= 2;
            if !small && up != i as u32 && self.node(node).winner == up {
                return;
            }
            *self.node_mut(node) = Node {
                time: up_time,
                winner: up,
            };
        }
    }

    /// The heap memory, in bytes.
    pub(crate) fn heap_bytes(&self) -> usize {
        self.keys.capacity() * std::mem::size_of::<K>()
            + self.nodes.capacity() * std::mem::size_of::<Siblings>()
    }

    fn winner(&self, left: usize, right: usize) -> u32 {
        match (self.winner_at(left), self.winner_at(right)) {
            (NONE, b) => b,
            (a, NONE) => a,
            (a, b) => {
                // Ties go left: to the lower ball, for a total order that is only partial.
                if self.keys[b as usize].before(&self.keys[a as usize]) {
                    b
                } else {
                    a
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_rng::Rng;

    impl Key for (f64, u32) {
        fn before(&self, other: &Self) -> bool {
            self.0
                .total_cmp(&other.0)
                .then(self.1.cmp(&other.1))
                .is_lt()
        }

        fn time(&self) -> f64 {
            self.0
        }
    }

    /// A key that orders by time only: ties are the queue's to break.
    #[derive(Clone, Copy, Debug, PartialEq)]
    struct Coarse(f64);

    impl Key for Coarse {
        fn before(&self, other: &Self) -> bool {
            self.0 < other.0
        }

        fn time(&self) -> f64 {
            self.0
        }
    }

    #[test]
    fn equal_keys_go_to_the_lowest_ball() {
        let mut rng = Rng(11);
        for n in [2usize, 3, 4, 5, 7, 16, 33, 64, 65, 257, SMALL_TREE + 1] {
            let mut keys = vec![Coarse(1.0); n];
            let mut queue = Queue::new(keys.clone());
            for _ in 0..300 {
                let i = (rng.uniform(0.0, n as f64) as usize).min(n - 1);
                keys[i] = Coarse(rng.uniform(0.0, 3.0).floor());
                queue.set(i, keys[i]);
                let least = keys.iter().map(|k| k.0).fold(f64::INFINITY, f64::min);
                let lowest = keys.iter().position(|k| k.0 == least);
                assert_eq!(queue.first(), lowest);
            }
        }
    }

    #[test]
    fn the_first_key_is_always_the_least_after_random_changes() {
        let mut rng = Rng(7);
        for n in [1usize, 2, 3, 4, 5, 16, 17, 64, 65, 100, SMALL_TREE + 1] {
            let mut keys: Vec<(f64, u32)> =
                (0..n).map(|i| (rng.uniform(0.0, 10.0), i as u32)).collect();
            let mut queue = Queue::new(keys.clone());
            for _ in 0..200 {
                let i = (rng.uniform(0.0, n as f64) as usize).min(n - 1);
                // Ties on purpose: a coarse time.
                keys[i].0 = rng.uniform(0.0, 4.0).floor();
                queue.set(i, keys[i]);
                let least = (0..n)
                    .min_by(|&a, &b| keys[a].0.total_cmp(&keys[b].0).then(a.cmp(&b)))
                    .expect("n ≥ 1");
                assert_eq!(queue.first(), Some(least));
                assert_eq!(queue.key(least), &keys[least]);
                // Every inner node too (the replay stops early): as built from scratch.
                let fresh = Queue::new(keys.clone());
                let bits = |q: &Queue<(f64, u32)>| -> Vec<(u32, u64)> {
                    (1..q.leaves)
                        .map(|n| q.node(n))
                        .map(|n| {
                            (
                                n.winner,
                                if n.winner == NONE {
                                    0
                                } else {
                                    n.time.to_bits()
                                },
                            )
                        })
                        .collect()
                };
                assert_eq!(bits(&queue), bits(&fresh));
            }
        }
        assert_eq!(Queue::<(f64, u32)>::new(Vec::new()).first(), None);
    }
}
