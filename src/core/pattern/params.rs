//! Parameter descriptors shared by every pattern: names, kinds, defaults and allowed ranges.
//!
//! The CLI (`--set key=value`, `points --list`) and the GUI (one slider per parameter) are both
//! generated from these descriptors, so a pattern's parameters are declared exactly once.

use super::PatternError;

/// The kind and allowed range of one parameter.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamKind {
    /// An integer in `min..=max`.
    Int { default: i64, min: i64, max: i64 },
    /// A finite float in `min..=max`.
    Float { default: f64, min: f64, max: f64 },
    /// One of a fixed list of names.
    Choice {
        default: &'static str,
        options: &'static [&'static str],
    },
}

/// One parameter of a pattern.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamSpec {
    /// The key used by `--set key=value` and in scene files.
    pub name: &'static str,
    /// One line: meaning, units and the special value 0 where it means "auto".
    pub doc: &'static str,
    /// Kind, default and range.
    pub kind: ParamKind,
}

impl ParamSpec {
    /// Human-readable allowed range, e.g. `an integer in 0..=65536`.
    pub fn allowed(&self) -> String {
        match &self.kind {
            ParamKind::Int { min, max, .. } => format!("an integer in {min}..={max}"),
            ParamKind::Float { min, max, .. } => format!("a finite number in [{min}, {max}]"),
            ParamKind::Choice { options, .. } => format!("one of {}", options.join(", ")),
        }
    }

    /// The default value as text.
    pub fn default_text(&self) -> String {
        match &self.kind {
            ParamKind::Int { default, .. } => default.to_string(),
            ParamKind::Float { default, .. } => default.to_string(),
            ParamKind::Choice { default, .. } => default.to_string(),
        }
    }
}

/// A parameter value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ParamValue {
    Int(i64),
    Float(f64),
    Choice(&'static str),
}

impl std::fmt::Display for ParamValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParamValue::Int(v) => write!(f, "{v}"),
            ParamValue::Float(v) => write!(f, "{v}"),
            ParamValue::Choice(v) => write!(f, "{v}"),
        }
    }
}

/// A named option set usable as a `Choice` parameter.
pub trait ChoiceParam: Copy + Sized {
    /// Option names, in order.
    const OPTIONS: &'static [&'static str];
    /// Index of this value in [`Self::OPTIONS`].
    fn index(self) -> usize;
    /// The value at `index` of [`Self::OPTIONS`].
    fn from_index(index: usize) -> Self;
    /// Name of this value.
    fn name(self) -> &'static str {
        Self::OPTIONS[self.index()]
    }
}

impl ParamSpec {
    /// Parses `text` as a value of this parameter; `None` when it is malformed, not finite or
    /// outside the allowed range. Callers wrap `None` in their own typed error.
    pub fn parse(&self, text: &str) -> Option<ParamValue> {
        let t = text.trim();
        match &self.kind {
            ParamKind::Int { min, max, .. } => {
                let v: i64 = t.parse().ok()?;
                (*min..=*max).contains(&v).then_some(ParamValue::Int(v))
            }
            ParamKind::Float { min, max, .. } => {
                let v: f64 = t.parse().ok()?;
                (v.is_finite() && v >= *min && v <= *max).then_some(ParamValue::Float(v))
            }
            ParamKind::Choice { options, .. } => options
                .iter()
                .find(|o| o.eq_ignore_ascii_case(t))
                .map(|o| ParamValue::Choice(o)),
        }
    }
}

/// Parses `text` as the value of `spec`, checking the range. Errors name the pattern and field.
pub fn parse_value(
    pattern: &'static str,
    spec: &ParamSpec,
    text: &str,
) -> Result<ParamValue, PatternError> {
    spec.parse(text).ok_or_else(|| PatternError::InvalidParam {
        pattern,
        field: spec.name,
        value: text.to_string(),
        allowed: spec.allowed(),
    })
}

/// Checks a value (e.g. from a slider or a scene file) against `spec`.
pub fn check_value(
    pattern: &'static str,
    spec: &ParamSpec,
    value: ParamValue,
) -> Result<ParamValue, PatternError> {
    match value {
        ParamValue::Choice(c) => parse_value(pattern, spec, c),
        ParamValue::Int(v) => match spec.kind {
            ParamKind::Float { .. } => parse_value(pattern, spec, &v.to_string()),
            _ => parse_value(pattern, spec, &v.to_string()),
        },
        ParamValue::Float(v) => match spec.kind {
            ParamKind::Int { .. } if v.fract() == 0.0 && v.is_finite() => {
                parse_value(pattern, spec, &format!("{}", v as i64))
            }
            _ => parse_value(pattern, spec, &format!("{v:?}")),
        },
    }
}

