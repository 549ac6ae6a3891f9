//! Per-student variants: with a course secret (`--variant-key`, or `variant_key` in an
//! autograder package's settings), a student's id alone determines that student's hidden
//! cases and the seed of their statistical checks, so every student is graded on inputs of
//! their own, and a regrade with the same key reproduces them exactly.
//!
//! Each variant is drawn from the declared domains like every hidden case
//! ([`super::domain`]), with the same tolerances and false-failure rates, so variants need
//! no calibration of their own (`tests/instructor/variants.rs` measures the overlap between
//! students; `tests/instructor/calibration.rs` the false failures over 50 gradings, each
//! with seeds and hidden cases of its own). What varies: the hidden
//! value cases (inputs, and so their expected answers) and the seed of the statistical
//! checks. What does not: the public cases, and the scenes of the estimator checks, whose
//! analytic answers are fixed configurations.
//!
//! Keys and seeds are SipHash-2-4 (keyed hashes): the key cannot be recovered from the
//! public id a report shows, nor one student's seeds from another's.

use siphasher::sip::SipHasher24;
use siphasher::sip128::{Hasher128, SipHasher24 as SipHasher128};
use std::hash::Hasher;

/// One student's variant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Variant {
    /// What a report shows: 12 hex digits, a hash of key and student that gives away
    /// neither.
    pub id: String,
    /// The seed of the student's hidden cases.
    pub hidden_seed: u64,
    /// The seed of the student's statistical checks.
    pub seed: u64,
}

/// Separates the uses of the key from each other (and from any other use of SipHash).
const KEY_DOMAIN: (u64, u64) = (0x7062_726c_6162_766b, 0x7661_7269_616e_746b); // "pbrlabvk", "variantk"

impl Variant {
    /// The variant of `student` under the course secret `key`.
    pub fn of(key: &str, student: &str) -> Self {
        let mut keyed = SipHasher128::new_with_keys(KEY_DOMAIN.0, KEY_DOMAIN.1);
        keyed.write(key.as_bytes());
        let (k0, k1) = {
            let h = keyed.finish128();
            (h.h1, h.h2)
        };
        let draw = |purpose: &str| {
            let mut h = SipHasher24::new_with_keys(k0, k1);
            h.write(purpose.as_bytes());
            h.write_u8(0xff);
            h.write(student.as_bytes());
            h.finish()
        };
        Self {
            id: format!("{:012x}", draw("id") >> 16),
            hidden_seed: draw("hidden cases"),
            seed: draw("statistical seed"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_variant_is_the_key_and_student_and_nothing_else() {
        let a = Variant::of("course secret", "ann");
        assert_eq!(a, Variant::of("course secret", "ann"), "reproducible");
        assert_ne!(
            a.hidden_seed,
            Variant::of("course secret", "bo").hidden_seed
        );
        assert_ne!(
            a.hidden_seed,
            Variant::of("other secret", "ann").hidden_seed
        );
        assert_ne!(a.hidden_seed, a.seed, "two seeds, not one");
        assert_eq!(a.id.len(), 12);
        assert!(a.id.chars().all(|c| c.is_ascii_hexdigit()), "{}", a.id);
    }
}
