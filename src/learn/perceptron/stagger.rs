//! The schedule of a perceptron's staggered sum-sets (study §4.2.1, figure 4.3).
//!
//! With p sets of at most q patterns and a stride s = q / p: set 1 alone takes patterns
//! 1…s, sets 1–2 take s+1…2s, and so on until all p take every pattern. The current set
//! (the one solved) is the oldest. When a pattern arrives and the current set is full, that
//! set is cleared, starts over with this pattern, and the next set — then holding q − s + 1
//! patterns — becomes current. So at most q patterns are ever fitted, and s of the oldest
//! are forgotten at a time.

/// Which sets take the next pattern, which one is current, and how full each is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Stagger {
    capacity: u64,
    stride: u64,
    /// Patterns arrived since the last clear of everything.
    arrived: u64,
    current: usize,
    counts: Vec<u64>,
}

/// What the arriving pattern does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Arrival {
    /// A set to clear before the pattern is added.
    pub(super) cleared: Option<usize>,
    /// The pattern goes to sets `0..receivers`.
    pub(super) receivers: usize,
}

impl Stagger {
    /// `sets` staggered sets (at least 1) of at most `capacity` patterns (at least 1).
    pub(super) fn new(sets: usize, capacity: usize) -> Self {
        let sets = sets.max(1);
        let capacity = capacity.max(1) as u64;
        Stagger {
            capacity,
            stride: (capacity / sets as u64).max(1),
            arrived: 0,
            current: 0,
            counts: vec![0; sets],
        }
    }

    /// Starts the schedule over, as if no pattern had arrived (every set must be cleared
    /// with it).
    pub(super) fn restart(&mut self) {
        self.arrived = 0;
        self.current = 0;
        self.counts.fill(0);
    }

    /// The set the answer is solved from.
    pub(super) fn current(&self) -> usize {
        self.current
    }

    /// Books one arriving pattern.
    pub(super) fn arrive(&mut self) -> Arrival {
        let mut cleared = None;
        if self.counts[self.current] >= self.capacity {
            self.counts[self.current] = 0;
            cleared = Some(self.current);
            self.current = (self.current + 1) % self.counts.len();
        }
        self.arrived += 1;
        let started = (self.arrived - 1) / self.stride + 1;
        let receivers = self.counts.len().min(started as usize);
        for count in &mut self.counts[..receivers] {
            *count += 1;
        }
        Arrival { cleared, receivers }
    }

    #[cfg(test)]
    pub(super) fn counts(&self) -> &[u64] {
        &self.counts
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Feeds patterns until `n` have arrived.
    fn feed_to(s: &mut Stagger, n: u64) -> Arrival {
        let mut last = None;
        while s.arrived < n {
            last = Some(s.arrive());
        }
        last.expect("at least one pattern fed")
    }

    #[test]
    fn sets_switch_exactly_on_the_figure_4_3_timeline() {
        let mut s = Stagger::new(5, 1000);
        // (a) 1–200: set 1 only.
        assert_eq!(feed_to(&mut s, 1).receivers, 1);
        assert_eq!(feed_to(&mut s, 200).receivers, 1);
        assert_eq!(s.counts(), [200, 0, 0, 0, 0]);
        // (b) 201–400 to sets 1–2, 401–600 to sets 1–3.
        assert_eq!(feed_to(&mut s, 201).receivers, 2);
        assert_eq!(feed_to(&mut s, 401).receivers, 3);
        assert_eq!(s.counts(), [401, 201, 1, 0, 0]);
        // (c) 801–1000 to all five; set 1 is still current.
        assert_eq!(feed_to(&mut s, 1000).receivers, 5);
        assert_eq!(s.counts(), [1000, 800, 600, 400, 200]);
        assert_eq!(s.current(), 0);
        // (d) pattern 1001 clears set 1; set 2, with 801 patterns, is current.
        let a = feed_to(&mut s, 1001);
        assert_eq!(
            a,
            Arrival {
                cleared: Some(0),
                receivers: 5
            }
        );
        assert_eq!(s.current(), 1);
        assert_eq!(s.counts(), [1, 801, 601, 401, 201]);
        // (e) set 2 is full after 1200 and cleared at 1201; set 3 takes over.
        assert_eq!(feed_to(&mut s, 1200).cleared, None);
        assert_eq!(s.current(), 1);
        assert_eq!(feed_to(&mut s, 1201).cleared, Some(1));
        assert_eq!(s.current(), 2);
        assert_eq!(s.counts(), [201, 1, 801, 601, 401]);
        // (f) and round again: set 1, restarted at 1001, is current from 1801.
        feed_to(&mut s, 1800);
        assert_eq!(s.current(), 4);
        assert_eq!(feed_to(&mut s, 1801).cleared, Some(4));
        assert_eq!(s.current(), 0);
        assert_eq!(s.counts()[0], 801);
        assert_eq!(feed_to(&mut s, 2001).cleared, Some(0));
        assert_eq!(s.current(), 1);
        assert_eq!(s.counts()[1], 801);
    }

    #[test]
    fn one_set_forgets_everything_at_once() {
        let mut s = Stagger::new(1, 3);
        assert_eq!(feed_to(&mut s, 3).cleared, None);
        assert_eq!(feed_to(&mut s, 4).cleared, Some(0));
        assert_eq!(s.counts(), [1]);
    }
}
