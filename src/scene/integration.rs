//! The integration-error study of a scene: the integrand and the study's N, realizations and
//! randomisation, shared by every column (each column studies its own pattern and seed).

use crate::core::integration::{Integrand, StudyRequest, MAX_NS, MAX_REALIZATIONS, MAX_STUDY_N};
#[cfg(doc)]
use crate::core::params::Params;
use crate::core::params::{declare_params, ParamError};
use crate::core::pattern::Pattern;
use serde::{Deserialize, Serialize};

/// The integration panel's study (used only while `panels.integration` is on).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct IntegrationSettings {
    /// The integrand (with `randomize`, the family each realization draws an instance of).
    pub integrand: Integrand,
    /// A new random instance of the integrand's family per realization (descriptor below).
    pub randomize: bool,
    /// The sample counts N of the curve, each in 1..=2²⁰, 1 to 64 values.
    pub ns: Vec<usize>,
    /// Realizations R per N, 1..=4096 (the panel shows them coming in: 1, 2, 4, … R).
    pub realizations: usize,
    /// Cranley–Patterson rotation of deterministic patterns per realization.
    pub shift: bool,
}

impl Default for IntegrationSettings {
    /// The disk, N = 16 … 4096 (powers of 2), 64 realizations, shifted.
    fn default() -> Self {
        IntegrationSettings {
            integrand: Integrand::default(),
            randomize: false,
            ns: DEFAULT_NS.to_vec(),
            realizations: 64,
            shift: true,
        }
    }
}

/// The default sample counts: 16 … 4096 in powers of two.
pub const DEFAULT_NS: [usize; 9] = [16, 32, 64, 128, 256, 512, 1024, 2048, 4096];

declare_params! {
    impl IntegrationSettings = "integration" {
        randomize: flag(false, "each realization draws a new centre, radius, σ or line"),
        realizations: count(64, 1, MAX_REALIZATIONS, "realizations R per N (the panel shows them coming in: 1, 2, 4, … R)"),
        shift: flag(true, "deterministic patterns are shifted per realization"),
    }
}

/// The documented ranges of the sample counts (what `Scene::validate` checks and the GUI
/// spans); the other settings have descriptors ([`Params`]).
pub mod limits {
    use std::ops::RangeInclusive;
    /// Each sample count.
    pub const N: RangeInclusive<usize> = 1..=super::MAX_STUDY_N;
    /// How many sample counts.
    pub const NS: RangeInclusive<usize> = 1..=super::MAX_NS;
}

impl IntegrationSettings {
    /// The study of a column's pattern and seed in its `dims` dimensions (2: the 2D study;
    /// other D take the pattern's points in [0,1)^D, `Pattern::generate_cube`).
    pub fn request(&self, pattern: Pattern, seed: u64, dims: usize) -> StudyRequest {
        StudyRequest {
            pattern,
            integrand: self.integrand,
            ns: self.ns.clone(),
            realizations: self.realizations,
            seed,
            shift: self.shift,
            randomize: self.randomize,
            dims,
        }
    }

    /// The first sample count (`ns`) out of its range, or a Genz integrand without an
    /// instance in one of the columns' dimensions `dims` (a list of `a` or `u` of another
    /// length than 1 or D: each column's study is in its own D): (field, value, allowed). The
    /// other settings and the integrand's parameters are checked through their descriptors.
    pub fn check(&self, dims: &[usize]) -> Option<(&'static str, String, String)> {
        for &d in dims {
            if let Some(Err(ParamError::Invalid {
                field,
                value,
                allowed,
                ..
            })) = self.integrand.in_dims(d)
            {
                let path = if field == "u" {
                    "integrand.u"
                } else {
                    "integrand.a"
                };
                let why = if d == 2 {
                    "the panel's study is 2D".to_string()
                } else {
                    format!("a column's study is in D = {d} dimensions")
                };
                return Some((path, value, format!("{allowed}; {why}")));
            }
        }
        if !limits::NS.contains(&self.ns.len()) {
            return Some((
                "ns",
                format!("{} values", self.ns.len()),
                format!(
                    "{} to {} sample counts",
                    limits::NS.start(),
                    limits::NS.end()
                ),
            ));
        }
        if let Some(n) = self.ns.iter().find(|n| !limits::N.contains(n)) {
            return Some((
                "ns",
                n.to_string(),
                format!(
                    "sample counts in {}..={}",
                    limits::N.start(),
                    limits::N.end()
                ),
            ));
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::params::Params;

    #[test]
    fn the_default_is_valid_and_bad_values_name_their_field() {
        assert_eq!(IntegrationSettings::default().check(&[2]), None);
        let bad = |f: fn(&mut IntegrationSettings)| {
            let mut s = IntegrationSettings::default();
            f(&mut s);
            s.check(&[2]).map(|c| c.0)
        };
        assert_eq!(bad(|s| s.ns.clear()), Some("ns"));
        assert_eq!(bad(|s| s.ns = vec![0]), Some("ns"));
        assert_eq!(bad(|s| s.ns = vec![MAX_STUDY_N + 1]), Some("ns"));
        assert_eq!(bad(|s| s.ns = vec![1; MAX_NS + 1]), Some("ns"));
        assert_eq!(bad(|s| s.ns = vec![1, MAX_STUDY_N]), None);
        // A Genz integrand in the 2D study: one number or two per list.
        let genz = |a: &str| {
            let mut s = IntegrationSettings {
                integrand: Integrand::from_name("genz-gaussian").unwrap(),
                ..Default::default()
            };
            s.integrand.set("a", a).unwrap();
            s.check(&[2])
        };
        assert_eq!(genz("3"), None);
        assert_eq!(genz("[3,4]"), None);
        let (field, value, allowed) = genz("[3,4,5]").unwrap();
        assert_eq!(
            (field, value.as_str()),
            ("integrand.a", "[3,4,5] (3 numbers)")
        );
        assert!(allowed.ends_with("the panel's study is 2D"), "{allowed}");
        // A column in D = 3 takes the list of 3, and then a list of 2 is refused for it.
        let mut s = IntegrationSettings {
            integrand: Integrand::from_name("genz-gaussian").unwrap(),
            ..Default::default()
        };
        s.integrand.set("a", "[3,4,5]").unwrap();
        assert_eq!(s.check(&[3]), None);
        s.integrand.set("a", "[3,4]").unwrap();
        let (_, _, allowed) = s.check(&[2, 3]).unwrap();
        assert!(allowed.ends_with("in D = 3 dimensions"), "{allowed}");
        let realizations = |r| {
            IntegrationSettings {
                realizations: r,
                ..Default::default()
            }
            .check_params()
            .map_err(|e| e.to_string())
        };
        assert_eq!(realizations(1), Ok(()));
        assert_eq!(realizations(MAX_REALIZATIONS), Ok(()));
        assert_eq!(
            realizations(0),
            Err("integration.realizations = 0: must be an integer in 1..=4096".into())
        );
        assert_eq!(
            realizations(MAX_REALIZATIONS + 1),
            Err("integration.realizations = 4097: must be an integer in 1..=4096".into())
        );
    }
}
