//! The schedule of a perceptron's staggered sum-sets (study §4.2.1, figure 4.3).
//!
//! With p sets of at most q patterns and a stride s = q / p: set 1 alone takes patterns
//! 1…s, sets 1–2 take s+1…2s, and so on until all p take every pattern. The current set
//! (the one solved) is the oldest. When a pattern arrives and the current set is full, that
//! set is cleared, starts over with this pattern, and the next set — then holding q − s + 1
//! patterns — becomes current. So at most q patterns are ever fitted, and s of the oldest
//! are forgotten at a time.
//!
//! A set, once started, takes every pattern until it is cleared, so it always holds the
//! patterns since its (re)start. The sums are therefore kept in blocks, a new one opened
//! whenever a set (re)starts: each pattern goes into the newest block only, and a set is
//! the sum of the blocks from the one it started with. The current set, the oldest, spans
//! every block still needed.

/// Which set is current, and when each set (re)started.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Stagger {
    capacity: u64,
    stride: u64,
    /// Patterns arrived since the last clear of everything.
    arrived: u64,
    current: usize,
    /// Sets started since the last clear of everything (the first `started` of `starts`).
    started: usize,
    /// Blocks opened since the last clear of everything.
    blocks: u64,
    /// Per set: where it last (re)started.
    starts: Vec<SetStart>,
}

/// Where a set (re)started: the number of its first pattern and of its first block.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct SetStart {
    arrival: u64,
    block: u64,
}

/// What the arriving pattern does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Arrival {
    /// The current set was full: it starts over, and the next set is current.
    pub(super) switched: bool,
    /// A set starts with this pattern: it opens a new block.
    pub(super) opens: bool,
}

impl Stagger {
    /// `sets` staggered sets (at least 1) of at most `capacity` patterns (at least
    /// `sets`, as the config demands: with fewer, a set other than the current one could
    /// outgrow it and the current set would no longer be the oldest).
    pub(super) fn new(sets: usize, capacity: usize) -> Self {
        let sets = sets.max(1);
        let capacity = capacity.max(sets) as u64;
        Stagger {
            capacity,
            stride: capacity / sets as u64,
            arrived: 0,
            current: 0,
            started: 0,
            blocks: 0,
            starts: vec![SetStart::default(); sets],
        }
    }

    /// Starts the schedule over, as if no pattern had arrived (every block must be dropped
    /// with it).
    pub(super) fn restart(&mut self) {
        self.arrived = 0;
        self.current = 0;
        self.started = 0;
        self.blocks = 0;
    }

    /// The number of the block the current set (re)started with: older blocks are no
    /// longer needed.
    pub(super) fn first_block(&self) -> u64 {
        self.starts[self.current].block
    }

    /// Books one arriving pattern.
    pub(super) fn arrive(&mut self) -> Arrival {
        self.arrived += 1;
        let here = SetStart {
            arrival: self.arrived,
            block: self.blocks,
        };
        let mut arrival = Arrival {
            switched: false,
            opens: false,
        };
        // The current set is full when it holds `capacity` patterns before this one.
        let current = &mut self.starts[self.current];
        if self.started > 0 && here.arrival - current.arrival >= self.capacity {
            *current = here;
            self.current = (self.current + 1) % self.starts.len();
            arrival = Arrival {
                switched: true,
                opens: true,
            };
        }
        // Set k first takes pattern k·stride + 1.
        if self.started < self.starts.len() && here.arrival > self.started as u64 * self.stride {
            self.starts[self.started] = here;
            self.started += 1;
            arrival.opens = true;
        }
        if arrival.opens {
            self.blocks += 1;
        }
        arrival
    }

    /// The patterns each set holds.
    #[cfg(test)]
    pub(super) fn counts(&self) -> Vec<u64> {
        let held = |start: &SetStart| self.arrived + 1 - start.arrival;
        let mut counts: Vec<u64> = self.starts[..self.started].iter().map(held).collect();
        counts.resize(self.starts.len(), 0);
        counts
    }

