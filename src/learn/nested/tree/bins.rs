//! Bins: the finest boxes of the input space, each keeping its last `bin_size` patterns.
//!
//! A bin is found by its [`BinKey`] through a hash map. Its patterns form a chain of
//! records, oldest first, each with the pattern's sequence number; once the bin is full a
//! new pattern overwrites the oldest record, which moves to the end of the chain. Patterns
//! older than a change of the mapping can be dropped; their records are reused. Bins are
//! also kept in the order they were last stored to, so that when the store must stay
//! bounded the bin stored to least recently can be dropped whole ([`Bins::evict`]); its
//! slot and records are reused. Which node a bin hangs on is the tree's business.

use super::{BinKey, Records};
use crate::learn::LearnError;
use crate::learn::Pattern;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// Hashes a bin key with the SplitMix64 finaliser: every key bit reaches every hash bit.
#[derive(Debug, Default, Clone, Copy)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        let mut z = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = self.0.rotate_left(8) ^ u64::from(b);
        }
    }

    fn write_u64(&mut self, value: u64) {
        self.0 ^= value;
    }
}

#[derive(Debug, Clone, Copy)]
struct Bin {
    key: BinKey,
    /// Oldest record.
    first: u32,
    /// Newest record.
    last: u32,
    len: u32,
    /// The bin stored to just before this one was last stored to ([`NO_BIN`] if none).
    older: u32,
    /// The bin stored to just after ([`NO_BIN`] if none).
    newer: u32,
}

/// The end of the recency list.
const NO_BIN: u32 = u32::MAX;

/// Every bin and the patterns they keep.
#[derive(Debug)]
pub(crate) struct Bins<const N: usize> {
    capacity: u32,
    bins: Vec<Bin>,
    index: HashMap<BinKey, u32, BuildHasherDefault<KeyHasher>>,
    /// For each record, the next newer record of its bin.
    next: Vec<u32>,
    /// For each record, its pattern's sequence number.
    seqs: Vec<u64>,
    /// Records of dropped patterns, to be reused.
    free: Vec<u32>,
    /// Slots of evicted bins, to be reused.
    free_bins: Vec<u32>,
    /// The bin stored to least recently, and most recently ([`NO_BIN`] when none).
    least_recent: u32,
    most_recent: u32,
    records: Records<N>,
}

impl<const N: usize> Bins<N> {
    /// No bins yet; each will keep at most `bin_size` patterns in `records`.
    pub(crate) fn new(bin_size: usize, records: Records<N>) -> Self {
        Bins {
            capacity: bin_size.clamp(1, u32::MAX as usize) as u32,
            bins: Vec::new(),
            index: HashMap::default(),
            next: Vec::new(),
            seqs: Vec::new(),
            free: Vec::new(),
            free_bins: Vec::new(),
            least_recent: NO_BIN,
            most_recent: NO_BIN,
            records,
        }
    }

    /// The bin named `key`, and whether it was created just now (empty; it counts as
    /// stored to most recently).
    pub(crate) fn find_or_create(&mut self, key: BinKey) -> (u32, bool) {
        let new_id = self
            .free_bins
            .last()
            .copied()
            .unwrap_or(self.bins.len() as u32);
        let id = *self.index.entry(key).or_insert(new_id);
        if id != new_id {
            return (id, false);
        }
        let bin = Bin {
            key,
            first: 0,
            last: 0,
            len: 0,
            older: NO_BIN,
            newer: NO_BIN,
        };
        if self.free_bins.pop().is_some() {
            self.bins[id as usize] = bin;
        } else {
            self.bins.push(bin);
        }
        self.link_most_recent(id);
        (id, true)
    }

    /// Puts bin `id`, not in the recency list, at its most recent end.
    fn link_most_recent(&mut self, id: u32) {
        let bin = &mut self.bins[id as usize];
        bin.older = self.most_recent;
        bin.newer = NO_BIN;
        match self.most_recent {
            NO_BIN => self.least_recent = id,
            newest => self.bins[newest as usize].newer = id,
        }
        self.most_recent = id;
    }

    /// Takes bin `id` out of the recency list.
    fn unlink(&mut self, id: u32) {
        let Bin { older, newer, .. } = self.bins[id as usize];
        match older {
            NO_BIN => self.least_recent = newer,
            older => self.bins[older as usize].newer = newer,
        }
        match newer {
            NO_BIN => self.most_recent = older,
            newer => self.bins[newer as usize].older = older,
        }
    }

    /// The bin stored to least recently, if there is any bin.
    pub(crate) fn least_recent(&self) -> Option<u32> {
        (self.least_recent != NO_BIN).then_some(self.least_recent)
    }