/// Declares a pattern's parameter struct together with its descriptors.
///
/// Kinds: `int(default, min, max, "doc")` (stored as `u32`),
/// `float(default, min, max, "doc")` (stored as `f64`), `choice(Type, "doc")` (stored as `Type`).
macro_rules! pattern_params {
    (
        $(#[$meta:meta])*
        $ty:ident = $name:literal, $summary:literal {
            $( $(#[$fmeta:meta])* $field:ident : $kind:ident ( $($arg:tt)* ) ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct $ty {
            $( $(#[$fmeta])* pub $field: pattern_params!(@ty $kind ( $($arg)* )), )*
        }

        impl Default for $ty {
            fn default() -> Self {
                Self { $( $field: pattern_params!(@default $kind ( $($arg)* )), )* }
            }
        }

        impl $ty {
            /// Name used on the command line and in scene files.
            pub const NAME: &'static str = $name;
            /// One-line description.
            pub const SUMMARY: &'static str = $summary;

            /// Descriptors of every parameter.
            pub fn specs() -> Vec<$crate::core::pattern::params::ParamSpec> {
                vec![ $( $crate::core::pattern::params::ParamSpec {
                    name: stringify!($field),
                    doc: pattern_params!(@doc $kind ( $($arg)* )),
                    kind: pattern_params!(@spec $kind ( $($arg)* )),
                }, )* ]
            }

            /// Current value of parameter `key`.
            #[allow(unused_variables)]
            pub fn get(&self, key: &str) -> Option<$crate::core::pattern::params::ParamValue> {
                $( if key == stringify!($field) {
                    return Some(pattern_params!(@get $kind self.$field));
                } )*
                None
            }

            /// Sets parameter `key` from text, checking its range.
            #[allow(unused_variables, unused_mut)]
            pub fn set(&mut self, key: &str, text: &str) -> Result<(), $crate::core::pattern::PatternError> {
                for spec in Self::specs() {
                    if spec.name == key {
                        let v = $crate::core::pattern::params::parse_value($name, &spec, text)?;
                        $( if key == stringify!($field) {
                            pattern_params!(@set $kind self.$field, v);
                        } )*
                        return Ok(());
                    }
                }
                Err($crate::core::pattern::PatternError::UnknownParam {
                    pattern: $name,
                    key: key.to_string(),
                    allowed: Self::specs().iter().map(|s| s.name).collect::<Vec<_>>().join(", "),
                })
            }
        }
    };
    (@ty int ($d:expr, $min:expr, $max:expr, $doc:literal)) => { u32 };
    (@ty float ($d:expr, $min:expr, $max:expr, $doc:literal)) => { f64 };
    (@ty choice ($t:ty, $doc:literal)) => { $t };
    (@default int ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default float ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default choice ($t:ty, $doc:literal)) => { <$t>::default() };
    (@doc int ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $doc };
    (@doc float ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $doc };
    (@doc choice ($t:ty, $doc:literal)) => { $doc };
    (@spec int ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::pattern::params::ParamKind::Int { default: $d as i64, min: $min as i64, max: $max as i64 }
    };
    (@spec float ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::pattern::params::ParamKind::Float { default: $d, min: $min, max: $max }
    };
    (@spec choice ($t:ty, $doc:literal)) => {
        $crate::core::pattern::params::ParamKind::Choice {
            default: <$t as $crate::core::pattern::params::ChoiceParam>::name(<$t>::default()),
            options: <$t as $crate::core::pattern::params::ChoiceParam>::OPTIONS,
        }
    };
    (@get int $e:expr) => { $crate::core::pattern::params::ParamValue::Int($e as i64) };
    (@get float $e:expr) => { $crate::core::pattern::params::ParamValue::Float($e) };
    (@get choice $e:expr) => {
        $crate::core::pattern::params::ParamValue::Choice($crate::core::pattern::params::ChoiceParam::name($e))
    };
    (@set int $e:expr, $v:expr) => {
        if let $crate::core::pattern::params::ParamValue::Int(x) = $v { $e = x as u32; }
    };
    (@set float $e:expr, $v:expr) => {
        if let $crate::core::pattern::params::ParamValue::Float(x) = $v { $e = x; }
    };
    (@set choice $e:expr, $v:expr) => {
        if let $crate::core::pattern::params::ParamValue::Choice(x) = $v {
            $e = $crate::core::pattern::params::choice_from_name(x, $e);
        }
    };
}
pub(crate) use pattern_params;

/// The option of `C` named `name` (case-insensitive); `current` if none matches.
pub fn choice_from_name<C: ChoiceParam>(name: &str, current: C) -> C {
    C::OPTIONS
        .iter()
        .position(|o| o.eq_ignore_ascii_case(name))
        .map(C::from_index)
        .unwrap_or(current)
}
