//! The data behind each figure as CSV (numbers in Rust's shortest round-trip form).

use super::{ColumnData, PanelKind};
use crate::export::ExportError;
use crate::scene::graph::ImageData;
use std::fmt::Write as _;

fn missing(kind: PanelKind) -> ExportError {
    ExportError::EmptyData {
        figure: kind.name(),
        reason: "not computed (panel hidden, effect off, still running, or its node failed)".into(),
    }
}

fn curve(header: &str, points: &[[f64; 2]], kind: PanelKind) -> Result<String, ExportError> {
    if points.is_empty() {
        return Err(ExportError::EmptyData {
            figure: kind.name(),
            reason: "the curve is empty".into(),
        });
    }
    let mut out = format!("{header}\n");
    for p in points {
        let _ = writeln!(out, "{},{}", p[0], p[1]);
    }
    Ok(out)
}

/// One image row per line, the top row first.
fn image_rows(image: &ImageData, kind: PanelKind) -> Result<String, ExportError> {
    if image.width == 0 || image.height == 0 {
        return Err(ExportError::EmptyData {
            figure: kind.name(),
            reason: "the image is empty".into(),
        });
    }
    let mut out = String::with_capacity(image.values.len() * 10);
    for row in image.values.chunks(image.width) {
        for (i, v) in row.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let _ = write!(out, "{v}");
        }
        out.push('\n');
    }
    Ok(out)
}