    /// Drops bin `id` and every pattern in it; returns its key and how many patterns it
    /// kept. Its slot and records are reused by bins and patterns to come.
    pub(crate) fn evict(&mut self, id: u32) -> (BinKey, usize) {
        self.unlink(id);
        let bin = self.bins[id as usize];
        let mut record = bin.first;
        for _ in 0..bin.len {
            self.free.push(record);
            record = self.next[record as usize];
        }
        self.index.remove(&bin.key);
        self.bins[id as usize].len = 0;
        self.free_bins.push(id);
        (bin.key, bin.len as usize)
    }

    /// Patterns kept in all bins together.
    pub(crate) fn stored(&self) -> usize {
        self.records.len() - self.free.len()
    }

    /// Stores `pattern`, number `seq`, in bin `id`; true when the bin grew, false when its
    /// oldest pattern made room. Sequence numbers must grow from call to call.
    pub(crate) fn store(
        &mut self,
        id: u32,
        pattern: &Pattern<N>,
        seq: u64,
    ) -> Result<bool, LearnError> {
        let bin = self.bins[id as usize];
        let (record, grew) = if bin.len < self.capacity {
            let record = match self.free.pop() {
                Some(record) => {
                    self.records.overwrite(record, pattern)?;
                    record
                }
                None => {
                    let record = self.records.push(pattern)?;
                    self.next.push(record);
                    self.seqs.push(seq);
                    record
                }
            };
            (record, true)
        } else {
            self.records.overwrite(bin.first, pattern)?;
            (bin.first, false)
        };
        self.seqs[record as usize] = seq;
        let bin = &mut self.bins[id as usize];
        if bin.len == 0 {
            bin.first = record;
        } else if record != bin.last {
            // (In a full one-pattern bin the record already is both ends.)
            if !grew {
                bin.first = self.next[record as usize];
            }
            self.next[bin.last as usize] = record;
        }
        bin.last = record;
        bin.len += u32::from(grew);
        if self.most_recent != id {
            self.unlink(id);
            self.link_most_recent(id);
        }
        Ok(grew)
    }

    /// The key of bin `id`.
    pub(crate) fn key(&self, id: u32) -> BinKey {
        self.bins[id as usize].key
    }

    /// Patterns bin `id` keeps.
    pub(crate) fn len(&self, id: u32) -> usize {
        self.bins[id as usize].len as usize
    }

    /// The newest pattern of bin `id`, which must hold one.
    pub(crate) fn latest(&mut self, id: u32) -> Result<Pattern<N>, LearnError> {
        debug_assert!(self.bins[id as usize].len > 0);
        self.records.read(self.bins[id as usize].last)
    }

    /// Calls `f` with each pattern of bin `id` and its sequence number, oldest first.
    pub(crate) fn for_each_pattern(
        &mut self,
        id: u32,
        mut f: impl FnMut(&Pattern<N>, u64),
    ) -> Result<(), LearnError> {
        let bin = self.bins[id as usize];
        let mut record = bin.first;
        for _ in 0..bin.len {
            f(&self.records.read(record)?, self.seqs[record as usize]);
            record = self.next[record as usize];
        }
        Ok(())
    }

    /// Drops the patterns of bin `id` numbered below `cutoff`; returns how many. The bin
    /// stays, empty if nothing was newer.
    pub(crate) fn drop_before(&mut self, id: u32, cutoff: u64) -> usize {
        let bin = &mut self.bins[id as usize];
        let mut dropped = 0;
        while bin.len > 0 && self.seqs[bin.first as usize] < cutoff {
            self.free.push(bin.first);
            bin.first = self.next[bin.first as usize];
            bin.len -= 1;
            dropped += 1;
        }
        dropped
    }

    /// Bins there are.
    #[cfg(test)]
    pub(crate) fn count(&self) -> usize {
        self.bins.len() - self.free_bins.len()
    }

