//! LWPR on functions whose answers are known: a smooth 5-D → 3-D function, a single field
//! against a weighted regression worked out by hand, and answers that stay finite in the
//! wrapper every run puts it in.

use super::field::ReceptiveField;
use super::output_model::OutputModel;
use super::projection::Input;
use super::{Lwpr, LwprSettings};
use crate::learn::change::WatchedLearner;
use crate::learn::{Learner, Query};
use nalgebra::Vector3;
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::sync::LazyLock;

/// Inputs in the unit box, so normalisation leaves them as they are.
const UNIT_BOX: [(f64, f64); 5] = [(0.0, 1.0); 5];

/// A smooth mapping of the unit box to three outputs of about unit size.
fn smooth(x: &Input) -> Vector3<f64> {
    Vector3::new(
        (2.0 * x[0]).sin() + x[1] * x[2] - 0.5 * x[3],
        (1.5 * x[1] + x[4]).cos() + 0.3 * x[0] * x[0],
        x[2] * (1.0 - x[3]) + 0.5 * (3.0 * x[4]).sin() * x[0],
    )
}

fn random_input(rng: &mut ChaCha8Rng) -> Input {
    Input::from_fn(|_, _| rng.random_range(0.0..1.0))
}

/// Normalised mean squared error of each output over `n` fresh inputs.
fn nmse(lwpr: &Lwpr, rng: &mut ChaCha8Rng, n: usize) -> [f64; 3] {
    let samples: Vec<(Input, Vector3<f64>)> = (0..n)
        .map(|_| {
            let x = random_input(rng);
            (x, smooth(&x))
        })
        .collect();
    std::array::from_fn(|i| {
        let mean = samples.iter().map(|(_, y)| y[i]).sum::<f64>() / n as f64;
        let variance = samples
            .iter()
            .map(|(_, y)| (y[i] - mean).powi(2))
            .sum::<f64>();
        let error: f64 = samples
            .iter()
            .map(|(x, y)| (lwpr.answer(x)[i].unwrap_or(0.0) - y[i]).powi(2))
            .sum();
        error / variance
    })
}

fn unit_settings() -> LwprSettings {
    LwprSettings {
        norm_out: 1.0,
        ..LwprSettings::default()
    }
}

#[test]
fn learns_a_smooth_5d_to_3d_function_to_an_nmse_below_one_percent_within_50000_samples() {
    let mut rng = ChaCha8Rng::seed_from_u64(17);
    let mut lwpr = Lwpr::new(unit_settings(), UNIT_BOX);
    let mut fields = Vec::new();
    for sample in 1..=50_000 {
        let x = random_input(&mut rng);
        lwpr.train(&x, &smooth(&x));
        if sample % 5_000 == 0 {
            fields.push(lwpr.fields().iter().sum::<usize>());
        }
    }
    let errors = nmse(&lwpr, &mut rng, 2_000);
    println!("nMSE {errors:?}, fields every 5,000 samples {fields:?}");
    assert!(errors.iter().all(|&e| e < 0.01), "nMSE {errors:?}");
}

#[test]
fn the_number_of_fields_grows_then_saturates() {
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    let mut lwpr = Lwpr::new(unit_settings(), UNIT_BOX);
    let mut counts = Vec::new();
    for sample in 1..=40_000 {
        let x = random_input(&mut rng);
        lwpr.train(&x, &smooth(&x));
        if sample % 2_000 == 0 {
            counts.push(lwpr.fields().iter().sum::<usize>());
        }
    }
    println!("fields every 2,000 samples: {counts:?}");
    let early_growth = counts[4] - counts[0];
    let late_growth = counts[19] - counts[15];
    assert!(counts[0] > 3, "fields were made: {counts:?}");
    assert!(early_growth > 0, "the field count grows: {counts:?}");
    assert!(
        late_growth * 10 <= early_growth.max(1) && late_growth <= counts[15] / 50,
        "the field count levels off: {counts:?}"
    );
}

/// One output's model with one field at `centre` of the fixed metric `d`·I that never
/// forgets and never adapts its metric.
fn fixed_single_field(d: f64) -> LwprSettings {
    LwprSettings {
        init_d: d,
        init_lambda: 1.0,
        final_lambda: 1.0,
        w_gen: 1e-9,
        ..unit_settings()
    }
}

