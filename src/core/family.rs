//! The one family mechanism: patterns, filters, integrands, 2D signals and the theorem's 1D
//! signals are each an enum with one parameter struct per member, declared with [`family!`].
//!
//! A family ([`Family`]) knows its members (each with its default parameters), every
//! member's name and one-line summary, finds a member by name ([`Family::from_name`], with
//! the one error [`UnknownName`]), and prints the list the CLI's `--list` shows
//! ([`Family::list_text`]). Parameters go through [`Params`] (descriptors, checked setters),
//! which [`family!`] implements by delegation. Every user of a family goes through it: the
//! CLI's one `from_args` and `--list`, the GUI's one picker, scene files (serde: the member's
//! name is the `kind` tag) and JSON ([`crate::core::params::params_json`]).

use crate::core::params::{fmt_text, ParamSpec, Params};

/// A name that is no member (nor preset, nor alias) of a family.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} '{name}': allowed {plural} are {allowed}")]
pub struct UnknownName {
    /// What a member is called (`pattern`).
    pub what: &'static str,
    /// The plural (`patterns`).
    pub plural: &'static str,
    /// The name given (cut as [`fmt_text`] does).
    pub name: String,
    /// The accepted names, comma-separated.
    pub allowed: String,
}

/// A family of parameter sets: an enum with one parameter struct per member ([`family!`]).
pub trait Family: Params + Sized + 'static {
    /// What one member is called in messages (`pattern`, `filter`, `integrand`, `signal`).
    const WHAT: &'static str;
    /// The plural of [`Family::WHAT`].
    const PLURAL: &'static str;
    /// Other spellings [`Family::from_name`] accepts, as (alias, member name); not listed.
    const ALIASES: &'static [(&'static str, &'static str)] = &[];

    /// Every member with its default parameters, in documentation order.
    fn all() -> Vec<Self>;

    /// The member's name: on the command line, in scene files (the `kind`) and in the GUI.
    fn name(&self) -> &'static str;

    /// The member's one-line description.
    fn summary(&self) -> &'static str;

    /// Named presets (name, description, member with preset parameters), accepted by
    /// [`Family::from_name`] and listed after the members.
    fn presets() -> Vec<(&'static str, &'static str, Self)> {
        Vec::new()
    }

    /// The descriptors `--list` shows for this member: those that apply now, plus those that
    /// apply only in another configuration of it (a windowed sinc's Kaiser `beta`).
    fn listed_specs(&self) -> Vec<ParamSpec> {
        self.specs()
    }

    /// The member (or preset) named `name`, case-insensitive, surrounding blanks ignored.
    fn from_name(name: &str) -> Result<Self, UnknownName> {
        let n = name.trim();
        let n = Self::ALIASES
            .iter()
            .find(|(alias, _)| alias.eq_ignore_ascii_case(n))
            .map_or(n, |(_, member)| member);
        Self::all()
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(n))
            .or_else(|| {
                Self::presets()
                    .into_iter()
                    .find(|(p, _, _)| p.eq_ignore_ascii_case(n))
                    .map(|(_, _, m)| m)
            })
            .ok_or_else(|| UnknownName {
                what: Self::WHAT,
                plural: Self::PLURAL,
                name: fmt_text(name),
                allowed: Self::names().join(", "),
            })
    }

    /// Every name [`Family::from_name`] lists as allowed: the members, then the presets.
    fn names() -> Vec<&'static str> {
        Self::all()
            .iter()
            .map(|m| m.name())
            .chain(Self::presets().iter().map(|(p, _, _)| *p))
            .collect()
    }

    /// The text of `--list`: each member's name, summary and parameters (`--set key=…`,
    /// default, allowed range, doc), then the presets, if any.
    fn list_text() -> String {
        let mut s = String::new();
        for m in Self::all() {
            s.push_str(&format!("{}\n    {}\n", m.name(), m.summary()));
            for spec in m.listed_specs() {
                s.push_str(&format!(
                    "    --set {}=…  default {}; {}\n        {}\n",
                    spec.name,
                    spec.default_text(),
                    spec.allowed(),
                    spec.doc
                ));
            }
        }
        let presets = Self::presets();
        if !presets.is_empty() {
            s.push_str("presets\n");
            for (name, doc, _) in presets {
                s.push_str(&format!("    {name}: {doc}\n"));
            }
        }
        s
    }
}

