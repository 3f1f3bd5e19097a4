//! The one parameter mechanism of patterns, filters, integrands, 2D and 1D signals and the
//! scene's settings.
//!
//! Every parameter struct declares its fields once, with [`declare_params!`]: name, doc,
//! default, range and kind (integer, float, signed scale, enum, bool, list, per-dimension
//! value, list of integers). The declaration gives the
//! struct, its `Default`, its serde form (RON in scene files) and an implementation of
//! [`Params`]: descriptors ([`ParamSpec`]), getters, checked setters and a whole-set check;
//! `declare_params! { impl T = "owner" { … } }` describes the scalar fields of an existing
//! settings struct. The families that dispatch over parameter structs (`Pattern`, `Filter`,
//! `Integrand`, `Signal`, `Signal1D`, declared with [`crate::core::family`]'s `family!`)
//! implement [`Params`] by delegation ([`dispatch_params!`]). Every user of parameters goes
//! through it:
//!
//! - the CLI's `--set key=value` ([`Params::set`]) and `points --list` / `filter --list`;
//! - the GUI's widgets (one slider, drag value, checkbox or combo box per descriptor, over the
//!   descriptor's range, so a widget can never clamp a valid value);
//! - `Scene::validate` ([`Params::check_params`]), which names the field path of a bad value.
//!
//! Errors ([`ParamError`]) name the owner, the field and the allowed range; numbers in them
//! are printed with at most 6 significant digits ([`fmt_num`]).

/// The kind, default and allowed range of one parameter.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamKind {
    /// An integer in `min..=max`.
    Int { default: i64, min: i64, max: i64 },
    /// A finite float in `[min, max]`; an end marked exclusive is left out (`(min, max]`,
    /// `[min, max)`), and the message prints that end with a parenthesis.
    Float {
        default: f64,
        min: f64,
        max: f64,
        min_exclusive: bool,
        max_exclusive: bool,
    },
    /// One of a fixed list of names.
    Choice {
        default: &'static str,
        options: &'static [&'static str],
    },
    /// `true` or `false`.
    Bool { default: bool },
    /// A finite float of either sign whose magnitude is in `[min, max]`, `0 < min` (a scale
    /// factor a ≠ 0 that may mirror: |a| in [0.05, 20]).
    Scale { default: f64, min: f64, max: f64 },
    /// Up to `default.len()` finite floats, each in `[min, max]`; missing trailing entries are 0.
    List {
        default: &'static [f64],
        min: f64,
        max: f64,
    },
    /// A value per dimension ([`PerDim`]): one finite float in `[min, max]` for every
    /// dimension, or a list of 1 to [`MAX_DIMS`] of them, one per dimension (whose length the
    /// user of the set checks against its dimension).
    PerDim { default: f64, min: f64, max: f64 },
    /// A list of 0 to [`MAX_DIMS`] integers ([`IntList`]), each in `min..=max`; empty (the
    /// default) means "not given", and the owner's own rule applies. Its length and any bound
    /// that depends on the point count are checked by the user of the set (a rank-1 lattice's
    /// generating vector: one entry per dimension, each below N).
    IntList { min: i64, max: i64 },
}

/// One parameter: its key, a one-line doc and its kind.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamSpec {
    /// The key used by `--set key=value` and in scene files.
    pub name: &'static str,
    /// One line: meaning, units and the special value 0 where it means "auto".
    pub doc: &'static str,
    /// Kind, default and range.
    pub kind: ParamKind,
}

/// A parameter value.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamValue {
    Int(i64),
    Float(f64),
    Choice(&'static str),
    Bool(bool),
    List(Vec<f64>),
}

impl ParamValue {
    fn text(&self, num: fn(f64) -> String) -> String {
        match self {
            ParamValue::Int(v) => v.to_string(),
            ParamValue::Float(v) => num(*v),
            ParamValue::Choice(v) => v.to_string(),
            ParamValue::Bool(v) => v.to_string(),
            ParamValue::List(v) => {
                let items: Vec<String> = v.iter().map(|x| num(*x)).collect();
                format!("[{}]", items.join(","))
            }
        }
    }

    /// The value for a message: numbers with at most 6 significant digits ([`fmt_num`]); a
    /// list longer than [`SHORT_LIST`] shows its first entries and its length.
    pub fn short(&self) -> String {
        match self {
            ParamValue::List(v) if v.len() > SHORT_LIST => {
                let items: Vec<String> = v[..SHORT_LIST - 1].iter().map(|x| fmt_num(*x)).collect();
                format!("[{},…] ({} numbers)", items.join(","), v.len())
            }
            other => other.text(fmt_num),
        }
    }
}

/// The value as `--set` accepts it; numbers parse back to the same bits ([`fmt_exact`]).
impl std::fmt::Display for ParamValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.text(fmt_exact))
    }
}

/// A parameter could not be set: the key is unknown, or the value is malformed or out of range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParamError {
    /// `owner` has no parameter `key`.
    #[error("{owner}: unknown parameter '{key}': allowed parameters are [{allowed}]")]
    Unknown {
        owner: &'static str,
        key: String,
        allowed: String,
    },
    /// `owner.field = value` is not allowed; `allowed` says what is.
    #[error("{owner}.{field} = {value}: must be {allowed}")]
    Invalid {
        owner: &'static str,
        field: &'static str,
        value: String,
        allowed: String,
    },
}

impl ParamError {
    /// The field the error is about (`None` for an unknown key).
    pub fn field(&self) -> Option<&'static str> {
        match self {
            ParamError::Invalid { field, .. } => Some(field),
            ParamError::Unknown { .. } => None,
        }
    }
}

use crate::core::cube::MAX_DIMS;
pub use crate::core::format::fmt_num;

/// The most entries of a list a message shows ([`ParamValue::short`]).
pub const SHORT_LIST: usize = 8;

/// A number as text that parses back to the same f64: the shortest round-trip digits, in
/// scientific notation when the plain form would be longer than 20 characters.
pub fn fmt_exact(v: f64) -> String {
    let plain = format!("{v}");
    if plain.len() > 20 {
        format!("{v:e}")
    } else {
        plain
    }
}

/// User text for an error message: a number as [`fmt_num`] prints it, other text cut to 40
/// characters.
pub fn fmt_text(text: &str) -> String {
    let t = text.trim();
    if let Ok(v) = t.parse::<f64>() {
        if t.len() > 12 {
            return fmt_num(v);
        }
    }
    if t.chars().count() > 40 {
        let cut: String = t.chars().take(40).collect();
        format!("{cut}…")
    } else {
        t.to_string()
    }
}

/// Options of a boolean parameter, as text.
pub const BOOL_OPTIONS: &[&str] = &["false", "true"];

