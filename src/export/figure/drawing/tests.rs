//! Tests of the drawing: its raster, SVG, text layout and markup.

use super::raster::BAND;
use super::*;
use std::collections::BTreeSet;

fn ink(img: &Rgb) -> usize {
    img.data.chunks_exact(3).filter(|p| p[0] < 250).count()
}

/// 3000 markers of two radii and colours at quarter-pixel centres (seed 11), a translucent
/// one and one across the page's edge, over a line: many share a stamp.
fn markers() -> Drawing {
    let mut d = Drawing::new(300, 200);
    d.ops.push(Op::Stroke {
        points: vec![[0.0, 100.5], [300.0, 100.5]],
        closed: false,
        width: 1.0,
        color: Rgba::BLACK,
    });
    let mut state = 11u64;
    let mut next = |m: u64| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 33) % m
    };
    for i in 0..3000 {
        let (x, y) = (next(1240) as f32 / 4.0 - 5.0, next(840) as f32 / 4.0 - 5.0);
        d.ops.push(Op::Circle {
            centre: [x, y],
            radius: if i % 3 == 0 { 2.25 } else { 1.5 },
            fill: true,
            width: 0.0,
            color: Rgba {
                rgb: if i % 2 == 0 {
                    [20, 20, 20]
                } else {
                    [31, 119, 180]
                },
                alpha: if i % 7 == 0 { 0.5 } else { 1.0 },
            },
        });
    }
    d
}

#[test]
fn circle_stamps_match_filling_each_circle_as_a_path() {
    let d = markers();
    let stamped = d.raster_with(true).unwrap();
    let filled = d.raster_with(false).unwrap();
    // The pixels on the edge of a band's pixmap (a band's top and bottom rows, the page's
    // first and last columns) are left out: there tiny-skia fills a path clipped by the
    // pixmap, and the edge pixel comes out up to ~16 levels off the unclipped coverage; a
    // stamp is rasterised whole and only clipped pixel by pixel, so it is right there too.
    let (w, h) = (d.width as usize, d.height as usize);
    let edge = |y: usize, x: usize| {
        matches!(y as u32 % BAND, 0 | 63) || y == h - 1 || x == 0 || x == w - 1
    };
    let diffs: Vec<i32> = (0..stamped.data.len())
        .filter(|i| !edge(i / 3 / w, (i / 3) % w))
        .map(|i| (stamped.data[i] as i32 - filled.data[i] as i32).abs())
        .collect();
    let max = diffs.iter().copied().max().unwrap();
    let mean = diffs.iter().sum::<i32>() as f64 / diffs.len() as f64;
    // Rounding only (coverage applied before or while compositing; a level or two per
    // marker, three where translucent markers overlap): under a quarter level on average
    // over this dense page, where most pixels lie under a marker's antialiased edge.
    assert!(max <= 3, "largest difference {max}");
    assert!(mean < 0.25, "mean difference {mean}");
    assert!(ink(&filled) > 10_000, "the markers are drawn");
}

#[test]
fn the_pipelined_png_is_the_raster_encoded() {
    let d = markers();
    let meta = [("Title".to_string(), "markers".to_string())];
    let img = d.raster().unwrap();
    let whole = crate::export::encode::png_rgb(img.width, img.height, &img.data, &meta);
    assert_eq!(d.png(&meta).unwrap(), whole.unwrap());
}

#[test]
fn scripts_are_marked_after_a_letter_and_one_or_two_characters_long() {
    use Script::*;
    let s = |t: &str| scripts(t);
    assert_eq!(
        s("f_s/2"),
        vec![
            (Normal, "f".into()),
            (Sub, "s".into()),
            (Normal, "/2".into())
        ]
    );
    assert_eq!(
        s("Φ_p1(i)"),
        vec![
            (Normal, "Φ".into()),
            (Sub, "p1".into()),
            (Normal, "(i)".into())
        ]
    );
    assert_eq!(s("N^-1"), vec![(Normal, "N".into()), (Super, "−1".into())]);
    assert_eq!(
        s("10^-3"),
        vec![(Normal, "10".into()), (Super, "−3".into())]
    );
    // Words, repeated markers and markers after a non-letter stay literal.
    for literal in [
        "per_pixel",
        "my_scene_v2",
        "log10_power",
        "a_b_c",
        "x ^ 2",
        "2_3",
        "x10^2",
        "_s",
    ] {
        assert_eq!(s(literal), vec![(Normal, literal.into())], "{literal}");
    }
}

#[test]
fn scripts_are_smaller_and_off_the_baseline_and_the_marker_is_not_drawn() {
    let font = font().unwrap();
    let plain = font.layout("fs", 20.0);
    let sub = font.layout("f_s", 20.0);
    let sup = font.layout("f^s", 20.0);
    assert_eq!(sub.glyphs.len(), 2);
    assert_eq!(sub.glyphs[0], plain.glyphs[0]);
    let (s, p) = (sub.glyphs[1], plain.glyphs[1]);
    assert_eq!((s.id, s.size), (p.id, SCRIPT_SIZE));
    assert!(
        s.y > p.y && sup.glyphs[1].y < p.y,
        "below and above the baseline"
    );
    assert!(sub.width < plain.width);
}

#[test]
fn base64_matches_rfc4648_vectors() {
    assert_eq!(base64(b""), "");
    assert_eq!(base64(b"f"), "Zg==");
    assert_eq!(base64(b"fo"), "Zm8=");
    assert_eq!(base64(b"foo"), "Zm9v");
    assert_eq!(base64(b"foob"), "Zm9vYg==");
    assert_eq!(base64(b"fooba"), "Zm9vYmE=");
    assert_eq!(base64(b"foobar"), "Zm9vYmFy");
    assert_eq!(base64(&[0xff, 0xfe, 0xfd]), "//79");
}

