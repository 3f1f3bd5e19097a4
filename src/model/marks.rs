//! The sizes of the marks that stand for points, shared by the panels and the figures.
//!
//! A mark's radius follows the mean spacing of the points it stands among, so that a pattern
//! of 64 points and one of 65536 both read as points; each view clamps it to what it can
//! draw (the panels to [`MIN_RADIUS_PX`]..=[`MAX_RADIUS_PX`] screen points, the figures to one
//! page pixel..=[`MAX_RADIUS_PX`] base pixels). Their colour is [`super::palette::INK`].

/// Largest radius of a mark, in screen points (panels) or base pixels (figures).
pub const MAX_RADIUS_PX: f64 = 4.0;
/// Smallest radius of a mark on screen, in points (a figure's smallest is one page pixel).
pub const MIN_RADIUS_PX: f64 = 0.8;

/// The radius of the markers of `n` points on a square plot `side` wide (in the plot's own
/// units): 0.18 of the mean spacing side/√n, unclamped.
pub fn marker_radius(side: f64, n: usize) -> f64 {
    side / (n.max(1) as f64).sqrt() * 0.18
}

/// The radius of a point's disc on a sphere drawn with radius `r` with `n` points: an eighth of
/// the mean spacing √(4π/n)·r, unclamped.
pub fn disc_radius(r: f64, n: usize) -> f64 {
    0.125 * r * (4.0 * std::f64::consts::PI / n.max(1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marks_follow_the_mean_spacing() {
        assert!((marker_radius(100.0, 100) - 1.8).abs() < 1e-12);
        assert!((marker_radius(100.0, 400) - 0.9).abs() < 1e-12);
        assert_eq!(marker_radius(100.0, 0), marker_radius(100.0, 1));
        let spacing = (4.0 * std::f64::consts::PI / 1000.0).sqrt() * 50.0;
        assert!((disc_radius(50.0, 1000) - spacing / 8.0).abs() < 1e-12);
    }
}
