//! `scene::cost`: the estimate of a scene follows its plan (shown nodes only, shared nodes
//! once) and every shipped scene is well inside the default budget.

use samplescope::core::budget::{Budget, OverBudget};
use samplescope::scene::cost::{check, estimate};
use samplescope::scene::{ReconMode, Scene, BUILTIN};

#[test]
fn every_shipped_scene_is_inside_the_default_budget() {
    for (name, text) in BUILTIN {
        let scene = Scene::from_ron(text, name).expect("builtin scene");
        let plan = estimate(&scene);
        let total: f64 = plan.iter().map(|e| e.seconds).sum();
        // Well inside: at most a tenth of the limit (the largest take a few seconds).
        assert!(total < 6.0, "{name}: {total} s");
        assert!(check(&scene, &Budget::default()).is_ok(), "{name}");
    }
}

#[test]
fn the_estimate_lists_the_shown_nodes_once() {
    let mut scene = Scene::builtin_default();
    scene.columns.truncate(1);
    let one: Vec<String> = estimate(&scene).into_iter().map(|e| e.operation).collect();
    // Points, spectrum, samples, reconstruction, reference, error, filter response.
    assert_eq!(one.len(), 7, "{one:?}");
    assert!(
        one[0].starts_with(scene.columns[0].pattern.name()),
        "{one:?}"
    );
    assert!(
        one.iter().any(|o| o.starts_with("spectrum 256×256")),
        "{one:?}"
    );
    assert!(
        one.iter()
            .any(|o| o.starts_with("scattered reconstruction")),
        "{one:?}"
    );
    // A second, identical column shares every job: nothing more to estimate.
    let mut two = scene.clone();
    two.columns.push(scene.columns[0].clone());
    assert_eq!(estimate(&two).len(), one.len());
    // Hidden panels cost nothing.
    let mut hidden = scene.clone();
    hidden.panels.spectrum = false;
    hidden.panels.zoneplate = false;
    hidden.panels.filter = false;
    let left: Vec<String> = estimate(&hidden).into_iter().map(|e| e.operation).collect();
    assert_eq!(left.len(), 1, "{left:?}");
}

#[test]
fn a_heavy_scene_is_refused_naming_its_costliest_node() {
    let mut scene = Scene::builtin_default();
    scene.recon.mode = ReconMode::Supersample { spp: 1024 };
    scene.recon.size = 2048;
    let err = check(&scene, &Budget::default()).expect_err("over budget");
    match &err {
        OverBudget::Time { largest, limit, .. } => {
            assert!(largest
                .operation
                .starts_with("supersampling 2048×2048 at 1024 spp"));
            assert_eq!(*limit, 60.0);
        }
        other => panic!("{other}"),
    }
    // The preview at 1/16 of the samples is part of the estimate.
    let ops: Vec<String> = estimate(&scene).into_iter().map(|e| e.operation).collect();
    assert!(
        ops.iter()
            .any(|o| o.starts_with("supersampling 2048×2048 at 64 spp")),
        "{ops:?}"
    );
}

#[test]
fn spectrum_settings_make_the_one_request() {
    use samplescope::core::spectrum::{DcMode, Method};
    use samplescope::scene::SpectrumSettings;
    let s = SpectrumSettings {
        size: 64,
        tolerance: 1e-4,
        exact: false,
        realizations: 5,
        mask_dc: true,
    };
    let r = s.request(100, false);
    assert_eq!(r.size, 64);
    assert_eq!(r.method, Method::Nufft { tolerance: 1e-4 });
    assert_eq!(r.realizations, 5);
    assert_eq!(r.dc, DcMode::Mask);
    assert_eq!(r.error_check_budget, 2 * 100 * 64);
    // A file is one set; the exact DFT and DC shown follow the switches.
    let r = SpectrumSettings {
        exact: true,
        mask_dc: false,
        ..s
    }
    .request(100, true);
    assert_eq!(r.realizations, 1);
    assert_eq!(r.method, Method::Exact);
    assert_eq!(r.dc, DcMode::Show);
}