    /// Drops every bin and pattern.
    pub(crate) fn clear(&mut self) -> Result<(), LearnError> {
        self.bins.clear();
        self.index.clear();
        self.next.clear();
        self.seqs.clear();
        self.free.clear();
        self.free_bins.clear();
        self.least_recent = NO_BIN;
        self.most_recent = NO_BIN;
        self.records.clear()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{SVector, Vector3};

    fn pattern(i: usize) -> Pattern<5> {
        Pattern {
            input: SVector::repeat(i as f64),
            target: Vector3::zeros(),
        }
    }

    fn kept(bins: &mut Bins<5>, id: u32) -> Vec<usize> {
        let mut seen = Vec::new();
        bins.for_each_pattern(id, |p, seq| {
            assert_eq!(p.input[0], seq as f64, "each pattern keeps its number");
            seen.push(seq as usize);
        })
        .unwrap();
        seen
    }

    fn key(branches: &[u8]) -> BinKey {
        let mut key = BinKey::default();
        branches.iter().for_each(|&b| key.push(b));
        key
    }

    #[test]
    fn a_full_bin_keeps_its_newest_patterns_in_order() {
        let mut bins = Bins::new(3, Records::in_memory());
        let (a, created) = bins.find_or_create(key(&[1, 2]));
        assert!(created);
        let (b, _) = bins.find_or_create(key(&[1, 3]));
        assert_eq!(bins.find_or_create(key(&[1, 2])), (a, false));
        let grew: Vec<bool> = (0..5)
            .map(|i| bins.store(a, &pattern(i), i as u64).unwrap())
            .collect();
        assert_eq!(grew, [true, true, true, false, false]);
        bins.store(b, &pattern(7), 7).unwrap();
        assert_eq!(kept(&mut bins, a), [2, 3, 4]);
        assert_eq!(kept(&mut bins, b), [7]);
        assert_eq!(bins.len(a), 3);
        bins.store(a, &pattern(5), 5).unwrap();
        assert_eq!(kept(&mut bins, a), [3, 4, 5]);
        assert_eq!(bins.latest(a).unwrap(), pattern(5));
        assert_eq!(bins.latest(b).unwrap(), pattern(7));
        assert_eq!(bins.key(b), key(&[1, 3]));
    }

    #[test]
    fn the_least_recently_stored_to_bin_is_evicted_and_its_room_reused() {
        let mut bins = Bins::new(2, Records::in_memory());
        let ids: Vec<u32> = (0..3).map(|b| bins.find_or_create(key(&[b])).0).collect();
        for (i, &id) in ids.iter().enumerate() {
            bins.store(id, &pattern(i), i as u64).unwrap();
        }
        // Bin 0 was stored to again: bin 1 is now the least recent.
        bins.store(ids[0], &pattern(3), 3).unwrap();
        assert_eq!(bins.least_recent(), Some(ids[1]));
        assert_eq!(bins.evict(ids[1]), (key(&[1]), 1));
        assert_eq!((bins.stored(), bins.count()), (3, 2));
        assert_eq!(bins.least_recent(), Some(ids[2]));
        let (again, created) = bins.find_or_create(key(&[1]));
        assert!(created, "an evicted bin is gone");
        assert_eq!(again, ids[1], "its slot is reused");
        bins.store(again, &pattern(4), 4).unwrap();
        assert_eq!(kept(&mut bins, again), [4]);
        assert_eq!(bins.records.len(), 4, "its record is reused");
        assert_eq!(bins.evict(ids[2]), (key(&[2]), 1));
        assert_eq!(bins.evict(ids[0]), (key(&[0]), 2));
        assert_eq!(bins.least_recent(), Some(again));
        assert_eq!(bins.evict(again), (key(&[1]), 1));
        assert_eq!(
            (bins.least_recent(), bins.stored(), bins.count()),
            (None, 0, 0)
        );
    }

    #[test]
    fn a_one_pattern_bin_keeps_the_newest() {
        let mut bins = Bins::new(1, Records::in_memory());
        let (a, _) = bins.find_or_create(key(&[0]));
        for i in 0..4 {
            bins.store(a, &pattern(i), i as u64).unwrap();
        }
        assert_eq!(kept(&mut bins, a), [3]);
        assert_eq!(bins.latest(a).unwrap(), pattern(3));
    }

    #[test]
    fn patterns_older_than_a_change_are_dropped_and_their_records_reused() {
        let mut bins = Bins::new(3, Records::in_memory());
        let (a, _) = bins.find_or_create(key(&[4]));
        let (b, _) = bins.find_or_create(key(&[5]));
        for i in 0..5 {
            bins.store(a, &pattern(i), i as u64).unwrap();
        }
        bins.store(b, &pattern(5), 5).unwrap();
        assert_eq!(bins.drop_before(a, 4), 2);
        assert_eq!(kept(&mut bins, a), [4]);
        assert_eq!(bins.drop_before(b, 4), 0);
        assert_eq!(bins.drop_before(b, 6), 1);
        assert_eq!((bins.len(b), kept(&mut bins, b)), (0, vec![]));
        let records = bins.records.len();
        let grew: Vec<bool> = (6..10)
            .map(|i| bins.store(a, &pattern(i), i as u64).unwrap())
            .collect();
        assert_eq!(grew, [true, true, false, false]);
        assert_eq!(kept(&mut bins, a), [7, 8, 9]);
        bins.store(b, &pattern(10), 10).unwrap();
        assert_eq!(kept(&mut bins, b), [10]);
        assert_eq!(bins.records.len(), records, "freed records were reused");
    }
}