#[test]
fn a_one_pixel_line_on_pixel_centres_covers_one_row_exactly() {
    let mut d = Drawing::new(20, 10);
    d.ops.push(Op::Stroke {
        points: vec![[2.5, 4.5], [17.5, 4.5]],
        closed: false,
        width: 1.0,
        color: Rgba::BLACK,
    });
    let img = d.raster().unwrap();
    for y in 0..10usize {
        for x in 0..20usize {
            let v = img.data[(y * 20 + x) * 3];
            let want = if y == 4 && (2..=17).contains(&x) {
                0
            } else {
                255
            };
            assert_eq!(v, want, "pixel ({x}, {y})");
        }
    }
}

#[test]
fn a_diagonal_line_is_antialiased() {
    let mut d = Drawing::new(40, 40);
    d.ops.push(Op::Stroke {
        points: vec![[2.0, 3.0], [38.0, 30.0]],
        closed: false,
        width: 1.5,
        color: Rgba::BLACK,
    });
    let img = d.raster().unwrap();
    let partial = img
        .data
        .chunks_exact(3)
        .filter(|p| p[0] > 10 && p[0] < 245)
        .count();
    let full = img.data.chunks_exact(3).filter(|p| p[0] <= 10).count();
    assert!(partial > full / 2, "blended {partial}, solid {full}");
}

#[test]
fn text_is_drawn_where_its_layout_says_and_rotated_runs_are_vertical() {
    let f = font().unwrap();
    let line = f.layout("periodogram", 26.0);
    assert!(line.width > 100.0 && line.width < 160.0, "{}", line.width);
    let mut d = Drawing::new(200, 200);
    d.ops.push(Op::Text {
        text: "periodogram".into(),
        glyphs: line.glyphs.clone(),
        origin: [20.0, 20.0],
        rot: [1.0, 0.0, 0.0, 1.0],
        scale: line.scale,
        color: Rgba::BLACK,
    });
    let img = d.raster().unwrap();
    let (mut x0, mut x1, mut y0, mut y1) = (usize::MAX, 0, usize::MAX, 0);
    for (i, p) in img.data.chunks_exact(3).enumerate() {
        if p[0] < 128 {
            let (x, y) = (i % 200, i / 200);
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
    }
    assert!(
        x0 >= 20 && (x1 as f32) <= 20.0 + line.width + 1.0,
        "{x0}..{x1}"
    );
    assert!(
        y0 >= 20 && (y1 as f32) <= 20.0 + line.height + 1.0,
        "{y0}..{y1}"
    );
    assert!(x1 - x0 > 3 * (y1 - y0), "a horizontal run");
    // The same run turned by R = Rotate270, as plotters' y-axis labels.
    let mut v = Drawing::new(200, 200);
    v.ops.push(Op::Text {
        text: "periodogram".into(),
        glyphs: line.glyphs,
        origin: [20.0, 180.0],
        rot: [0.0, -1.0, 1.0, 0.0],
        scale: line.scale,
        color: Rgba::BLACK,
    });
    let img = v.raster().unwrap();
    let rows: BTreeSet<usize> = img
        .data
        .chunks_exact(3)
        .enumerate()
        .filter(|(_, p)| p[0] < 128)
        .map(|(i, _)| i / 200)
        .collect();
    let cols: BTreeSet<usize> = img
        .data
        .chunks_exact(3)
        .enumerate()
        .filter(|(_, p)| p[0] < 128)
        .map(|(i, _)| i % 200)
        .collect();
    assert!(
        rows.len() > 3 * cols.len(),
        "{} rows, {} cols",
        rows.len(),
        cols.len()
    );
    assert!(ink(&img) > 100);
}

#[test]
fn placing_a_drawing_translates_every_shape() {
    let mut a = Drawing::new(10, 10);
    a.ops.push(Op::Circle {
        centre: [1.0, 2.0],
        radius: 1.0,
        fill: true,
        width: 0.0,
        color: Rgba::BLACK,
    });
    a.ops.push(Op::Image {
        x: 0.0,
        y: 0.0,
        width: 2.0,
        height: 2.0,
        image: Arc::new(Rgb {
            width: 1,
            height: 1,
            data: vec![0, 0, 0],
        }),
    });
    let mut page = Drawing::new(100, 100);
    page.place(a, 10.0, 20.0);
    assert!(matches!(
        page.ops[0],
        Op::Circle {
            centre: [11.0, 22.0],
            ..
        }
    ));
    assert!(matches!(
        page.ops[1],
        Op::Image {
            x: 10.0,
            y: 20.0,
            ..
        }
    ));
}

#[test]
fn images_are_nearest_neighbour_over_their_rectangle() {
    let mut d = Drawing::new(8, 4);
    d.ops.push(Op::Image {
        x: 2.0,
        y: 0.0,
        width: 4.0,
        height: 4.0,
        // 2×2: black, white / white, black.
        image: Arc::new(Rgb {
            width: 2,
            height: 2,
            data: vec![0, 0, 0, 255, 255, 255, 255, 255, 255, 0, 0, 0],
        }),
    });
    let img = d.raster().unwrap();
    let at = |x: usize, y: usize| img.data[(y * 8 + x) * 3];
    assert_eq!(
        [at(1, 0), at(2, 0), at(3, 1), at(4, 0), at(6, 0)],
        [255, 0, 0, 255, 255]
    );
    assert_eq!([at(2, 2), at(4, 3), at(5, 2)], [255, 0, 0]);
}
