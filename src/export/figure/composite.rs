//! Composites: a column's figures side by side, and every column of a scene one row each.

use super::canvas::{crisp_bitmap, ensure_font};
use super::{
    base_size, check_scale, context_metadata, encode_png, panel_rgb, rgb_to_rgba, ColumnData,
    FigureContext, PanelKind, Rgb, MAX_COMPOSITE_PIXELS,
};
use crate::export::ExportError;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Height of a column's caption band and of the comparison's title band at scale 1.
const CAPTION_H: u32 = 36;
const HEADING_H: u32 = 44;

fn size_of_row(kinds: &[PanelKind], scale: u32) -> (u64, u64) {
    let w: u64 = kinds.iter().map(|&k| base_size(k).0 as u64).sum();
    let h = kinds
        .iter()
        .map(|&k| base_size(k).1 as u64)
        .max()
        .unwrap_or(0)
        + CAPTION_H as u64;
    (w * scale as u64, h * scale as u64)
}

/// (width, height) in pixels of [`column_png`] with figures `kinds` at `scale`.
pub fn column_size(kinds: &[PanelKind], scale: u32) -> (u64, u64) {
    size_of_row(kinds, scale)
}

/// (width, height) in pixels of [`comparison_png`] of `columns` columns with figures `kinds`
/// at `scale`; compare its product with [`MAX_COMPOSITE_PIXELS`] before asking for it.
pub fn comparison_size(kinds: &[PanelKind], columns: usize, scale: u32) -> (u64, u64) {
    let (w, h) = size_of_row(kinds, scale);
    (w, (HEADING_H * scale) as u64 + h * columns as u64)
}

fn check_size(width: u64, height: u64) -> Result<(u32, u32), ExportError> {
    if width * height > MAX_COMPOSITE_PIXELS {
        return Err(ExportError::TooLarge {
            width,
            height,
            max_pixels: MAX_COMPOSITE_PIXELS,
        });
    }
    Ok((width as u32, height as u32))
}

/// Draws `text` centred in the band `y0..y0 + h` of an RGB buffer `width` wide.
fn caption(
    buf: &mut [u8],
    (width, height): (u32, u32),
    text: &str,
    y0: u32,
    h: u32,
    px: f64,
) -> Result<(), ExportError> {
    let err = |e: &dyn std::fmt::Display| ExportError::Draw {
        figure: "composite",
        message: e.to_string(),
    };
    let root = crisp_bitmap(buf, (width, height))?.into_drawing_area();
    let style = ("sans-serif", px)
        .into_font()
        .color(&BLACK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    root.draw_text(text, &style, ((px * 0.8) as i32, (y0 + h / 2) as i32))
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))
}

/// Copies `img` into the RGB buffer `width` wide at (x0, y0).
fn blit(buf: &mut [u8], width: u32, img: &Rgb, x0: u32, y0: u32) {
    let row = img.width as usize * 3;
    for y in 0..img.height as usize {
        let dst = ((y0 as usize + y) * width as usize + x0 as usize) * 3;
        buf[dst..dst + row].copy_from_slice(&img.data[y * row..(y + 1) * row]);
    }
}

