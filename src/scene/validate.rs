//! A scene's check of every value against its documented range and every parameter against its descriptor.

use super::graph::NodeKind;
use super::{
    limits, motion, Location, Motion, PixelSampling, ReconMode, Scene, SceneError, MAX_SCENE_N,
};
use crate::core::params::{ParamError, Params};
use crate::core::signal::theorem::TheoremError;

impl Scene {
    /// Checks every value against its documented range ([`limits`]) and every parameter of
    /// every pattern, signal and filter against its descriptor; the error names the field path
    /// (`columns[1].pattern.cols`, `signal.k`, `filter.filter.sigma`, `recon.mode.spp`).
    pub fn validate(&self, source_name: &str) -> Result<(), SceneError> {
        let invalid = |field: &str, value: String, allowed: &str| SceneError::Invalid {
            source_name: source_name.to_string(),
            location: Location::default(),
            field: field.to_string(),
            value,
            allowed: allowed.to_string(),
        };
        let param = |prefix: &str, e: ParamError| match e {
            ParamError::Invalid {
                field,
                value,
                allowed,
                ..
            } => invalid(&format!("{prefix}.{field}"), value, &allowed),
            ParamError::Unknown { key, allowed, .. } => invalid(
                &format!("{prefix}.{key}"),
                "(set)".into(),
                &format!("one of the parameters [{allowed}]"),
            ),
        };
        fn int_range<T: PartialOrd + std::fmt::Display + Copy>(
            v: T,
            r: &std::ops::RangeInclusive<T>,
        ) -> Option<String> {
            (!r.contains(&v)).then(|| format!("an integer in {}..={}", r.start(), r.end()))
        }
        // Free text first: its length bounds the work of laying it out and the metadata of
        // every figure that carries it.
        let text_len = |field: &str, text: &str, max: usize| {
            let len = text.chars().count();
            if len > max {
                Err(invalid(
                    field,
                    format!("{len} characters"),
                    &format!("at most {max} characters"),
                ))
            } else {
                Ok(())
            }
        };
        text_len("title", &self.title, limits::TITLE_CHARS)?;
        text_len("notes", &self.notes, limits::NOTES_CHARS)?;
        for (i, c) in self.columns.iter().enumerate() {
            text_len(
                &format!("columns[{i}].label"),
                &c.label,
                limits::LABEL_CHARS,
            )?;
            if let Some(imp) = &c.points {
                text_len(
                    &format!("columns[{i}].points.path"),
                    &imp.path,
                    limits::PATH_CHARS,
                )?;
                text_len(
                    &format!("columns[{i}].points.source"),
                    &imp.source,
                    limits::PATH_CHARS,
                )?;
            }
        }
        let ncols = self.columns.len();
        if !limits::COLUMNS.contains(&ncols) {
            return Err(invalid(
                "columns",
                format!("{ncols} columns"),
                &format!(
                    "{}..={} columns",
                    limits::COLUMNS.start(),
                    limits::COLUMNS.end()
                ),
            ));
        }
        if let Some(allowed) = int_range(self.n, &limits::N) {
            return Err(invalid("n", self.n.to_string(), &allowed));
        }
        for (i, c) in self.columns.iter().enumerate() {
            if c.points.is_none() {
                c.pattern
                    .check_params()
                    .map_err(|e| param(&format!("columns[{i}].pattern"), e))?;
            }
            check_dims(self, i, c)
                .map_err(|(field, value, allowed)| invalid(&field, value, &allowed))?;
            if c.strata && (c.points.is_some() || c.pattern.strata(self.n).is_none()) {
                return Err(invalid(
                    &format!("columns[{i}].strata"),
                    "true".into(),
                    &format!(
                        "false: {} has no strata for N = {} (stratified patterns: grid, jitter, \
                         multijitter, cmj with a column count dividing N; nrooks; lhs)",
                        if c.points.is_some() {
                            "imported points"
                        } else {
                            c.pattern.name()
                        },
                        self.n
                    ),
                ));
            }
            if let Some(k) = c.elementary_k {
                let field = format!("columns[{i}].elementary_k");
                if let Some(allowed) = int_range(k, &limits::ELEMENTARY_K) {
                    return Err(invalid(&field, format!("Some({k})"), &allowed));
                }
                let n = c.points.as_ref().map_or(self.n, |p| p.points.len());
                if c.points.as_ref().is_none_or(|p| !p.points.is_empty()) {
                    if !n.is_power_of_two() {
                        return Err(invalid(
                            &field,
                            format!("Some({k})"),
                            &format!("None: elementary intervals need N = 2^m points, and N = {n}"),
                        ));
                    }
                    let m = n.trailing_zeros();
                    if k > m {
                        return Err(invalid(
                            &field,
                            format!("Some({k})"),
                            &format!("an integer in 0..={m} (N = {n} = 2^{m})"),
                        ));
                    }
                }
            }
        }
        for (i, c) in self.columns.iter().enumerate() {
            let field = format!("columns[{i}].pixels");
            match (c.pixels, self.recon.mode) {
                (PixelSampling::PerPixel, _) => {}
                (_, ReconMode::Scattered | ReconMode::Resample { .. }) => {
                    return Err(invalid(
                        &field,
                        c.pixels.name().into(),
                        "per-pixel: image-plane and zsobol apply only to recon.mode: Supersample",
                    ))
                }
                (PixelSampling::ImagePlane { tile }, ReconMode::Supersample { spp }) => {
                    if tile > self.recon.size {
                        return Err(invalid(
                            &format!("{field}.tile"),
                            tile.to_string(),
                            &format!(
                                "0 (the whole image) or a tile side in 1..={}",
                                self.recon.size
                            ),
                        ));
                    }
                    let t = if tile == 0 { self.recon.size } else { tile };
                    if spp.saturating_mul(t * t) > crate::core::pattern::MAX_N {
                        return Err(invalid(
                            &format!("{field}.tile"),
                            tile.to_string(),
                            &format!(
                                "a tile with spp·T² ≤ {} points (spp = {spp})",
                                crate::core::pattern::MAX_N
                            ),
                        ));
                    }
                }
                (PixelSampling::ZSobol, ReconMode::Supersample { spp }) => {
                    if !spp.is_power_of_two() {
                        return Err(invalid(
                            "recon.mode.spp",
                            spp.to_string(),
                            &format!("a power of two with columns[{i}].pixels: zsobol"),
                        ));
                    }
                }
            }
        }
        self.signal.check_params().map_err(|e| param("signal", e))?;
        self.filter
            .filter
            .check_params()
            .map_err(|e| param("filter.filter", e))?;
        if let Err(e) = self.filter.validate() {
            return Err(invalid(
                "filter.mode",
                format!("{:?}", self.filter.mode).to_lowercase(),
                &e.to_string(),
            ));
        }
        // Whether a shown panel asks for a node that reconstructs (the panel table's rule; the
        // reconstruction and convergence nodes do not depend on the column).
        let reconstructs = [NodeKind::Reconstruction, NodeKind::Convergence]
            .into_iter()
            .any(|k| super::panels::asks_for(self, 0, k));
        if reconstructs && self.filter.reconstruction_refusal().is_some() {
            return Err(invalid(
                "filter.filter",
                self.filter.filter.name().to_string(),
                "a filter that passes constants (H(0) ≠ 0: not band-pass, high-pass or cosc, nor a setting that makes H(0) vanish) while effects.reconstruction or effects.convergence is on; turn those off to show the kernel alone",
            ));
        }
        self.spectrum
            .check_params()
            .map_err(|e| param("spectrum", e))?;
        self.recon.check_params().map_err(|e| param("recon", e))?;
        self.matrix.check_params().map_err(|e| param("matrix", e))?;
        self.recon
            .mode
            .check_params()
            .map_err(|e| param("recon.mode", e))?;
        self.theorem
            .signal
            .check_params()
            .map_err(|e| param("theorem.signal", e))?;
        self.theorem
            .filter
            .check_params()
            .map_err(|e| param("theorem.filter", e))?;
        match self.theorem.validate() {
            Err(TheoremError::InvalidParam {
                field,
                value,
                allowed,
            }) => return Err(invalid(&format!("theorem.{field}"), value, &allowed)),
            Err(TheoremError::Param(e)) => {
                // The part of the theorem's settings it belongs to (`signal`, `pair`).
                let owner = match &e {
                    ParamError::Invalid { owner, .. } | ParamError::Unknown { owner, .. } => *owner,
                };
                return Err(param(&format!("theorem.{owner}"), e));
            }
            Err(TheoremError::Filter(e)) => {
                return Err(invalid(
                    "theorem.filter",
                    self.theorem.filter.name().to_string(),
                    &e.to_string(),
                ))
            }
            Ok(()) => {}
        }
        self.integration
            .integrand
            .check_params()
            .map_err(|e| param("integration.integrand", e))?;
        let dims: Vec<usize> = self
            .columns
            .iter()
            .filter(|c| c.points.is_none())
            .map(|c| c.dims)
            .collect();
        if let Some((field, value, allowed)) = self.integration.check(&dims) {
            return Err(invalid(&format!("integration.{field}"), value, &allowed));
        }
        self.integration
            .check_params()
            .map_err(|e| param("integration", e))?;
        if let Some(m) = &self.motion {
            match m.validate() {
                Err(motion::MotionError::InvalidParam {
                    field,
                    value,
                    allowed,
                }) => return Err(invalid(field, value.to_string(), &allowed)),
                Err(motion::MotionError::Unsupported { signal }) => {
                    return Err(invalid(
                        "motion",
                        signal.to_string(),
                        "used with a zone-plate, grating or step-edge signal",
                    ))
                }
                Ok(()) => {}
            }
            if let Err(motion::MotionError::Unsupported { signal }) =
                Motion::check_signal(&self.signal)
            {
                return Err(invalid(
                    "motion",
                    format!("Some(..) with a {signal} signal"),
                    "None, or a zone-plate, grating or step-edge signal",
                ));
            }
        }
        self.animation
            .check_params()
            .map_err(|e| param("animation", e))?;
        if let Some(k) = self.prefix {
            if let Some(allowed) = int_range(k, &(1..=self.n)) {
                return Err(invalid(
                    "prefix",
                    format!("Some({k})"),
                    &format!("None, or Some(k) with k {} (N = {})", &allowed[3..], self.n),
                ));
            }
            if let Some((ci, col)) = self
                .columns
                .iter()
                .enumerate()
                .find(|(_, c)| c.points.is_none() && !c.pattern.plays_in_order())
            {
                return Err(invalid(
                    "prefix",
                    format!(
                        "Some({k}) with columns[{ci}].pattern {}",
                        col.pattern.name()
                    ),
                    &format!(
                        "None: a prefix plays only when every column plays in order ({}, or \
                         imported points)",
                        super::animation::in_order_patterns()
                    ),
                ));
            }
        }
        for (ci, col) in self.columns.iter().enumerate() {
            if let Some(imp) = &col.points {
                let field = format!("columns[{ci}].points.points");
                if imp.points.is_empty() {
                    return Err(invalid(
                        &field,
                        "no points".into(),
                        "at least one point (or a `path` to a point file)",
                    ));
                }
                if imp.points.len() > MAX_SCENE_N {
                    return Err(invalid(
                        &field,
                        format!("{} points", imp.points.len()),
                        &format!("at most {MAX_SCENE_N} points"),
                    ));
                }
                if let Some(j) = imp.first_outside() {
                    let [x, y] = imp.points[j];
                    return Err(invalid(
                        &format!("{field}[{j}]"),
                        format!("({x}, {y})"),
                        "inside [0,1)² (or set `normalize: true`)",
                    ));
                }
            }
        }
        Ok(())
    }
}

