//! Reading a run's data files back as series, and smoothing them as the study's figures do
//! (a moving average over a number of points).

use crate::files::{read_text, MAX_RUN_FILE_BYTES};
use std::io;
use std::path::Path;

/// One data file: (trial, value) points and the minutes used at each.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Series {
    /// (trial, value) points in file order.
    pub points: Vec<(f64, f64)>,
    /// (trial, minutes used) points in file order.
    pub minutes: Vec<(f64, f64)>,
}

impl Series {
    /// Reads a `trial value minutes` file; a missing file is an empty series. A last line
    /// without its newline (a run killed while writing) is left out; any other line that is
    /// not three finite numbers (a run writes no `nan` or `inf`) is an error naming it.
    pub fn read(path: &Path) -> io::Result<Series> {
        let text = match read_text(path, MAX_RUN_FILE_BYTES).map_err(io::Error::from) {
            Ok(text) => text,
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Series::default()),
            Err(e) => return Err(e),
        };
        let whole = match text.rfind('\n') {
            Some(end) => &text[..=end],
            None => "",
        };
        let mut series = Series::default();
        for (index, line) in whole.lines().enumerate() {
            let mut fields = line.split_whitespace().map(str::parse::<f64>);
            let fault = match (fields.next(), fields.next(), fields.next(), fields.next()) {
                (Some(Ok(trial)), Some(Ok(value)), Some(Ok(minutes)), None) => {
                    if [trial, value, minutes].iter().all(|v| v.is_finite()) {
                        series.points.push((trial, value));
                        series.minutes.push((trial, minutes));
                        continue;
                    }
                    "holds a number that is not finite"
                }
                _ => "is not `trial value minutes`",
            };
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!(
                    "line {}: `{}` {fault}",
                    index + 1,
                    crate::experiment::config::shown(line)
                ),
            ));
        }
        Ok(series)
    }

    /// The points smoothed by a centred moving average over `window` points.
    pub fn smoothed(&self, window: usize) -> Vec<(f64, f64)> {
        moving_average(&self.points, window)
    }
}

/// A centred moving average over `window` points (shorter at the ends).
pub fn moving_average(points: &[(f64, f64)], window: usize) -> Vec<(f64, f64)> {
    let half = window.max(1) / 2;
    let mut prefix = Vec::with_capacity(points.len() + 1);
    prefix.push(0.0);
    for (_, v) in points {
        prefix.push(prefix[prefix.len() - 1] + v);
    }
    (0..points.len())
        .map(|i| {
            let (lo, hi) = (i.saturating_sub(half), (i + half + 1).min(points.len()));
            (points[i].0, (prefix[hi] - prefix[lo]) / (hi - lo) as f64)
        })
        .collect()
}

/// At most about `at_most` of `points`, evenly spaced by index, the last one always
/// kept: a million-trial run's curves drawn from a few thousand points look the same at
/// the plot's width and draw in a fraction of the time.
pub(super) fn decimated(points: &[(f64, f64)], at_most: usize) -> Vec<(f64, f64)> {
    let stride = points.len().div_ceil(at_most.max(1)).max(1);
    let mut kept: Vec<(f64, f64)> = points.iter().copied().step_by(stride).collect();
    if let Some(&last) = points.last() {
        if kept.last() != Some(&last) {
            kept.push(last);
        }
    }
    kept
}

/// The trials at which the run's events happened, from its `info` file.
pub fn event_trials(info: &str) -> Vec<f64> {
    info.lines()
        .filter_map(|l| l.strip_prefix("event "))
        .filter_map(|e| e.split(':').nth(1)?.parse().ok())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_moving_average_is_centred_and_shrinks_at_the_ends() {
        let points: Vec<_> = (0..5).map(|i| (i as f64, i as f64 * 2.0)).collect();
        let smooth = moving_average(&points, 3);
        assert_eq!(
            smooth,
            vec![(0.0, 1.0), (1.0, 2.0), (2.0, 4.0), (3.0, 6.0), (4.0, 7.0)]
        );
        assert_eq!(moving_average(&points, 1), points);
    }

    #[test]
    fn a_torn_last_line_is_left_out_and_garbage_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("1step");
        std::fs::write(&path, "1 2.5 0.1\n2 3.5 0.2\n3 4.").unwrap();
        let series = Series::read(&path).unwrap();
        assert_eq!(series.points, vec![(1.0, 2.5), (2.0, 3.5)]);
        std::fs::write(&path, "1 2.5 0.1\nnot a line\n3 4.5 0.3\n").unwrap();
        let err = Series::read(&path).unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::InvalidData);
        assert!(err.to_string().starts_with("line 2: `not a line`"), "{err}");
    }

    #[test]
    fn a_line_with_a_number_that_is_not_finite_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("1step");
        for bad in ["2 nan 0.2", "2 inf 0.2", "NaN 3.5 0.2", "2 3.5 -inf"] {
            std::fs::write(&path, format!("1 2.5 0.1\n{bad}\n")).unwrap();
            let err = Series::read(&path).unwrap_err();
            assert_eq!(err.kind(), io::ErrorKind::InvalidData);
            let want = format!("line 2: `{bad}` holds a number that is not finite");
            assert_eq!(err.to_string(), want);
        }
    }

    #[test]
    fn decimation_keeps_evenly_spaced_points_and_the_last() {
        let points: Vec<(f64, f64)> = (0..10).map(|i| (f64::from(i), f64::from(i * i))).collect();
        let kept = decimated(&points, 4);
        assert_eq!(kept, vec![(0.0, 0.0), (3.0, 9.0), (6.0, 36.0), (9.0, 81.0)]);
        assert_eq!(decimated(&points, 100), points);
        assert_eq!(decimated(&points[..0], 4), vec![]);
        let kept = decimated(&points, 3);
        assert_eq!(kept.len(), 4, "every 4th, then the last: {kept:?}");
        assert_eq!(kept.last(), Some(&(9.0, 81.0)));
    }

    #[test]
    fn events_are_read_from_info() {
        let info = "host x\nevent rotate:1500:90\nevent elongate:20:2:-10\nseed 1\n";
        assert_eq!(event_trials(info), vec![1500.0, 20.0]);
    }
}