/// Whether two strings are equal, at compile time ([`family!`] checks that a member's scene
/// name is its struct's `NAME`).
pub const fn same_name(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Declares a family: the enum (one variant per member, each holding its parameter struct
/// declared with [`declare_params!`](crate::core::params::declare_params)), its serde form
/// (internally tagged: the `kind` is the member's name), [`Family`] and [`Params`] by
/// delegation.
///
/// ```ignore
/// family! {
///     /// Every filter.
///     Filter = "filter", "filters" {
///         Box(BoxFilter) = "box",
///         Tent(Tent) = "tent",
///     }
///     dyn Kernel => kernel;          // optional: `fn kernel(&self) -> &dyn Kernel`
///     impl { fn presets() -> … }     // optional: more items of the `Family` impl
/// }
/// ```
///
/// Each member's name is written once more, for serde's tag; a compile-time check refuses a
/// name that differs from the struct's `NAME`.
macro_rules! family {
    (
        $(#[$meta:meta])*
        $enum:ident = $what:literal, $plural:literal {
            $( $(#[$vmeta:meta])* $variant:ident ( $ty:ident ) = $name:literal ),* $(,)?
        }
        $( dyn $tr:path => $method:ident; )?
        $( impl { $($extra:tt)* } )?
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(tag = "kind")]
        pub enum $enum {
            $( $(#[$vmeta])* #[serde(rename = $name)] $variant($ty), )*
        }

        $( const _: () = assert!(
            $crate::core::family::same_name($name, $ty::NAME),
            concat!("the serde name of ", stringify!($variant), " is not ", stringify!($ty), "::NAME")
        ); )*

        impl $crate::core::family::Family for $enum {
            const WHAT: &'static str = $what;
            const PLURAL: &'static str = $plural;

            fn all() -> Vec<Self> {
                vec![ $( $enum::$variant($ty::default()), )* ]
            }

            fn name(&self) -> &'static str {
                match self { $( $enum::$variant(_) => $ty::NAME, )* }
            }

            fn summary(&self) -> &'static str {
                match self { $( $enum::$variant(_) => $ty::SUMMARY, )* }
            }

            $( $($extra)* )?
        }

        /// The [`Family`](crate::core::family::Family) methods, callable without importing it.
        impl $enum {
            /// Every member with its default parameters, in documentation order.
            pub fn all() -> Vec<Self> {
                <Self as $crate::core::family::Family>::all()
            }

            /// The member's name: on the command line, in scene files and in the GUI.
            pub fn name(&self) -> &'static str {
                <Self as $crate::core::family::Family>::name(self)
            }

            /// The member's one-line description.
            pub fn summary(&self) -> &'static str {
                <Self as $crate::core::family::Family>::summary(self)
            }

            /// Named presets: (name, description, member with preset parameters).
            pub fn presets() -> Vec<(&'static str, &'static str, Self)> {
                <Self as $crate::core::family::Family>::presets()
            }

            /// The member (or preset) named `name`, case-insensitive.
            pub fn from_name(name: &str) -> Result<Self, $crate::core::family::UnknownName> {
                <Self as $crate::core::family::Family>::from_name(name)
            }
        }

        $crate::core::family::family!(@dyn $enum [$($variant),*] $( $tr => $method )?);

        $crate::core::params::dispatch_params!($enum { $( $variant ),* });
    };
    (@dyn $enum:ident [$($variant:ident),*]) => {};
    (@dyn $enum:ident [$($variant:ident),*] $tr:path => $method:ident) => {
        impl $enum {
            /// The member as the trait every member implements.
            pub fn $method(&self) -> &dyn $tr {
                match self { $( $enum::$variant(p) => p, )* }
            }
        }
    };
}
pub(crate) use family;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::filter::Filter;
    use crate::core::integration::Integrand;
    use crate::core::params::params_json;
    use crate::core::pattern::Pattern;
    use crate::core::signal::Signal;
    use serde::{de::DeserializeOwned, Serialize};

    /// Every family lists, parses and round-trips through JSON and RON the same way.
    fn check<F>()
    where
        F: Family + Serialize + DeserializeOwned + std::fmt::Debug + PartialEq,
    {
        let all = F::all();
        assert!(!all.is_empty(), "{}", F::WHAT);
        let names = F::names();
        let mut unique = names.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), names.len(), "{}: a name twice", F::WHAT);
        let list = F::list_text();
        for m in &all {
            let name = m.name();
            m.check_params().unwrap();
            assert_eq!(F::from_name(name).as_ref(), Ok(m), "{name}");
            let shouted = format!("  {}  ", name.to_ascii_uppercase());
            assert_eq!(F::from_name(&shouted).as_ref(), Ok(m), "{name}");
            // serde: the member's name is the `kind` tag; JSON and RON give the member back.
            let json = serde_json::to_string(m).unwrap();
            assert!(json.contains(&format!("\"kind\":\"{name}\"")), "{json}");
            assert_eq!(&serde_json::from_str::<F>(&json).unwrap(), m, "{json}");
            let ron_text = ron::to_string(m).unwrap();
            assert_eq!(&ron::from_str::<F>(&ron_text).unwrap(), m, "{ron_text}");
            // JSON of the parameters: one key per descriptor that applies.
            let keys: Vec<String> = match params_json(m) {
                serde_json::Value::Object(map) => map.keys().cloned().collect(),
                other => panic!("{other}"),
            };
            // (A parameter "not given", such as rank1's empty `z`, is left out.)
            let mut specs: Vec<String> = m
                .specs()
                .iter()
                .filter(|s| !m.get(s.name).is_some_and(|v| s.is_unset(&v)))
                .map(|s| s.name.to_string())
                .collect();
            specs.sort_unstable();
            assert_eq!(keys, specs, "{name}");
            // The list names the member, its summary and every parameter it can take.
            let entry = format!("{name}\n    {}\n", m.summary());
            assert!(list.contains(&entry), "{entry}");
            for spec in m.listed_specs() {
                assert!(
                    list.contains(&format!(
                        "    --set {}=…  default {}",
                        spec.name,
                        spec.default_text()
                    )),
                    "{name}.{}",
                    spec.name
                );
            }
        }
        for (preset, doc, m) in F::presets() {
            assert_eq!(F::from_name(preset), Ok(m), "{preset}");
            assert!(list.contains(&format!("    {preset}: {doc}\n")), "{preset}");
        }
        for (alias, member) in F::ALIASES {
            assert_eq!(F::from_name(alias).map(|m| m.name()), Ok(*member));
        }
        let err = F::from_name("nosuch").unwrap_err();
        assert_eq!(
            err.to_string(),
            format!(
                "unknown {} 'nosuch': allowed {} are {}",
                F::WHAT,
                F::PLURAL,
                names.join(", ")
            )
        );
        let long = "x".repeat(100);
        let err = F::from_name(&long).unwrap_err();
        assert_eq!(err.name.chars().count(), 41, "a long name is cut");
    }

    #[test]
    fn every_family_lists_parses_and_round_trips_the_same_way() {
        check::<Pattern>();
        check::<Filter>();
        check::<Integrand>();
        check::<Signal>();
        check::<crate::core::signal::theorem::Signal1D>();
    }

    #[test]
    fn the_filter_list_shows_the_kaiser_beta_and_presets() {
        let list = Filter::list_text();
        assert!(list.contains("windowed-sinc\n"), "{list}");
        assert!(list.contains("    --set beta=…"), "{list}");
        assert!(list.contains("presets\n    catmull-rom: "), "{list}");
        assert_eq!(
            Signal::from_name("ZonePlate").map(|s| s.name()),
            Ok("zone-plate")
        );
    }

    #[test]
    fn same_name_compares_bytes() {
        assert!(same_name("zone-plate", "zone-plate"));
        assert!(!same_name("zone-plate", "zone-plat"));
        assert!(!same_name("box", "bix"));
    }
}