impl ParamSpec {
    /// Human-readable allowed range, e.g. `an integer in 0..=65536`.
    pub fn allowed(&self) -> String {
        match &self.kind {
            ParamKind::Int { min, max, .. } => format!("an integer in {min}..={max}"),
            ParamKind::Float {
                min,
                max,
                min_exclusive,
                max_exclusive,
                ..
            } => {
                let open = if *min_exclusive { "(" } else { "[" };
                let close = if *max_exclusive { ")" } else { "]" };
                format!(
                    "a finite number in {open}{}, {}{close}",
                    fmt_num(*min),
                    fmt_num(*max)
                )
            }
            ParamKind::Scale { min, max, .. } => format!(
                "a finite number with |{}| in [{}, {}]",
                self.name,
                fmt_num(*min),
                fmt_num(*max)
            ),
            ParamKind::Choice { options, .. } => format!("one of {}", options.join(", ")),
            ParamKind::Bool { .. } => "true or false".to_string(),
            ParamKind::List { default, min, max } => format!(
                "a list [a,b,…] of 1 to {} finite numbers in [{}, {}] (missing ones are 0)",
                default.len(),
                fmt_num(*min),
                fmt_num(*max)
            ),
            ParamKind::PerDim { min, max, .. } => format!(
                "one finite number in [{}, {}] (every dimension) or a list [a,b,…] of one per \
                 dimension (at most {MAX_DIMS})",
                fmt_num(*min),
                fmt_num(*max)
            ),
            ParamKind::IntList { min, max } => format!(
                "a list [a,b,…] of up to {MAX_DIMS} integers, one per dimension, each an integer \
                 in {min}..={max} ([] = not given)"
            ),
        }
    }

    /// The default value.
    pub fn default_value(&self) -> ParamValue {
        match &self.kind {
            ParamKind::Int { default, .. } => ParamValue::Int(*default),
            ParamKind::Float { default, .. } | ParamKind::Scale { default, .. } => {
                ParamValue::Float(*default)
            }
            ParamKind::Choice { default, .. } => ParamValue::Choice(default),
            ParamKind::Bool { default } => ParamValue::Bool(*default),
            ParamKind::List { default, .. } => ParamValue::List(default.to_vec()),
            ParamKind::PerDim { default, .. } => ParamValue::Float(*default),
            ParamKind::IntList { .. } => ParamValue::List(Vec::new()),
        }
    }

    /// Whether `value` is this parameter's "not given" (an empty [`ParamKind::IntList`]):
    /// such a value is left out of [`Params::params_text`] and [`params_json`].
    pub fn is_unset(&self, value: &ParamValue) -> bool {
        matches!((&self.kind, value), (ParamKind::IntList { .. }, ParamValue::List(v)) if v.is_empty())
    }

    /// The default value as text.
    pub fn default_text(&self) -> String {
        self.default_value().to_string()
    }

    /// Whether this is a boolean parameter.
    pub fn is_bool(&self) -> bool {
        matches!(self.kind, ParamKind::Bool { .. })
    }

    fn float_ok(&self, v: f64) -> bool {
        match self.kind {
            ParamKind::Float {
                min,
                max,
                min_exclusive,
                max_exclusive,
                ..
            } => {
                let above = if min_exclusive { v > min } else { v >= min };
                let below = if max_exclusive { v < max } else { v <= max };
                v.is_finite() && above && below
            }
            ParamKind::Scale { min, max, .. } => v.is_finite() && v.abs() >= min && v.abs() <= max,
            ParamKind::List { min, max, .. } | ParamKind::PerDim { min, max, .. } => {
                v.is_finite() && v >= min && v <= max
            }
            _ => false,
        }
    }

    /// `value` converted to this parameter's kind (an integral float for an integer, an
    /// integer for a float, a name for a choice), if it is allowed; `None` otherwise.
    pub fn accept(&self, value: &ParamValue) -> Option<ParamValue> {
        match (&self.kind, value) {
            (ParamKind::Int { min, max, .. }, ParamValue::Int(v)) => {
                (*min..=*max).contains(v).then_some(ParamValue::Int(*v))
            }
            (ParamKind::Int { min, max, .. }, ParamValue::Float(v)) => {
                let ok =
                    v.is_finite() && v.fract() == 0.0 && *v >= *min as f64 && *v <= *max as f64;
                ok.then_some(ParamValue::Int(*v as i64))
            }
            (ParamKind::Float { .. } | ParamKind::Scale { .. }, ParamValue::Float(v)) => {
                self.float_ok(*v).then_some(ParamValue::Float(*v))
            }
            (ParamKind::Float { .. } | ParamKind::Scale { .. }, ParamValue::Int(v)) => self
                .float_ok(*v as f64)
                .then_some(ParamValue::Float(*v as f64)),
            (ParamKind::Choice { options, .. }, ParamValue::Choice(c)) => options
                .iter()
                .find(|o| o.eq_ignore_ascii_case(c))
                .map(|o| ParamValue::Choice(o)),
            (ParamKind::Bool { .. }, ParamValue::Bool(b)) => Some(ParamValue::Bool(*b)),
            (ParamKind::List { default, .. }, ParamValue::List(v)) => {
                let ok = !v.is_empty()
                    && v.len() <= default.len()
                    && v.iter().all(|x| self.float_ok(*x));
                ok.then(|| {
                    let mut full = v.clone();
                    full.resize(default.len(), 0.0);
                    ParamValue::List(full)
                })
            }
            // One number, or a list of one per dimension (a list of one is the number).
            (ParamKind::PerDim { .. }, ParamValue::Float(v)) => {
                self.float_ok(*v).then_some(ParamValue::Float(*v))
            }
            (ParamKind::PerDim { .. }, ParamValue::Int(v)) => self
                .float_ok(*v as f64)
                .then_some(ParamValue::Float(*v as f64)),
            (ParamKind::PerDim { .. }, ParamValue::List(v)) => {
                let ok = (1..=MAX_DIMS).contains(&v.len()) && v.iter().all(|x| self.float_ok(*x));
                ok.then(|| match v[..] {
                    [x] => ParamValue::Float(x),
                    _ => ParamValue::List(v.clone()),
                })
            }
            // Integers (as f64, exact below 2⁵³) in range; one integer is a list of one.
            (&ParamKind::IntList { min, max }, ParamValue::List(v)) => {
                let ok = v.len() <= MAX_DIMS
                    && v.iter().all(|x| {
                        x.is_finite() && x.fract() == 0.0 && *x >= min as f64 && *x <= max as f64
                    });
                ok.then(|| ParamValue::List(v.clone()))
            }
            (&ParamKind::IntList { min, max }, ParamValue::Int(v)) => (min..=max)
                .contains(v)
                .then(|| ParamValue::List(vec![*v as f64])),
            _ => None,
        }
    }

