//! Hostile but realistic inputs against the binary: every case in `tests/bad_inputs/*.case`
//! (a config, URDF, data file or command line) must end within seconds with its expected
//! exit code and message — no panic, abort, hang or silent acceptance — and a refused run
//! must leave no run folder.
//!
//! A case file holds `key: value` lines (`#` starts a comment):
//! - `config: NAME VALUE` — the complete default config (`eyehand config defaults`) with entry NAME's line replaced
//!   (repeatable; a repeated entry such as `obstacle` replaces its commented example line
//!   `# NAME …`), written to `{config}`; `{line}` is the first replaced line's number;
//!   `config_bom: yes` writes that config after a UTF-8 byte-order mark; `\0` in NAME VALUE
//!   is a NUL byte;
//! - `urdf: FROM => TO` — the shipped URDF with FROM replaced by TO, written to `{urdf}`;
//!   `urdf_bom: yes` writes it after a byte-order mark;
//! - `file: PATH => TEXT` — TEXT (`\n` for a newline) written to `{dir}/PATH`;
//! - `fifo: PATH` — a FIFO made at `{dir}/PATH`, which nothing writes to;
//! - `args:` the command line (`{dir}` is the case's own folder, `{huge}` 100,000 sevens);
//! - `stdout_to: full` (`/dev/full`) or `closed` (a pipe whose reader is gone);
//! - `exit:` the expected code; `stdout:` / `stderr:` the expected first words;
//!   `stderr_max:` the most characters stderr may have.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// A case running longer than this hangs.
const TIME_LIMIT: Duration = Duration::from_secs(15);
const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// How a case ended, judged against what it expects.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Verdict {
    /// Expected a refusal and got it, with the expected message.
    ClearError,
    /// Expected success and got it.
    Works,
    Panic,
    Abort,
    Hang,
    /// Exit 0 where a refusal was expected.
    SilentAcceptance,
    /// Another code or message than expected.
    Unexpected,
}

#[derive(Debug, Default)]
struct Case {
    configs: Vec<String>,
    config_bom: bool,
    urdf: Option<(String, String)>,
    urdf_bom: bool,
    files: Vec<(String, String)>,
    fifos: Vec<String>,
    args: String,
    stdout_to: Option<String>,
    exit: i32,
    stdout: String,
    stderr: String,
    stderr_max: Option<usize>,
}

fn parse_case(text: &str) -> Case {
    let mut case = Case::default();
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let (key, value) = line.split_once(':').expect("key: value");
        let value = value.trim().to_string();
        let pair = |v: &str| {
            let (a, b) = v.split_once(" => ").expect("FROM => TO");
            (a.to_string(), b.replace("\\n", "\n"))
        };
        match key {
            "config" => case.configs.push(value),
            "config_bom" => case.config_bom = value == "yes",
            "urdf" => case.urdf = Some(pair(&value)),
            "urdf_bom" => case.urdf_bom = value == "yes",
            "file" => case.files.push(pair(&value)),
            "fifo" => case.fifos.push(value),
            "args" => case.args = value,
            "stdout_to" => case.stdout_to = Some(value),
            "exit" => case.exit = value.parse().expect("exit code"),
            "stdout" => case.stdout = value,
            "stderr" => case.stderr = value,
            "stderr_max" => case.stderr_max = Some(value.parse().expect("a length")),
            other => panic!("unknown key {other}"),
        }
    }
    case
}

