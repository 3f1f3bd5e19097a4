//! What the four figures of the 1D sampling theorem share: the view they draw, their data
//! check, titles, caption line and metadata.

use super::draw::{empty, present, Frame, Role};
use crate::core::params::Params;
use crate::export::ExportError;
use crate::model::{ColumnData, FigureContext, FigureKind, TheoremView};

/// The theorem view of `data`, or the error that it was not computed.
pub(super) fn view(kind: FigureKind, data: &ColumnData) -> Result<&TheoremView, ExportError> {
    present(kind, data.theorem.data().map(|v| &**v))
}

/// Refuses a missing view, one whose curves `has_curves` finds nothing to draw in, and a
/// sampling rate that is not positive.
pub(super) fn check(
    kind: FigureKind,
    data: &ColumnData,
    has_curves: impl Fn(&TheoremView) -> bool,
) -> Result<(), ExportError> {
    let v = view(kind, data)?;
    if !has_curves(v) {
        return Err(empty(kind, "the curves have no finite point"));
    }
    if !(v.settings.rate.is_finite() && v.settings.rate > 0.0) {
        return Err(empty(kind, "the sampling rate is not positive"));
    }
    Ok(())
}

/// "`what`: signal (params), f_s = …, filter" (`what` alone without a view).
pub(super) fn title(what: &str, data: &ColumnData) -> String {
    match data.theorem.data() {
        Some(v) => format!("{what}: {}", setup(v)),
        None => what.to_string(),
    }
}

/// "signal (params), f_s = …, filter": the theorem view's settings in words.
pub(super) fn setup(v: &TheoremView) -> String {
    let s = &v.settings;
    let params = s
        .signal
        .specs()
        .iter()
        .filter_map(|spec| match s.signal.get(spec.name) {
            Some(crate::core::params::ParamValue::Float(x)) => Some(format!("{} {x}", spec.name)),
            _ => None,
        })
        .collect::<Vec<_>>()
        .join(", ");
    format!(
        "{} ({params}), f_s = {}, {} filter",
        s.signal.name(),
        s.rate,
        s.filter.name()
    )
}

/// The caption line under the theorem figures: the pre- and post-aliasing terms, absolute
/// and relative to the signal's energy (power, for periodic signals).
pub fn theorem_caption(v: &TheoremView) -> String {
    let e = &v.errors;
    let unit = if e.periodic { "power" } else { "energy" };
    format!(
        "pre-aliasing {:.3e} ({:.3} % of {unit}) · post-aliasing {:.3e} ({:.3} %) · Nyquist f_s/2 = {}",
        e.pre_aliasing,
        100.0 * e.relative(e.pre_aliasing),
        e.post_aliasing,
        100.0 * e.relative(e.post_aliasing),
        0.5 * v.settings.rate
    )
}

/// The caption line of a theorem figure drawn in `f`: [`theorem_caption`] when the figure
/// stands alone; empty (the band left blank) as a composite's panel, whose block caption
/// gives the setup and the error terms once for every theorem panel ([`block_caption`]).
pub(super) fn caption(f: &Frame<'_, '_>, v: &TheoremView) -> String {
    match f.role {
        Role::Alone => theorem_caption(v),
        Role::Panel => String::new(),
    }
}

/// The caption of a composite's block of theorem panels: the setup, then the error terms.
pub(super) fn block_caption(v: &TheoremView) -> String {
    format!("{} · {}", setup(v), theorem_caption(v))
}

/// The scene, then the theorem view's settings and error terms, as metadata (the 2D
/// pattern, N and seed do not apply).
pub(super) fn metadata(ctx: &FigureContext, data: &ColumnData) -> Vec<(String, String)> {
    let mut m = vec![("scene".to_string(), ctx.scene_title.clone())];
    let Some(v) = data.theorem.data() else {
        return m;
    };
    let s = &v.settings;
    let e = &v.errors;
    let unit = if e.periodic { "power" } else { "energy" };
    let term = |name: &str, x: f64| {
        (
            name.to_string(),
            format!("{x:e} ({} % of the signal's {unit})", 100.0 * e.relative(x)),
        )
    };
    m.extend([
        (
            "signal".into(),
            ron::to_string(&s.signal).unwrap_or_else(|_| s.signal.name().into()),
        ),
        (
            "sampling rate".into(),
            format!("{} samples per unit", s.rate),
        ),
        (
            "filter".into(),
            ron::to_string(&s.filter).unwrap_or_else(|_| s.filter.name().into()),
        ),
        ("extent".into(), format!("x in [-{0}, {0}]", s.extent)),
        (
            "transform pair".into(),
            format!(
                "{}, a = {}, s = {}",
                s.pair.kind.name(),
                s.pair.scale,
                s.pair.shift
            ),
        ),
        (format!("signal {unit}"), format!("{:e}", e.signal_energy)),
        term("pre-aliasing", e.pre_aliasing),
        term("post-aliasing", e.post_aliasing),
        term("smoothing", e.smoothing),
        term("lost above Nyquist", e.lost),
        term("total error", e.total),
        (
            "error band".into(),
            format!("|omega| <= {}, tail <= {:e}", e.band, e.tail_bound),
        ),
    ]);
    m
}
