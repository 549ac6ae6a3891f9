//! How much of a task's points a partly right check earns: a per-course setting
//! (`pbrlab grade --credit`, the autograder's `credit`, `grade-class --credit`).
//!
//! It applies to the checks made of independent exact cases (values, hidden values and
//! stability); a statistical check (sampling, estimator, image) is one test and earns all
//! or nothing whatever the policy. Within a task, each check's share of the points is its
//! weight; the policy decides the fraction of that share a failed check keeps. By default
//! a values check's share is split equally over the declared regions of the domain its
//! cases lie in (each boundary, special value and band, the interior, the worked cases):
//! a bug confined to one region costs that region's share, whether one draw in 2,000
//! lands there or a hundred.

use super::verdict::{CheckKind, CheckResult};

/// The credit policy.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "policy", rename_all = "snake_case")]
pub enum Credit {
    /// A check earns its share only when every case passes.
    AllOrNothing,
    /// A check earns the fraction of its cases that pass: smith_g1 with 26 of 30 value
    /// cases right keeps 26/30 of the values' share.
    PerCase,
    /// A values check earns the fraction of its regions ([`CheckResult::regions`]) in
    /// which every case passes, each region an equal share; any other check earns per
    /// case (the default).
    #[default]
    PerRegion,
    /// A check earns its whole share when at least this fraction of its cases pass, and
    /// nothing below.
    Threshold {
        /// The fraction of cases, in [0, 1].
        fraction: f64,
    },
}

impl std::str::FromStr for Credit {
    type Err = String;

    /// `all-or-nothing`, `per-case`, `per-region` or `threshold:F` with F in [0, 1].
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "all-or-nothing" => Ok(Credit::AllOrNothing),
            "per-case" => Ok(Credit::PerCase),
            "per-region" => Ok(Credit::PerRegion),
            _ => {
                let fraction = s
                    .strip_prefix("threshold:")
                    .and_then(|f| f.parse::<f64>().ok())
                    .filter(|f| (0.0..=1.0).contains(f))
                    .ok_or_else(|| {
                        format!(
                            "`{s}`: expected all-or-nothing, per-case, per-region or \
                             threshold:F with F in [0, 1] (e.g. threshold:0.9)"
                        )
                    })?;
                Ok(Credit::Threshold { fraction })
            }
        }
    }
}

impl Credit {
    /// The fraction of its share, in [0, 1], that `check` earns.
    pub fn of(self, check: &CheckResult) -> f64 {
        if check.passed {
            return 1.0;
        }
        let per_case = matches!(check.kind, CheckKind::Values | CheckKind::Stability);
        if !per_case || check.total == 0 {
            return 0.0;
        }
        let right = check.total.saturating_sub(check.failed) as f64 / check.total as f64;
        match self {
            Credit::AllOrNothing => 0.0,
            Credit::PerRegion if !check.regions.is_empty() => {
                let passing = check.regions.iter().filter(|r| r.failed == 0).count();
                passing as f64 / check.regions.len() as f64
            }
            Credit::PerCase | Credit::PerRegion => right,
            Credit::Threshold { fraction } => {
                if right >= fraction {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// Sets every check's `credit` by this policy.
    pub fn apply(self, checks: &mut [CheckResult]) {
        for c in checks {
            c.credit = self.of(c);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(kind: CheckKind, failed: usize, total: usize) -> CheckResult {
        let mut c = CheckResult::new("c", kind);
        c.failed = failed;
        c.total = total;
        c.passed = failed == 0;
        c
    }

    #[test]
    fn each_policy_credits_a_partly_right_value_check_as_documented() {
        let values = check(CheckKind::Values, 4, 30);
        assert_eq!(Credit::AllOrNothing.of(&values), 0.0);
        assert!((Credit::PerCase.of(&values) - 26.0 / 30.0).abs() < 1e-12);
        assert_eq!(Credit::Threshold { fraction: 0.8 }.of(&values), 1.0);
        assert_eq!(Credit::Threshold { fraction: 0.9 }.of(&values), 0.0);
        let sampling = check(CheckKind::Sampling, 1, 4);
        assert_eq!(
            Credit::PerCase.of(&sampling),
            0.0,
            "a statistical test is one test"
        );
        assert_eq!(Credit::PerCase.of(&check(CheckKind::Values, 0, 30)), 1.0);
        assert_eq!(Credit::PerCase.of(&check(CheckKind::Values, 30, 30)), 0.0);
    }

    #[test]
    fn per_region_gives_a_bug_in_one_region_that_region_s_share() {
        use crate::grade::verdict::RegionTally;
        let region = |name: &str, total, failed| RegionTally {
            name: name.into(),
            total,
            failed,
        };
        let mut values = check(CheckKind::Values, 1, 2001);
        values.regions = vec![
            region("the interior", 1900, 0),
            region("cos θ of w: on the horizon", 1, 1),
            region("alpha = 0", 100, 0),
            region("the worked cases", 0, 0),
        ];
        assert_eq!(Credit::PerRegion.of(&values), 0.75);
        assert!((Credit::PerCase.of(&values) - 2000.0 / 2001.0).abs() < 1e-12);
        let stability = check(CheckKind::Stability, 1, 4);
        assert_eq!(
            Credit::PerRegion.of(&stability),
            0.75,
            "no regions: per case"
        );
        assert_eq!(Credit::default(), Credit::PerRegion);
    }

    #[test]
    fn the_policy_reads_from_its_command_line_spelling() {
        assert_eq!("per-case".parse(), Ok(Credit::PerCase));
        assert_eq!("per-region".parse(), Ok(Credit::PerRegion));
        assert_eq!("all-or-nothing".parse(), Ok(Credit::AllOrNothing));
        assert_eq!(
            "threshold:0.9".parse(),
            Ok(Credit::Threshold { fraction: 0.9 })
        );
        assert!("threshold:2".parse::<Credit>().is_err());
        assert!("half".parse::<Credit>().is_err());
    }
}
