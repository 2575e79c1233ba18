//! The process's memory use, read from `/proc/self/status` (Linux); 0 where it is not
//! available.

/// Resident memory now (kB).
pub fn resident_kb() -> u64 {
    status_kb("VmRSS:")
}

/// Peak resident memory of the process so far (kB).
pub fn peak_rss_kb() -> u64 {
    status_kb("VmHWM:")
}

fn status_kb(field: &str) -> u64 {
    let Ok(status) = std::fs::read_to_string("/proc/self/status") else {
        return 0;
    };
    status
        .lines()
        .find_map(|l| l.strip_prefix(field))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_figures_are_plausible_on_linux() {
        if cfg!(target_os = "linux") {
            let now = resident_kb();
            assert!(now > 100, "resident {now} kB");
            assert!(peak_rss_kb() >= now);
        }
    }
}