/// A column's `dims` and `project` (field, value, allowed): D in 2..=the pattern's `max_dims`
/// (exactly 2 for imported points and the 2D-only patterns), N·D within the coordinates a point
/// set holds, i ≠ j both below D; and a column beyond the plain 2D pattern only where its
/// points are what is shown (supersampling and the convergence curve draw fresh 2D samples in
/// every pixel; the integration study of a 2D integrand is 2D).
fn check_dims(s: &Scene, i: usize, c: &super::Column) -> Result<(), (String, String, String)> {
    use crate::core::cube::MAX_COORDS;
    let field = |name: &str| format!("columns[{i}].{name}");
    let max = if c.points.is_some() {
        2
    } else {
        c.pattern.max_dims()
    };
    if !(2..=max).contains(&c.dims) {
        let why = if c.points.is_some() {
            "2 (imported points are 2D)".to_string()
        } else if max == 2 {
            format!(
                "2 ({} is defined in 2 dimensions only; the patterns defined in d dimensions \
                 are {})",
                c.pattern.name(),
                crate::core::pattern::cube::CUBE_PATTERNS
            )
        } else {
            format!("an integer in 2..={max}")
        };
        return Err((field("dims"), c.dims.to_string(), why));
    }
    if c.dims > 2 && s.n.saturating_mul(c.dims) > MAX_COORDS {
        return Err((
            field("dims"),
            c.dims.to_string(),
            format!(
                "an integer in 2..={} for n = {} (n · dims ≤ {MAX_COORDS} coordinates)",
                (MAX_COORDS / s.n).min(max),
                s.n
            ),
        ));
    }
    let (a, b) = c.project;
    if a >= c.dims || b >= c.dims || a == b {
        return Err((
            field("project"),
            format!("({a}, {b})"),
            format!(
                "two different dimensions (i, j) in 0..={} (dims = {})",
                c.dims - 1,
                c.dims
            ),
        ));
    }
    if !c.is_plain_2d() {
        let supersamples = matches!(s.recon.mode, ReconMode::Supersample { .. })
            && super::panels::asks_for(s, i, NodeKind::Reconstruction);
        let converges = super::panels::asks_for(s, i, NodeKind::Convergence);
        if supersamples || converges {
            return Err((
                field("dims"),
                format!("{} with project ({a}, {b})", c.dims),
                format!(
                    "2 with project (0, 1) while {} is on: it draws fresh 2D samples in every \
                     pixel (a projection is shown by the scattered reconstruction)",
                    if supersamples {
                        "recon.mode: Supersample"
                    } else {
                        "effects.convergence"
                    }
                ),
            ));
        }
        if c.dims != 2
            && s.panels.integration
            && c.points.is_none()
            && s.integration.integrand.is_planar()
        {
            return Err((
                field("dims"),
                c.dims.to_string(),
                format!(
                    "2 while the integration panel studies {} (defined on [0,1]² only; the \
                     genz-* integrands take any D)",
                    s.integration.integrand.name()
                ),
            ));
        }
    }
    Ok(())
}