/// Draws one column row (caption + figures) into `buf` at height `y0`.
fn draw_row(
    buf: &mut [u8],
    size: (u32, u32),
    y0: u32,
    kinds: &[PanelKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<(), ExportError> {
    let cap_h = CAPTION_H * scale;
    caption(
        buf,
        size,
        &format!("{} · N = {} · seed {}", ctx.column_title, ctx.n, ctx.seed),
        y0,
        cap_h,
        16.0 * scale as f64,
    )?;
    let mut x = 0;
    for &k in kinds {
        let img = panel_rgb(k, ctx, data, scale)?;
        blit(buf, size.0, &img, x, y0 + cap_h);
        x += img.width;
    }
    Ok(())
}

fn panels_list(kinds: &[PanelKind]) -> String {
    kinds
        .iter()
        .map(|k| k.name())
        .collect::<Vec<_>>()
        .join(", ")
}

fn no_panels(figure: &'static str) -> ExportError {
    ExportError::EmptyData {
        figure,
        reason: "no panel to compose".into(),
    }
}

fn column_rgb(
    kinds: &[PanelKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Rgb, ExportError> {
    check_scale(scale)?;
    ensure_font()?;
    if kinds.is_empty() {
        return Err(no_panels("column"));
    }
    let (w, h) = size_of_row(kinds, scale);
    let (w, h) = check_size(w, h)?;
    let mut buf = vec![255u8; w as usize * h as usize * 3];
    draw_row(&mut buf, (w, h), 0, kinds, ctx, data, scale)?;
    Ok(Rgb {
        width: w,
        height: h,
        data: buf,
    })
}

fn column_meta(kinds: &[PanelKind], ctx: &FigureContext, scale: u32) -> Vec<(String, String)> {
    let mut m = vec![
        ("Title".to_string(), ctx.column_caption()),
        (
            "Software".to_string(),
            format!("samplescope {}", env!("CARGO_PKG_VERSION")),
        ),
        ("figure".to_string(), "column".to_string()),
    ];
    m.extend(context_metadata(ctx));
    m.push(("panels".into(), panels_list(kinds)));
    m.push(("scale".into(), scale.to_string()));
    m
}

/// A column's figures `kinds` side by side under a caption (label, N, seed), as PNG with
/// the column's metadata. Its width is the sum of the figures' widths, its height the
/// tallest figure plus the caption, all × `scale`.
pub fn column_png(
    kinds: &[PanelKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<Vec<u8>, ExportError> {
    let img = column_rgb(kinds, ctx, data, scale)?;
    encode_png(&img, &column_meta(kinds, ctx, scale))
}

/// [`column_png`] as (width, height, RGBA8), for the clipboard.
pub fn column_rgba(
    kinds: &[PanelKind],
    ctx: &FigureContext,
    data: &ColumnData,
    scale: u32,
) -> Result<(u32, u32, Vec<u8>), ExportError> {
    let img = column_rgb(kinds, ctx, data, scale)?;
    Ok((img.width, img.height, rgb_to_rgba(&img.data)))
}

fn comparison_rgb(
    kinds: &[PanelKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
) -> Result<Rgb, ExportError> {
    check_scale(scale)?;
    ensure_font()?;
    if kinds.is_empty() {
        return Err(no_panels("comparison"));
    }
    let Some((first, _)) = columns.first() else {
        return Err(ExportError::EmptyData {
            figure: "comparison",
            reason: "no column".into(),
        });
    };
    let (_, row_h) = size_of_row(kinds, scale);
    let head = (HEADING_H * scale) as u64;
    let (cw, ch) = comparison_size(kinds, columns.len(), scale);
    let (w, h) = check_size(cw, ch)?;
    let mut buf = vec![255u8; w as usize * h as usize * 3];
    caption(
        &mut buf,
        (w, h),
        &first.scene_title,
        0,
        head as u32,
        20.0 * scale as f64,
    )?;
    for (i, (ctx, data)) in columns.iter().enumerate() {
        let y0 = head + row_h * i as u64;
        draw_row(&mut buf, (w, h), y0 as u32, kinds, ctx, data, scale)?;
    }
    Ok(Rgb {
        width: w,
        height: h,
        data: buf,
    })
}

fn comparison_meta(
    kinds: &[PanelKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
) -> Vec<(String, String)> {
    let mut m = vec![(
        "Software".to_string(),
        format!("samplescope {}", env!("CARGO_PKG_VERSION")),
    )];
    if let Some((c, _)) = columns.first() {
        m.insert(0, ("Title".into(), c.scene_title.clone()));
        m.push(("figure".into(), "comparison".into()));
        m.push(("scene".into(), c.scene_title.clone()));
        m.push(("N".into(), c.n.to_string()));
        m.push(("signal".into(), c.signal.clone()));
        m.push(("filter".into(), c.filter.clone()));
        m.push(("reconstruction".into(), c.recon.clone()));
    }
    let cols = columns
        .iter()
        .map(|(c, _)| {
            format!(
                "{}: {} {} seed {}",
                c.column_title, c.pattern, c.pattern_params, c.seed
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    m.push(("columns".into(), cols));
    m.push(("panels".into(), panels_list(kinds)));
    m.push(("scale".into(), scale.to_string()));
    m
}

/// Every column of a comparison, one row each (its caption, then its figures `kinds`),
/// under the scene's title, as PNG with the scene's metadata and every column's pattern,
/// parameters and seed. Refused with [`ExportError::TooLarge`] beyond
/// [`MAX_COMPOSITE_PIXELS`].
pub fn comparison_png(
    kinds: &[PanelKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
) -> Result<Vec<u8>, ExportError> {
    let img = comparison_rgb(kinds, columns, scale)?;
    encode_png(&img, &comparison_meta(kinds, columns, scale))
}

/// [`comparison_png`] as (width, height, RGBA8), for the clipboard.
pub fn comparison_rgba(
    kinds: &[PanelKind],
    columns: &[(FigureContext, ColumnData)],
    scale: u32,
) -> Result<(u32, u32, Vec<u8>), ExportError> {
    let img = comparison_rgb(kinds, columns, scale)?;
    Ok((img.width, img.height, rgb_to_rgba(&img.data)))
}
