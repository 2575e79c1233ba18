//! Learners on the real (kinematic) simulator with loose bounds: each must actually learn
//! the eye-hand mapping from its own moves.

use eyehand::experiment::{run, Config, RunOptions, RunSummary};
use eyehand::learn::Method;

/// A run of `method` with its shipped config (`configs/<method>.conf`).
fn run_method(method: Method, trials: usize, seed: u64) -> RunSummary {
    let data = tempfile::tempdir().unwrap();
    let path = format!("{}/configs/{method}.conf", env!("CARGO_MANIFEST_DIR"));
    let mut config = Config::from_file(std::path::Path::new(&path)).unwrap();
    config.trials = trials;
    config.seed = seed;
    let summary = run(&RunOptions::new(config, data.path())).unwrap().summary;
    assert!(
        summary.learned,
        "{method} at its defaults learned: {:?}",
        summary.not_learned
    );
    summary
}

fn step(summary: &RunSummary, n: usize) -> f64 {
    summary.mean_distance_mm[n - 1].expect("the step was taken")
}

#[test]
fn lin5_reaches_below_a_millimetre_after_four_steps_within_3000_trials() {
    let summary = run_method(Method::Lin5, 3000, 1);
    println!(
        "lin5, 3000 trials: {:?} mm, {} nodes",
        summary.mean_distance_mm, summary.nodes
    );
    assert!(
        step(&summary, 4) < 1.0,
        "4-step mean {} mm",
        step(&summary, 4)
    );
    assert!(summary.nodes > 50, "the tree grew: {} nodes", summary.nodes);
    assert!(summary.failures < 300, "{} failures", summary.failures);
}

#[test]
fn lin8_reaches_below_two_millimetres_after_four_steps_within_3000_trials() {
    let summary = run_method(Method::Lin8, 3000, 1);
    println!(
        "lin8, 3000 trials: {:?} mm, {} nodes",
        summary.mean_distance_mm, summary.nodes
    );
    assert!(
        step(&summary, 4) < 2.0,
        "4-step mean {} mm",
        step(&summary, 4)
    );
    assert!(summary.nodes > 20, "the tree grew: {} nodes", summary.nodes);
    assert!(summary.failures < 300, "{} failures", summary.failures);
}

#[test]
fn nnw_gets_within_three_millimetres_after_three_steps_within_1000_trials() {
    let summary = run_method(Method::Nnw, 1000, 1);
    println!(
        "nnw, 1000 trials: {:?} mm, {} nodes",
        summary.mean_distance_mm, summary.nodes
    );
    assert!(
        step(&summary, 3) < 3.0,
        "3-step mean {} mm",
        step(&summary, 3)
    );
    assert!(summary.nodes > 20, "the tree grew: {} nodes", summary.nodes);
    assert!(summary.failures < 100, "{} failures", summary.failures);
}

#[test]
fn ffn_gets_within_a_centimetre_after_five_steps_within_400_trials() {
    let summary = run_method(Method::Ffn, 400, 1);
    println!("ffn, 400 trials: {:?} mm", summary.mean_distance_mm);
    assert!(
        step(&summary, 5) < 10.0,
        "5-step mean {} mm",
        step(&summary, 5)
    );
    assert!(
        step(&summary, 5) < step(&summary, 1) / 4.0,
        "feedback steps close in"
    );
}

#[test]
fn kohonen_gets_within_three_centimetres_after_five_steps_within_1000_trials() {
    let summary = run_method(Method::Kohonen, 1000, 1);
    println!("kohonen, 1000 trials: {:?} mm", summary.mean_distance_mm);
    assert!(
        step(&summary, 5) < 30.0,
        "5-step mean {} mm",
        step(&summary, 5)
    );
    assert_eq!(summary.nodes, 16_807, "a 7⁵ map");
}

#[test]
fn lwpr_closes_in_on_the_target_within_2000_trials() {
    let summary = run_method(Method::Lwpr, 2000, 1);
    println!(
        "lwpr, 2000 trials: {:?} mm, {} fields",
        summary.mean_distance_mm, summary.nodes
    );
    assert!(
        step(&summary, 4) < 15.0,
        "4-step mean {} mm",
        step(&summary, 4)
    );
    assert!(
        step(&summary, 4) < step(&summary, 1) / 5.0,
        "feedback steps close in: {:?}",
        summary.mean_distance_mm
    );
    assert!(summary.nodes > 20, "fields were made: {}", summary.nodes);
    assert!(summary.failures < 200, "{} failures", summary.failures);
}

/// `method` (its shipped config) gets within 5 mm after four steps within 5,000 trials.
fn learns_within_five_millimetres_after_four_steps(method: Method) -> RunSummary {
    let summary = run_method(method, 5000, 1);
    println!("{method}, 5000 trials: {:?} mm", summary.mean_distance_mm);
    assert!(
        step(&summary, 4) <= 5.0,
        "{method}: 4-step mean {} mm",
        step(&summary, 4)
    );
    assert!(
        step(&summary, 4) < step(&summary, 1) / 3.0,
        "{method}: feedback steps close in: {:?}",
        summary.mean_distance_mm
    );
    assert!(
        summary.failures < 300,
        "{method}: {} failures",
        summary.failures
    );
    summary
}

#[test]
fn issgp_gets_within_five_millimetres_after_four_steps_within_5000_trials() {
    let summary = learns_within_five_millimetres_after_four_steps(Method::Issgp);
    assert_eq!(summary.nodes, 500, "D features");
}

#[test]
fn mlp_gets_within_five_millimetres_after_four_steps_within_5000_trials() {
    learns_within_five_millimetres_after_four_steps(Method::Mlp);
}
