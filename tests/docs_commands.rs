//! The docs say what is true: every command block marked runnable in README.md and docs/
//! (a line `<!-- runnable -->` right before a ```sh block) runs with the built binary and
//! exits 0, and every path ARCHITECTURE.md names exists.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");
const EYEHAND: &str = env!("CARGO_BIN_EXE_eyehand");
const MARKER: &str = "<!-- runnable -->";
/// The repository's top-level folders a path in ARCHITECTURE.md may start with.
const TOP_LEVEL: [&str; 10] = [
    "src", "tests", "benches", "examples", "python", "configs", "tools", "scripts", "docs",
    "assets",
];

/// A runnable block: the page, the line of its marker and the commands.
struct Block {
    page: PathBuf,
    line: usize,
    script: String,
}

/// README.md and every page in docs/.
fn doc_pages() -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = std::fs::read_dir(Path::new(ROOT).join("docs"))
        .expect("docs/")
        .map(|entry| entry.expect("a docs/ entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    pages.insert(0, Path::new(ROOT).join("README.md"));
    pages
}

/// The blocks of `page` marked runnable; a marker not followed by a ```sh block fails.
fn runnable_blocks(page: &Path) -> Vec<Block> {
    let text = std::fs::read_to_string(page).expect("a docs page");
    let lines: Vec<&str> = text.lines().collect();
    let mut blocks = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if line.trim() != MARKER {
            continue;
        }
        assert_eq!(
            lines.get(i + 1).map(|l| l.trim()),
            Some("```sh"),
            "{}:{}: {MARKER} must come right before a ```sh block",
            page.display(),
            i + 1
        );
        let body: Vec<&str> = lines[i + 2..]
            .iter()
            .take_while(|l| l.trim() != "```")
            .copied()
            .collect();
        blocks.push(Block {
            page: page.to_path_buf(),
            line: i + 1,
            script: body.join("\n"),
        });
    }
    blocks
}

/// Runs `block` as one `sh -e` script in a fresh folder with `configs/` linked in and the
/// built binary on the PATH as `eyehand`.
fn run_block(block: &Block) -> std::process::Output {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let bin = dir.path().join("bin");
    std::fs::create_dir(&bin).unwrap();
    std::os::unix::fs::symlink(EYEHAND, bin.join("eyehand")).unwrap();
    std::os::unix::fs::symlink(Path::new(ROOT).join("configs"), dir.path().join("configs"))
        .unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    Command::new("sh")
        .args(["-e", "-c", &block.script])
        .current_dir(dir.path())
        .env("PATH", path)
        .output()
        .expect("sh runs")
}

#[test]
fn every_runnable_docs_block_exits_0() {
    let blocks: Vec<Block> = doc_pages()
        .iter()
        .flat_map(|p| runnable_blocks(p))
        .collect();
    assert!(
        blocks.len() >= 5,
        "only {} runnable blocks found: the marker must be `{MARKER}`",
        blocks.len()
    );
    for block in &blocks {
        let started = Instant::now();
        let out = run_block(block);
        assert!(
            out.status.success(),
            "{}:{}: the block exited with {}\n{}\nstdout:\n{}\nstderr:\n{}",
            block.page.display(),
            block.line,
            out.status,
            block.script,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        eprintln!(
            "{}:{}: ok in {:.1} s",
            block.page.display(),
            block.line,
            started.elapsed().as_secs_f64()
        );
    }
}

/// The path a backticked `token` names, if it names one: from the repository when it starts
/// with a top-level folder, else (a file `*.rs` or a folder `name/`) from `section`.
fn named_path(token: &str, section: Option<&str>) -> Option<PathBuf> {
    let plain = token
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "_/.-".contains(c));
    if !plain || !token.contains(['/', '.']) {
        return None;
    }
    let first = token.split('/').next().unwrap_or_default();
    if token.contains('/') && TOP_LEVEL.contains(&first) {
        return Some(Path::new(ROOT).join(token));
    }
    let relative = token.ends_with(".rs") || token.ends_with('/');
    section
        .filter(|_| relative)
        .map(|folder| Path::new(ROOT).join(folder).join(token))
}

/// The backticked tokens of `line`.
fn backticked(line: &str) -> impl Iterator<Item = &str> {
    line.split('`').skip(1).step_by(2)
}

#[test]
fn every_path_architecture_names_exists() {
    let text = std::fs::read_to_string(Path::new(ROOT).join("ARCHITECTURE.md")).unwrap();
    let mut section: Option<String> = None;
    let mut checked = 0;
    let mut missing = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line.starts_with('#') {
            section = backticked(line)
                .find(|t| t.starts_with("src/") && t.ends_with('/'))
                .map(str::to_string);
            continue;
        }
        for token in backticked(line) {
            if let Some(path) = named_path(token, section.as_deref()) {
                checked += 1;
                if !path.exists() {
                    missing.push(format!("line {}: `{token}`", i + 1));
                }
            }
        }
    }
    assert!(
        checked >= 100,
        "only {checked} paths found in ARCHITECTURE.md"
    );
    assert!(
        missing.is_empty(),
        "ARCHITECTURE.md names paths that do not exist:\n{}",
        missing.join("\n")
    );
}
