/// How the `mis` task weights its two samples (Veach and Guibas 1995). The weights of the
/// light sample and the BSDF sample of the same direction must sum to 1 wherever either
/// strategy could have produced it; any such choice gives an unbiased estimate, and the
/// heuristics differ only in variance.
///
/// Delta lobes (mirror, glass) and point lights can be found by one strategy only: their
/// samples always get weight 1, whatever the heuristic.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Heuristic {
    /// BSDF sampling alone: the BSDF sample has weight 1, a light sample on an area light
    /// or the environment has weight 0 (so it need not be traced at all).
    Bsdf,
    /// Light sampling alone: a light sample has weight 1, a BSDF sample that reaches an
    /// area light or the environment has weight 0.
    Light,
    /// The balance heuristic: `w_a = p_a / (p_a + p_b)`.
    Balance,
    /// The power heuristic with exponent 2: `w_a = p_a² / (p_a² + p_b²)`.
    #[default]
    Power,
}

/// A rule that combines two sampling strategies by multiple importance sampling (Veach and
/// Guibas 1995): the scene format's `heuristic` under `strategy: mis`, and the convergence
/// studies' MIS estimators. [`Heuristic`] adds the single-strategy weightings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MisHeuristic {
    /// The balance heuristic: `w_a = p_a / (p_a + p_b)`.
    Balance,
    /// The power heuristic with exponent 2: `w_a = p_a² / (p_a² + p_b²)`.
    Power,
}

impl From<MisHeuristic> for Heuristic {
    fn from(h: MisHeuristic) -> Self {
        match h {
            MisHeuristic::Balance => Heuristic::Balance,
            MisHeuristic::Power => Heuristic::Power,
        }
    }
}
