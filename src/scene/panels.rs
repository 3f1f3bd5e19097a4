//! The one rule for what a scene shows: which [`FigureKind`]s each column has. The node table's
//! `shown` rules ([`super::graph::NODES`]) ask it which nodes the visible panels need,
//! `samplescope render` writes exactly these figures, and the GUI saves its composites from
//! the same lists.

use super::Scene;
use crate::model::FigureKind;

/// Whether column `column` of `scene` shows `kind`: its panel is visible and the effects it
/// draws are on. The theorem's figures belong to column 0 only (the view does not depend on
/// the column).
pub fn shows(scene: &Scene, column: usize, kind: FigureKind) -> bool {
    let p = scene.panels;
    let fx = scene.effects;
    let recon = p.zoneplate && fx.reconstruction;
    match kind {
        FigureKind::Pattern => p.pattern,
        FigureKind::Sphere => p.sphere,
        FigureKind::Spectrum | FigureKind::Raps => p.spectrum,
        FigureKind::Reconstruction => recon,
        FigureKind::Reference | FigureKind::Error => recon && fx.error,
        FigureKind::Kernel | FigureKind::Response => p.filter,
        FigureKind::Convergence => p.cost && fx.convergence,
        FigureKind::Integration => p.integration && column == 0,
        FigureKind::TheoremSignal
        | FigureKind::TheoremSpectrum
        | FigureKind::TheoremReconstructed
        | FigureKind::TheoremPair => p.theorem && column == 0,
    }
}

/// Whether the scene computes the integration study (of every column: the one plot of the
/// integration figure, column 0's, shows them all).
pub fn shows_integration(scene: &Scene) -> bool {
    scene.panels.integration
}

/// The figures column `column` has, in [`FigureKind::ALL`] order: what `render` writes for it.
pub fn available_in(scene: &Scene, column: usize) -> Vec<FigureKind> {
    FigureKind::ALL
        .into_iter()
        .filter(|&k| shows(scene, column, k))
        .collect()
}

/// The figures the scene computes (those of column 0, the theorem's included).
pub fn available(scene: &Scene) -> Vec<FigureKind> {
    available_in(scene, 0)
}

/// The figures of column `column`'s composite: the [`FigureKind::COMPOSITE`] kinds it shows.
pub fn composite_in(scene: &Scene, column: usize) -> Vec<FigureKind> {
    FigureKind::COMPOSITE
        .into_iter()
        .filter(|&k| shows(scene, column, k))
        .collect()
}

/// The figures of a column composite of the scene (column 0's, the theorem's included).
pub fn composite(scene: &Scene) -> Vec<FigureKind> {
    composite_in(scene, 0)
}

/// The figures of the comparison (every column one row, the same figures in each): the
/// composite figures every column has, so the theorem figures only when the scene has a
/// single column.
pub fn comparison(scene: &Scene) -> Vec<FigureKind> {
    let mut kinds = composite(scene);
    kinds.retain(|k| scene.columns.len() == 1 || !k.is_theorem());
    kinds
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn theorem_figures_belong_to_column_zero_and_single_column_comparisons() {
        let mut scene = Scene {
            columns: vec![Default::default(), Default::default()],
            ..Default::default()
        };
        scene.panels.theorem = true;
        assert!(available_in(&scene, 0).contains(&FigureKind::TheoremPair));
        assert!(!available_in(&scene, 1).iter().any(|k| k.is_theorem()));
        assert!(composite_in(&scene, 0).contains(&FigureKind::TheoremSignal));
        assert!(!composite(&scene).contains(&FigureKind::TheoremPair));
        assert!(!comparison(&scene).iter().any(|k| k.is_theorem()));
        scene.columns.truncate(1);
        assert!(comparison(&scene).contains(&FigureKind::TheoremSpectrum));
    }

    #[test]
    fn error_figures_need_the_reconstruction_and_error_effects() {
        let mut scene = Scene::default();
        assert!(shows(&scene, 0, FigureKind::Error));
        scene.effects.error = false;
        assert!(shows(&scene, 0, FigureKind::Reconstruction));
        assert!(!shows(&scene, 0, FigureKind::Reference));
        scene.effects.reconstruction = false;
        assert!(!shows(&scene, 0, FigureKind::Reconstruction));
    }
}
