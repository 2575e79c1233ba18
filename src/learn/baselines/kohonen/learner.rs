//! The Kohonen learner: the lattice plus a local linear map per neuron,
//! Δθ ≈ uᵣ + Aᵣ·(x − wᵣ), trained on each trial's adjusted patterns. The winner's
//! neighbours move their weights towards the input and their linear maps towards the
//! pattern by a normalised least-mean-squares step; neighbourhood width and rates shrink
//! exponentially over `anneal_patterns` patterns.

use super::Lattice;
use crate::learn::baselines::net::InputScaling;
use crate::learn::change::SingleModel;
use crate::learn::MethodFacts;
use crate::learn::{adjusted_pattern, Observation, PatternSettings, Query};
use crate::learn::{LearnError, Learner, LearnerStats, Method};
use nalgebra::{SMatrix, SVector, Vector3};

/// Settings of the `kohonen` learner.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KohonenSettings {
    /// Neurons per lattice side; 7 (7⁵ = 16,807 neurons) by default.
    pub side: usize,
    /// Neighbourhood width (lattice steps) at the start; 2.0 by default.
    pub sigma_start: f64,
    /// Neighbourhood width at the end of annealing; 0.5 by default.
    pub sigma_end: f64,
    /// Weight learning rate at the start; 0.5 by default.
    pub rate_start: f64,
    /// Weight learning rate at the end; 0.02 by default.
    pub rate_end: f64,
    /// Linear-map learning rate at the start; 0.8 by default.
    pub map_rate_start: f64,
    /// Linear-map learning rate at the end; 0.2 by default.
    pub map_rate_end: f64,
    /// Patterns over which widths and rates shrink; 150,000 by default.
    pub anneal_patterns: usize,
    /// Which pose pairs are patterns (`minimal_joint_move`).
    pub patterns: PatternSettings,
}

impl Default for KohonenSettings {
    fn default() -> Self {
        KohonenSettings {
            side: 7,
            sigma_start: 2.0,
            sigma_end: 0.5,
            rate_start: 0.5,
            rate_end: 0.02,
            map_rate_start: 0.8,
            map_rate_end: 0.2,
            anneal_patterns: 150_000,
            patterns: PatternSettings::default(),
        }
    }
}

/// A local linear map: output and Jacobian (scaled inputs → degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
struct LinearMap {
    output: Vector3<f64>,
    jacobian: SMatrix<f64, 3, 5>,
}

/// A 5-D Kohonen map of local linear maps.
#[derive(Debug, Clone)]
pub struct KohonenLearner {
    settings: KohonenSettings,
    lattice: Lattice<5>,
    maps: Vec<LinearMap>,
    scaling: InputScaling<5>,
    patterns_seen: usize,
}

impl KohonenLearner {
    /// A map over inputs in `bounds` (θ2, θ3, cx, cy, cz), its weights on a regular grid.
    pub fn new(settings: KohonenSettings, bounds: [(f64, f64); 5]) -> KohonenLearner {
        let lattice = Lattice::regular(settings.side);
        let empty = LinearMap {
            output: Vector3::zeros(),
            jacobian: SMatrix::zeros(),
        };
        KohonenLearner {
            settings,
            maps: vec![empty; lattice.len()],
            lattice,
            scaling: InputScaling::new(bounds),
            patterns_seen: 0,
        }
    }

    /// (σ, weight rate, map rate) now.
    fn schedule(&self) -> (f64, f64, f64) {
        let s = &self.settings;
        let f = (self.patterns_seen as f64 / s.anneal_patterns.max(1) as f64).min(1.0);
        let between = |start: f64, end: f64| start * (end / start).powf(f);
        (
            between(s.sigma_start, s.sigma_end),
            between(s.rate_start, s.rate_end),
            between(s.map_rate_start, s.map_rate_end),
        )
    }

    fn train(&mut self, x: &SVector<f64, 5>, target: &Vector3<f64>) {
        let (sigma, rate, map_rate) = self.schedule();
        let winner = self.lattice.winner(x);
        for (i, h) in self.lattice.neighbourhood(winner, sigma) {
            let offset = x - self.lattice.weight(i);
            let map = &mut self.maps[i];
            let error = target - (map.output + map.jacobian * offset);
            let step = map_rate * h;
            map.output += error * step;
            map.jacobian += error * offset.transpose() * (step / (1.0 + offset.norm_squared()));
        }
        self.lattice.adapt(x, winner, sigma, rate);
        self.patterns_seen += 1;
    }
}

impl Learner for KohonenLearner {
    fn name(&self) -> &str {
        Method::Kohonen.name()
    }

    fn propose(&mut self, query: &Query) -> Vector3<f64> {
        let x = self.scaling.apply(&query.five_inputs());
        let winner = self.lattice.winner(&x);
        let map = &self.maps[winner];
        let out = map.output + map.jacobian * (x - self.lattice.weight(winner));
        if out.iter().all(|v| v.is_finite()) {
            out
        } else {
            Vector3::zeros()
        }
    }

    fn learn(&mut self, path: &[Observation]) -> Result<(), LearnError> {
        for (from, to) in self.settings.patterns.pairs(path) {
            let p = adjusted_pattern(from, to);
            let x = self.scaling.apply(&p.input);
            self.train(&x, &p.target);
        }
        Ok(())
    }

    fn stats(&self) -> LearnerStats {
        LearnerStats {
            nodes: self.lattice.len(),
            bins: 0,
            patterns: 0,
            levels: Vec::new(),
        }
    }
}

/// It cannot forget: under change detection it recovers by `change_recovery correct`.
impl SingleModel for KohonenLearner {}

/// What the program knows of `kohonen` besides its learner (see [`Method::facts`](crate::learn::Method::facts)).
pub(crate) const KOHONEN_FACTS: MethodFacts = MethodFacts {
    name: "kohonen",
    size: |stats| format!("map: {} cells; ", stats.nodes),
    counts_nodes: true,
    kb_per_trial: 0.0,
    bounded: true,
    watches_changes: true,
    slow_entries: "feedback_steps, bin_size, max_stored_patterns",
    // The map of 16,807 cells fills slowly: the study ran its map for 20,000 trials.
    shared_defaults: &[("trials", "20000")],
};
