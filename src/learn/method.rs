//! The learning methods a run can choose.

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

    /// The method's name as written in configs and folder names.
    pub fn name(self) -> &'static str {
        match self {
            Method::Lin5 => "lin5",
            Method::Lin8 => "lin8",
            Method::Nnw => "nnw",
            Method::Ffn => "ffn",
            Method::Kohonen => "kohonen",
            Method::Ik => "ik",
            Method::Lwpr => "lwpr",
            Method::Issgp => "issgp",
            Method::Mlp => "mlp",
            Method::Broyden => "broyden",
        }
    }
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
