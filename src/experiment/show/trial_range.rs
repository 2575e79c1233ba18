//! Trial ranges on the command line: `N` or `A..B` (both ends included).

use std::fmt;
use std::ops::RangeInclusive;
use std::str::FromStr;

/// Trials `first..=last` (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TrialRange {
    /// The first trial.
    pub first: usize,
    /// The last trial (included).
    pub last: usize,
}

impl TrialRange {
    /// The single trial `trial`.
    pub fn single(trial: usize) -> TrialRange {
        TrialRange {
            first: trial,
            last: trial,
        }
    }

    /// True when `trial` is in the range.
    pub fn contains(&self, trial: usize) -> bool {
        self.range().contains(&trial)
    }

    /// The range as Rust spells it.
    pub fn range(&self) -> RangeInclusive<usize> {
        self.first..=self.last
    }
}

impl FromStr for TrialRange {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let number = |s: &str| match s.trim().parse::<usize>() {
            Ok(n) if n >= 1 => Ok(n),
            _ => Err(format!(
                "`{text}`: trials are whole numbers from 1 (N or A..B)"
            )),
        };
        let range = match text.split_once("..") {
            Some((a, b)) => TrialRange {
                first: number(a)?,
                last: number(b.strip_prefix('=').unwrap_or(b))?,
            },
            None => TrialRange::single(number(text)?),
        };
        if range.first > range.last {
            return Err(format!("`{text}`: the first trial comes after the last"));
        }
        Ok(range)
    }
}

impl fmt::Display for TrialRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", self.first, self.last)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_trials_and_ranges_parse_and_bad_ones_say_why() {
        assert_eq!("7".parse(), Ok(TrialRange::single(7)));
        let range: TrialRange = "3..5".parse().unwrap();
        assert_eq!((range.first, range.last), (3, 5));
        assert!(range.contains(5) && !range.contains(6));
        assert_eq!("3..=5".parse::<TrialRange>(), Ok(range));
        for bad in ["0", "5..3", "a..2", "", "1..", "-1"] {
            assert!(bad.parse::<TrialRange>().is_err(), "{bad}");
        }
    }
}
