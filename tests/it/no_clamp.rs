//! No silent clamps: every GUI widget spans exactly the range a scene may hold (the parameter
//! descriptors and `scene::limits`), so drawing a valid scene, with every panel and so every
//! control shown, leaves it unchanged. Checked for every shipped scene and for scenes with
//! each documented limit reached, one value at a time.

use eframe::egui;
use egui_kittest::Harness;
use samplescope::core::budget::Budget;
use samplescope::core::filter::{Filter, Window, WindowedSinc};
use samplescope::core::integration::Integrand;
use samplescope::core::params::{ParamKind, ParamValue, Params};
use samplescope::core::pattern::Pattern;
use samplescope::core::signal::theorem::Gaussian1D;
use samplescope::core::signal::theorem::{Signal1D, EXTENT_RANGE, MAX_RATE, MIN_RATE};
use samplescope::core::signal::Signal;
use samplescope::scene::integration::limits as integration_limits;
use samplescope::scene::{
    limits, Column, IntegrationSettings, ReconMode, Scene, BUILTIN, DEFAULT_GRID, DEFAULT_SPP,
    MAX_COLUMNS,
};
use samplescope::ui::SamplescopeApp;

/// Every panel on, so that every control is drawn.
fn all_panels(mut s: Scene) -> Scene {
    let p = &mut s.panels;
    p.pattern = true;
    p.spectrum = true;
    p.zoneplate = true;
    p.filter = true;
    p.cost = true;
    p.theorem = true;
    p.integration = true;
    p.sphere = true;
    p.matrix = true;
    s
}

/// Copies of `params` with one parameter at a time at the low and the high end of its range
/// (each option of a choice; both values of a flag), keeping only valid sets.
fn at_limits<P: Params>(params: &P) -> Vec<P> {
    let mut out = Vec::new();
    for spec in params.specs() {
        let values = match &spec.kind {
            ParamKind::Int { min, max, .. } => vec![ParamValue::Int(*min), ParamValue::Int(*max)],
            ParamKind::Float { min, max, .. } => {
                vec![ParamValue::Float(*min), ParamValue::Float(*max)]
            }
            ParamKind::Scale { min, max, .. } => {
                [*min, *max, -*min, -*max].map(ParamValue::Float).to_vec()
            }
            ParamKind::Choice { options, .. } => {
                options.iter().map(|o| ParamValue::Choice(o)).collect()
            }
            ParamKind::Bool { .. } => vec![ParamValue::Bool(false), ParamValue::Bool(true)],
            ParamKind::List { default, min, max } => vec![
                ParamValue::List(vec![*min; default.len()]),
                ParamValue::List(vec![*max; default.len()]),
                ParamValue::List(vec![*max]),
            ],
            // One number at each end, and a list of two (one per dimension of the 2D study).
            ParamKind::PerDim { min, max, .. } => vec![
                ParamValue::Float(*min),
                ParamValue::Float(*max),
                ParamValue::List(vec![*min, *max]),
            ],
            // A list of integers: its smallest entry per dimension of the 2D scene (its largest
            // allowed entry depends on N, below the descriptor's bound; the patterns' own
            // checks refuse an entry ≥ N), and not given.
            ParamKind::IntList { min, .. } => vec![
                ParamValue::List(vec![*min as f64; 2]),
                ParamValue::List(Vec::new()),
            ],
        };
        for v in values {
            let mut p = params.clone();
            // An exclusive minimum is not itself allowed: set_value refuses it, so the set is
            // skipped (its smallest allowed value is covered by the descriptors' own tests).
            if p.set_value(spec.name, &v).is_ok() {
                out.push(p);
            }
        }
    }
    out
}