    /// The set the answer is solved from.
    #[cfg(test)]
    pub(super) fn current(&self) -> usize {
        self.current
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Feeds patterns until `n` have arrived; the last one's arrival.
    fn feed_to(s: &mut Stagger, n: u64) -> Arrival {
        let mut last = None;
        while s.arrived < n {
            last = Some(s.arrive());
        }
        last.expect("at least one pattern fed")
    }

    const OPENS: Arrival = Arrival {
        switched: false,
        opens: true,
    };
    const SWITCHES: Arrival = Arrival {
        switched: true,
        opens: true,
    };
    const PLAIN: Arrival = Arrival {
        switched: false,
        opens: false,
    };

    #[test]
    fn sets_switch_exactly_on_the_figure_4_3_timeline() {
        let mut s = Stagger::new(5, 1000);
        // (a) 1–200: set 1 only, in block 0.
        assert_eq!(feed_to(&mut s, 1), OPENS);
        assert_eq!(feed_to(&mut s, 200), PLAIN);
        assert_eq!(s.counts(), [200, 0, 0, 0, 0]);
        // (b) 201–400 to sets 1–2 (set 2 opens block 1), 401–600 to sets 1–3.
        assert_eq!(feed_to(&mut s, 201), OPENS);
        assert_eq!(feed_to(&mut s, 400), PLAIN);
        assert_eq!(feed_to(&mut s, 401), OPENS);
        assert_eq!(s.counts(), [401, 201, 1, 0, 0]);
        // (c) 801–1000 to all five; set 1 is still current and spans blocks 0–4.
        assert_eq!(feed_to(&mut s, 1000), PLAIN);
        assert_eq!(s.counts(), [1000, 800, 600, 400, 200]);
        assert_eq!((s.current(), s.first_block()), (0, 0));
        // (d) pattern 1001 clears set 1, which opens block 5; set 2, with 801 patterns
        // from block 1 on, is current.
        assert_eq!(feed_to(&mut s, 1001), SWITCHES);
        assert_eq!((s.current(), s.first_block()), (1, 1));
        assert_eq!(s.counts(), [1, 801, 601, 401, 201]);
        // (e) set 2 is full after 1200 and cleared at 1201; set 3 takes over.
        assert_eq!(feed_to(&mut s, 1200), PLAIN);
        assert_eq!(s.current(), 1);
        assert_eq!(feed_to(&mut s, 1201), SWITCHES);
        assert_eq!((s.current(), s.first_block()), (2, 2));
        assert_eq!(s.counts(), [201, 1, 801, 601, 401]);
        // (f) and round again: set 1, restarted at 1001 in block 5, is current from 1801.
        feed_to(&mut s, 1800);
        assert_eq!(s.current(), 4);
        assert_eq!(feed_to(&mut s, 1801), SWITCHES);
        assert_eq!((s.current(), s.first_block()), (0, 5));
        assert_eq!(s.counts()[0], 801);
        assert_eq!(feed_to(&mut s, 2001), SWITCHES);
        assert_eq!((s.current(), s.first_block()), (1, 6));
        assert_eq!(s.counts()[1], 801);
    }

    #[test]
    fn one_set_forgets_everything_at_once() {
        let mut s = Stagger::new(1, 3);
        assert_eq!(feed_to(&mut s, 3), PLAIN);
        assert_eq!(feed_to(&mut s, 4), SWITCHES);
        assert_eq!(s.counts(), [1]);
        assert_eq!(s.first_block(), 1);
    }

    #[test]
    fn a_set_holds_the_patterns_from_its_first_block_on() {
        // Strides that do not divide the capacity.
        for (sets, capacity) in [(3, 1000), (5, 5), (4, 10), (2, 7), (5, 1000)] {
            let mut s = Stagger::new(sets, capacity);
            // The first pattern of every block.
            let mut block_starts = vec![];
            for arrived in 1..=5000u64 {
                if s.arrive().opens {
                    block_starts.push(arrived);
                }
                let first = block_starts[s.first_block() as usize];
                let current = s.counts()[s.current()];
                assert_eq!(current, arrived - first + 1, "{sets} sets of {capacity}");
                assert!(s.counts().iter().all(|&c| c <= current));
            }
        }
    }
}
