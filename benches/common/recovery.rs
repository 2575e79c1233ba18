//! Reading recovery after an event from a run's files: the detector's alarms (the 4-step
//! figures come from [`FourStepTrace`](eyehand::experiment::FourStepTrace)).

use std::path::Path;

/// The trials of the alarms in a run's `changes` file.
pub fn alarms(folder: &Path) -> Vec<usize> {
    let changes = std::fs::read_to_string(folder.join("changes")).unwrap_or_default();
    changes
        .lines()
        .filter_map(|l| l.split(' ').next()?.parse().ok())
        .collect()
}

/// Trials from `event` to the first alarm at or after it (`-`: none), as a table cell.
pub fn detected_after(alarms: &[usize], event: usize) -> String {
    alarms
        .iter()
        .find(|&&t| t >= event)
        .map_or("-".into(), |t| (t - event).to_string())
}