/// Scenes with each documented limit reached, one value at a time.
fn limit_scenes() -> Vec<(String, Scene)> {
    let base = all_panels(Scene::builtin_default());
    let mut out: Vec<(String, Scene)> = Vec::new();
    let mut push = |name: String, s: Scene| {
        s.validate(&name)
            .unwrap_or_else(|e| panic!("{name} must be a valid scene: {e}"));
        out.push((name, s));
    };
    for n in [*limits::N.start(), *limits::N.end()] {
        push(format!("n={n}"), Scene { n, ..base.clone() });
    }
    // The settings with descriptors: every parameter at each end of its range.
    for spectrum in at_limits(&base.spectrum) {
        let s = Scene {
            spectrum,
            ..base.clone()
        };
        push(format!("spectrum={spectrum:?}"), s);
    }
    for matrix in at_limits(&base.matrix) {
        let s = Scene {
            matrix,
            ..base.clone()
        };
        push(format!("matrix={matrix:?}"), s);
    }
    for recon in at_limits(&base.recon) {
        let s = Scene {
            recon,
            ..base.clone()
        };
        push(format!("recon={recon:?}"), s);
    }
    let modes = [
        ReconMode::Supersample { spp: DEFAULT_SPP },
        ReconMode::Resample { grid: DEFAULT_GRID },
    ];
    for mode in modes.iter().flat_map(at_limits) {
        let mut s = base.clone();
        s.recon.mode = mode;
        push(format!("recon.mode={mode:?}"), s);
    }
    {
        let mut s = base.clone();
        s.n = 1 << 10;
        s.columns = (0..MAX_COLUMNS)
            .map(|i| Column {
                seed: u64::MAX - i as u64,
                elementary_k: Some(if i == 0 { 10 } else { 0 }),
                ..Column::default()
            })
            .collect();
        push(
            format!("columns={MAX_COLUMNS}, seeds at u64::MAX, elementary k 0 and 10"),
            s,
        );
    }
    // A column in d dimensions: D at each end of its range (the pattern's, and N·D), the
    // projection at the last pair and swapped.
    for (name, dims, project) in [
        ("sobol", 1024, (1023, 0)),
        ("halton", 3, (2, 1)),
        ("padded", 16, (14, 15)),
        ("rank1", 2, (1, 0)),
    ] {
        let mut s = base.clone();
        s.columns[0].pattern = Pattern::from_name(name).unwrap();
        s.columns[0].dims = dims;
        s.columns[0].project = project;
        s.panels.integration = false;
        s.effects.convergence = false;
        push(format!("{name} dims={dims} project={project:?}"), s);
    }
    // The player of a prefix (a sequence's column): k at each end, the animation's frames
    // and rate at each end of their ranges (drawn by the player of a prefix and of motion).
    {
        let mut s = base.clone();
        s.columns = vec![Column {
            pattern: Pattern::from_name("sobol").unwrap(),
            ..Column::default()
        }];
        s.n = 256;
        for prefix in [None, Some(1), Some(255), Some(256)] {
            push(
                format!("prefix={prefix:?}"),
                Scene {
                    prefix,
                    ..s.clone()
                },
            );
        }
        for animation in at_limits(&s.animation) {
            let t = Scene {
                animation,
                prefix: Some(100),
                ..s.clone()
            };
            push(format!("animation={animation:?}"), t);
        }
    }
    for p in Pattern::all() {
        for q in at_limits(&p) {
            let mut s = base.clone();
            s.columns[0].pattern = q;
            push(format!("pattern {q:?}"), s);
        }
    }
    let kaiser = Filter::WindowedSinc(WindowedSinc {
        window: Window::Kaiser { beta: 5.0 },
        ..WindowedSinc::default()
    });
    for f in Filter::all().into_iter().chain([kaiser]) {
        for g in at_limits(&f) {
            let mut s = base.clone();
            s.filter.filter = g;
            // A kernel that cannot reconstruct (H(0) = 0) is shown with the reconstruction off,
            // as the shipped band-pass, high-pass and cosc scenes do (scene validation refuses
            // it otherwise).
            if s.filter.reconstruction_refusal().is_some() {
                s.effects.reconstruction = false;
                s.effects.convergence = false;
            }
            if s.filter.validate().is_ok() {
                push(format!("filter {g:?}"), s);
            }
        }
    }
    for sig in Signal::all() {
        for t in at_limits(&sig) {
            let mut s = base.clone();
            s.signal = t;
            push(format!("signal {t:?}"), s);
        }
    }
    for sig in Signal1D::all() {
        for t in at_limits(&sig) {
            let mut s = base.clone();
            s.theorem.signal = t;
            s.theorem.rate = 1.0;
            if s.theorem.validate().is_ok() {
                push(format!("theorem signal {t:?}"), s);
            }
        }
    }
    let th = |f: &dyn Fn(&mut Scene)| {
        let mut s = base.clone();
        f(&mut s);
        s
    };
    push(
        "theorem.rate=min".into(),
        th(&|s| s.theorem.rate = MIN_RATE),
    );
    push(
        "theorem.rate=max".into(),
        th(&|s| {
            s.theorem.rate = MAX_RATE;
            s.theorem.signal = Signal1D::Gaussian(Gaussian1D { sigma: 0.01 });
            s.theorem.extent = EXTENT_RANGE.0;
        }),
    );
    push(
        "theorem.extent=min".into(),
        th(&|s| s.theorem.extent = EXTENT_RANGE.0),
    );
    push(
        "theorem.extent=max".into(),
        th(&|s| {
            s.theorem.extent = EXTENT_RANGE.1;
            s.theorem.rate = 1.0;
        }),
    );
    for pair in at_limits(&base.theorem.pair) {
        push(
            format!("theorem.pair={pair:?}"),
            th(&|s| s.theorem.pair = pair),
        );
    }
    for f in Integrand::all() {
        for g in at_limits(&f) {
            let mut s = base.clone();
            s.integration.integrand = g;
            push(format!("integrand {g:?}"), s);
        }
    }
    let study = |f: &dyn Fn(&mut IntegrationSettings)| {
        let mut s = base.clone();
        f(&mut s.integration);
        s
    };
    let (n_lo, n_hi) = (*integration_limits::N.start(), *integration_limits::N.end());
    for (name, ns) in [
        ("one N at the minimum", vec![n_lo]),
        ("one N at the maximum", vec![n_hi]),
        (
            "N not powers of two, unordered, repeated",
            vec![1000, 10, 77, 10],
        ),
        ("the most N", vec![n_lo; *integration_limits::NS.end()]),
    ] {
        push(
            format!("integration.ns: {name}"),
            study(&|s| s.ns = ns.clone()),
        );
    }
    let Some(ParamKind::Int { min, max, .. }) = IntegrationSettings::default()
        .spec("realizations")
        .map(|s| s.kind)
    else {
        panic!("integration.realizations has an integer descriptor");
    };
    for r in [min as usize, max as usize] {
        push(
            format!("integration.realizations={r}"),
            study(&|s| s.realizations = r),
        );
    }
    push(
        "integration randomize, no shift".into(),
        study(&|s| {
            s.randomize = true;
            s.shift = false
        }),
    );
    // The theorem's own descriptors (rate and extent at their ends need each other: above).
    for theorem in at_limits(&base.theorem) {
        if theorem.validate().is_ok() {
            push(format!("theorem={theorem:?}"), th(&|s| s.theorem = theorem));
        }
    }
    out
}

