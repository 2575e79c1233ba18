//! The learning methods a run can choose, and the facts each learner's folder declares
//! about itself.

use crate::learn::LearnerStats;
use std::fmt;
use std::str::FromStr;

/// A learning method, as named in configs, on the command line and in `data/<method>/`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// Nested Perceptron with input adjustment (5 inputs).
    Lin5,
    /// Nested Perceptron without input adjustment (8 inputs).
    Lin8,
    /// Nested Network: a feed-forward net per tree node.
    Nnw,
    /// One feed-forward net over the whole input space.
    Ffn,
    /// A 7⁵ Kohonen map of local linear maps.
    Kohonen,
    /// A model-based controller that inverts the nominal URDF geometry.
    Ik,
    /// Locally weighted projection regression (Vijayakumar, D'Souza and Schaal 2005).
    Lwpr,
    /// Incremental sparse spectrum GP regression (Gijsberts and Metta 2013).
    Issgp,
    /// A two-hidden-layer perceptron trained by Adam on a replay buffer.
    Mlp,
    /// Uncalibrated visual servoing on an image Jacobian estimated online (Broyden).
    Broyden,
}

impl Method {
    /// Every method, in the order they are listed to users.
    pub const ALL: [Method; 10] = [
        Method::Lin5,
        Method::Lin8,
        Method::Nnw,
        Method::Ffn,
        Method::Kohonen,
        Method::Ik,
        Method::Lwpr,
        Method::Issgp,
        Method::Mlp,
        Method::Broyden,
    ];

    /// What the program knows of the method besides its learner, declared in the
    /// learner's own folder. The match names every variant: a new method does not compile
    /// until its facts are listed here.
    pub const fn facts(self) -> &'static MethodFacts {
        use crate::learn::{baselines, nested, online};
        match self {
            Method::Lin5 => &nested::LIN5_FACTS,
            Method::Lin8 => &nested::LIN8_FACTS,
            Method::Nnw => &nested::NNW_FACTS,
            Method::Ffn => &baselines::FFN_FACTS,
            Method::Kohonen => &baselines::KOHONEN_FACTS,
            Method::Ik => &baselines::IK_FACTS,
            Method::Lwpr => &online::LWPR_FACTS,
            Method::Issgp => &online::ISSGP_FACTS,
            Method::Mlp => &online::MLP_FACTS,
            Method::Broyden => &baselines::BROYDEN_FACTS,
        }
    }

    /// The method's name as written in configs and folder names.
    pub fn name(self) -> &'static str {
        self.facts().name
    }
}

/// What the program knows of a built-in method besides its learner: its name, how its
/// size is reported, what the Slurm memory estimate counts for it, and which of the entries
/// shared by several learners apply to it. Each learner's folder declares its own.
#[derive(Debug, Clone, Copy)]
pub struct MethodFacts {
    /// The name in configs, on the command line and in `data/<method>/`.
    pub name: &'static str,
    /// The learner's size in its own terms, from its figures, ending in `; ` (empty for
    /// one that has none to speak of).
    pub size: fn(&LearnerStats) -> String,
    /// True when its size (`nodes`) is a count of nodes: tree nodes, receptive fields, map
    /// cells.
    pub counts_nodes: bool,
    /// Memory a run keeps per trial (kB), for the Slurm memory estimate: the patterns
    /// stored.
    pub kb_per_trial: f64,
    /// True when its root box is the input boundaries 0–4 (the `boundary_*` entries).
    pub bounded: bool,
    /// True when it watches for a change under `merge_strategy change_detection`.
    pub watches_changes: bool,
    /// The entries that make a trial's learning long, named when a trial takes long.
    pub slow_entries: &'static str,
    /// Its own defaults for entries it shares with other methods, as `(entry, value)` with
    /// the value as a config file writes it: its best shipped settings, which a run of it
    /// takes for every such entry its config, `--set`s and flags do not give.
    pub shared_defaults: &'static [(&'static str, &'static str)],
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Method::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                let names: Vec<_> = Method::ALL.iter().map(|m| m.name()).collect();
                format!(
                    "unknown method `{s}` (expected one of {})",
                    names.join(", ")
                )
            })
    }
}
