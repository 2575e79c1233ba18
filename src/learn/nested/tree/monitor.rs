//! Running means of a pattern error over a window of the most recent patterns.

/// The mean error E and mean squared error E² of the last `window` patterns.
///
/// Values are kept (as `f32`) in a ring so the oldest can leave the sums; the sums are
/// recomputed from the ring each time it wraps, so rounding never accumulates. The ring
/// grows with the values it is given, up to the window: a tree has a monitor for every
/// sub-box of every node, and most see only a few values.
#[derive(Debug, Clone)]
pub(crate) struct Monitor {
    ring: Vec<f32>,
    window: usize,
    next: usize,
    len: usize,
    sum: f64,
    sum_sq: f64,
}

impl Monitor {
    /// An empty monitor averaging over `window` (at least 1) values.
    pub(crate) fn new(window: usize) -> Self {
        Monitor {
            ring: Vec::new(),
            window: window.max(1),
            next: 0,
            len: 0,
            sum: 0.0,
            sum_sq: 0.0,
        }
    }

    /// Adds one error value.
    pub(crate) fn push(&mut self, error: f64) {
        let value = error as f32;
        if self.is_full() {
            let old = f64::from(self.ring[self.next]);
            self.sum -= old;
            self.sum_sq -= old * old;
        } else {
            self.len += 1;
        }
        if self.next < self.ring.len() {
            self.ring[self.next] = value;
        } else {
            if self.ring.len() == self.ring.capacity() {
                // Doubling, but never past the window.
                let more = self.ring.len().max(4).min(self.window - self.ring.len());
                self.ring.reserve_exact(more);
            }
            self.ring.push(value);
        }
        let value = f64::from(value);
        self.sum += value;
        self.sum_sq += value * value;
        self.next += 1;
        if self.next == self.window {
            self.next = 0;
            self.sum = self.ring.iter().map(|&v| f64::from(v)).sum();
            self.sum_sq = self.ring.iter().map(|&v| f64::from(v).powi(2)).sum();
        }
    }

    /// Values held: the window once full.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Whether a whole window of values has arrived.
    pub(crate) fn is_full(&self) -> bool {
        self.len == self.window
    }

    /// Mean of the values held, `None` when empty.
    pub(crate) fn mean(&self) -> Option<f64> {
        (self.len > 0).then(|| self.sum / self.len as f64)
    }

    /// Mean of the squared values held, `None` when empty.
    pub(crate) fn mean_square(&self) -> Option<f64> {
        (self.len > 0).then(|| self.sum_sq / self.len as f64)
    }

    /// Forgets every value.
    pub(crate) fn clear(&mut self) {
        self.next = 0;
        self.len = 0;
        self.sum = 0.0;
        self.sum_sq = 0.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn means_cover_the_last_window_only() {
        let mut m = Monitor::new(3);
        assert_eq!(m.mean(), None);
        m.push(1.0);
        m.push(2.0);
        assert!(!m.is_full());
        assert_eq!(m.mean(), Some(1.5));
        m.push(3.0);
        m.push(10.0); // 1 leaves
        assert!(m.is_full());
        assert_eq!(m.len(), 3);
        assert_eq!(m.mean(), Some(5.0));
        assert_eq!(m.mean_square(), Some((4.0 + 9.0 + 100.0) / 3.0));
        m.clear();
        assert_eq!((m.len(), m.mean()), (0, None));
    }

    #[test]
    fn the_ring_grows_with_its_values_up_to_the_window() {
        let mut m = Monitor::new(300);
        assert_eq!(m.ring.capacity(), 0);
        for i in 0..10 {
            m.push(f64::from(i));
        }
        assert!(m.ring.capacity() < 20, "{}", m.ring.capacity());
        for i in 0..1000 {
            m.push(f64::from(i));
        }
        assert_eq!(m.ring.capacity(), 300);
        assert_eq!(m.mean(), Some((700..1000).sum::<i32>() as f64 / 300.0));
        m.clear();
        m.push(2.0);
        assert_eq!((m.len(), m.mean()), (1, Some(2.0)));
    }

    #[test]
    fn long_streams_do_not_drift() {
        let mut m = Monitor::new(7);
        for i in 0..100_000 {
            m.push(if i % 2 == 0 { 1e6 } else { 1e-3 });
        }
        // Within a window the error stays tiny; once the ring wraps it is gone.
        for _ in 0..7 {
            m.push(0.5);
        }
        assert!((m.mean().unwrap() - 0.5).abs() < 1e-9);
        for _ in 0..7 {
            m.push(0.5);
        }
        assert_eq!(m.mean(), Some(0.5));
        assert_eq!(m.mean_square(), Some(0.25));
    }
}
