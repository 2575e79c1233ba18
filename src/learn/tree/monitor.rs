//! Running means of a pattern error over a window of the most recent patterns.

/// The mean error E and mean squared error E² of the last `window` patterns.
///
/// Values are kept (as `f32`) in a ring so the oldest can leave the sums; the sums are
/// recomputed from the ring each time it wraps, so rounding never accumulates.
#[derive(Debug, Clone)]
pub(crate) struct Monitor {
    ring: Box<[f32]>,
    next: usize,
    len: usize,
    sum: f64,
    sum_sq: f64,
}

impl Monitor {
    /// An empty monitor averaging over `window` (at least 1) values.
    pub(crate) fn new(window: usize) -> Self {
        Monitor {
            ring: vec![0.0; window.max(1)].into_boxed_slice(),
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
        self.ring[self.next] = value;
        let value = f64::from(value);
        self.sum += value;
        self.sum_sq += value * value;
        self.next += 1;
        if self.next == self.ring.len() {
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
        self.len == self.ring.len()
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
