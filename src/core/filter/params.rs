//! Parameter descriptors of the filters, for the CLI (`--set key=value`, `filter --list`) and the
//! GUI (one slider or choice box per parameter).
//!
//! The descriptor types ([`ParamSpec`], [`ParamKind`], [`ParamValue`]) are the generic ones of
//! [`crate::core::pattern::params`]; every range check of a filter goes through its specs, so the
//! ranges shown by `--list` and the GUI are exactly those that [`FilterParams::validate`]
//! enforces. Booleans are `Choice` parameters with options `false`, `true`.

use super::FilterError;
pub use crate::core::pattern::params::{ParamKind, ParamSpec, ParamValue};

/// Options of a boolean parameter.
pub const BOOL_OPTIONS: &[&str] = &["false", "true"];

/// A filter's parameter struct: names, descriptors, getters and checked setters.
pub trait FilterParams: Copy {
    /// Name used on the command line and in scene files.
    const NAME: &'static str;
    /// One-line description.
    const SUMMARY: &'static str;

    /// Descriptors of every parameter that currently applies (e.g. `beta` only with a Kaiser
    /// window).
    fn specs(&self) -> Vec<ParamSpec>;

    /// Current value of parameter `key`.
    fn get(&self, key: &str) -> Option<ParamValue>;

    /// Stores an already parsed and range-checked value of parameter `key` (one of `specs()`).
    fn put(&mut self, key: &str, value: ParamValue);

    /// Constraints between fields, beyond the per-field ranges of `specs()`.
    fn check_extra(&self) -> Result<(), FilterError> {
        Ok(())
    }

    /// For a parameter `key` that exists only in some configurations and is not settable now:
    /// its static name and why (`None`: the key is simply unknown).
    fn inactive_reason(&self, key: &str) -> Option<(&'static str, &'static str)> {
        let _ = key;
        None
    }

    /// Checks every field against its descriptor (finite, inside \[min, max\]) and the
    /// cross-field constraints.
    fn validate(&self) -> Result<(), FilterError> {
        for spec in self.specs() {
            if let (ParamKind::Float { min, max, .. }, Some(ParamValue::Float(v))) =
                (&spec.kind, self.get(spec.name))
            {
                if !v.is_finite() || v < *min || v > *max {
                    return Err(FilterError::InvalidParam {
                        filter: Self::NAME,
                        field: spec.name,
                        value: format!("{v}"),
                        allowed: spec.allowed(),
                    });
                }
            }
        }
        self.check_extra()
    }

    /// Sets parameter `key` from text. The change is applied only if the whole parameter set is
    /// then valid; otherwise the error names the field and its allowed range.
    fn set(&mut self, key: &str, text: &str) -> Result<(), FilterError> {
        let key = key.trim();
        let specs = self.specs();
        let Some(spec) = specs.iter().find(|s| s.name == key) else {
            if let Some((field, reason)) = self.inactive_reason(key) {
                return Err(FilterError::InvalidParam {
                    filter: Self::NAME,
                    field,
                    value: text.to_string(),
                    allowed: reason.to_string(),
                });
            }
            return Err(FilterError::UnknownParam {
                filter: Self::NAME,
                key: key.to_string(),
                allowed: specs.iter().map(|s| s.name).collect::<Vec<_>>().join(", "),
            });
        };
        let value = parse_param(Self::NAME, spec, text)?;
        let mut next = *self;
        next.put(key, value);
        next.validate()?;
        *self = next;
        Ok(())
    }
}

/// Parses `text` as a value of `spec` and checks its range. Errors name the filter, the field
/// and the allowed range.
pub fn parse_param(
    filter: &'static str,
    spec: &ParamSpec,
    text: &str,
) -> Result<ParamValue, FilterError> {
    spec.parse(text).ok_or_else(|| FilterError::InvalidParam {
        filter,
        field: spec.name,
        value: text.to_string(),
        allowed: spec.allowed(),
    })
}

/// A float descriptor.
pub fn float_spec(
    name: &'static str,
    doc: &'static str,
    default: f64,
    min: f64,
    max: f64,
) -> ParamSpec {
    ParamSpec {
        name,
        doc,
        kind: ParamKind::Float { default, min, max },
    }
}

/// A boolean descriptor (choice `false` | `true`).
pub fn bool_spec(name: &'static str, doc: &'static str, default: bool) -> ParamSpec {
    ParamSpec {
        name,
        doc,
        kind: ParamKind::Choice {
            default: BOOL_OPTIONS[default as usize],
            options: BOOL_OPTIONS,
        },
    }
}

/// Declares a filter parameter struct with `float(default, min, max, "doc")` and
/// `flag(default, "doc")` fields, its `Default`, and its [`FilterParams`] impl. An optional
/// `check(p) { … }` block adds cross-field constraints (it evaluates to `Result<(), FilterError>`).
macro_rules! filter_params {
    (
        $(#[$meta:meta])*
        $ty:ident = $name:literal, $summary:literal {
            $( $(#[$fmeta:meta])* $field:ident : $kind:ident ( $($arg:tt)* ) ),* $(,)?
        }
        $( check($p:ident) $body:block )?
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct $ty {
            $( $(#[$fmeta])* pub $field: filter_params!(@ty $kind), )*
        }

        impl Default for $ty {
            fn default() -> Self {
                Self { $( $field: filter_params!(@default $kind ( $($arg)* )), )* }
            }
        }

        impl $crate::core::filter::params::FilterParams for $ty {
            const NAME: &'static str = $name;
            const SUMMARY: &'static str = $summary;

            fn specs(&self) -> Vec<$crate::core::filter::params::ParamSpec> {
                vec![ $( filter_params!(@spec $field $kind ( $($arg)* )), )* ]
            }

            fn get(&self, key: &str) -> Option<$crate::core::filter::params::ParamValue> {
                $( if key == stringify!($field) {
                    return Some(filter_params!(@get $kind self.$field));
                } )*
                None
            }

            fn put(&mut self, key: &str, value: $crate::core::filter::params::ParamValue) {
                $( if key == stringify!($field) {
                    filter_params!(@put $kind self.$field, value);
                } )*
            }

            fn check_extra(&self) -> Result<(), $crate::core::filter::FilterError> {
                filter_params!(@check self $( $p $body )?)
            }
        }
    };
    (@ty float) => { f64 };
    (@ty flag) => { bool };
    (@default float ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default flag ($d:expr, $doc:literal)) => { $d };
    (@spec $field:ident float ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::filter::params::float_spec(stringify!($field), $doc, $d, $min, $max)
    };
    (@spec $field:ident flag ($d:expr, $doc:literal)) => {
        $crate::core::filter::params::bool_spec(stringify!($field), $doc, $d)
    };
    (@get float $e:expr) => { $crate::core::filter::params::ParamValue::Float($e) };
    (@get flag $e:expr) => {
        $crate::core::filter::params::ParamValue::Choice(
            $crate::core::filter::params::BOOL_OPTIONS[$e as usize],
        )
    };
    (@put float $e:expr, $v:expr) => {
        if let $crate::core::filter::params::ParamValue::Float(x) = $v { $e = x; }
    };
    (@put flag $e:expr, $v:expr) => {
        if let $crate::core::filter::params::ParamValue::Choice(x) = $v { $e = x == "true"; }
    };
    (@check $s:ident) => { Ok(()) };
    (@check $s:ident $p:ident $body:block) => { { let $p = $s; $body } };
}
pub(crate) use filter_params;