/// See [`super::panel_csv`] for the columns of each kind.
pub(crate) fn panel_csv(kind: PanelKind, d: &ColumnData) -> Result<String, ExportError> {
    match kind {
        PanelKind::Pattern => {
            let p = d.points.as_ref().ok_or_else(|| missing(kind))?;
            let pts: Vec<[f64; 2]> = p.points.iter().map(|p| [p.x, p.y]).collect();
            curve("x,y", &pts, kind)
        }
        PanelKind::Spectrum => {
            let s = d.spectrum.as_ref().ok_or_else(|| missing(kind))?;
            let im = &s.image;
            if im.width == 0 || im.height == 0 {
                return Err(ExportError::EmptyData {
                    figure: kind.name(),
                    reason: "the periodogram image is empty".into(),
                });
            }
            // Row 0 of the display image is the highest ky; k_min = −⌊M/2⌋.
            let kx0 = -((im.width / 2) as i64);
            let ky0 = -((im.height / 2) as i64);
            let mut out = String::from("kx,ky,log10_power\n");
            for r in (0..im.height).rev() {
                let ky = (im.height - 1 - r) as i64 + ky0;
                for c in 0..im.width {
                    let _ = writeln!(
                        out,
                        "{},{ky},{}",
                        c as i64 + kx0,
                        im.values[r * im.width + c]
                    );
                }
            }
            Ok(out)
        }
        PanelKind::Raps => {
            let s = d.spectrum.as_ref().ok_or_else(|| missing(kind))?;
            curve("radius,power", &s.raps, kind)
        }
        PanelKind::Reconstruction => {
            let r = d.reconstruction.as_ref().ok_or_else(|| missing(kind))?;
            image_rows(&r.image, kind)
        }
        PanelKind::Reference => {
            let r = d.reference.as_ref().ok_or_else(|| missing(kind))?;
            image_rows(&r.image, kind)
        }
        PanelKind::Error => {
            let r = d.error.as_ref().ok_or_else(|| missing(kind))?;
            image_rows(&r.image, kind)
        }
        PanelKind::Kernel => {
            let r = d.response.as_ref().ok_or_else(|| missing(kind))?;
            curve("x,h", &r.kernel, kind)
        }
        PanelKind::Response => {
            let r = d.response.as_ref().ok_or_else(|| missing(kind))?;
            curve("omega,magnitude", &r.magnitude, kind)
        }
        PanelKind::Convergence => {
            let c = d.convergence.as_ref().ok_or_else(|| missing(kind))?;
            let pts: Vec<[f64; 2]> = c.iter().map(|p| [p.spp as f64, p.rmse]).collect();
            curve("spp,rmse", &pts, kind)
        }
        PanelKind::TheoremSignal
        | PanelKind::TheoremSpectrum
        | PanelKind::TheoremReconstructed
        | PanelKind::TheoremPair => {
            let v = d.theorem.as_ref().ok_or_else(|| missing(kind))?;
            let sp = &v.spectrum;
            let pp = &v.pair;
            let impulse_re: Vec<[f64; 2]> =
                pp.impulses_omega.iter().map(|i| [i[0], i[1]]).collect();
            let impulse_im: Vec<[f64; 2]> =
                pp.impulses_omega.iter().map(|i| [i[0], i[2]]).collect();
            let mut series: Vec<(String, &[[f64; 2]])> = Vec::new();
            let header = match kind {
                PanelKind::TheoremPair => {
                    if pp.impulses_x.is_empty() {
                        series.push(("p".into(), &pp.spatial));
                        series.push(("abs_P".into(), &pp.magnitude));
                        series.push(("re_P".into(), &pp.re));
                        series.push(("im_P".into(), &pp.im));
                    } else {
                        series.push(("impulse_x".into(), &pp.impulses_x));
                        series.push(("impulse_re".into(), &impulse_re));
                        series.push(("impulse_im".into(), &impulse_im));
                    }
                    "series,position,value"
                }
                PanelKind::TheoremSignal => {
                    series.push(("f".into(), &v.signal));
                    series.push(("sample".into(), &v.samples));
                    series.push(("f_r".into(), &v.reconstruction));
                    "series,x,value"
                }
                PanelKind::TheoremSpectrum => {
                    if !sp.original.is_empty() {
                        series.push(("F".into(), &sp.original));
                    }
                    for (k, c) in &sp.replicas {
                        series.push((format!("replica_{k}"), c));
                    }
                    for (k, c) in &sp.lines {
                        series.push((format!("line_{k}"), c));
                    }
                    series.push(("G".into(), &sp.gain));
                    "series,omega,magnitude"
                }
                _ => {
                    if sp.original.is_empty() {
                        if let Some((_, c)) = sp.lines.iter().find(|(k, _)| *k == 0) {
                            series.push(("F_line".into(), c));
                        }
                        series.push(("F_r_line".into(), &sp.reconstructed_lines));
                    } else {
                        series.push(("F".into(), &sp.original));
                        series.push(("F_r".into(), &sp.reconstructed));
                    }
                    "series,omega,magnitude"
                }
            };
            if series.iter().all(|(_, c)| c.is_empty()) {
                return Err(ExportError::EmptyData {
                    figure: kind.name(),
                    reason: "the curves are empty".into(),
                });
            }
            let mut out = format!("{header}\n");
            for (name, c) in &series {
                for p in c.iter() {
                    let _ = writeln!(out, "{name},{},{}", p[0], p[1]);
                }
            }
            Ok(out)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::graph::SpectrumData;
    use std::sync::Arc;

    #[test]
    fn spectrum_rows_run_from_lowest_ky_with_centred_frequencies() {
        // 2×2 display image: row 0 is ky = 0 (the highest), row 1 is ky = −1.
        let image = ImageData::new(2, 2, vec![1.0, 2.0, 3.0, 4.0]);
        let d = ColumnData {
            spectrum: Some(Arc::new(SpectrumData {
                image,
                auto_range: (0.0, 1.0),
                raps: vec![],
                anisotropy: vec![],
                stages: vec![],
            })),
            ..Default::default()
        };
        let csv = panel_csv(PanelKind::Spectrum, &d).unwrap();
        assert_eq!(csv, "kx,ky,log10_power\n-1,-1,3\n0,-1,4\n-1,0,1\n0,0,2\n");
        let e = panel_csv(PanelKind::Raps, &d).unwrap_err().to_string();
        assert!(e.contains("raps") && e.contains("empty"), "{e}");
    }

    #[test]
    fn missing_data_is_an_error_naming_the_figure() {
        let e = panel_csv(PanelKind::Kernel, &ColumnData::default())
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("kernel:"), "{e}");
    }
}
