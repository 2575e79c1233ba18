//! Memory a config's values make a run allocate, estimated per entry, so that a value that
//! would need more memory than the machine has is refused with the figure before any work
//! starts (instead of an allocation failure after the run folder was made).

use super::{Config, ConfigErrorKind};

/// Physical memory assumed where `/proc/meminfo` cannot be read (bytes).
const ASSUMED_MEMORY: f64 = 64e9;
/// A feedback step: its pose in the trial's path (48 B), its slot in the run's per-step
/// figures (24 B) and its distance (8 B).
const BYTES_PER_STEP: u64 = 80;
/// One value of an error window (an `f32`).
const BYTES_PER_WINDOW_VALUE: u64 = 4;
/// A node keeps its own error window and one per sub-box (32) once that box is used.
const WINDOWS_PER_NODE: u64 = 33;
/// One sum-set of lin8's perceptron (the larger one): a 9×9 and a 9×3 matrix of f64 and
/// a sequence number.
const BYTES_PER_SUM_SET: u64 = 872;
/// A hidden unit of a node's net: 9 weights, their gradient and its two activations.
const BYTES_PER_NODE_UNIT: u64 = 160;
/// A hidden unit of ffn's one net: 9 weights times the weights, gradient and the
/// conjugate-gradient search's four vectors.
const BYTES_PER_FFN_UNIT: u64 = 432;
/// A pattern in ffn's window: 5 inputs and 3 targets.
const BYTES_PER_FFN_PATTERN: u64 = 64;
/// A value waiting to enter the change detector's baseline.
const BYTES_PER_LAGGING_VALUE: u64 = 8;

/// The machine's physical memory (bytes), from `/proc/meminfo`.
pub(crate) fn machine_memory() -> f64 {
    std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|text| {
            let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
            let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
            Some(kb * 1024.0)
        })
        .unwrap_or(ASSUMED_MEMORY)
}

impl Config {
    /// Refuses the first entry whose value alone would need more memory than `available`
    /// bytes (at the start of a run: one node's share for the per-node entries).
    pub(super) fn check_memory(&self, available: f64) -> Result<(), ConfigErrorKind> {
        let levels = (self.tree_depth as u64).saturating_add(1);
        let needs: [(&'static str, usize, u64); 8] = [
            ("feedback_steps", self.feedback_steps, BYTES_PER_STEP),
            (
                "monitor_ave",
                self.monitor_ave,
                BYTES_PER_WINDOW_VALUE * levels,
            ),
            (
                "am_error_iters",
                self.am_error_iters,
                BYTES_PER_WINDOW_VALUE * WINDOWS_PER_NODE,
            ),
            ("nr_of_matrices", self.nr_of_matrices, BYTES_PER_SUM_SET),
            ("hidden_units", self.hidden_units, BYTES_PER_NODE_UNIT),
            (
                "ffn_hidden_units",
                self.ffn_hidden_units,
                BYTES_PER_FFN_UNIT,
            ),
            ("ffn_window", self.ffn_window, BYTES_PER_FFN_PATTERN),
            ("change_lag", self.change_lag, BYTES_PER_LAGGING_VALUE),
        ];
        for (name, value, per_unit) in needs {
            let needed_bytes = value as f64 * per_unit as f64;
            if needed_bytes > available {
                return Err(ConfigErrorKind::TooMuchMemory {
                    name,
                    value: value as u64,
                    per_unit,
                    needed_bytes,
                    available_bytes: available,
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_billion_feedback_steps_need_80_gb() {
        let mut config = Config::default_config();
        config.feedback_steps = 1_000_000_000;
        let err = config.check_memory(16e9).unwrap_err();
        assert!(matches!(
            err,
            ConfigErrorKind::TooMuchMemory { name: "feedback_steps", needed_bytes, .. }
                if needed_bytes == 80e9
        ));
        assert!(err
            .to_string()
            .starts_with("feedback_steps 1000000000 would need 80 GB"));
        assert_eq!(Config::default_config().check_memory(1e9), Ok(()));
    }

    #[test]
    fn the_machine_has_some_memory() {
        assert!(machine_memory() > 1e8);
    }
}