    /// Parses `text` (as typed on the command line: `3`, `0.25`, `square`, `true`, `[1,2,3]`)
    /// as a value of this parameter; `None` when it is malformed, not finite or out of range.
    pub fn parse(&self, text: &str) -> Option<ParamValue> {
        let t = text.trim();
        let value = match &self.kind {
            ParamKind::Int { .. } => ParamValue::Int(t.parse().ok()?),
            ParamKind::Float { .. } | ParamKind::Scale { .. } => ParamValue::Float(t.parse().ok()?),
            ParamKind::Choice { options, .. } => {
                let t = t.trim_matches('"');
                ParamValue::Choice(options.iter().find(|o| o.eq_ignore_ascii_case(t))?)
            }
            ParamKind::Bool { .. } => ParamValue::Bool(match t.to_ascii_lowercase().as_str() {
                "true" | "1" | "yes" | "on" => true,
                "false" | "0" | "no" | "off" => false,
                _ => return None,
            }),
            ParamKind::List { .. } | ParamKind::PerDim { .. } => {
                let inner = t.strip_prefix('[').unwrap_or(t);
                let inner = inner.strip_suffix(']').unwrap_or(inner);
                let items: Result<Vec<f64>, _> =
                    inner.split(',').map(|s| s.trim().parse::<f64>()).collect();
                ParamValue::List(items.ok()?)
            }
            // Integers only (`1.5` and `1e3` are refused); `[]` or nothing is the empty list.
            ParamKind::IntList { .. } => {
                let inner = t.strip_prefix('[').unwrap_or(t);
                let inner = inner.strip_suffix(']').unwrap_or(inner).trim();
                if inner.is_empty() {
                    ParamValue::List(Vec::new())
                } else {
                    let items: Result<Vec<f64>, _> = inner
                        .split(',')
                        .map(|s| s.trim().parse::<i64>().map(|i| i as f64))
                        .collect();
                    ParamValue::List(items.ok()?)
                }
            }
        };
        self.accept(&value)
    }

    /// The error for a rejected `value` (already formatted) of this parameter.
    pub fn invalid(&self, owner: &'static str, value: String) -> ParamError {
        ParamError::Invalid {
            owner,
            field: self.name,
            value,
            allowed: self.allowed(),
        }
    }
}

/// A named option set usable as a `choice` parameter (an enum with unit variants).
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
    /// The option named `name` (case-insensitive), if any.
    fn from_name(name: &str) -> Option<Self> {
        Self::OPTIONS
            .iter()
            .position(|o| o.eq_ignore_ascii_case(name))
            .map(Self::from_index)
    }
}

/// A value per dimension (the `per_dim` kind): one number for every dimension, or a list of
/// one number per dimension (1 to [`MAX_DIMS`] entries; a list of one is that number). Its
/// serde form is a number or a list; it is `Copy` like every parameter set, so it holds its
/// entries inline.
#[derive(Clone, Copy)]
pub struct PerDim {
    len: u16,
    values: [f64; MAX_DIMS],
}

impl PerDim {
    /// The same number in every dimension.
    pub const fn all(v: f64) -> Self {
        let mut values = [0.0; MAX_DIMS];
        values[0] = v;
        PerDim { len: 1, values }
    }

    /// One number per dimension; `None` for an empty list or one longer than [`MAX_DIMS`].
    pub fn list(v: &[f64]) -> Option<Self> {
        if !(1..=MAX_DIMS).contains(&v.len()) {
            return None;
        }
        let mut values = [0.0; MAX_DIMS];
        values[..v.len()].copy_from_slice(v);
        Some(PerDim {
            len: v.len() as u16,
            values,
        })
    }

    /// The entries given: one (every dimension) or one per dimension.
    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.len as usize]
    }

    /// Whether one number stands for every dimension.
    pub fn is_one(&self) -> bool {
        self.len == 1
    }

    /// The values of `dims` dimensions: the one number repeated, or the list when it has
    /// `dims` entries; otherwise `Err(len)`, the number of entries given.
    pub fn expand(&self, dims: usize) -> Result<Vec<f64>, usize> {
        match self.as_slice() {
            [v] => Ok(vec![*v; dims]),
            list if list.len() == dims => Ok(list.to_vec()),
            list => Err(list.len()),
        }
    }

    /// The value as a parameter value: a number, or a list.
    pub fn value(&self) -> ParamValue {
        match self.as_slice() {
            [v] => ParamValue::Float(*v),
            list => ParamValue::List(list.to_vec()),
        }
    }

    /// Stores an accepted value (a number or a list of 1 to [`MAX_DIMS`] numbers).
    pub fn put(&mut self, value: ParamValue) {
        let next = match value {
            ParamValue::Float(v) => Some(PerDim::all(v)),
            ParamValue::List(v) => PerDim::list(&v),
            _ => None,
        };
        if let Some(next) = next {
            *self = next;
        }
    }
}

impl PartialEq for PerDim {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl std::fmt::Debug for PerDim {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.as_slice() {
            [v] => write!(f, "{v:?}"),
            list => f.debug_list().entries(list).finish(),
        }
    }
}

impl serde::Serialize for PerDim {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.as_slice() {
            [v] => s.serialize_f64(*v),
            list => serde::Serialize::serialize(list, s),
        }
    }
}

impl<'de> serde::Deserialize<'de> for PerDim {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Visit;
        impl<'de> serde::de::Visitor<'de> for Visit {
            type Value = PerDim;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                write!(f, "a number or a list of 1 to {MAX_DIMS} numbers")
            }
            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<PerDim, E> {
                Ok(PerDim::all(v))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<PerDim, E> {
                Ok(PerDim::all(v as f64))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<PerDim, E> {
                Ok(PerDim::all(v as f64))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<PerDim, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    if v.len() == MAX_DIMS {
                        return Err(serde::de::Error::invalid_length(v.len() + 1, &self));
                    }
                    v.push(x);
                }
                PerDim::list(&v).ok_or_else(|| serde::de::Error::invalid_length(0, &self))
            }
        }
        d.deserialize_any(Visit)
    }
}

/// A list of integers (the `int_list` kind): 0 to [`MAX_DIMS`] entries, each below 2³²; empty
/// is "not given". Its serde form is a list (a scene file's `z: [1, 433, 229]`); it is `Copy`
/// like every parameter set, so it holds its entries inline.
#[derive(Clone, Copy)]
pub struct IntList {
    len: u16,
    values: [u32; MAX_DIMS],
}

impl IntList {
    /// The empty list ("not given").
    pub const EMPTY: IntList = IntList {
        len: 0,
        values: [0; MAX_DIMS],
    };

    /// The list `v`; `None` when it is longer than [`MAX_DIMS`].
    pub fn list(v: &[u32]) -> Option<Self> {
        if v.len() > MAX_DIMS {
            return None;
        }
        let mut values = [0; MAX_DIMS];
        values[..v.len()].copy_from_slice(v);
        Some(IntList {
            len: v.len() as u16,
            values,
        })
    }

    /// The entries.
    pub fn as_slice(&self) -> &[u32] {
        &self.values[..self.len as usize]
    }

    /// Whether the list is empty ("not given").
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The value as a parameter value: a list of numbers (integers exactly).
    pub fn value(&self) -> ParamValue {
        ParamValue::List(self.as_slice().iter().map(|&v| f64::from(v)).collect())
    }

