//! The one parameter mechanism, across every owner: descriptors agree with the structs, values
//! round-trip through `--set` text, one name per pattern everywhere, and the scene, the CLI and
//! the descriptors refuse the same values with errors naming the field path.

use samplescope::core::filter::Filter;
use samplescope::core::params::{ParamKind, Params};
use samplescope::core::pattern::Pattern;
use samplescope::core::signal::theorem::Signal1D;
use samplescope::core::signal::Signal;
use samplescope::scene::Scene;
use std::process::Command;

fn check_owner<P: Params + PartialEq + std::fmt::Debug>(p: &P) {
    p.check_params()
        .unwrap_or_else(|e| panic!("{}: defaults invalid: {e}", p.owner()));
    for spec in p.specs() {
        let value = p.get(spec.name).expect("every spec has a value");
        // The descriptor's default is the struct's default.
        assert_eq!(value, spec.default_value(), "{}.{}", p.owner(), spec.name);
        // The value's text is accepted by --set and gives the same value back.
        let mut q = p.clone();
        q.set(spec.name, &value.to_string())
            .unwrap_or_else(|e| panic!("{}.{} = {value}: {e}", p.owner(), spec.name));
        assert_eq!(&q, p, "{}.{} round trip", p.owner(), spec.name);
        // Values just outside a numeric range are refused and leave the set unchanged.
        let outside = match spec.kind {
            ParamKind::Int { min, max, .. } => vec![(min - 1).to_string(), (max + 1).to_string()],
            ParamKind::Float { min, max, .. } => vec![
                format!("{:e}", min - min.abs().max(1.0)),
                format!("{:e}", max + max.abs().max(1.0)),
                "NaN".into(),
            ],
            _ => vec!["no-such-value".into()],
        };
        for text in outside {
            let mut q = p.clone();
            let e = q.set(spec.name, &text).unwrap_err().to_string();
            assert!(
                e.starts_with(&format!("{}.{} = ", p.owner(), spec.name)) && e.contains("must be"),
                "{e}"
            );
            assert_eq!(&q, p);
        }
    }
}

#[test]
fn every_owner_s_descriptors_match_its_defaults_and_round_trip() {
    for p in Pattern::all() {
        check_owner(&p);
    }
    for f in Filter::all() {
        check_owner(&f);
    }
    for s in Signal::all() {
        check_owner(&s);
    }
    for s in Signal1D::all() {
        check_owner(&s);
    }
}

#[test]
fn one_name_per_pattern_filter_and_signal_in_scenes_and_on_the_command_line() {
    for p in Pattern::all() {
        let ron = ron::to_string(&p).unwrap();
        assert!(ron.contains(&format!("kind:\"{}\"", p.name())), "{ron}");
        assert_eq!(Pattern::from_name(p.name()).unwrap().name(), p.name());
    }
    for f in Filter::all() {
        let ron = ron::to_string(&f).unwrap();
        assert!(ron.contains(&format!("kind:\"{}\"", f.name())), "{ron}");
    }
    for s in Signal::all() {
        let ron = ron::to_string(&s).unwrap();
        assert!(ron.contains(&format!("kind:\"{}\"", s.name())), "{ron}");
    }
}

const SCENE: &str = r#"(
    title: "bad parameters",
    columns: [
        (pattern: (kind: "jitter"), seed: 1),
        (pattern: (kind: "nrooks", amount: 1.5), seed: 2),
    ],
    n: 64,
)"#;

#[test]
fn a_scene_s_bad_parameter_is_named_by_path_and_position() {
    let e = Scene::from_ron(SCENE, "s.ron").unwrap_err().to_string();
    assert_eq!(
        e,
        "s.ron:5:36: columns[1].pattern.amount = 1.5: must be a finite number in [0, 1]"
    );
    let cases = [
        (
            r#"(signal: (kind: "zone-plate", k: 2e12))"#,
            "s.ron:1:31: signal.k = 2e12: must be a finite number in [-1e12, 1e12]",
        ),
        (
            r#"(filter: (filter: (kind: "gaussian", sigma: 0), mode: separable))"#,
            "s.ron:1:38: filter.filter.sigma = 0: must be a finite number in [0.001, 1000]",
        ),
        (
            r#"(signal: (kind: "polygon", size: 0.0))"#,
            "s.ron:1:28: signal.size = 0: must be a finite number in (0, 2]",
        ),
        (
            r#"(signal: (kind: "sum-of-sines", amps: [0.9, 0.9, 0.0, 0.0]))"#,
            "s.ron:1:33: signal.amps = 1.8: must be amplitudes with Σ|aₖ| ≤ 1 (value shown is Σ|aₖ|)",
        ),
        (
            r#"(n: 16, columns: [(elementary_k: Some(24))])"#,
            "s.ron:1:20: columns[0].elementary_k = Some(24): must be an integer in 0..=4 (N = 16 = 2^4)",
        ),
        (
            r#"(n: 100, columns: [(elementary_k: Some(2))])"#,
            "s.ron:1:21: columns[0].elementary_k = Some(2): must be None: elementary intervals need N = 2^m points, and N = 100",
        ),
        (
            r#"(theorem: (signal: (kind: "tent", radius: 1e9)))"#,
            "s.ron:1:35: theorem.signal.radius = 1e9: must be a finite number in [0.01, 100]",
        ),
    ];
    for (text, want) in cases {
        let e = Scene::from_ron(text, "s.ron").unwrap_err().to_string();
        assert_eq!(e, want, "{text}");
    }
    // Unknown fields of a parameter struct are refused by the parser, with their position.
    let e = Scene::from_ron(r#"(signal: (kind: "grating", frequncy: 3.0))"#, "s.ron")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("s.ron:1:"), "{e}");
    assert!(e.contains("frequncy"), "{e}");
}

fn samplescope(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .output()
        .expect("run samplescope")
}

#[test]
fn the_cli_takes_unquoted_enums_and_lists_and_names_bad_fields() {
    let ok = samplescope(&[
        "recon",
        "--signal",
        "polygon",
        "--signal-set",
        "shape=thin-triangle",
        "--size",
        "16",
        "-n",
        "64",
        "--json",
    ]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let ok = samplescope(&[
        "recon",
        "--signal",
        "sum-of-sines",
        "--signal-set",
        "amps=[0.25,0.25]",
        "--size",
        "16",
        "-n",
        "64",
        "--json",
    ]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let bad = samplescope(&[
        "recon",
        "--signal",
        "zone-plate",
        "--signal-set",
        "k=5e-324x",
        "--size",
        "16",
        "-n",
        "64",
    ]);
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(
        err.contains("zone-plate.k = 5e-324x: must be a finite number in [-1e12, 1e12]"),
        "{err}"
    );
    let help = samplescope(&["recon", "--help"]);
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains("amps=[") && help.contains("shape=square"),
        "{help}"
    );
}
