//! The verdicts of a stability case.

use serde::{Deserialize, Serialize};

/// What a stability case concluded about one implementation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Finite, in range, and the right value or limit.
    Pass,
    /// Finite and in range, but not the right value or limit.
    WrongValue,
    /// A NaN anywhere in the result.
    #[serde(rename = "nan")]
    NaN,
    /// An infinity anywhere in the result (and no NaN).
    Inf,
    /// Finite but outside the range the quantity can take (a negative BRDF, G1 > 1, …).
    OutOfRange,
    /// The code panicked (other than `todo!()`).
    Panic,
    /// The task is still a `todo!()` stub.
    NotAttempted,
    /// The code did not return within the time limit.
    Hang,
    /// The code brought its process down (a stack overflow, an abort, a memory fault):
    /// only a case run in a process of its own can report this.
    Crash,
}

impl Verdict {
    /// True for [`Verdict::Pass`].
    pub fn passed(self) -> bool {
        self == Verdict::Pass
    }

    /// True for the verdicts that mean the code ran and got it wrong (everything except
    /// [`Verdict::Pass`] and [`Verdict::NotAttempted`]).
    pub fn failed(self) -> bool {
        !matches!(self, Verdict::Pass | Verdict::NotAttempted)
    }

    /// The verdict as written in tables and JSON.
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::WrongValue => "wrong value",
            Verdict::NaN => "NaN",
            Verdict::Inf => "inf",
            Verdict::OutOfRange => "out of range",
            Verdict::Panic => "panic",
            Verdict::NotAttempted => "not attempted",
            Verdict::Hang => "hang",
            Verdict::Crash => "crash",
        }
    }
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.label())
    }
}