    /// Stores an accepted value (a list of at most [`MAX_DIMS`] integers in `0..2³²`).
    pub fn put(&mut self, value: ParamValue) {
        if let ParamValue::List(v) = value {
            let ints: Vec<u32> = v.iter().map(|&x| x as u32).collect();
            if let Some(next) = IntList::list(&ints) {
                *self = next;
            }
        }
    }
}

impl Default for IntList {
    fn default() -> Self {
        IntList::EMPTY
    }
}

impl PartialEq for IntList {
    fn eq(&self, other: &Self) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl std::fmt::Debug for IntList {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.as_slice()).finish()
    }
}

impl serde::Serialize for IntList {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        serde::Serialize::serialize(self.as_slice(), s)
    }
}

impl<'de> serde::Deserialize<'de> for IntList {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Visit;
        impl<'de> serde::de::Visitor<'de> for Visit {
            type Value = IntList;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                write!(f, "a list of up to {MAX_DIMS} integers in 0..2^32")
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<IntList, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<u32>()? {
                    if v.len() == MAX_DIMS {
                        return Err(serde::de::Error::invalid_length(v.len() + 1, &self));
                    }
                    v.push(x);
                }
                IntList::list(&v).ok_or_else(|| serde::de::Error::invalid_length(v.len(), &self))
            }
        }
        d.deserialize_seq(Visit)
    }
}

/// A set of named parameters with descriptors: a pattern, a filter, a signal.
pub trait Params: Clone {
    /// The name errors start with (`jitter`, `gaussian`, `zone-plate`).
    fn owner(&self) -> &'static str;

    /// Descriptors of every parameter that currently applies (a filter's `beta` only with a
    /// Kaiser window).
    fn specs(&self) -> Vec<ParamSpec>;

    /// Current value of parameter `key`.
    fn get(&self, key: &str) -> Option<ParamValue>;

    /// Stores an already checked value of parameter `key` (converted by [`ParamSpec::accept`]).
    fn put(&mut self, key: &str, value: ParamValue);

    /// Constraints between fields, beyond the per-field ranges of [`Params::specs`].
    fn check_joint(&self) -> Result<(), ParamError> {
        Ok(())
    }

    /// For a key that exists only in some configurations and does not apply now: its static
    /// name and why (`None`: the key is simply unknown).
    fn inactive_reason(&self, key: &str) -> Option<(&'static str, &'static str)> {
        let _ = key;
        None
    }

    /// Every parameter that applies now as `key=value`, separated by spaces (titles and
    /// metadata); a list that is not given ([`ParamSpec::is_unset`]) is left out.
    fn params_text(&self) -> String {
        self.specs()
            .iter()
            .filter_map(|s| self.get(s.name).map(|v| (s, v)))
            .filter(|(s, v)| !s.is_unset(v))
            .map(|(s, v)| format!("{}={v}", s.name))
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// The descriptor of `key`, if it applies now.
    fn spec(&self, key: &str) -> Option<ParamSpec> {
        self.specs().into_iter().find(|s| s.name == key)
    }

    /// Checks every field against its descriptor, then the joint constraints.
    fn check_params(&self) -> Result<(), ParamError> {
        for spec in self.specs() {
            if let Some(v) = self.get(spec.name) {
                if spec.accept(&v).is_none() {
                    return Err(spec.invalid(self.owner(), v.short()));
                }
            }
        }
        self.check_joint()
    }

    /// Sets `key` to `value`; applied only if the whole set is then valid.
    fn set_value(&mut self, key: &str, value: &ParamValue) -> Result<(), ParamError> {
        let spec = self.lookup(key)?;
        let v = spec
            .accept(value)
            .ok_or_else(|| spec.invalid(self.owner(), value.short()))?;
        let mut next = self.clone();
        next.put(spec.name, v);
        next.check_params()?;
        *self = next;
        Ok(())
    }

    /// Sets `key` from text checked against its own descriptor only, not the joint
    /// constraints: for applying several settings at once, in any order, before one
    /// [`Params::check_params`] of the whole set (`low=0.4 high=0.5` on a band-pass whose
    /// default `high` is below 0.4). Returns the parameter's static name.
    fn set_field(&mut self, key: &str, text: &str) -> Result<&'static str, ParamError> {
        let spec = self.lookup(key)?;
        let v = spec
            .parse(text)
            .ok_or_else(|| spec.invalid(self.owner(), fmt_text(text)))?;
        self.put(spec.name, v);
        Ok(spec.name)
    }

    /// Applies several `(key, value text)` settings at once, as the CLI's `--set` and the
    /// Python module's keyword arguments do: enum settings first, so that a parameter that
    /// exists only for one option (`beta` with `window=kaiser`) may be given in any order; each
    /// value checked against its own descriptor as it is applied ([`Params::set_field`]); the
    /// constraints between fields checked once, after every setting, so the order never
    /// matters. An error about a field that was not given marks its value `(default)`. On an
    /// error the set may be partly changed (callers drop it).
    fn set_all(&mut self, pairs: &[(&str, &str)]) -> Result<(), ParamError> {
        let is_choice =
            |k: &str| matches!(self.spec(k).map(|s| s.kind), Some(ParamKind::Choice { .. }));
        let mut ordered: Vec<(&str, &str)> = pairs.to_vec();
        ordered.sort_by_key(|(k, _)| !is_choice(k));
        let mut given = Vec::with_capacity(ordered.len());
        for (k, v) in ordered {
            given.push(self.set_field(k, v)?);
        }
        self.check_params().map_err(|e| match e {
            ParamError::Invalid {
                owner,
                field,
                value,
                allowed,
            } if !given.contains(&field) => ParamError::Invalid {
                owner,
                field,
                value: format!("{value} (default)"),
                allowed,
            },
            e => e,
        })
    }

    /// Sets `key` from text (`--set key=value`); applied only if the whole set is then valid.
    fn set(&mut self, key: &str, text: &str) -> Result<(), ParamError> {
        let spec = self.lookup(key)?;
        let v = spec
            .parse(text)
            .ok_or_else(|| spec.invalid(self.owner(), fmt_text(text)))?;
        self.set_value(spec.name, &v)
    }

    /// The descriptor of `key`, or the error for a key that is unknown or does not apply now.
    fn lookup(&self, key: &str) -> Result<ParamSpec, ParamError> {
        let key = key.trim();
        let specs = self.specs();
        if let Some(s) = specs.iter().find(|s| s.name == key) {
            return Ok(s.clone());
        }
        if let Some((field, reason)) = self.inactive_reason(key) {
            return Err(ParamError::Invalid {
                owner: self.owner(),
                field,
                value: "(any)".to_string(),
                allowed: reason.to_string(),
            });
        }
        Err(ParamError::Unknown {
            owner: self.owner(),
            key: fmt_text(key),
            allowed: specs.iter().map(|s| s.name).collect::<Vec<_>>().join(", "),
        })
    }
}

