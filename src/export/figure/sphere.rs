//! The points on the sphere: the lecture's cylinder wrap and radial projection
//! ([`crate::core::pattern::sphere`]), in two orthographic views side by side — the front
//! ([`OrthoView::FRONT`]) and the back (the opposite direction) — so that every point is seen
//! on the near side of one view. Near points are filled discs; the far hemisphere's points
//! show through dimmed and smaller; the sphere's outline is a circle.

use super::draw::{draw_err, empty, fitted_text, present, Frame, DESC_PX, INK, MARGIN};
use super::{context_metadata, Area, Figure};
use crate::core::pattern::sphere::{pattern_to_sphere, OrthoView};
use crate::export::ExportError;
use crate::model::{marks, ColumnData, FigureContext, FigureKind};
use plotters::prelude::*;
use std::fmt::Write as _;

/// The sphere figure.
pub(super) struct Sphere;

const KIND: FigureKind = FigureKind::Sphere;

/// Width of one view, and height of the band under it that names it.
const VIEW_W: u32 = 380;
const LABEL_H: u32 = 30;
/// The far hemisphere's points.
const DIMMED: RGBColor = RGBColor(196, 200, 212);

/// A view's direction in degrees, for its label and the metadata.
fn degrees(v: OrthoView) -> (f64, f64) {
    let yaw = v.yaw.to_degrees().rem_euclid(360.0);
    (yaw.round(), v.pitch.to_degrees().round())
}

fn view_label(name: &str, v: OrthoView) -> String {
    let (a, e) = degrees(v);
    format!("{name}: from azimuth {a}°, elevation {e}°")
}

/// Radius of a point's disc on a sphere of radius `r` (plotters' pixels) with `n` points:
/// an eighth of the mean spacing √(4π/n)·r, from one page pixel to 4 base pixels.
fn disc_radius(r: f64, n: usize, s: u32) -> u32 {
    marks::disc_radius(r, n)
        .clamp(super::canvas::SUB as f64, marks::MAX_RADIUS_PX * s as f64)
        .round() as u32
}

impl Figure for Sphere {
    fn kind(&self) -> FigureKind {
        KIND
    }

    fn base_size(&self) -> (u32, u32) {
        (2 * VIEW_W, 510)
    }

    fn title(&self, ctx: &FigureContext, _data: &ColumnData) -> String {
        format!("on the sphere, {}", ctx.column_caption())
    }

    fn panel_title(&self, _ctx: &FigureContext, _data: &ColumnData) -> String {
        "on the sphere".to_string()
    }

    fn has_data(&self, data: &ColumnData) -> bool {
        data.points.is_ready()
    }

    fn check(&self, data: &ColumnData) -> Result<(), ExportError> {
        let p = present(KIND, data.points.data())?;
        if p.points.is_empty() {
            return Err(empty(KIND, "the point set is empty"));
        }
        Ok(())
    }

    fn draw(&self, f: &mut Frame<'_, '_>, body: &Area<'_>) -> Result<(), ExportError> {
        let de = |e| draw_err(KIND, e);
        let look = f.look;
        let pts = pattern_to_sphere(&present(KIND, f.data.points.data())?.points);
        let (front, back) = body.split_horizontally(look.u(VIEW_W));
        for (area, view, name) in [
            (front, OrthoView::FRONT, "front"),
            (back, OrthoView::FRONT.opposite(), "back"),
        ] {
            let (_, h) = area.dim_in_pixel();
            let (plot, band) = area.split_vertically(h - look.u(LABEL_H));
            fitted_text(&band, &view_label(name, view), DESC_PX, look, KIND)?;
            let (w, h) = plot.dim_in_pixel();
            let r = (w.min(h) / 2).saturating_sub(2 * look.u(MARGIN)) as f64;
            let (cx, cy) = (w as f64 / 2.0, h as f64 / 2.0);
            let rad = disc_radius(r, pts.len(), look.s);
            let back_rad = (rad as f64 * 0.7).round().max(1.0) as u32;
            let projected: Vec<((i32, i32), f64)> = pts
                .iter()
                .map(|&q| {
                    let (s, depth) = view.project(q);
                    let px = ((cx + s.x * r).round() as i32, (cy - s.y * r).round() as i32);
                    (px, depth)
                })
                .collect();
            for &(p, _) in projected.iter().filter(|p| p.1 < 0.0) {
                plot.draw(&Circle::new(p, back_rad, DIMMED.filled()))
                    .map_err(de)?;
            }
            plot.draw(&Circle::new(
                (cx.round() as i32, cy.round() as i32),
                r.round() as u32,
                look.line(BLACK, 1),
            ))
            .map_err(de)?;
            for &(p, _) in projected.iter().filter(|p| p.1 >= 0.0) {
                plot.draw(&Circle::new(p, rad, INK.filled())).map_err(de)?;
            }
        }
        Ok(())
    }

    fn csv(&self, data: &ColumnData) -> Result<String, ExportError> {
        self.check(data)?;
        let p = present(KIND, data.points.data())?;
        // Shortest round-trip form, as the other figures' CSV.
        let mut out = String::from("x,y,z\n");
        for q in pattern_to_sphere(&p.points) {
            let _ = writeln!(out, "{},{},{}", q.x, q.y, q.z);
        }
        Ok(out)
    }

    /// The context, the mapping and the two views.
    fn metadata(&self, ctx: &FigureContext, _data: &ColumnData) -> Vec<(String, String)> {
        let mut m = context_metadata(ctx);
        m.push((
            "mapping".into(),
            "cylinder wrap and radial projection: phi = 2 pi u, z = 1 - 2v, r = sqrt(1 - z^2)"
                .into(),
        ));
        m.push((
            "views".into(),
            format!(
                "orthographic; {}; {}",
                view_label("front", OrthoView::FRONT),
                view_label("back", OrthoView::FRONT.opposite())
            ),
        ));
        m
    }
}
