//! [`BlockQueue`]: items held back until a block of [`LANES`] is waiting, the one queue of the
//! batches' lane stages (the friction batch's held pairs, the first-window lanes' pairs, the
//! pairs a step walks one by one).

use crate::simd::LANES;

/// Up to `2·LANES` items in the order pushed: room for a block and for what one more step
/// adds before the block is taken.
#[derive(Clone, Copy, Debug)]
pub(super) struct BlockQueue<T> {
    items: [T; 2 * LANES],
    len: usize,
}

impl<T: Copy + Default> Default for BlockQueue<T> {
    fn default() -> Self {
        Self {
            items: [T::default(); 2 * LANES],
            len: 0,
        }
    }
}

impl<T: Copy + Default> BlockQueue<T> {
    /// Holds `item`.
    ///
    /// # Panics
    /// If `2·LANES` items are held: the callers take a block whenever one is full, so a step
    /// adds at most a block to fewer than a block (an item dropped would be a pair never
    /// answered).
    #[inline(always)]
    pub(super) fn push(&mut self, item: T) {
        assert!(self.len < self.items.len(), "a block is taken when full");
        self.items[self.len] = item;
        self.len += 1;
    }

    /// How many items are held.
    #[inline(always)]
    pub(super) fn len(&self) -> usize {
        self.len
    }

    /// The items held, oldest first.
    #[inline(always)]
    pub(super) fn items(&self) -> &[T] {
        &self.items[..self.len]
    }

    /// The first block if one is full, taken out.
    #[inline(always)]
    pub(super) fn take_block(&mut self) -> Option<[T; LANES]> {
        if self.len >= LANES {
            Some(self.take().0)
        } else {
            None
        }
    }

    /// The first `min(len, LANES)` items, taken out, in a block (defaults past them), and
    /// how many.
    #[inline(always)]
    pub(super) fn take(&mut self) -> ([T; LANES], usize) {
        let len = self.len.min(LANES);
        let mut block = [T::default(); LANES];
        block[..len].copy_from_slice(&self.items[..len]);
        self.items.copy_within(len..self.len, 0);
        self.len -= len;
        (block, len)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_come_out_in_order_and_a_full_queue_refuses_more() {
        let mut queue = BlockQueue::<usize>::default();
        assert_eq!(queue.take_block(), None);
        for i in 0..LANES + 3 {
            queue.push(i);
        }
        assert_eq!(queue.take_block(), Some(std::array::from_fn(|i| i)));
        assert_eq!(queue.items(), &[LANES, LANES + 1, LANES + 2]);
        let (block, len) = queue.take();
        assert_eq!((block[..len].to_vec(), block[len]), (queue_rest(), 0));
        assert_eq!(queue.len(), 0);
        for i in 0..2 * LANES {
            queue.push(i);
        }
        let full = std::panic::catch_unwind(move || queue.push(0));
        assert!(full.is_err(), "a pair is never dropped");
    }

    fn queue_rest() -> Vec<usize> {
        vec![LANES, LANES + 1, LANES + 2]
    }
}
