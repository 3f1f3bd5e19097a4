//! `samplescope filter`: a reconstruction filter's quality metrics and frequency response.
//!
//! - Without flags: the four metrics (smoothing, post-aliasing, ringing, anisotropy) as text.
//! - `--json`: the metrics as one JSON object with keys `name`, `mode`, `params`, `smoothing`,
//!   `post_aliasing`, `ringing`, `overshoot`, `undershoot`, `anisotropy`, `omega_max`.
//! - `--response OUT.csv`: the response profile as CSV `omega,magnitude,phase`, ω in cycles per
//!   sample from 0 to 2 in steps of 1/256 (513 rows), H divided by H(0) where H(0) ≠ 0 (raw H
//!   for zero-DC filters: cosc, band-pass, high-pass), phase in radians in (−π, π]. Separable
//!   mode writes the 1D response H(ω); radial mode the Hankel profile H₂(ρ).
//! - `--list`: every filter and preset with its parameters, defaults and allowed ranges.

use super::session::{check_outputs, write_output, Session};
use super::CliError;
use super::{out, outln};
use samplescope::core::budget;
use samplescope::core::family::Family;
use samplescope::core::filter::{Filter, Filter2D, FilterMetrics, Mode2D};
use samplescope::core::params::{params_json, Params};
use serde_json::{json, Value};

/// Upper end of the `--response` CSV, in cycles per sample.
pub const CSV_OMEGA_MAX: f64 = 2.0;
/// Steps of the `--response` CSV (step 2/512 = 1/256 cycles per sample).
pub const CSV_STEPS: usize = 512;

/// Arguments of `samplescope filter`.
#[derive(clap::Args, Debug)]
pub struct FilterArgs {
    /// Filter name or preset (see --list).
    #[arg(required_unless_present = "list")]
    pub kernel: Option<String>,
    /// Filter parameter, `key=value`; repeatable (`window` is applied before the others).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// How the 1D kernel becomes 2D: separable h(x)h(y) or radial h(|p|).
    #[arg(long, default_value = "separable", value_name = "separable|radial")]
    pub mode: String,
    /// Write the response profile as CSV `omega,magnitude,phase` (ω from 0 to 2, step 1/256).
    #[arg(long, value_name = "OUT.csv")]
    pub response: Option<String>,
    /// Print the metrics as JSON.
    #[arg(long)]
    pub json: bool,
    /// List every filter and preset with its parameters.
    #[arg(long, conflicts_with_all = ["kernel", "set", "mode", "response", "json"])]
    pub list: bool,
}

/// Runs `samplescope filter`.
pub fn run(args: &FilterArgs, session: &Session) -> Result<(), CliError> {
    if args.list {
        session.refuse_budget_flags("--list")?;
        out!("{}", list_text())?;
        return Ok(());
    }
    let Some(name) = &args.kernel else {
        return Err(CliError::Usage(
            "filter: a kernel name is required (see `samplescope filter --list`)".into(),
        ));
    };
    let filter: Filter =
        super::from_args("", name, "--set", &args.set, "samplescope filter --list")?;
    let mode = Mode2D::from_name(&args.mode)?;
    let f2 = Filter2D::new(filter, mode)?;
    check_outputs(&[("--response", args.response.as_deref())])?;
    if session.admit(vec![budget::filter_metrics(&f2)])?.is_none() {
        return Ok(());
    }
    if let Some(path) = &args.response {
        let text = response_csv(&f2)?;
        write_output(std::path::Path::new(path), text.as_bytes(), &session.cancel)?;
    }
    let metrics = f2.metrics()?;
    if args.json {
        outln!("{}", metrics_json(&f2, &metrics))?;
    } else {
        out!("{}", metrics_text(&f2, &metrics))?;
    }
    Ok(())
}

/// The `--response` CSV text.
pub fn response_csv(f2: &Filter2D) -> Result<String, CliError> {
    let curve = f2.response_profile(CSV_OMEGA_MAX, CSV_STEPS)?;
    let mut text = String::with_capacity(curve.samples.len() * 64);
    text.push_str("omega,magnitude,phase\n");
    for s in &curve.samples {
        text.push_str(&format!("{:?},{:?},{:?}\n", s.omega, s.magnitude, s.phase));
    }
    Ok(text)
}

/// The `--json` output.
pub fn metrics_json(f2: &Filter2D, m: &FilterMetrics) -> Value {
    json!({
        "name": f2.filter.name(),
        "mode": f2.mode.name(),
        "params": params_json(&f2.filter),
        "smoothing": m.smoothing,
        "post_aliasing": m.post_aliasing,
        "ringing": m.ringing,
        "overshoot": m.overshoot,
        "undershoot": m.undershoot,
        "anisotropy": m.anisotropy,
        "omega_max": m.omega_max,
    })
}

/// The plain-text metrics.
pub fn metrics_text(f2: &Filter2D, m: &FilterMetrics) -> String {
    let params = f2
        .filter
        .specs()
        .iter()
        .filter_map(|s| f2.filter.get(s.name).map(|v| format!("{}={v}", s.name)))
        .collect::<Vec<_>>()
        .join(" ");
    format!(
        "{} ({}) {}\n\
         smoothing      {:.6}  pass-band loss below Nyquist: 1 − 2∫₀^½ |H(ω)|/|H(0)| dω\n\
         post_aliasing  {:.6}  energy of H above Nyquist / energy up to ω = {}\n\
         ringing        {:.6}  step response: overshoot {:.6}, undershoot {:.6}\n\
         anisotropy     {:.6}  max over |ω| < ½ of (max − min)/mean of |H₂| over angles\n",
        f2.filter.name(),
        f2.mode.name(),
        params,
        m.smoothing,
        m.post_aliasing,
        m.omega_max,
        m.ringing,
        m.overshoot,
        m.undershoot,
        m.anisotropy
    )
}

/// The text of `filter --list`: the filters and presets, then the 2D modes.
pub fn list_text() -> String {
    format!(
        "{}modes: --mode {}\n",
        Filter::list_text(),
        Mode2D::NAMES.join(" | ")
    )
}