#[test]
fn drawing_any_valid_scene_with_every_control_shown_leaves_it_unchanged() {
    let mut h: Harness<'static, SamplescopeApp> = Harness::builder()
        .with_size(egui::Vec2::new(1400.0, 1000.0))
        .wgpu()
        .build_eframe(|cc| {
            let mut app = crate::hermetic_app(cc);
            app.view.show_timings = false;
            // Nothing is computed: this test is about the widgets only.
            app.budget = Budget {
                seconds: 0.0,
                bytes: 0.0,
            };
            app
        });
    let mut scenes: Vec<(String, Scene)> = BUILTIN
        .iter()
        .map(|(name, text)| {
            let scene = Scene::from_ron(text, name).expect("shipped scenes parse");
            (name.to_string(), all_panels(scene))
        })
        .collect();
    let limits = limit_scenes();
    assert!(limits.len() > 150, "only {} limit scenes", limits.len());
    scenes.extend(limits);
    let mut changed = Vec::new();
    for (name, scene) in &scenes {
        h.state_mut().set_scene(scene.clone(), name.clone());
        h.step();
        h.step();
        let app = h.state();
        assert!(
            app.over_budget.is_some(),
            "{name}: a zero budget refuses every scene"
        );
        if &app.scene != scene {
            changed.push(format!(
                "{name}:\n  before {:?}\n  after  {:?}",
                scene, app.scene
            ));
        }
    }
    assert!(
        changed.is_empty(),
        "{} of {} scenes changed by drawing:\n{}",
        changed.len(),
        scenes.len(),
        changed.join("\n")
    );
}

#[test]
fn a_scene_over_the_budget_is_not_computed_until_the_user_asks() {
    let mut h: Harness<'static, SamplescopeApp> = Harness::builder()
        .with_size(egui::Vec2::new(1400.0, 1000.0))
        .wgpu()
        .build_eframe(|cc| {
            let mut app = crate::hermetic_app(cc);
            app.view.show_timings = false;
            app
        });
    crate::settle(&mut h, 1);
    let generation = h.state().engine.generation();
    // 2^20 best-candidate points: hours of work, far beyond the 60 s budget.
    let mut s = Scene::builtin_default();
    s.n = 1 << 20;
    s.columns[0].pattern = Pattern::from_name("best-candidate").unwrap();
    h.state_mut().set_scene(s.clone(), "huge".into());
    h.step();
    h.step();
    let msg = h.state().over_budget.clone().expect("refused");
    assert!(
        msg.contains("best candidate") || msg.contains("best-candidate"),
        "{msg}"
    );
    assert!(msg.contains("limit"), "{msg}");
    assert_eq!(
        h.state().engine.generation(),
        generation,
        "nothing submitted"
    );
    // Back to a small N: computed again, the banner gone.
    h.state_mut().scene.n = 256;
    crate::settle(&mut h, 1);
    assert!(h.state().over_budget.is_none());
    assert!(h.state().engine.generation() > generation);
}
