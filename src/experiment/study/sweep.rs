//! `eyehand sweep`: the cross product of config settings and seeds from one config, one
//! cell each. The seeds come from `--seeds` only; `--set seed=…` is refused.

use super::plan::{Cell, StudyKind, StudyPlan, MAX_CELLS};
use super::StudyError;
use crate::experiment::RunRequest;
use std::path::Path;

/// One `--set name=v1,v2,…` of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// The config entry.
    pub name: String,
    /// Its values, as written.
    pub values: Vec<String>,
}

impl std::str::FromStr for Setting {
    type Err = StudyError;

    fn from_str(text: &str) -> Result<Self, StudyError> {
        let bad = || StudyError::BadSetting { text: text.into() };
        let (name, values) = text.split_once('=').ok_or_else(bad)?;
        let values: Vec<String> = values.split(',').map(str::to_string).collect();
        if name.is_empty() || values.iter().any(String::is_empty) {
            return Err(bad());
        }
        if let Some(value) = first_repeat(&values) {
            return Err(StudyError::Duplicate {
                what: name.into(),
                value: value.clone(),
            });
        }
        Ok(Setting {
            name: name.to_string(),
            values,
        })
    }
}

/// The first value that occurs twice in `values`.
pub(super) fn first_repeat<T: PartialEq>(values: &[T]) -> Option<&T> {
    values
        .iter()
        .enumerate()
        .find(|(i, v)| values[..*i].contains(v))
        .map(|(_, v)| v)
}

/// Seeds from `1..5` (inclusive) or `1,2,3`: no seed twice, at most [`MAX_CELLS`] of them.
pub fn parse_seeds(text: &str) -> Result<Vec<u64>, StudyError> {
    let bad = || StudyError::BadSeeds { text: text.into() };
    let seeds: Vec<u64> = if let Some((first, last)) = text.split_once("..") {
        let first: u64 = first.trim().parse().map_err(|_| bad())?;
        let last: u64 = last.trim().parse().map_err(|_| bad())?;
        if first > last {
            return Err(bad());
        }
        let count = (last - first).saturating_add(1);
        if count > MAX_CELLS as u64 {
            return Err(StudyError::TooManyCells {
                cells: count,
                max: MAX_CELLS,
            });
        }
        (first..=last).collect()
    } else {
        text.split(',')
            .map(|s| s.trim().parse().map_err(|_| bad()))
            .collect::<Result<_, _>>()?
    };
    if let Some(seed) = first_repeat(&seeds) {
        return Err(StudyError::Duplicate {
            what: "seed".into(),
            value: seed.to_string(),
        });
    }
    Ok(seeds)
}

/// Every combination of the settings' values (the first setting varies slowest).
pub fn combinations(settings: &[Setting]) -> Vec<Vec<(String, String)>> {
    settings.iter().fold(vec![Vec::new()], |done, setting| {
        done.iter()
            .flat_map(|prefix| {
                setting.values.iter().map(move |value| {
                    let mut next = prefix.clone();
                    next.push((setting.name.clone(), value.clone()));
                    next
                })
            })
            .collect()
    })
}

/// Refuses more than [`MAX_CELLS`] cells, counting without overflow.
pub(super) fn check_cell_count(factors: impl IntoIterator<Item = usize>) -> Result<(), StudyError> {
    let cells = factors
        .into_iter()
        .fold(1u64, |n, f| n.saturating_mul(f as u64));
    if cells > MAX_CELLS as u64 {
        return Err(StudyError::TooManyCells {
            cells,
            max: MAX_CELLS,
        });
    }
    Ok(())
}

/// The sweep's plan: every combination × every seed from `config`, each cell's final config
/// (all its settings applied) checked before anything runs.
pub fn sweep_plan(
    config: &Path,
    settings: &[Setting],
    seeds: &[u64],
) -> Result<StudyPlan, StudyError> {
    for (i, setting) in settings.iter().enumerate() {
        if setting.name == "seed" {
            return Err(StudyError::SeedSetting);
        }
        if settings[..i].iter().any(|s| s.name == setting.name) {
            return Err(StudyError::RepeatedSetting {
                name: setting.name.clone(),
            });
        }
    }
    check_cell_count(settings.iter().map(|s| s.values.len()).chain([seeds.len()]))?;
    let mut cells = Vec::new();
    for combination in combinations(settings) {
        let label = combination
            .iter()
            .map(|(n, v)| format!("{n}={v}"))
            .collect::<Vec<_>>()
            .join(" ");
        for &seed in seeds {
            let request = RunRequest {
                config: Some(config.to_path_buf()),
                sets: combination.clone(),
                seed: Some(seed),
                plot: false,
                ..RunRequest::default()
            };
            cells.push(Cell {
                label: label.clone(),
                seed,
                request,
            });
        }
    }
    let plan = StudyPlan {
        kind: StudyKind::Sweep,
        cells,
    };
    plan.check()?;
    Ok(plan)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_and_seeds_parse() {
        let s: Setting = "split_error=1e-4,1e-5".parse().unwrap();
        assert_eq!(s.values, ["1e-4", "1e-5"]);
        assert!("split_error".parse::<Setting>().is_err());
        assert!("split_error=1,".parse::<Setting>().is_err());
        assert!(matches!(
            "bin_size=3,5,3".parse::<Setting>(),
            Err(StudyError::Duplicate { .. })
        ));
        assert_eq!(parse_seeds("1..5").unwrap(), vec![1, 2, 3, 4, 5]);
        assert_eq!(parse_seeds("3,1").unwrap(), vec![3, 1]);
        assert!(parse_seeds("5..1").is_err());
        assert!(parse_seeds("a").is_err());
        assert!(matches!(
            parse_seeds("1,2,1"),
            Err(StudyError::Duplicate { .. })
        ));
    }

    #[test]
    fn huge_seed_ranges_are_refused_without_counting_them() {
        for text in [
            "1..18446744073709551615",
            "0..18446744073709551615",
            "1..1001",
        ] {
            assert!(
                matches!(parse_seeds(text), Err(StudyError::TooManyCells { .. })),
                "{text}"
            );
        }
        assert_eq!(parse_seeds("1..1000").unwrap().len(), MAX_CELLS);
        assert!(check_cell_count([usize::MAX, usize::MAX]).is_err());
        assert!(check_cell_count([10, 4]).is_ok());
    }

    #[test]
    fn combinations_are_the_cross_product() {
        let a: Setting = "a=1,2".parse().unwrap();
        let b: Setting = "b=x,y,z".parse().unwrap();
        let all = combinations(&[a, b]);
        assert_eq!(all.len(), 6);
        assert_eq!(
            all[0],
            vec![("a".into(), "1".into()), ("b".into(), "x".into())]
        );
        assert_eq!(
            all[5],
            vec![("a".into(), "2".into()), ("b".into(), "z".into())]
        );
    }
}