/// A parameter set as a JSON object `{key: value}` of every parameter that applies now:
/// numbers as numbers (a non-finite one as `null`), choices as their names, booleans as
/// booleans, lists as arrays; a list that is not given ([`ParamSpec::is_unset`]) is left out.
/// The `--json` outputs of every command use it.
pub fn params_json(p: &impl Params) -> serde_json::Value {
    let num = |x: f64| {
        if x.is_finite() {
            serde_json::Value::from(x)
        } else {
            serde_json::Value::Null
        }
    };
    let map: serde_json::Map<String, serde_json::Value> = p
        .specs()
        .iter()
        .filter_map(|s| {
            let v = p.get(s.name)?;
            if s.is_unset(&v) {
                return None;
            }
            let v = match v {
                // A list of integers as integers.
                ParamValue::List(v) if matches!(s.kind, ParamKind::IntList { .. }) => v
                    .into_iter()
                    .map(|x| serde_json::Value::from(x as i64))
                    .collect(),
                ParamValue::Int(i) => serde_json::Value::from(i),
                ParamValue::Float(x) => num(x),
                ParamValue::Bool(b) => serde_json::Value::from(b),
                ParamValue::Choice(c) => serde_json::Value::from(c),
                ParamValue::List(v) => v.into_iter().map(num).collect(),
            };
            Some((s.name.to_string(), v))
        })
        .collect();
    serde_json::Value::Object(map)
}

