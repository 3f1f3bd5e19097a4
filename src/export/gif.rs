//! The one animated-figure encoder: RGBA frames of one size become a GIF89a that loops for
//! ever (the NETSCAPE2.0 application extension, which PowerPoint, Keynote, Google Slides and
//! browsers play), each frame with its own palette of at most 256 colours (exact when the
//! frame has that few, else NeuQuant's, deterministic for the same pixels: same frames, same
//! bytes).
//!
//! **Rate.** A GIF holds each frame a whole number of centiseconds. Frame i is held
//! round(100 (i + 1) / fps) − round(100 i / fps) cs, so the delays alternate between
//! ⌊100/fps⌋ and ⌈100/fps⌉ and the animation keeps the asked mean rate (24 fps: 4, 4, 5, 4,
//! 4, 4, …, 25 cs every 6 frames). Rates above [`MAX_FPS`] would need delays under 2 cs, which
//! browsers replace by 10 cs.
//!
//! **Budget.** Frames × width × height is checked against [`MAX_GIF_PIXELS`] before any frame
//! is drawn ([`check_budget`]); the file is at most about that many bytes (LZW codes of at
//! most 12 bits per pixel, usually far fewer).

use super::ExportError;

/// The most frames × width × height pixels an animated figure may hold: 2^28 (about 186
/// frames of a 1600×900 comparison, 1.4 GB of pixels uncompressed; the frames are encoded one
/// at a time, so memory stays at one frame).
pub const MAX_GIF_PIXELS: u64 = 1 << 28;
/// The fastest rate a GIF plays reliably (delays of 2 cs).
pub const MAX_FPS: f64 = 50.0;
/// NeuQuant's sampling factor: 1 (every pixel, slowest) to 30; 10 is its authors' balance.
const QUANT_SPEED: i32 = 10;

/// The delay of frame `i` at `fps`, in centiseconds (see the module docs).
pub fn delay_cs(i: usize, fps: f64) -> u16 {
    let at = |j: usize| (100.0 * j as f64 / fps).round();
    (at(i + 1) - at(i)).clamp(1.0, f64::from(u16::MAX)) as u16
}

/// Whether `frames` frames of `width` × `height` fit [`MAX_GIF_PIXELS`] (and a GIF's 65535
/// pixels per side); the error is one line naming `field` (the frame count's name where the
/// caller reads it: `--frames`, `animation.frames`) and the frames that would fit.
pub fn check_budget(field: &str, frames: usize, width: u64, height: u64) -> Result<(), String> {
    let side = u64::from(u16::MAX);
    if width > side || height > side {
        return Err(format!(
            "an animated GIF of {width}×{height} pixels: a GIF holds at most {side} pixels per \
             side; use a smaller --scale"
        ));
    }
    let per_frame = (width * height).max(1);
    let total = (frames as u64).saturating_mul(per_frame);
    if total > MAX_GIF_PIXELS {
        let most = (MAX_GIF_PIXELS / per_frame).max(1);
        return Err(format!(
            "{field} = {frames}: {frames} frames of {width}×{height} pixels are {total} pixels, \
             more than the animated figure's budget of {MAX_GIF_PIXELS}; must be an integer in \
             2..={most} at this size (or use a smaller --scale)"
        ));
    }
    Ok(())
}

/// A GIF being written, frame by frame (memory: the file so far and one frame).
pub struct GifWriter {
    encoder: gif::Encoder<Vec<u8>>,
    width: u16,
    height: u16,
    fps: f64,
    frames: usize,
}

fn encoding(e: gif::EncodingError) -> ExportError {
    ExportError::Encode(format!("GIF: {e}"))
}

impl GifWriter {
    /// A looping GIF of `width` × `height` pixels played at `fps` frames per second.
    pub fn new(width: u32, height: u32, fps: f64) -> Result<GifWriter, ExportError> {
        let side = |v: u32, field: &'static str| {
            u16::try_from(v)
                .ok()
                .filter(|&s| s > 0)
                .ok_or(ExportError::OutOfRange {
                    field,
                    value: i64::from(v),
                    min: 1,
                    max: i64::from(u16::MAX),
                })
        };
        let (w, h) = (side(width, "width")?, side(height, "height")?);
        if !(fps.is_finite() && (1.0..=MAX_FPS).contains(&fps)) {
            return Err(ExportError::Encode(format!(
                "GIF: fps = {fps}: must be a number in 1..={MAX_FPS}"
            )));
        }
        let mut encoder = gif::Encoder::new(Vec::new(), w, h, &[]).map_err(encoding)?;
        encoder
            .set_repeat(gif::Repeat::Infinite)
            .map_err(encoding)?;
        Ok(GifWriter {
            encoder,
            width: w,
            height: h,
            fps,
            frames: 0,
        })
    }

    /// Appends a frame: `rgba` holds width × height RGBA8 pixels, row 0 at the top (alpha is
    /// ignored: figures are opaque). The buffer is used as scratch.
    pub fn frame(&mut self, rgba: &mut [u8]) -> Result<(), ExportError> {
        let expected = usize::from(self.width) * usize::from(self.height) * 4;
        if rgba.len() != expected {
            return Err(ExportError::Encode(format!(
                "GIF: frame {} has {} bytes, expected {expected} ({}×{} RGBA)",
                self.frames,
                rgba.len(),
                self.width,
                self.height
            )));
        }
        for px in rgba.chunks_exact_mut(4) {
            px[3] = 255;
        }
        let mut frame = gif::Frame::from_rgba_speed(self.width, self.height, rgba, QUANT_SPEED);
        frame.delay = delay_cs(self.frames, self.fps);
        frame.dispose = gif::DisposalMethod::Keep;
        self.encoder.write_frame(&frame).map_err(encoding)?;
        self.frames += 1;
        Ok(())
    }

    /// The frames written so far.
    pub fn frames(&self) -> usize {
        self.frames
    }

    /// The finished file (its trailer written).
    pub fn finish(self) -> Result<Vec<u8>, ExportError> {
        self.encoder
            .into_inner()
            .map_err(|e| ExportError::Encode(format!("GIF: {e}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn delays_keep_the_mean_rate() {
        for fps in [1.0, 7.0, 12.0, 24.0, 25.0, 29.97, 50.0] {
            let n = 600;
            let total: u64 = (0..n).map(|i| u64::from(delay_cs(i, fps))).sum();
            assert_eq!(total, (100.0 * n as f64 / fps).round() as u64, "{fps}");
            let lo = (100.0 / fps).floor() as u16;
            assert!((0..n).all(|i| (lo..=lo + 1).contains(&delay_cs(i, fps))));
        }
        assert_eq!(
            (0..6).map(|i| delay_cs(i, 24.0)).collect::<Vec<_>>(),
            [4, 4, 5, 4, 4, 4]
        );
    }

    #[test]
    fn the_budget_names_the_field_and_the_frames_that_fit() {
        check_budget("--frames", 48, 1600, 900).unwrap();
        let e = check_budget("--frames", 1000, 1600, 900).unwrap_err();
        assert!(
            e.starts_with("--frames = 1000:") && e.contains("2..=186"),
            "{e}"
        );
        assert!(check_budget("--frames", 2, 70000, 10).is_err());
    }
}