/// Writes the case's files into `dir`; returns the placeholders and their values.
fn prepare(case: &Case, dir: &Path) -> Vec<(&'static str, String)> {
    let huge = "7".repeat(100_000);
    let config_path = dir.join("case.conf");
    let mut config = eyehand::experiment::defaults_text();
    let mut first_line = 0;
    for replacement in &case.configs {
        let replacement = replacement.replace("{huge}", &huge).replace("\\0", "\0");
        let name = replacement.split_whitespace().next().unwrap();
        let lines: Vec<&str> = config.lines().collect();
        let first_word = |l: &str| l.split_whitespace().next() == Some(name);
        let at = lines.iter().position(|l| first_word(l)).or_else(|| {
            lines
                .iter()
                .position(|l| l.strip_prefix("# ").is_some_and(first_word))
        });
        let at = at.unwrap_or_else(|| {
            let similar = name.get(..8).unwrap_or(name);
            lines
                .iter()
                .position(|l| l.starts_with(similar))
                .expect("an entry to replace")
        });
        first_line = if first_line == 0 { at + 1 } else { first_line };
        let mut lines: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        lines[at] = replacement;
        config = lines.join("\n") + "\n";
    }
    let bom = |yes: bool| if yes { "\u{feff}" } else { "" };
    std::fs::write(&config_path, format!("{}{config}", bom(case.config_bom))).unwrap();
    let urdf_path = dir.join("case.urdf");
    let mut urdf = std::fs::read_to_string(format!("{ROOT}/urdf/oscar6.urdf")).unwrap();
    if let Some((from, to)) = &case.urdf {
        assert!(urdf.contains(from.as_str()), "the URDF has `{from}`");
        urdf = urdf.replacen(from.as_str(), to, 1);
    }
    std::fs::write(&urdf_path, format!("{}{urdf}", bom(case.urdf_bom))).unwrap();
    for (path, text) in &case.files {
        let path = dir.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    for path in &case.fifos {
        let path = std::ffi::CString::new(dir.join(path).to_str().unwrap()).unwrap();
        // SAFETY: a valid NUL-terminated path and a plain mode.
        assert_eq!(unsafe { libc::mkfifo(path.as_ptr(), 0o600) }, 0, "mkfifo");
    }
    vec![
        ("{config}", config_path.display().to_string()),
        ("{urdf}", urdf_path.display().to_string()),
        ("{dir}", dir.display().to_string()),
        ("{line}", first_line.to_string()),
        ("{huge}", huge),
    ]
}

fn fill(text: &str, values: &[(&str, String)]) -> String {
    values
        .iter()
        .fold(text.to_string(), |t, (key, value)| t.replace(key, value))
}

/// Waits for `child` up to the time limit; `None` if it had to be killed.
fn wait_limited(child: &mut Child) -> Option<ExitStatus> {
    let started = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return Some(status);
        }
        if started.elapsed() > TIME_LIMIT {
            child.kill().unwrap();
            child.wait().unwrap();
            return None;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// True when `data` holds a run folder (`<data>/<method>/<id>`).
fn has_run_folder(data: &Path) -> bool {
    let Ok(methods) = std::fs::read_dir(data) else {
        return false;
    };
    methods
        .flatten()
        .any(|m| std::fs::read_dir(m.path()).is_ok_and(|mut ids| ids.next().is_some()))
}

fn run_case(case: &Case, dir: &Path) -> (Verdict, String) {
    use std::os::unix::process::ExitStatusExt;
    let values = prepare(case, dir);
    let args: Vec<String> = case
        .args
        .split_whitespace()
        .map(|a| fill(a, &values))
        .collect();
    let mut command = Command::new(env!("CARGO_BIN_EXE_eyehand"));
    command.args(&args).current_dir(ROOT).stderr(Stdio::piped());
    command.stdout(match case.stdout_to.as_deref() {
        Some("full") => Stdio::from(std::fs::File::create("/dev/full").unwrap()),
        _ => Stdio::piped(),
    });
    let mut child = command.spawn().unwrap();
    let stdout_pipe = child.stdout.take();
    let stdout_reader = match case.stdout_to.as_deref() {
        Some("closed") => {
            drop(stdout_pipe);
            None
        }
        _ => stdout_pipe.map(|mut pipe| {
            std::thread::spawn(move || {
                let mut text = String::new();
                let _ = pipe.read_to_string(&mut text);
                text
            })
        }),
    };
    let mut stderr_pipe = child.stderr.take().unwrap();
    let stderr_reader = std::thread::spawn(move || {
        let mut text = String::new();
        let _ = stderr_pipe.read_to_string(&mut text);
        text
    });
    let Some(status) = wait_limited(&mut child) else {
        return (Verdict::Hang, "killed after the time limit".into());
    };
    let stdout = stdout_reader.map_or(String::new(), |r| r.join().unwrap());
    let stderr = stderr_reader.join().unwrap();
    let seen = format!("exit {status}, stdout `{stdout:.200}`, stderr `{stderr:.300}`");
    let code = status.code();
    let verdict = if code == Some(101) {
        Verdict::Panic
    } else if status.signal() == Some(6) || code == Some(134) {
        Verdict::Abort
    } else if code == Some(0) && case.exit != 0 {
        Verdict::SilentAcceptance
    } else if code != Some(case.exit)
        || !stdout.starts_with(&fill(&case.stdout, &values))
        || !stderr.starts_with(&fill(&case.stderr, &values))
        || case
            .stderr_max
            .is_some_and(|max| stderr.chars().count() > max)
        || (case.exit == 2 && has_run_folder(&dir.join("data")))
    {
        Verdict::Unexpected
    } else if case.exit == 0 {
        Verdict::Works
    } else {
        Verdict::ClearError
    };
    (verdict, seen)
}

fn case_files() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(format!("{ROOT}/tests/bad_inputs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "case"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_bad_input_ends_in_a_clear_error_or_works() {
    let files = case_files();
    assert!(files.len() >= 50, "the corpus has its cases");
    let mut tally: Vec<(Verdict, usize)> = Vec::new();
    let mut wrong = Vec::new();
    for file in &files {
        let case = parse_case(&std::fs::read_to_string(file).unwrap());
        let dir = tempfile::tempdir().unwrap();
        let (verdict, seen) = run_case(&case, dir.path());
        match tally.iter_mut().find(|(v, _)| *v == verdict) {
            Some((_, n)) => *n += 1,
            None => tally.push((verdict, 1)),
        }
        if !matches!(verdict, Verdict::ClearError | Verdict::Works) {
            wrong.push(format!("{}: {verdict:?}: {seen}", file.display()));
        }
    }
    println!("| cases | verdict |\n|---|---|");
    for (verdict, n) in &tally {
        println!("| {n} | {verdict:?} |");
    }
    assert!(
        wrong.is_empty(),
        "{} of {} cases:\n{}",
        wrong.len(),
        files.len(),
        wrong.join("\n")
    );
}