/// Declares a parameter struct with its descriptors: the struct (serde: every field optional,
/// unknown fields refused), `Default`, the consts `NAME` and `SUMMARY`, and [`Params`].
///
/// `declare_params! { impl Type = "owner" { … } }` implements [`Params`] for an existing struct
/// over the fields listed (a scene setting whose other fields are families or lists).
///
/// `Type = "name" in "owner", "summary" { … }` names errors after `owner` instead of `name`
/// (the theorem's 1D signals all say `signal.width`).
///
/// Field kinds:
/// - `int(default, min, max, "doc")`, stored as `u32`; `count(default, min, max, "doc")`, stored
///   as `usize`;
/// - `float(default, min, max, "doc")` (in `[min, max]`), `below(default, min, max, "doc")` (in
///   `[min, max)`: `max` itself is refused, e.g. an offset modulo 1) and
///   `positive(default, max, "doc")` (in `(0, max]`), stored as `f64`;
/// - `choice(Type, "doc")`, stored as `Type` (a [`ChoiceParam`]), default `Type::default()`;
/// - `scale(default, min, max, "doc")` (either sign, magnitude in `[min, max]`), stored as `f64`;
/// - `flag(default, "doc")`, stored as `bool`;
/// - `list(N, [defaults], min, max, "doc")`, stored as `[f64; N]`;
/// - `per_dim(default, min, max, "doc")`, stored as [`PerDim`]: one number for every
///   dimension or a list of one per dimension, each in `[min, max]`.
/// - `int_list(min, max, "doc")`, stored as [`IntList`]: up to [`MAX_DIMS`] integers, each in
///   `min..=max`, empty by default ("not given"; mark the field
///   `#[serde(skip_serializing_if = "IntList::is_empty")]` so that scene files stay as before).
///
/// An optional `check(p) { … }` block adds joint constraints (`Result<(), ParamError>`).
macro_rules! declare_params {
    (
        $(#[$meta:meta])*
        $ty:ident = $name:literal $( in $owner:literal )?, $summary:literal {
            $( $(#[$fmeta:meta])* $field:ident : $kind:ident ( $($arg:tt)* ) ),* $(,)?
        }
        $( check($p:ident) $body:block )?
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct $ty {
            $( $(#[$fmeta])* pub $field: $crate::core::params::declare_params!(@ty $kind ( $($arg)* )), )*
        }

        impl Default for $ty {
            fn default() -> Self {
                Self { $( $field: $crate::core::params::declare_params!(@default $kind ( $($arg)* )), )* }
            }
        }

        impl $ty {
            /// Name used on the command line and in scene files.
            pub const NAME: &'static str = $name;
            /// One-line description.
            pub const SUMMARY: &'static str = $summary;
        }

        $crate::core::params::declare_params!(@impl $ty = [$name $($owner)?] {
            $( $field : $kind ( $($arg)* ) ),*
        } $( check($p) $body )?);
    };
    // `Params` for an existing struct, over the listed fields (a scene setting whose other
    // fields are families or lists checked on their own).
    (
        impl $ty:ident = $name:literal {
            $( $(#[$fmeta:meta])* $field:ident : $kind:ident ( $($arg:tt)* ) ),* $(,)?
        }
        $( check($p:ident) $body:block )?
    ) => {
        $crate::core::params::declare_params!(@impl $ty = [$name] {
            $( $field : $kind ( $($arg)* ) ),*
        } $( check($p) $body )?);
    };
    (
        @impl $ty:ident = [$name:literal $($owner:literal)?] {
            $( $field:ident : $kind:ident ( $($arg:tt)* ) ),*
        }
        $( check($p:ident) $body:block )?
    ) => {
        impl $crate::core::params::Params for $ty {
            fn owner(&self) -> &'static str {
                $crate::core::params::declare_params!(@owner $name $($owner)?)
            }

            fn specs(&self) -> Vec<$crate::core::params::ParamSpec> {
                vec![ $( $crate::core::params::ParamSpec {
                    name: stringify!($field),
                    doc: $crate::core::params::declare_params!(@doc $kind ( $($arg)* )),
                    kind: $crate::core::params::declare_params!(@spec $kind ( $($arg)* )),
                }, )* ]
            }

            #[allow(unused_variables)]
            fn get(&self, key: &str) -> Option<$crate::core::params::ParamValue> {
                $( if key == stringify!($field) {
                    return Some($crate::core::params::declare_params!(@get $kind self.$field));
                } )*
                None
            }

            #[allow(unused_variables)]
            fn put(&mut self, key: &str, value: $crate::core::params::ParamValue) {
                $( if key == stringify!($field) {
                    $crate::core::params::declare_params!(@put $kind self.$field, value);
                    return;
                } )*
            }

            fn check_joint(&self) -> Result<(), $crate::core::params::ParamError> {
                $crate::core::params::declare_params!(@check self $( $p $body )?)
            }
        }
    };
    (@owner $name:literal) => { $name };
    (@owner $name:literal $owner:literal) => { $owner };
    (@ty int ($($a:tt)*)) => { u32 };
    (@ty count ($($a:tt)*)) => { usize };
    (@ty float ($($a:tt)*)) => { f64 };
    (@ty positive ($($a:tt)*)) => { f64 };
    (@ty below ($($a:tt)*)) => { f64 };
    (@ty scale ($($a:tt)*)) => { f64 };
    (@ty choice ($t:ty, $doc:literal)) => { $t };
    (@ty flag ($($a:tt)*)) => { bool };
    (@ty list ($n:literal, $($a:tt)*)) => { [f64; $n] };
    (@ty per_dim ($($a:tt)*)) => { $crate::core::params::PerDim };
    (@ty int_list ($($a:tt)*)) => { $crate::core::params::IntList };
    (@default int ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default count ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default float ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default positive ($d:expr, $max:expr, $doc:literal)) => { $d };
    (@default below ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default scale ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $d };
    (@default choice ($t:ty, $doc:literal)) => { <$t>::default() };
    (@default flag ($d:expr, $doc:literal)) => { $d };
    (@default list ($n:literal, [$($d:expr),*], $min:expr, $max:expr, $doc:literal)) => { [$($d),*] };
    (@default per_dim ($d:expr, $min:expr, $max:expr, $doc:literal)) => { $crate::core::params::PerDim::all($d) };
    (@default int_list ($min:expr, $max:expr, $doc:literal)) => { $crate::core::params::IntList::EMPTY };
    (@doc $kind:ident ($($a:tt)*)) => { $crate::core::params::declare_params!(@last $($a)*) };
    (@last $doc:literal) => { $doc };
    (@last $x:tt $($rest:tt)+) => { $crate::core::params::declare_params!(@last $($rest)+) };
    (@spec int ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Int { default: $d as i64, min: $min as i64, max: $max as i64 }
    };
    (@spec count ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Int { default: $d as i64, min: $min as i64, max: $max as i64 }
    };
    (@spec float ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Float { default: $d, min: $min, max: $max, min_exclusive: false, max_exclusive: false }
    };
    (@spec below ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Float { default: $d, min: $min, max: $max, min_exclusive: false, max_exclusive: true }
    };
    (@spec positive ($d:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Float { default: $d, min: 0.0, max: $max, min_exclusive: true, max_exclusive: false }
    };
    (@spec scale ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Scale { default: $d, min: $min, max: $max }
    };
    (@spec choice ($t:ty, $doc:literal)) => {
        $crate::core::params::ParamKind::Choice {
            default: <$t as $crate::core::params::ChoiceParam>::name(<$t>::default()),
            options: <$t as $crate::core::params::ChoiceParam>::OPTIONS,
        }
    };
    (@spec flag ($d:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::Bool { default: $d }
    };
    (@spec list ($n:literal, [$($d:expr),*], $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::List { default: &[$($d),*], min: $min, max: $max }
    };
    (@spec per_dim ($d:expr, $min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::PerDim { default: $d, min: $min, max: $max }
    };
    (@spec int_list ($min:expr, $max:expr, $doc:literal)) => {
        $crate::core::params::ParamKind::IntList { min: $min as i64, max: $max as i64 }
    };
    (@get int $e:expr) => { $crate::core::params::ParamValue::Int($e as i64) };
    (@get count $e:expr) => { $crate::core::params::ParamValue::Int($e as i64) };
    (@get float $e:expr) => { $crate::core::params::ParamValue::Float($e) };
    (@get positive $e:expr) => { $crate::core::params::ParamValue::Float($e) };
    (@get below $e:expr) => { $crate::core::params::ParamValue::Float($e) };
    (@get scale $e:expr) => { $crate::core::params::ParamValue::Float($e) };
    (@get choice $e:expr) => {
        $crate::core::params::ParamValue::Choice($crate::core::params::ChoiceParam::name($e))
    };
    (@get flag $e:expr) => { $crate::core::params::ParamValue::Bool($e) };
    (@get list $e:expr) => { $crate::core::params::ParamValue::List($e.to_vec()) };
    (@get per_dim $e:expr) => { $e.value() };
    (@get int_list $e:expr) => { $e.value() };
    (@put int $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Int(x) = $v { $e = x as u32; }
    };
    (@put count $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Int(x) = $v { $e = x as usize; }
    };
    (@put float $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Float(x) = $v { $e = x; }
    };
    (@put positive $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Float(x) = $v { $e = x; }
    };
    (@put below $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Float(x) = $v { $e = x; }
    };
    (@put scale $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Float(x) = $v { $e = x; }
    };
    (@put choice $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Choice(x) = $v {
            if let Some(c) = $crate::core::params::ChoiceParam::from_name(x) { $e = c; }
        }
    };
    (@put flag $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::Bool(x) = $v { $e = x; }
    };
    (@put list $e:expr, $v:expr) => {
        if let $crate::core::params::ParamValue::List(x) = $v {
            for (slot, x) in $e.iter_mut().zip(x) { *slot = x; }
        }
    };
    (@put per_dim $e:expr, $v:expr) => { $e.put($v) };
    (@put int_list $e:expr, $v:expr) => { $e.put($v) };
    (@check $s:ident) => { Ok(()) };
    (@check $s:ident $p:ident $body:block) => { { let $p = $s; $body } };
}
pub(crate) use declare_params;

/// Implements [`Params`] for an enum whose variants each hold one parameter struct, by
/// delegation: `dispatch_params!(Pattern { Grid, Random, … })`.
macro_rules! dispatch_params {
    ($enum:ident { $( $variant:ident ),* $(,)? }) => {
        impl $crate::core::params::Params for $enum {
            fn owner(&self) -> &'static str {
                match self { $( $enum::$variant(p) => $crate::core::params::Params::owner(p), )* }
            }
            fn specs(&self) -> Vec<$crate::core::params::ParamSpec> {
                match self { $( $enum::$variant(p) => $crate::core::params::Params::specs(p), )* }
            }
            fn get(&self, key: &str) -> Option<$crate::core::params::ParamValue> {
                match self { $( $enum::$variant(p) => $crate::core::params::Params::get(p, key), )* }
            }
            fn put(&mut self, key: &str, value: $crate::core::params::ParamValue) {
                match self { $( $enum::$variant(p) => $crate::core::params::Params::put(p, key, value), )* }
            }
            fn check_joint(&self) -> Result<(), $crate::core::params::ParamError> {
                match self { $( $enum::$variant(p) => $crate::core::params::Params::check_joint(p), )* }
            }
            fn inactive_reason(&self, key: &str) -> Option<(&'static str, &'static str)> {
                match self { $( $enum::$variant(p) => $crate::core::params::Params::inactive_reason(p, key), )* }
            }
        }
    };
}
pub(crate) use dispatch_params;

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
    #[serde(rename_all = "kebab-case")]
    pub enum Shape {
        #[default]
        Square,
        Triangle,
    }
    impl ChoiceParam for Shape {
        const OPTIONS: &'static [&'static str] = &["square", "triangle"];
        fn index(self) -> usize {
            self as usize
        }
        fn from_index(i: usize) -> Self {
            [Shape::Square, Shape::Triangle][i]
        }
    }

    declare_params! {
        /// A test set with one field of every kind.
        Every = "every", "one field of every kind" {
            count: int(3, 1, 10, "an integer"),
            scale: float(0.5, 0.0, 1.0, "a float"),
            width: positive(1.0, 2.0, "a positive float"),
            gain: scale(1.0, 0.5, 4.0, "a signed scale"),
            shape: choice(Shape, "a choice"),
            on: flag(true, "a flag"),
            amps: list(3, [0.5, 0.25, 0.0], -1.0, 1.0, "a list"),
            gains: per_dim(1.0, 0.0, 2.0, "a value per dimension"),
            #[serde(skip_serializing_if = "IntList::is_empty")]
            ids: int_list(1, 100, "a list of integers"),
        }
        check(p) {
            if p.amps.iter().map(|a| a.abs()).sum::<f64>() > 1.0 {
                return Err(ParamError::Invalid {
                    owner: "every",
                    field: "amps",
                    value: fmt_num(p.amps.iter().map(|a| a.abs()).sum()),
                    allowed: "Σ|a| ≤ 1".into(),
                });
            }
            Ok(())
        }
    }

    #[test]
    fn defaults_match_the_descriptors_and_are_valid() {
        let e = Every::default();
        for spec in e.specs() {
            assert_eq!(
                e.get(spec.name),
                Some(spec.default_value()),
                "{}",
                spec.name
            );
        }
        e.check_params().unwrap();
        assert_eq!(e.spec("doc"), None);
        assert_eq!(
            (Every::NAME, Every::SUMMARY),
            (e.owner(), "one field of every kind")
        );
    }

    #[test]
    fn set_parses_every_kind() {
        let mut e = Every::default();
        e.set("count", "7").unwrap();
        e.set("scale", "0.25").unwrap();
        e.set("width", "2").unwrap();
        e.set("gain", "-0.5").unwrap();
        e.set("shape", "Triangle").unwrap();
        e.set("on", "false").unwrap();
        e.set("amps", "[0.1, -0.2]").unwrap();
        assert_eq!(
            e,
            Every {
                count: 7,
                scale: 0.25,
                width: 2.0,
                gain: -0.5,
                shape: Shape::Triangle,
                on: false,
                amps: [0.1, -0.2, 0.0],
                gains: PerDim::all(1.0),
                ids: IntList::EMPTY,
            }
        );
        // Unquoted and quoted enum values, list without brackets.
        e.set("shape", "\"square\"").unwrap();
        e.set("amps", "0.3,0.3,0.3").unwrap();
        assert_eq!(e.shape, Shape::Square);
        assert_eq!(e.amps, [0.3, 0.3, 0.3]);
        // A value per dimension: one number, a list, a list of one (the number), no brackets.
        e.set("gains", "0.5").unwrap();
        assert_eq!((e.gains, e.gains.is_one()), (PerDim::all(0.5), true));
        assert_eq!(e.get("gains"), Some(ParamValue::Float(0.5)));
        e.set("gains", "[0.25, 2, 0]").unwrap();
        assert_eq!(e.gains.as_slice(), &[0.25, 2.0, 0.0]);
        assert_eq!(e.get("gains"), Some(ParamValue::List(vec![0.25, 2.0, 0.0])));
        assert_eq!(
            e.params_text().split(' ').next_back(),
            Some("gains=[0.25,2,0]")
        );
        e.set("gains", "[1.5]").unwrap();
        assert_eq!(e.gains, PerDim::all(1.5));
        e.set("gains", "1,2").unwrap();
        assert_eq!(e.gains.expand(2), Ok(vec![1.0, 2.0]));
        assert_eq!(e.gains.expand(3), Err(2));
        assert_eq!(PerDim::all(0.75).expand(3), Ok(vec![0.75; 3]));
        let long = vec![1.0; MAX_DIMS];
        e.set("gains", &format!("{long:?}")).unwrap();
        assert_eq!(e.gains.as_slice().len(), MAX_DIMS);
    }

    #[test]
    fn a_value_per_dimension_round_trips_through_ron_and_json() {
        for g in [PerDim::all(0.5), PerDim::list(&[0.25, 2.0, 0.0]).unwrap()] {
            let e = Every {
                gains: g,
                ..Every::default()
            };
            let text = ron::to_string(&e).unwrap();
            assert_eq!(ron::from_str::<Every>(&text).unwrap(), e, "{text}");
            let json = serde_json::to_string(&e).unwrap();
            assert_eq!(serde_json::from_str::<Every>(&json).unwrap(), e, "{json}");
        }
        // One number is written as a number; integers and a list of one read back.
        let e: Every = ron::from_str("(gains: 2)").unwrap();
        assert_eq!(e.gains, PerDim::all(2.0));
        assert!(ron::to_string(&e).unwrap().contains("gains:2.0"));
        let e: Every = ron::from_str("(gains: [1.5])").unwrap();
        assert_eq!(e.gains, PerDim::all(1.5));
        assert_eq!(format!("{:?}", e.gains), "1.5");
        assert!(ron::from_str::<Every>("(gains: [])").is_err());
        let too_long = format!("(gains: {:?})", vec![1.0; MAX_DIMS + 1]);
        assert!(ron::from_str::<Every>(&too_long).is_err());
        assert_eq!(
            params_json(&Every::default())["gains"],
            serde_json::json!(1.0)
        );
    }

    #[test]
    fn a_list_of_integers_parses_round_trips_and_is_left_out_when_not_given() {
        let mut e = Every::default();
        assert!(e.ids.is_empty());
        assert_eq!(e.get("ids"), Some(ParamValue::List(vec![])));
        // Not given: left out of the parameter text, JSON and the serde form.
        assert!(!e.params_text().contains("ids"));
        assert!(params_json(&e).get("ids").is_none());
        assert!(!ron::to_string(&e).unwrap().contains("ids"));
        for text in ["1,2,100", "[1, 2, 100]", " [1,2,100] "] {
            e.set("ids", text).unwrap();
            assert_eq!(e.ids.as_slice(), &[1, 2, 100], "{text}");
        }
        assert_eq!(e.get("ids"), Some(ParamValue::List(vec![1.0, 2.0, 100.0])));
        assert!(e.params_text().ends_with(" ids=[1,2,100]"));
        assert_eq!(params_json(&e)["ids"], serde_json::json!([1, 2, 100]));
        assert!(params_json(&e)["ids"][0].is_i64());
        let text = ron::to_string(&e).unwrap();
        assert!(text.contains("ids:[1,2,100]"), "{text}");
        assert_eq!(ron::from_str::<Every>(&text).unwrap(), e);
        let json = serde_json::to_string(&e).unwrap();
        assert_eq!(serde_json::from_str::<Every>(&json).unwrap(), e);
        // The text form parses back to the same list; `[]` clears it.
        let mut again = Every::default();
        again
            .set("ids", &e.get("ids").unwrap().to_string())
            .unwrap();
        assert_eq!(again, e);
        e.set("ids", "[]").unwrap();
        assert!(e.ids.is_empty());
        // One integer is a list of one; the longest list is MAX_DIMS entries.
        let spec = e.spec("ids").unwrap();
        assert_eq!(
            spec.accept(&ParamValue::Int(7)),
            Some(ParamValue::List(vec![7.0]))
        );
        let long = vec!["1"; MAX_DIMS].join(",");
        e.set("ids", &long).unwrap();
        assert_eq!(e.ids.as_slice().len(), MAX_DIMS);
        assert!(e.set("ids", &format!("{long},1")).is_err());
        assert_eq!(e.ids.as_slice().len(), MAX_DIMS);
        assert!(ron::from_str::<Every>(&format!("(ids: [{long},1])")).is_err());
        assert!(ron::from_str::<Every>("(ids: [1, -2])").is_err());
        assert!(ron::from_str::<Every>("(ids: 3)").is_err());
        // A value written directly out of range is found by the whole-set check.
        let bad = Every {
            ids: IntList::list(&[1, 200]).unwrap(),
            ..Every::default()
        };
        assert_eq!(bad.check_params().unwrap_err().field(), Some("ids"));
    }

    #[test]
    fn bad_values_name_the_field_and_leave_the_set_unchanged() {
        let mut e = Every::default();
        let before = e;
        let cases = [
            ("count", "0", "every.count = 0: must be an integer in 1..=10"),
            ("count", "2.5", "every.count = 2.5: must be an integer in 1..=10"),
            ("scale", "NaN", "every.scale = NaN: must be a finite number in [0, 1]"),
            ("width", "0", "every.width = 0: must be a finite number in (0, 2]"),
            ("gain", "0", "every.gain = 0: must be a finite number with |gain| in [0.5, 4]"),
            ("gain", "-4.5", "every.gain = -4.5: must be a finite number with |gain| in [0.5, 4]"),
            ("gain", "0.25", "every.gain = 0.25: must be"),
            ("gain", "inf", "every.gain = inf: must be"),
            ("shape", "circle", "every.shape = circle: must be one of square, triangle"),
            ("on", "maybe", "every.on = maybe: must be true or false"),
            ("amps", "[1,2]", "every.amps = [1,2]: must be a list [a,b,…] of 1 to 3 finite numbers in [-1, 1] (missing ones are 0)"),
            ("amps", "[0.1,0.2,0.3,0.4]", "must be a list"),
            ("amps", "[0.6,0.6]", "every.amps = 1.2: must be Σ|a| ≤ 1"),
            ("gains", "3", "every.gains = 3: must be one finite number in [0, 2] (every dimension) or a list [a,b,…] of one per dimension (at most 1024)"),
            ("gains", "[1,-1]", "every.gains = [1,-1]: must be one finite number"),
            ("gains", "[]", "every.gains = []: must be one finite number"),
            ("ids", "[1,0]", "every.ids = [1,0]: must be a list [a,b,…] of up to 1024 integers, one per dimension, each an integer in 1..=100 ([] = not given)"),
            ("ids", "1,101", "every.ids = 1,101: must be a list"),
            ("ids", "1.5", "every.ids = 1.5: must be a list"),
            ("ids", "1e2", "every.ids = 1e2: must be a list"),
            ("ids", "[1,,2]", "every.ids = [1,,2]: must be a list"),
        ];
        for (key, text, want) in cases {
            let err = e.set(key, text).unwrap_err().to_string();
            assert!(err.contains(want), "{key}={text}: {err}");
            assert_eq!(e, before);
        }
        let err = e.set("size", "1").unwrap_err().to_string();
        assert_eq!(
            err,
            "every: unknown parameter 'size': allowed parameters are [count, scale, width, gain, shape, on, amps, gains, ids]"
        );
    }

    #[test]
    fn check_params_finds_values_written_directly() {
        let mut list = vec![1.0; 20];
        list[3] = 5.0;
        let e = Every {
            gains: PerDim::list(&list).unwrap(),
            ..Every::default()
        };
        // A long list is shown by its first entries and its length.
        assert_eq!(
            e.check_params().unwrap_err().to_string(),
            "every.gains = [1,1,1,5,1,1,1,…] (20 numbers): must be one finite number in [0, 2] \
             (every dimension) or a list [a,b,…] of one per dimension (at most 1024)"
        );
        let e = Every {
            scale: f64::INFINITY,
            ..Every::default()
        };
        let err = e.check_params().unwrap_err();
        assert_eq!(err.field(), Some("scale"));
        assert_eq!(
            err.to_string(),
            "every.scale = inf: must be a finite number in [0, 1]"
        );
    }

    #[test]
    fn accept_converts_between_int_and_float() {
        let e = Every::default();
        let count = e.spec("count").unwrap();
        assert_eq!(
            count.accept(&ParamValue::Float(4.0)),
            Some(ParamValue::Int(4))
        );
        assert_eq!(count.accept(&ParamValue::Float(4.5)), None);
        let scale = e.spec("scale").unwrap();
        assert_eq!(
            scale.accept(&ParamValue::Int(1)),
            Some(ParamValue::Float(1.0))
        );
        assert_eq!(scale.accept(&ParamValue::Int(2)), None);
        // A signed scale: either sign, its magnitude ranged.
        let gain = e.spec("gain").unwrap();
        for ok in [0.5, 4.0, -0.5, -4.0, 1.0] {
            assert_eq!(
                gain.accept(&ParamValue::Float(ok)),
                Some(ParamValue::Float(ok))
            );
        }
        assert_eq!(
            gain.accept(&ParamValue::Int(-2)),
            Some(ParamValue::Float(-2.0))
        );
        for bad in [0.0, 0.49, -0.49, 4.01, -4.01, f64::NAN, f64::NEG_INFINITY] {
            assert_eq!(gain.accept(&ParamValue::Float(bad)), None, "{bad}");
        }
    }

    #[test]
    fn serde_refuses_unknown_fields_and_fills_defaults() {
        let e: Every = ron::from_str("(count: 4, shape: triangle)").unwrap();
        assert_eq!(e.count, 4);
        assert_eq!(e.shape, Shape::Triangle);
        assert_eq!(e.scale, 0.5);
        assert!(ron::from_str::<Every>("(cnt: 4)").is_err());
    }

    #[test]
    fn numbers_have_at_most_six_significant_digits() {
        let cases = [
            (5e-324, "5e-324"),
            (1.0 / 3.0, "0.333333"),
            (123456789.0, "1.23457e8"),
            (1e300, "1e300"),
            (-2.5, "-2.5"),
            (16777216.0, "1.67772e7"),
            (1e6, "1e6"),
            (999999.0, "999999"),
            (0.0001, "0.0001"),
            (0.00001234, "1.234e-5"),
            (1e12, "1e12"),
            (f64::NAN, "NaN"),
            (0.0, "0"),
        ];
        for (v, want) in cases {
            assert_eq!(fmt_num(v), want, "{v:e}");
        }
        assert_eq!(fmt_text("0.000000000000000000000000000001"), "1e-30");
        for v in [5e-324, 1.0 / 3.0, 1e300, -2.5, 0.1 + 0.2] {
            assert_eq!(fmt_exact(v).parse::<f64>().unwrap(), v);
        }
        assert_eq!(fmt_exact(5e-324), "5e-324");
        assert_eq!(fmt_text(&"x".repeat(100)).chars().count(), 41);
    }
}