#[test]
fn a_single_field_matches_the_weighted_least_squares_line_worked_out_by_hand() {
    // y = 1 + 2t + 3t² sampled along input 2, the other inputs at the centre's values: the
    // field's model must be the weighted least-squares line through the samples, each
    // weighted by its activation exp(−d·(t − c)²/2).
    let (d, centre) = (16.0, 0.2);
    let settings = fixed_single_field(d);
    let along = |t: f64| Input::new(0.5, 0.5, t, 0.5, 0.5);
    let target = |t: f64| 1.0 + 2.0 * t + 3.0 * t * t;
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut ts = vec![centre];
    ts.extend((0..4_000).map(|_| rng.random_range(0.0..1.0)));
    let mut model = OutputModel::default();
    for &t in &ts {
        model.train(&along(t), target(t), &settings);
    }
    assert_eq!(model.len(), 1, "one field covers every sample");
    // By hand: weighted means, then slope = Σw(t − t̄)(y − ȳ) / Σw(t − t̄)².
    let w: Vec<f64> = ts
        .iter()
        .map(|t| (-0.5 * d * (t - centre).powi(2)).exp())
        .collect();
    let sum_w: f64 = w.iter().sum();
    let t_bar = ts.iter().zip(&w).map(|(t, w)| w * t).sum::<f64>() / sum_w;
    let y_bar = ts.iter().zip(&w).map(|(t, w)| w * target(*t)).sum::<f64>() / sum_w;
    let (mut sty, mut stt) = (0.0, 0.0);
    for (t, w) in ts.iter().zip(&w) {
        sty += w * (t - t_bar) * (target(*t) - y_bar);
        stt += w * (t - t_bar).powi(2);
    }
    let slope = sty / stt;
    let field: &ReceptiveField = &model.fields()[0];
    for t in [0.0, 0.2, 0.5, 0.8] {
        let by_hand = y_bar + slope * (t - t_bar);
        let learned = field.predict(&along(t));
        assert!(
            (learned - by_hand).abs() < 2e-3,
            "at t = {t}: learned {learned}, by hand {by_hand}"
        );
    }
    // A straight line would be far off: the weighting is what is being checked.
    let unweighted_slope = 2.0 + 3.0; // the least-squares slope of 2t + 3t² on U(0, 1)
    assert!((slope - unweighted_slope).abs() > 0.3, "slope {slope}");
}

/// A model (and its settings) trained on 20,000 patterns of an output that depends on all
/// five inputs.
fn trained_on_five_inputs() -> (OutputModel, LwprSettings) {
    let settings = LwprSettings {
        init_d: 1.0,
        ..unit_settings()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    let mut model = OutputModel::default();
    for _ in 0..20_000 {
        let x = random_input(&mut rng);
        model.train(&x, x[0] - 2.0 * x[1] + 3.0 * x[2] + x[3] - x[4], &settings);
    }
    (model, settings)
}

#[test]
fn a_field_adds_projections_when_the_output_depends_on_several_inputs() {
    let (model, _) = trained_on_five_inputs();
    let most = model.fields().iter().map(|f| f.projections()).max();
    assert!(most > Some(2), "projections: {most:?}");
}

#[test]
fn a_field_made_next_to_a_neighbour_starts_with_its_number_of_projections() {
    let (model, settings) = trained_on_five_inputs();
    let neighbour = model
        .fields()
        .iter()
        .max_by_key(|f| f.projections())
        .expect("fields");
    assert!(neighbour.projections() > 2, "{}", neighbour.projections());
    let x = Input::repeat(0.5);
    let next_to = ReceptiveField::new(x, 0.0, Some(neighbour), &settings);
    assert_eq!(next_to.projections(), neighbour.projections());
    let alone = ReceptiveField::new(x, 0.0, None, &settings);
    assert_eq!(alone.projections(), 2);
}

#[test]
fn overlapping_fields_are_pruned_below_w_prune() {
    let settings = LwprSettings {
        w_prune: 0.5,
        ..unit_settings()
    };
    let mut model = OutputModel::default();
    // Two fields made far apart, then a pattern between them activating both above 0.5.
    model.train(&Input::repeat(0.40), 1.0, &settings);
    model.train(&Input::repeat(0.60), 1.0, &settings);
    assert_eq!(model.len(), 2);
    model.train(&Input::repeat(0.50), 1.0, &settings);
    assert_eq!(
        model.len(),
        1,
        "one of the two overlapping fields is dropped"
    );
}

/// A learner trained on a few thousand samples of the smooth function.
static TRAINED: LazyLock<Lwpr> = LazyLock::new(|| {
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut lwpr = Lwpr::new(unit_settings(), UNIT_BOX);
    for _ in 0..3_000 {
        let x = random_input(&mut rng);
        lwpr.train(&x, &smooth(&x));
    }
    lwpr
});

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    #[test]
    fn propose_is_always_finite(
        c in prop::array::uniform3(prop_oneof![-1e9..1e9f64, -2.0..2.0f64]),
        theta2 in prop_oneof![-1e9..1e9f64, -2.0..2.0f64],
        theta3 in prop_oneof![-1e9..1e9f64, -2.0..2.0f64],
    ) {
        let mut lwpr = WatchedLearner::unwatched(Box::new(TRAINED.clone()));
        let query = Query { c: Vector3::from(c), theta2_deg: theta2, theta3_deg: theta3 };
        let answer = lwpr.propose(&query);
        prop_assert!(answer.iter().all(|v| v.is_finite()), "{answer}");
        let mut empty = WatchedLearner::unwatched(Box::new(Lwpr::new(unit_settings(), UNIT_BOX)));
        prop_assert_eq!(empty.propose(&query), Vector3::zeros());
    }
}

#[test]
fn propose_of_a_non_finite_query_is_zero() {
    let mut lwpr = WatchedLearner::unwatched(Box::new(TRAINED.clone()));
    let query = Query {
        c: Vector3::new(f64::NAN, 0.5, f64::INFINITY),
        theta2_deg: 0.5,
        theta3_deg: 0.5,
    };
    assert_eq!(lwpr.propose(&query), Vector3::zeros());
}
