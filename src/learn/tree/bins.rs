//! Bins: the finest boxes of the input space, each keeping its last `bin_size` patterns.
//!
//! A bin is found by its [`BinKey`] through a hash map. Its patterns form a chain of
//! records, oldest first, each with the pattern's sequence number; once the bin is full a
//! new pattern overwrites the oldest record, which moves to the end of the chain. Patterns
//! older than a change of the mapping can be dropped; their records are reused. Which node
//! a bin hangs on is the tree's business.

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
}

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
            records,
        }
    }

    /// The bin named `key`, and whether it was created just now (empty).
    pub(crate) fn find_or_create(&mut self, key: BinKey) -> (u32, bool) {
        let new_id = self.bins.len() as u32;
        let id = *self.index.entry(key).or_insert(new_id);
        if id == new_id {
            self.bins.push(Bin {
                key,
                first: 0,
                last: 0,
                len: 0,
            });
        }
        (id, id == new_id)
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
        self.bins.len()
    }

    /// Drops every bin and pattern.
    pub(crate) fn clear(&mut self) -> Result<(), LearnError> {
        self.bins.clear();
        self.index.clear();
        self.next.clear();
        self.seqs.clear();
        self.free.clear();
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
