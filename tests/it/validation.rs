//! Validation that is right and never silent: every range a message prints is the range that is
//! accepted, joint constraints see every setting at once, requests are checked in full before an
//! estimate or the budget, options that would have no effect are refused, a pattern that stops
//! short of N fails (unless `--allow-fewer`), and exit statuses follow one rule: bad input 2,
//! environment 1.

use samplescope::core::filter::Filter;
use samplescope::core::integration::Integrand;
use samplescope::core::params::{ParamKind, ParamValue, Params};
use samplescope::core::pattern::{Pattern, PatternError};
use samplescope::core::signal::theorem::Signal1D;
use samplescope::core::signal::Signal;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

fn samplescope(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .env("DISPLAY", "")
        .env("WAYLAND_DISPLAY", "")
        .stdin(Stdio::null())
        .output()
        .unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The run failed with status 2 and its first line of standard error contains every one of
/// `words`; nothing was written to standard output.
#[track_caller]
fn refused(args: &[&str], words: &[&str]) -> String {
    let o = samplescope(args);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    let first = err.lines().next().unwrap_or_default();
    for w in words {
        assert!(first.contains(w), "{args:?}: {w:?} not in {first:?}");
    }
    assert!(o.stdout.is_empty(), "{args:?}: wrote to stdout");
    assert!(!err.contains("panicked"), "{err}");
    err
}

/// The neighbouring f64 of `x` above (`dir` = 1) or below (−1) (`f64::next_up` needs Rust 1.86).
fn step(x: f64, dir: i64) -> f64 {
    if x == 0.0 {
        return dir as f64 * f64::from_bits(1);
    }
    let up = (x > 0.0) == (dir > 0);
    let bits = x.to_bits();
    f64::from_bits(if up { bits + 1 } else { bits - 1 })
}

fn dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("validation-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

// ---------------------------------------------------------------------------------------------
// Item 7: messages print the range that is accepted.

/// The bounds a message prints: `(lo, hi, lo_included, hi_included)` of "… in [a, b)" or
/// "an integer in a..=b".
fn printed_bounds(allowed: &str) -> Option<(String, String, bool, bool)> {
    if let Some(rest) = allowed.strip_prefix("an integer in ") {
        let (a, b) = rest.split_once("..=")?;
        return Some((a.to_string(), b.to_string(), true, true));
    }
    let at = allowed.find(" in [").or_else(|| allowed.find(" in ("))? + 4;
    let open = &allowed[at..at + 1];
    let rest = &allowed[at + 1..];
    let end = rest.find([']', ')'])?;
    let (a, b) = rest[..end].split_once(", ")?;
    let close = &rest[end..end + 1];
    Some((a.to_string(), b.to_string(), open == "[", close == "]"))
}

/// Every descriptor of `p`: the bounds its message prints are accepted when the message says
/// they are included and refused when it says they are excluded; the values just inside are
/// accepted and those just outside refused. Returns the number of numeric descriptors checked.
fn check_message_bounds<P: Params>(p: &P, failures: &mut Vec<String>) -> usize {
    let mut checked = 0;
    for spec in p.specs() {
        let allowed = spec.allowed();
        let accepts = |text: &str| spec.parse(text).is_some();
        let (lo, hi, lo_in, hi_in) = match &spec.kind {
            // A value per dimension's one number is checked as a float.
            ParamKind::Int { .. } | ParamKind::Float { .. } | ParamKind::PerDim { .. } => {
                match printed_bounds(&allowed) {
                    Some(b) => b,
                    None => {
                        failures.push(format!(
                            "{}.{}: no bounds in {allowed:?}",
                            p.owner(),
                            spec.name
                        ));
                        continue;
                    }
                }
            }
            ParamKind::List { .. } => {
                // Each entry of a list is checked as a one-entry list.
                let Some((lo, hi, lo_in, hi_in)) = printed_bounds(&allowed) else {
                    failures.push(format!(
                        "{}.{}: no bounds in {allowed:?}",
                        p.owner(),
                        spec.name
                    ));
                    continue;
                };
                for (text, want) in [(&lo, lo_in), (&hi, hi_in)] {
                    if accepts(&format!("[{text}]")) != want {
                        failures.push(format!(
                            "{}.{}: [{text}] accepted = {} but the message says {allowed:?}",
                            p.owner(),
                            spec.name,
                            !want
                        ));
                    }
                }
                checked += 1;
                continue;
            }
            ParamKind::IntList { min, max } => {
                // Each entry of a list of integers: the printed bounds in and one step out.
                let printed = allowed
                    .find("an integer in ")
                    .and_then(|at| printed_bounds(allowed[at..].split(" (").next()?));
                if printed != Some((min.to_string(), max.to_string(), true, true)) {
                    failures.push(format!(
                        "{}.{}: bounds {min}..={max} not in {allowed:?}",
                        p.owner(),
                        spec.name
                    ));
                }
                for (v, want) in [
                    (*min, true),
                    (*max, true),
                    (min - 1, false),
                    (max + 1, false),
                ] {
                    if accepts(&format!("[{v}]")) != want {
                        failures.push(format!("{}.{} = [{v}]: {allowed}", p.owner(), spec.name));
                    }
                }
                checked += 1;
                continue;
            }
            _ => continue,
        };
        checked += 1;
        for (text, want, end) in [(&lo, lo_in, "lower"), (&hi, hi_in, "upper")] {
            if accepts(text) != want {
                failures.push(format!(
                    "{}.{}: the {end} bound {text} is {} but the message says {allowed:?}",
                    p.owner(),
                    spec.name,
                    if want { "refused" } else { "accepted" }
                ));
            }
        }
        // Just inside and just outside each printed bound.
        match &spec.kind {
            ParamKind::Int { min, max, .. } => {
                for (v, want) in [
                    (*min, true),
                    (*max, true),
                    (min - 1, false),
                    (max + 1, false),
                ] {
                    if accepts(&v.to_string()) != want {
                        failures.push(format!("{}.{} = {v}: {allowed}", p.owner(), spec.name));
                    }
                }
            }
            ParamKind::Float { .. } | ParamKind::PerDim { .. } => {
                let (a, b): (f64, f64) = (lo.parse().unwrap(), hi.parse().unwrap());
                let cases = [
                    (step(a, -1), false),
                    (step(a, 1), true),
                    (step(b, -1), true),
                    (step(b, 1), false),
                ];
                for (v, want) in cases {
                    if accepts(&format!("{v:e}")) != want {
                        failures.push(format!(
                            "{}.{} = {v:e}: accepted = {} but the message says {allowed:?}",
                            p.owner(),
                            spec.name,
                            !want
                        ));
                    }
                }
            }
            _ => {}
        }
    }
    checked
}

/// Every parameter set of every family, with each choice option (a choice can bring its own
/// parameters: a Kaiser window's `beta`).
fn every_choice<P: Params>(p: &P) -> Vec<P> {
    let mut out = vec![p.clone()];
    for spec in p.specs() {
        if let ParamKind::Choice { options, .. } = spec.kind {
            for o in options {
                let mut q = p.clone();
                if q.set_value(spec.name, &ParamValue::Choice(o)).is_ok() {
                    out.push(q);
                }
            }
        }
    }
    out
}

#[test]
fn every_descriptor_s_message_bounds_match_the_accepted_set_at_the_edges() {
    let mut failures = Vec::new();
    let mut checked = 0;
    for p in Pattern::all() {
        for q in every_choice(&p) {
            checked += check_message_bounds(&q, &mut failures);
        }
    }
    for f in Filter::all() {
        for q in every_choice(&f) {
            checked += check_message_bounds(&q, &mut failures);
        }
    }
    for s in Signal::all() {
        for q in every_choice(&s) {
            checked += check_message_bounds(&q, &mut failures);
        }
    }
    for s in Signal1D::all() {
        checked += check_message_bounds(&s, &mut failures);
    }
    for i in Integrand::all() {
        checked += check_message_bounds(&i, &mut failures);
    }
    assert!(checked > 80, "only {checked} descriptors checked");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_pattern_generates_at_the_edges_its_descriptors_accept() {
    // The generator agrees with the descriptor: a value the descriptor accepts at either end
    // of its range is never refused by the generator for that field (unless the refusal is
    // about n, which the descriptor cannot know).
    let mut failures = Vec::new();
    for p in Pattern::all() {
        for spec in p.specs() {
            let edges: Vec<ParamValue> = match spec.kind {
                ParamKind::Int { min, max, .. } => vec![ParamValue::Int(min), ParamValue::Int(max)],
                ParamKind::Float {
                    min,
                    max,
                    min_exclusive,
                    max_exclusive,
                    ..
                } => vec![
                    ParamValue::Float(if min_exclusive { step(min, 1) } else { min }),
                    ParamValue::Float(if max_exclusive { step(max, -1) } else { max }),
                ],
                _ => continue,
            };
            for v in edges {
                let mut q = p;
                if q.set_value(spec.name, &v).is_err() {
                    continue; // a joint constraint with the other defaults
                }
                for n in [1usize, 2, 64, 89] {
                    match q.validate(n) {
                        Err(PatternError::InvalidParam { field, allowed, .. })
                            if field == spec.name && !allowed.contains("n =") =>
                        {
                            failures.push(format!(
                                "{}.{} = {v}: n = {n}: the generator refuses it ({allowed})",
                                p.name(),
                                spec.name
                            ));
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn kronecker_offsets_are_refused_at_one_with_a_half_open_range() {
    let e = refused(
        &["points", "kronecker", "-n", "4", "--set", "offset_x=1"],
        &["kronecker.offset_x = 1", "[0, 1)"],
    );
    assert!(!e.contains("[0, 1]"), "{e}");
    // The largest offset below 1 is accepted.
    let o = samplescope(&[
        "points",
        "kronecker",
        "-n",
        "4",
        "--set",
        "offset_x=0.9999999999999999",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn joint_constraints_see_every_setting_in_any_order() {
    for order in [["low=0.4", "high=0.5"], ["high=0.5", "low=0.4"]] {
        let o = samplescope(&[
            "filter",
            "band-pass",
            "--set",
            order[0],
            "--set",
            order[1],
            "--json",
        ]);
        assert!(o.status.success(), "{order:?}: {}", stderr(&o));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(v["params"]["low"], 0.4);
        assert_eq!(v["params"]["high"], 0.5);
    }
    // A pair that is wrong together is refused, naming both ends, whatever the order.
    for order in [["low=0.5", "high=0.4"], ["high=0.4", "low=0.5"]] {
        refused(
            &["filter", "band-pass", "--set", order[0], "--set", order[1]],
            &["band-pass.low = 0.5", "high = 0.4"],
        );
    }
    // A default that conflicts with a setting is marked as the default.
    refused(
        &["filter", "band-pass", "--set", "high=0.1"],
        &["band-pass.low = 0.125 (default)", "high = 0.1"],
    );
    // recon --filter-set goes through the same path: the joint check never blames a default
    // that the next setting changes.
    let o = samplescope(&[
        "recon",
        "-n",
        "64",
        "--size",
        "16",
        "--filter",
        "band-pass",
        "--filter-set",
        "low=0.4",
        "--filter-set",
        "high=0.5",
    ]);
    assert!(!stderr(&o).contains("band-pass.low"), "{}", stderr(&o));
    // Scene files: every field is read before the joint check (low 0.4 above the default
    // high 0.375 is fine with high 0.5 given too, in either order of the fields).
    let mut scene = samplescope::scene::Scene::builtin_default();
    let mut band = Filter::from_name("band-pass").unwrap();
    band.set_field("high", "0.5").unwrap();
    band.set_field("low", "0.4").unwrap();
    scene.filter.filter = band;
    // A band-pass cannot reconstruct: show the kernel alone.
    scene.effects.reconstruction = false;
    scene.effects.convergence = false;
    let text = scene.to_ron();
    let loaded = samplescope::scene::Scene::from_ron(&text, "band.ron").unwrap();
    assert_eq!(loaded.filter.filter, band);
    let swapped =
        text.replacen("low: 0.4,", "", 1)
            .replacen("high: 0.5,", "high: 0.5, low: 0.4,", 1);
    assert_ne!(swapped, text, "{text}");
    let loaded = samplescope::scene::Scene::from_ron(&swapped, "band.ron").unwrap();
    assert_eq!(loaded.filter.filter, band);
}

#[test]
fn estimate_and_budget_never_hide_a_request_that_would_be_refused() {
    let d = dir("estimate");
    let scene = d.join("fib.ron");
    let mut s = samplescope::scene::Scene::builtin_default();
    s.n = 1000;
    for c in &mut s.columns {
        c.pattern = Pattern::from_name("fibonacci").unwrap();
        c.points = None;
    }
    std::fs::write(&scene, s.to_ron()).unwrap();
    let scene = scene.to_str().unwrap();
    let out = d.join("out");
    let out = out.to_str().unwrap();
    let cases: Vec<Vec<&str>> = vec![
        vec!["points", "fibonacci", "-n", "1000"],
        vec!["points", "hex", "-n", "63"],
        vec!["points", "grid", "-n", "64", "--set", "cols=5"],
        vec!["analyze", "fibonacci", "-n", "1000"],
        vec![
            "recon",
            "--pattern",
            "fibonacci",
            "-n",
            "1000",
            "--size",
            "8",
        ],
        vec!["recon", "--pattern", "hex", "--spp", "3", "--size", "8"],
        vec![
            "converge",
            "--pattern",
            "fibonacci",
            "--integrand",
            "disk",
            "--n",
            "13,1000",
            "--realizations",
            "2",
        ],
        vec!["render", scene, "--out", out],
    ];
    for case in cases {
        for extra in [vec!["--estimate"], vec!["--budget", "1e-9"]] {
            let mut args = case.clone();
            args.extend(extra.iter());
            let e = refused(&args, &[]);
            assert!(
                e.contains("n = 1000")
                    || e.contains("n = 63")
                    || e.contains("cols")
                    || e.contains("n = 3"),
                "{args:?}: {e}"
            );
            assert!(!e.contains("budget"), "{args:?}: the budget hid it: {e}");
        }
    }
}

#[test]
fn validate_refuses_exactly_what_generation_refuses() {
    // Pattern::validate is the generators' own checks: over small n and parameter edge
    // cases it refuses a request exactly when generating it fails (with the same error).
    let mut variants: Vec<Pattern> = Vec::new();
    for p in Pattern::all() {
        variants.push(p);
        for spec in p.specs() {
            let values: Vec<ParamValue> = match spec.kind {
                ParamKind::Int { min, max, .. } => [min, min + 1, 2, 3, 4, 8, max.min(70)]
                    .into_iter()
                    .filter(|v| (min..=max).contains(v))
                    .map(ParamValue::Int)
                    .collect(),
                ParamKind::Float { .. } => [0.0, 0.25, 1.0, 0.5, 0.9]
                    .into_iter()
                    .map(ParamValue::Float)
                    .collect(),
                ParamKind::Bool { .. } => vec![ParamValue::Bool(true)],
                ParamKind::Choice { options, .. } => {
                    options.iter().map(|o| ParamValue::Choice(o)).collect()
                }
                _ => vec![],
            };
            for v in values {
                let mut q = p;
                if q.set_value(spec.name, &v).is_ok() {
                    variants.push(q);
                }
            }
        }
    }
    let mut compared = 0;
    for p in &variants {
        if matches!(p, Pattern::Lloyd(_) | Pattern::Sot(_) | Pattern::Gbn(_)) {
            // Iterative: only the iteration count matters and generation is slow at its edge.
            continue;
        }
        for n in [1usize, 2, 3, 5, 8, 12, 13, 16, 21, 30, 64] {
            let v = p.validate(n);
            let g = p.generate_with(n, 3, &samplescope::core::cancel::Cancel::never());
            match (&v, &g) {
                (Ok(()), Ok(_)) => {}
                (Err(a), Err(b)) => assert_eq!(a, b, "{p:?} n = {n}"),
                _ => panic!(
                    "{p:?} n = {n}: validate {v:?} but generate {:?}",
                    g.map(|g| g.points.len())
                ),
            }
            compared += 1;
        }
    }
    assert!(compared > 1000, "{compared}");
}

// ---------------------------------------------------------------------------------------------
// Item 8: options that would have no effect are refused, naming the conflict.

#[test]
fn options_that_would_have_no_effect_are_refused_naming_the_conflict() {
    let d = dir("no-effect");
    let csv = d.join("p.csv");
    std::fs::write(&csv, "x,y\n0.25,0.5\n0.75,0.5\n").unwrap();
    let csv = csv.to_str().unwrap();
    let scene = d.join("s.ron");
    std::fs::write(&scene, samplescope::scene::BUILTIN[0].1).unwrap();
    let scene = scene.to_str().unwrap();
    let out = d.join("out");
    let out = out.to_str().unwrap();
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (
            vec!["analyze", "--points", csv, "-n", "5"],
            vec!["-n", "--points"],
        ),
        (
            vec!["analyze", "--points", csv, "--allow-fewer"],
            vec!["--allow-fewer", "--points"],
        ),
        (
            vec!["analyze", "grid", "-n", "16", "--realizations", "4"],
            vec!["--realizations 4", "deterministic"],
        ),
        (
            vec!["analyze", "grid", "-n", "16", "--seed", "3"],
            vec!["--seed 3", "grid"],
        ),
        (
            vec![
                "converge",
                "--pattern",
                "jitter",
                "--integrand",
                "disk",
                "--randomize",
                "--integrand-set",
                "r=0.2",
                "--n",
                "16",
                "--realizations",
                "2",
            ],
            vec!["--randomize", "--integrand-set"],
        ),
        (
            vec![
                "converge",
                "--pattern",
                "jitter",
                "--integrand",
                "bilinear",
                "--randomize",
                "--n",
                "16",
                "--realizations",
                "2",
            ],
            vec!["--randomize", "bilinear"],
        ),
        (
            vec![
                "converge",
                "--pattern",
                "random",
                "--integrand",
                "disk",
                "--no-shift",
                "--n",
                "16",
                "--realizations",
                "2",
            ],
            vec!["--no-shift", "random"],
        ),
        (
            vec![
                "converge",
                "--pattern",
                "sobol",
                "--integrand",
                "disk",
                "--no-shift",
                "--seed",
                "4",
                "--n",
                "16",
                "--realizations",
                "2",
            ],
            vec!["--seed 4", "--no-shift"],
        ),
        (
            vec!["points", "--list", "jitter", "-n", "5"],
            vec!["--list"],
        ),
        (
            vec!["points", "--list", "--sphere"],
            vec!["--list", "--sphere"],
        ),
        (
            vec!["points", "--list", "--estimate"],
            vec!["--estimate", "--list"],
        ),
        (vec!["filter", "--list", "gaussian"], vec!["--list"]),
        (vec!["filter", "--list", "--json"], vec!["--list", "--json"]),
        (
            vec!["filter", "--list", "--budget", "5"],
            vec!["--budget", "--list"],
        ),
        (
            vec![
                "points",
                "jitter",
                "-n",
                "16",
                "--set",
                "amount=0.5",
                "--set",
                "amount=0.25",
            ],
            vec!["--set amount", "twice"],
        ),
        (
            vec![
                "filter",
                "gaussian",
                "--set",
                "sigma=0.5",
                "--set",
                " sigma=0.6",
            ],
            vec!["--set sigma", "twice"],
        ),
        (
            vec![
                "recon",
                "-n",
                "64",
                "--filter-set",
                "radius=1",
                "--filter-set",
                "radius=2",
            ],
            vec!["--filter-set radius", "twice"],
        ),
        (
            vec!["points", "grid", "-n", "16", "--seed", "3"],
            vec!["--seed 3", "grid"],
        ),
        (
            vec!["points", "jitter", "-n", "16", "--allow-fewer"],
            vec!["--allow-fewer", "jitter"],
        ),
        (
            vec!["recon", "--pattern", "halton", "-n", "64", "--seed", "1"],
            vec!["--seed 1", "halton"],
        ),
        (
            vec![
                "recon",
                "--pattern",
                "poisson-dart",
                "--spp",
                "4",
                "--allow-fewer",
            ],
            vec!["--allow-fewer", "--spp"],
        ),
        (
            vec![
                "render", scene, "--out", out, "--format", "csv", "--scale", "2",
            ],
            vec!["--scale 2", "--format csv"],
        ),
        (
            vec![
                "render", scene, "--out", out, "--format", "csv", "--aspect", "4:3",
            ],
            vec!["--aspect", "--format csv"],
        ),
        (
            vec!["--scene", scene, "points", "jitter", "-n", "4"],
            vec!["--scene"],
        ),
        (
            vec!["--points", csv, "analyze", "jitter", "-n", "4"],
            vec!["--points"],
        ),
        (
            vec!["--lecture", "render", scene, "--out", out],
            vec!["--lecture", "GUI"],
        ),
    ];
    for (args, words) in cases {
        refused(&args, &words);
    }
    // The same options where they do have an effect are accepted.
    for args in [
        vec!["points", "jitter", "-n", "16", "--seed", "3"],
        vec!["points", "poisson-dart", "-n", "16", "--allow-fewer"],
        vec!["points", "--list"],
    ] {
        let o = samplescope(&args);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    }
    assert!(
        !std::path::Path::new(out).exists(),
        "a refused render wrote {out}"
    );
}

// ---------------------------------------------------------------------------------------------
// Item 9: a pattern that stops short of N fails, naming the parameter.

#[test]
fn a_pattern_that_stops_short_fails_naming_the_parameter_unless_allow_fewer() {
    let dart = ["--set", "max_misses=1"];
    let mut points = vec!["points", "poisson-dart", "-n", "64"];
    points.extend(dart);
    refused(
        &points,
        &[
            "poisson-dart",
            "of 64 points",
            "max_misses",
            "--allow-fewer",
        ],
    );
    let mut allowed = points.clone();
    allowed.push("--allow-fewer");
    let o = samplescope(&allowed);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = String::from_utf8_lossy(&o.stdout).lines().count() - 1;
    assert!((1..64).contains(&rows), "{rows} rows");
    assert!(stderr(&o).contains(&format!("placed {rows} of 64 points")));

    // Bridson's maximal set at a radius near the packing bound holds fewer than n points.
    refused(
        &[
            "points",
            "poisson-bridson",
            "-n",
            "64",
            "--set",
            "radius=0.13",
            "--set",
            "k=1",
        ],
        &["poisson-bridson", "of 64 points", "radius"],
    );

    let mut analyze = vec!["analyze", "poisson-dart", "-n", "64", "--size", "16"];
    analyze.extend(dart);
    refused(&analyze, &["max_misses"]);
    let mut recon = vec![
        "recon",
        "--pattern",
        "poisson-dart",
        "-n",
        "64",
        "--size",
        "16",
    ];
    recon.extend(dart);
    refused(&recon, &["max_misses"]);
    // Supersampling draws the pattern in every pixel: a pixel never gets fewer samples.
    let mut spp = vec![
        "recon",
        "--pattern",
        "poisson-dart",
        "--spp",
        "64",
        "--size",
        "4",
    ];
    spp.extend(dart);
    refused(&spp, &["max_misses"]);
    let mut converge = vec![
        "converge",
        "--pattern",
        "poisson-dart",
        "--integrand",
        "disk",
        "--n",
        "64",
        "--realizations",
        "2",
    ];
    converge.extend(dart);
    refused(&converge, &["--n 64", "max_misses"]);

    // A scene column with such a pattern fails with the one line (the GUI shows it on the
    // column), in render and in the compute graph alike.
    let d = dir("short");
    let mut s = samplescope::scene::Scene::builtin_default();
    s.n = 64;
    let mut p = Pattern::from_name("poisson-dart").unwrap();
    p.set("max_misses", "1").unwrap();
    s.columns[0].pattern = p;
    s.columns[0].points = None;
    let path = d.join("short.ron");
    std::fs::write(&path, s.to_ron()).unwrap();
    let out = d.join("out");
    refused(
        &[
            "render",
            path.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--format",
            "csv",
        ],
        &["column 1", "max_misses"],
    );
    // Core: generate() never returns fewer points silently.
    let e = p.generate(64, 0).unwrap_err();
    assert!(
        matches!(e, PatternError::TooFew { requested: 64, .. }),
        "{e:?}"
    );
}

// ---------------------------------------------------------------------------------------------
// Item 10: one rule for exit statuses (bad input 2, environment 1) and messages.

#[test]
fn bad_input_files_exit_2_and_read_errors_of_existing_files_exit_1() {
    let d = dir("exit");
    let out = d.join("out");
    let out = out.to_str().unwrap();
    // A scene that is not UTF-8 text: bad input, as the same fault in a point file is.
    let latin1 = d.join("latin1.ron");
    let mut bytes = samplescope::scene::BUILTIN[0].1.as_bytes().to_vec();
    bytes.splice(0..0, b"// caf\xe9\n".iter().copied());
    std::fs::write(&latin1, &bytes).unwrap();
    refused(
        &["render", latin1.to_str().unwrap(), "--out", out],
        &["latin1.ron", "not UTF-8"],
    );
    let latin1_csv = d.join("latin1.csv");
    std::fs::write(&latin1_csv, b"x,y\n0.5,0.5 \xe9\n").unwrap();
    refused(
        &["analyze", "--points", latin1_csv.to_str().unwrap()],
        &["UTF-8"],
    );
    // A file that does not exist: bad input, named by the user or by a scene.
    let missing = d.join("missing.csv");
    refused(
        &["analyze", "--points", missing.to_str().unwrap()],
        &["missing.csv"],
    );
    refused(
        &[
            "render",
            d.join("missing.ron").to_str().unwrap(),
            "--out",
            out,
        ],
        &["missing.ron"],
    );
    let with_points = d.join("with-points.ron");
    let text = std::fs::read_to_string("tests/data/scene-with-imported-points.ron").unwrap();
    let named = text
        .lines()
        .find_map(|l| l.split("path: \"").nth(1).and_then(|r| r.split('"').next()))
        .expect("the scene names a point file")
        .to_string();
    std::fs::write(&with_points, text.replace(&named, "nowhere.csv")).unwrap();
    refused(
        &["render", with_points.to_str().unwrap(), "--out", out],
        &["nowhere.csv"],
    );
    // A directory where a file is expected: bad input.
    refused(
        &["analyze", "--points", d.to_str().unwrap()],
        &["directory"],
    );
    // An existing file that cannot be read (a directory opened for reading fails with EISDIR
    // only when read: use /proc/self/mem, which exists and fails on read at offset 0).
    let o = samplescope(&["analyze", "--points", "/proc/self/mem"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
}

#[test]
fn a_scene_with_a_byte_order_mark_loads() {
    let text = format!("\u{feff}{}", samplescope::scene::BUILTIN[0].1);
    samplescope::scene::Scene::from_ron(&text, "bom.ron").unwrap();
    let d = dir("bom");
    let path = d.join("bom.ron");
    std::fs::write(&path, &text).unwrap();
    let o = samplescope(&[
        "render",
        path.to_str().unwrap(),
        "--out",
        d.join("out").to_str().unwrap(),
        "--estimate",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Errors after a BOM are placed where an editor shows them: as without the mark.
    let broken = samplescope::scene::BUILTIN[0]
        .1
        .replacen("title:", "title: ]", 1);
    let plain = samplescope::scene::Scene::from_ron(&broken, "s.ron").unwrap_err();
    let marked = samplescope::scene::Scene::from_ron(&format!("\u{feff}{broken}"), "s.ron");
    assert_eq!(marked.unwrap_err().to_string(), plain.to_string());
    assert!(!plain.to_string().starts_with("s.ron:1:1:"), "{plain}");
}

#[test]
fn deep_nesting_is_one_user_facing_line_with_its_place() {
    // A value nested 200 deep where the scene holds a number.
    let deep = format!("k: {}0{}", "[".repeat(200), "]".repeat(200));
    let text = samplescope::scene::BUILTIN[0]
        .1
        .replacen("k: 64.0", &deep, 1);
    assert_ne!(text, samplescope::scene::BUILTIN[0].1);
    let line = 1 + text[..text.find("k: [").unwrap()].matches('\n').count();
    let e = samplescope::scene::Scene::from_ron(&text, "deep.ron")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with(&format!("deep.ron:{line}:")), "{e}");
    assert!(e.contains("nested more than 128 levels"), "{e}");
    assert!(
        !e.contains("serde_stacker") && !e.contains("recursion"),
        "{e}"
    );
    assert!(!e.contains('\n'), "{e}");
}

#[test]
fn messages_name_the_flag_and_print_at_most_six_significant_digits() {
    refused(&["recon", "-n", "64", "--size", "0"], &["--size = 0"]);
    refused(&["recon", "--spp", "0", "--size", "8"], &["--spp = 0"]);
    let d = dir("digits");
    let scene = d.join("s.ron");
    std::fs::write(&scene, samplescope::scene::BUILTIN[0].1).unwrap();
    let e = refused(
        &[
            "render",
            scene.to_str().unwrap(),
            "--out",
            "x",
            "--aspect",
            "1:10.01",
        ],
        &["0.0999001"],
    );
    assert!(!e.contains("0.0999000999"), "{e}");
    // No number in any refusal has more than 6 significant digits.
    for args in [
        vec![
            "render",
            scene.to_str().unwrap(),
            "--out",
            "x",
            "--aspect",
            "1:10.01",
        ],
        vec![
            "points",
            "poisson-bridson",
            "-n",
            "64",
            "--set",
            "radius=1e-9",
        ],
        vec![
            "points",
            "poisson-dart",
            "-n",
            "64",
            "--set",
            "max_misses=1",
        ],
        vec![
            "points",
            "gbn",
            "-n",
            "64",
            "--set",
            "sigma=1.0000000000000002",
        ],
        vec![
            "points",
            "kronecker",
            "-n",
            "4",
            "--set",
            "offset_y=1.0000000000000002",
        ],
    ] {
        let o = samplescope(&args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        for sig in significant_digits(&err) {
            assert!(
                sig <= 6,
                "{args:?}: a number with {sig} significant digits in {err}"
            );
        }
    }
}

/// The significant digits of every decimal number (with a point) in `text`.
fn significant_digits(text: &str) -> Vec<usize> {
    let mut out = Vec::new();
    let mut token = String::new();
    for c in text.chars().chain([' ']) {
        if c.is_ascii_digit() || c == '.' {
            token.push(c);
            continue;
        }
        let t = token.trim_matches('.');
        if t.contains('.') {
            let digits: String = t.chars().filter(char::is_ascii_digit).collect();
            out.push(digits.trim_start_matches('0').trim_end_matches('0').len());
        }
        token.clear();
    }
    out
}

#[test]
fn a_failed_write_of_help_version_or_a_list_exits_1() {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    for args in [
        vec!["--help"],
        vec!["--version"],
        vec!["points", "--help"],
        vec!["points", "--list"],
        vec!["filter", "--list"],
    ] {
        let o = Command::new(env!("CARGO_BIN_EXE_samplescope"))
            .args(&args)
            .stdout(full.try_clone().unwrap())
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert!(
            err.contains("No space left") || err.contains("writing"),
            "{args:?}: {err}"
        );
    }
    // A closed pipe is not a failure: the reader has what it wanted.
    let o = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "'{}' --help | head -c 1 >/dev/null",
            env!("CARGO_BIN_EXE_samplescope")
        ))
        .output()
        .unwrap();
    assert!(o.status.success());
}

#[test]
fn the_gui_column_shows_the_line_instead_of_fewer_points() {
    use egui_kittest::kittest::Queryable;
    let mut h = egui_kittest::Harness::builder()
        .with_size(eframe::egui::Vec2::new(1400.0, 1000.0))
        .wgpu()
        .build_eframe(|cc| crate::hermetic_app(cc));
    crate::settle(&mut h, 1);
    let mut s = samplescope::scene::Scene::builtin_default();
    s.n = 64;
    let mut p = Pattern::from_name("poisson-dart").unwrap();
    p.set("max_misses", "1").unwrap();
    s.columns[0].pattern = p;
    h.state_mut().set_scene(s, "short".into());
    crate::settle(&mut h, 2);
    let points = &h.state().results[0][&samplescope::scene::graph::NodeKind::Points];
    let e = points.value.as_ref().unwrap_err().to_string();
    assert!(
        e.contains("of 64 points") && e.contains("max_misses"),
        "{e}"
    );
    // The pattern panel (and the panels that need the points) show the line.
    let shown = h.query_all_by_label_contains("raise max_misses").count();
    assert!(shown >= 1, "the line is not shown");
    assert!(
        h.query_all_by_label_contains("pattern: poisson-dart: placed")
            .count()
            == 1
    );
}
