//! Keeping the pattern store bounded: with `max_stored_patterns` set, once the bins hold
//! more patterns than that, the bins stored to least recently are dropped whole.
//!
//! A bin keeps at most `bin_size` patterns, but the bins themselves have no bound: at
//! depth 8 nearly every pattern opens a finest box of its own (2⁴⁰ of them), so a long run
//! keeps more and more bins and patterns. The cap forgets the regions the arm has not
//! visited for longest, as a full bin forgets its oldest pattern. A dropped bin leaves the
//! node it hangs on (the deepest on its key's path) and the per-depth counts; its slot and
//! records are reused.

use super::{Approximator, BranchRule, NestedTree};

impl<A: Approximator<N>, R: BranchRule<N>, const N: usize> NestedTree<A, R, N> {
    /// Drops the least recently stored-to bins while the store holds more patterns than
    /// `max_stored_patterns` (0: no cap). Returns how many bins were dropped.
    pub(super) fn evict_over_cap(&mut self) -> usize {
        let cap = self.settings().max_stored_patterns;
        let mut evicted = 0;
        while cap > 0 && self.store.bins().stored() > cap {
            let Some(bin) = self.store.bins().least_recent() else {
                break;
            };
            let holder = self.descend(self.store.bins().key(bin)).deepest();
            self.store.evict(&mut self.nodes, holder, bin);
            evicted += 1;
        }
        evicted
    }
}
