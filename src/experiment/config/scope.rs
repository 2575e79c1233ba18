//! What a config entry applies to: every run, some methods, one simulator or camera, or
//! nothing (an entry kept from the study's config that eyehand does not implement).

use super::values::{CameraKind, SimKind};
use crate::learn::Method;
use std::fmt;

/// What an entry's value changes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scope {
    /// Every run.
    All,
    /// Runs of these methods only.
    Methods(&'static [Method]),
    /// Runs on this simulator only.
    Sim(SimKind),
    /// Runs with this camera only.
    Camera(CameraKind),
    /// Nothing: the study's config had it, eyehand accepts it and records it as unused.
    Unused,
}

/// The nested learners (the tree).
pub(super) const NESTED: Scope = Scope::Methods(&[Method::Lin5, Method::Lin8, Method::Nnw]);
/// The Nested Perceptrons.
pub(super) const PERCEPTRONS: Scope = Scope::Methods(&[Method::Lin5, Method::Lin8]);
/// The learners whose root box the input boundaries 0–4 are (their facts say `bounded`).
pub(super) const BOUNDED: Scope = Scope::Methods(&BOUNDED_METHODS);
/// The learners that watch for a change (`merge_strategy change_detection`; their facts
/// say `watches_changes`).
pub(super) const WATCHING: Scope = Scope::Methods(&WATCHING_METHODS);
/// `lin8` alone.
pub(super) const LIN8: Scope = Scope::Methods(&[Method::Lin8]);
/// `nnw` alone.
pub(super) const NNW: Scope = Scope::Methods(&[Method::Nnw]);
/// The learners made of nets (`nnw`, `ffn`).
pub(super) const NETS: Scope = Scope::Methods(&[Method::Nnw, Method::Ffn]);
/// `ffn` alone.
pub(super) const FFN: Scope = Scope::Methods(&[Method::Ffn]);
/// `kohonen` alone.
pub(super) const KOHONEN: Scope = Scope::Methods(&[Method::Kohonen]);
/// `lwpr` alone.
pub(super) const LWPR: Scope = Scope::Methods(&[Method::Lwpr]);
/// `issgp` alone.
pub(super) const ISSGP: Scope = Scope::Methods(&[Method::Issgp]);
/// `mlp` alone.
pub(super) const MLP: Scope = Scope::Methods(&[Method::Mlp]);
/// The single-model regressors of Δθ in `norm_out` units (`lwpr`, `issgp`, `mlp`).
pub(super) const REGRESSORS: Scope = Scope::Methods(&[Method::Lwpr, Method::Issgp, Method::Mlp]);
/// `broyden` alone.
pub(super) const BROYDEN: Scope = Scope::Methods(&[Method::Broyden]);
/// The dynamic simulator.
pub(super) const DYNAMIC: Scope = Scope::Sim(SimKind::Dynamic);
/// The ray-cast camera.
pub(super) const RAYCAST: Scope = Scope::Camera(CameraKind::Raycast);

/// What a learner's facts say that puts it in a scope several learners share.
#[derive(Debug, Clone, Copy)]
enum SharedBy {
    /// `bounded`.
    Bounded,
    /// `watches_changes`.
    Watching,
}

const BOUNDED_METHODS: [Method; sharing_count(SharedBy::Bounded)] = sharing(SharedBy::Bounded);
const WATCHING_METHODS: [Method; sharing_count(SharedBy::Watching)] = sharing(SharedBy::Watching);

/// Whether `method`'s facts put it in the scope `by` names.
const fn shares(method: Method, by: SharedBy) -> bool {
    let facts = method.facts();
    match by {
        SharedBy::Bounded => facts.bounded,
        SharedBy::Watching => facts.watches_changes,
    }
}

/// How many methods share `by`.
const fn sharing_count(by: SharedBy) -> usize {
    let (mut count, mut i) = (0, 0);
    while i < Method::ALL.len() {
        if shares(Method::ALL[i], by) {
            count += 1;
        }
        i += 1;
    }
    count
}

/// The methods that share `by`, in the order of [`Method::ALL`]; `N` is their count.
const fn sharing<const N: usize>(by: SharedBy) -> [Method; N] {
    let mut methods = [Method::Lin5; N];
    let (mut n, mut i) = (0, 0);
    while i < Method::ALL.len() {
        if shares(Method::ALL[i], by) {
            methods[n] = Method::ALL[i];
            n += 1;
        }
        i += 1;
    }
    methods
}

impl fmt::Display for Scope {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Scope::All => f.write_str("all"),
            Scope::Methods(methods) => {
                let names: Vec<&str> = methods.iter().map(|m| m.name()).collect();
                f.write_str(&names.join(" "))
            }
            Scope::Sim(kind) => write!(f, "sim {kind}"),
            Scope::Camera(kind) => write!(f, "camera {kind}"),
            Scope::Unused => f.write_str("unused"),
        }
    }
}
