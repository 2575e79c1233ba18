//! The tree's pattern store: the bins with their patterns, and the per-depth counts of
//! nodes, bins and patterns, changed only together with the bin lists and pattern tallies
//! of the nodes the bins hang on, so the three always agree.

use super::{Approximator, BinKey, Bins, Levels, NodeArena, Records, TreeSettings};
use crate::learn::{LearnError, LevelStats, Pattern};

/// Every bin, the patterns it keeps, and the per-depth counts (see [`Levels`]). Each
/// change that moves patterns in, out or between nodes goes through one method here,
/// given the node arena, and updates the bins, the nodes' bin lists and tallies, and the
/// counts at once.
#[derive(Debug)]
pub(crate) struct PatternStore<const N: usize> {
    bins: Bins<N>,
    levels: Levels,
}

impl<const N: usize> PatternStore<N> {
    /// An empty store by `settings` (bin size, depths, error window), keeping its patterns
    /// in `records`.
    pub(crate) fn new(settings: &TreeSettings, records: Records<N>) -> Self {
        PatternStore {
            bins: Bins::new(settings.bin_size, records),
            levels: Levels::new(settings.max_depth, settings.monitor_ave),
        }
    }

    /// The bins, to read.
    pub(crate) fn bins(&self) -> &Bins<N> {
        &self.bins
    }

    /// Each depth's figures, root first.
    pub(crate) fn level_stats(&self) -> Vec<LevelStats> {
        self.levels.stats()
    }

    /// Nodes at every depth.
    pub(crate) fn total_nodes(&self) -> usize {
        self.levels.total_nodes()
    }

    /// Throws away every bin, pattern and count.
    pub(crate) fn clear(&mut self) -> Result<(), LearnError> {
        self.bins.clear()?;
        self.levels.clear();
        Ok(())
    }

    /// A node was made at `depth`.
    pub(crate) fn node_added(&mut self, depth: usize) {
        self.levels.node_added(depth);
    }

    /// A node at `depth` made error `error` on a pattern.
    pub(crate) fn record_error(&mut self, depth: usize, error: f64) {
        self.levels.record_error(depth, error);
    }

    /// The newest pattern of bin `bin`.
    pub(crate) fn latest(&mut self, bin: u32) -> Result<Pattern<N>, LearnError> {
        self.bins.latest(bin)
    }

    /// Calls `f` with every pattern of bin `bin` and its number, oldest first.
    pub(crate) fn for_each_pattern(
        &mut self,
        bin: u32,
        f: impl FnMut(&Pattern<N>, u64),
    ) -> Result<(), LearnError> {
        self.bins.for_each_pattern(bin, f)
    }

    /// Keeps pattern number `seq`, with bin key `key`, in its bin, which hangs on node
    /// `id` (the deepest on its path); the bin is made there if it is new.
    pub(crate) fn keep<A: Approximator<N>>(
        &mut self,
        nodes: &mut NodeArena<A, N>,
        id: u32,
        key: BinKey,
        pattern: &Pattern<N>,
        seq: u64,
    ) -> Result<(), LearnError> {
        let (bin, created) = self.bins.find_or_create(key);
        let node = &mut nodes[id as usize];
        if created {
            node.bins.push(bin);
            self.levels.bin_added(node.depth);
        }
        if self.bins.store(bin, pattern, seq)? {
            node.patterns_added(key.branch(node.depth + 1), 1);
            self.levels.pattern_added(node.depth);
        }
        Ok(())
    }

    /// Bin sinking: moves exactly the bins of node `parent` that its new child `child`
    /// covers onto the child (which holds none yet). Returns the patterns moved.
    pub(crate) fn sink<A: Approximator<N>>(
        &mut self,
        nodes: &mut NodeArena<A, N>,
        parent: u32,
        child: u32,
    ) -> usize {
        let (branch, depth) = (nodes[child as usize].branch, nodes[child as usize].depth);
        let mut kept = std::mem::take(&mut nodes[parent as usize].bins);
        let mut sunk = Vec::new();
        kept.retain(|&bin| {
            let covered = self.bins.key(bin).branch(depth) == Some(branch);
            if covered {
                sunk.push(bin);
            }
            !covered
        });
        let mut patterns = 0;
        let node = &mut nodes[child as usize];
        debug_assert_eq!(node.patterns(), 0, "a new child holds no patterns");
        for &bin in &sunk {
            let n = self.bins.len(bin);
            patterns += n;
            node.patterns_added(self.bins.key(bin).branch(depth + 1), n);
        }
        let moved_bins = sunk.len();
        node.bins = sunk;
        self.levels
            .bins_moved(depth - 1, depth, moved_bins, patterns);
        let p = &mut nodes[parent as usize];
        p.bins = kept;
        p.box_split_off(branch, patterns);
        patterns
    }

    /// Node `id`, being cut, goes: its bins, patterns and all, go up to node `holder` (the
    /// parent of the cut subtree), counted in sub-box `branch` of it.
    pub(crate) fn lift<A: Approximator<N>>(
        &mut self,
        nodes: &mut NodeArena<A, N>,
        id: u32,
        holder: u32,
        branch: u8,
    ) {
        let to = nodes[holder as usize].depth;
        let node = &mut nodes[id as usize];
        let mut bins = std::mem::take(&mut node.bins);
        let patterns = node.patterns();
        self.levels.node_removed(node.depth);
        self.levels.bins_moved(node.depth, to, bins.len(), patterns);
        let h = &mut nodes[holder as usize];
        h.bins.append(&mut bins);
        h.patterns_added(Some(branch), patterns);
    }

    /// Drops bin `bin`, which hangs on node `holder`, patterns and all.
    pub(crate) fn evict<A: Approximator<N>>(
        &mut self,
        nodes: &mut NodeArena<A, N>,
        holder: u32,
        bin: u32,
    ) {
        let (key, patterns) = self.bins.evict(bin);
        let node = &mut nodes[holder as usize];
        let at = node.bins.iter().position(|&b| b == bin);
        debug_assert!(at.is_some(), "a bin hangs on its deepest covering node");
        if let Some(at) = at {
            node.bins.remove(at);
        }
        node.patterns_removed(key.branch(node.depth + 1), patterns);
        self.levels.bin_removed(node.depth, patterns);
    }

    /// Drops the patterns numbered below `cutoff` from the bins of node `id`.
    pub(crate) fn drop_before<A: Approximator<N>>(
        &mut self,
        nodes: &mut NodeArena<A, N>,
        id: u32,
        cutoff: u64,
    ) {
        let node = &mut nodes[id as usize];
        for at in 0..node.bins.len() {
            let bin = node.bins[at];
            let dropped = self.bins.drop_before(bin, cutoff);
            if dropped == 0 {
                continue;
            }
            node.patterns_removed(self.bins.key(bin).branch(node.depth + 1), dropped);
            self.levels.patterns_removed(node.depth, dropped);
        }
    }
}
