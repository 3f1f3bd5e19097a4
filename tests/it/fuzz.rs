//! The fuzz suite: generated command lines and mutated scene texts never panic, never hang, and
//! end with a documented exit status (0, 1 for the environment, 2 for bad input).
//!
//! Both use proptest with a fixed seed (the same cases on every run) and no regression files.
//! Command lines run the real binary with `--budget 2`, so any valid command estimated beyond
//! two seconds is refused at once: the time of each run stays bounded.

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use samplescope::scene::{Scene, BUILTIN};
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn runner(cases: u32, seed: u8) -> TestRunner {
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    )
}

/// Pieces a careless user or an attacker might type.
const VALUES: &[&str] = &[
    "0",
    "1",
    "-1",
    "2",
    "15",
    "64",
    "1000",
    "4096",
    "16777216",
    "16777217",
    "1e308",
    "-1e308",
    "5e-324",
    "NaN",
    "inf",
    "-0",
    "0.5",
    "1.5",
    "abc",
    "",
    " ",
    "=",
    "==",
    "[",
    "[1,2]",
    "[,]",
    "\u{feff}1",
    "é",
    "jitter",
    "hex",
    "sobol",
    "halton",
    "best-candidate",
    "poisson-dart",
    "gaussian",
    "mitchell",
    "windowed-sinc",
    "zone-plate",
    "polygon",
    "sum-of-sines",
    "radial",
    "separable",
    "png",
    "svg,csv",
    "jpeg",
];
const SETTINGS: &[&str] = &[
    "amount=",
    "cols=",
    "m=",
    "radius=",
    "k=",
    "base_x=",
    "base_y=",
    "skip=",
    "scramble=",
    "rows=",
    "dims=",
    "x_dim=",
    "sigma=",
    "b=",
    "c=",
    "window=",
    "beta=",
    "shape=",
    "amps=",
    "freqs=",
    "bogus=",
    "",
    "=",
];
const SUBCOMMANDS: &[&str] = &["points", "analyze", "filter", "recon", "render", "converge"];
const FLAGS: &[&str] = &[
    "-n",
    "--seed",
    "--size",
    "--realizations",
    "--tolerance",
    "--exact",
    "--normalize",
    "--mode",
    "--json",
    "--list",
    "--spp",
    "--signal",
    "--pattern",
    "--filter",
    "--scale",
    "--format",
    "--sphere",
    "--estimate",
    "--points",
    "--out",
    "--spectrum",
    "--raps",
    "--response",
    "--no-cache",
    "--bogus",
];
const SET_FLAGS: &[&str] = &["--set", "--filter-set", "--signal-set"];

/// One argument: a flag with or without a value, a setting, or a bare value.
fn arg() -> impl Strategy<Value = Vec<String>> {
    let value = proptest::sample::select(VALUES).prop_map(str::to_string);
    prop_oneof![
        (proptest::sample::select(FLAGS), value.clone()).prop_map(|(f, v)| vec![f.into(), v]),
        proptest::sample::select(FLAGS).prop_map(|f| vec![f.to_string()]),
        (
            proptest::sample::select(SET_FLAGS),
            proptest::sample::select(SETTINGS),
            value.clone()
        )
            .prop_map(|(f, k, v)| vec![f.into(), format!("{k}{v}")]),
        value.prop_map(|v| vec![v]),
    ]
}

fn command_line() -> impl Strategy<Value = Vec<String>> {
    (
        proptest::sample::select(SUBCOMMANDS),
        proptest::sample::select(VALUES),
        proptest::collection::vec(arg(), 0..6),
    )
        .prop_map(|(sub, first, rest)| {
            let mut v = vec![sub.to_string(), first.to_string()];
            v.extend(rest.into_iter().flatten());
            v
        })
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("samplescope-fuzz-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the binary in `dir` (relative outputs land there), killing it after `limit`.
fn run(dir: &PathBuf, args: &[String], limit: Duration) -> Result<(Option<i32>, String), String> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .arg("--budget")
        .arg("2")
        .args(args)
        .current_dir(dir)
        .env("DISPLAY", "")
        .env("WAYLAND_DISPLAY", "")
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            let mut err = String::new();
            if let Some(mut s) = child.stderr.take() {
                use std::io::Read;
                let _ = s.read_to_string(&mut err);
            }
            return Ok((status.code(), err));
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("still running after {limit:?}"));
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn generated_command_lines_end_with_a_documented_status_and_never_panic() {
    let dir = temp_dir("cli");
    std::fs::write(dir.join("scene.ron"), BUILTIN[0].1).unwrap();
    let statuses = std::cell::RefCell::new(std::collections::BTreeMap::new());
    runner(160, 7)
        .run(&command_line(), |args| {
            let (code, err) = run(&dir, &args, Duration::from_secs(30))
                .map_err(|e| TestCaseError::fail(format!("{args:?}: {e}")))?;
            *statuses.borrow_mut().entry(code).or_insert(0) += 1;
            prop_assert!(
                matches!(code, Some(0) | Some(1) | Some(2)),
                "{args:?}: status {code:?}\n{err}"
            );
            prop_assert!(!err.contains("panicked"), "{args:?}: {err}");
            if code != Some(0) {
                // Errors are short: at most a usage block from clap or one line of ours.
                prop_assert!(err.len() < 4000, "{args:?}: {} bytes on stderr", err.len());
            }
            Ok(())
        })
        .unwrap();
    // The generator reaches both success and refusal.
    assert!(
        statuses.borrow().get(&Some(2)).copied().unwrap_or(0) > 20,
        "{:?}",
        statuses.borrow()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A shipped scene text with a few random edits: spans deleted, duplicated or replaced by
/// tokens that break the syntax or push a value out of range.
fn mutated_scene() -> impl Strategy<Value = String> {
    const TOKENS: &[&str] = &[
        "(",
        ")",
        "[",
        "]",
        "{",
        "}",
        ",",
        ":",
        "\"",
        "'",
        "r#\"",
        "//",
        "/*",
        "Some(",
        "None",
        "1e999",
        "-1",
        "NaN",
        "0",
        "4294967296",
        "18446744073709551616",
        "kind: \"hex\"",
        "kind: \"jiter\"",
        "n: 0",
        "n: 16777216",
        "size: 1",
        "spp: 5000",
        "points: Some((path: \"/dev/zero\"))",
        "elementary_k: Some(99)",
        "\u{0}",
        "é",
        "\u{feff}",
        "true",
        "false",
        "mode: radial",
    ];
    let n = BUILTIN.len();
    (
        0..n,
        proptest::collection::vec(
            (
                0usize..10_000,
                0usize..40,
                0usize..3,
                proptest::sample::select(TOKENS),
            ),
            1..4,
        ),
    )
        .prop_map(move |(i, edits)| {
            let mut text: Vec<char> = BUILTIN[i].1.chars().collect();
            for (at, len, op, token) in edits {
                let at = at % (text.len() + 1);
                let end = (at + len).min(text.len());
                match op {
                    0 => {
                        text.drain(at..end);
                    }
                    1 => {
                        let span: Vec<char> = text[at..end].to_vec();
                        for (k, c) in span.into_iter().enumerate() {
                            text.insert(at + k, c);
                        }
                    }
                    _ => {
                        text.splice(at..end, token.chars());
                    }
                }
            }
            text.into_iter().collect()
        })
}

#[test]
fn mutated_scene_texts_load_or_fail_cleanly_and_quickly() {
    let loaded = std::cell::Cell::new(0);
    let refused = std::cell::Cell::new(0);
    runner(400, 11)
        .run(&mutated_scene(), |text| {
            let start = Instant::now();
            match Scene::from_ron(&text, "fuzz.ron") {
                Ok(scene) => {
                    loaded.set(loaded.get() + 1);
                    // A scene that loads is valid, has a finite cost estimate, and survives
                    // its own text.
                    scene
                        .validate("fuzz.ron")
                        .map_err(|e| TestCaseError::fail(e.to_string()))?;
                    let plan = samplescope::scene::cost::estimate(&scene);
                    prop_assert!(plan.iter().all(|e| e.seconds >= 0.0 && e.bytes >= 0.0));
                    let again = Scene::from_ron(&scene.to_ron(), "again.ron")
                        .map_err(|e| TestCaseError::fail(format!("round trip: {e}")))?;
                    prop_assert_eq!(again, scene);
                }
                Err(e) => {
                    refused.set(refused.get() + 1);
                    let msg = e.to_string();
                    prop_assert!(msg.starts_with("fuzz.ron"), "{msg}");
                    prop_assert!(!msg.contains('\n'), "one line: {msg}");
                }
            }
            prop_assert!(
                start.elapsed() < Duration::from_secs(2),
                "took {:?}",
                start.elapsed()
            );
            Ok(())
        })
        .unwrap();
    assert!(
        loaded.get() > 10 && refused.get() > 100,
        "loaded {}, refused {}",
        loaded.get(),
        refused.get()
    );
}

/// One argument group (a flag and its value stay together).
fn group(words: &[&str]) -> Vec<String> {
    words.iter().map(|w| w.to_string()).collect()
}

/// A command line that asks for something impossible or pointless: options that would have no
/// effect together, a key set twice, a seed for a deterministic pattern, `--allow-fewer` for a
/// pattern that never stops short, an N the pattern refuses hidden behind `--estimate` or a tiny
/// `--budget`. With the word its refusal must name. The groups come in random order.
fn invalid_combination() -> impl Strategy<Value = (Vec<String>, String)> {
    use proptest::sample::select;
    let seed = (0u64..1000).prop_map(|s| s.to_string());
    let deterministic = select(
        &[
            "grid",
            "halton",
            "hammersley",
            "van-der-corput",
            "kronecker",
        ][..],
    );
    let random = select(
        &[
            "random",
            "jitter",
            "nrooks",
            "best-candidate",
            "pmj02",
            "lhs",
        ][..],
    );
    const LIST_EXTRA: &[&[&str]] = &[
        &["jitter"],
        &["-n", "16"],
        &["--seed", "2"],
        &["--set", "amount=0.5"],
        &["--out", "x.csv"],
        &["--sphere"],
        &["--allow-fewer"],
        &["--estimate"],
        &["--budget", "9"],
    ];
    const FILTER_LIST_EXTRA: &[&[&str]] = &[
        &["gaussian"],
        &["--set", "radius=1"],
        &["--mode", "radial"],
        &["--response", "r.csv"],
        &["--json"],
        &["--budget-memory", "1"],
    ];
    // (subcommand words, flag, key, two values)
    type Twice = (
        &'static [&'static str],
        &'static str,
        &'static str,
        &'static str,
        &'static str,
    );
    const TWICE: &[Twice] = &[
        (
            &["points", "jitter", "-n", "16"],
            "--set",
            "amount",
            "0.5",
            "0.25",
        ),
        (&["filter", "mitchell"], "--set", "b", "0.1", "0.2"),
        (
            &["recon", "-n", "64", "--size", "8"],
            "--signal-set",
            "k",
            "100",
            "200",
        ),
        (
            &["recon", "-n", "64", "--size", "8"],
            "--filter-set",
            "sigma",
            "0.4",
            "0.5",
        ),
        (
            &["analyze", "halton", "-n", "16"],
            "--set",
            "base_x",
            "2",
            "5",
        ),
    ];
    let short_free = select(&["jitter", "grid", "sobol", "best-candidate", "halton"][..]);
    const BAD_N: &[(&[&str], &str)] = &[
        (&["fibonacci", "1000"], "n = 1000"),
        (&["hex", "63"], "n = 63"),
        (&["fibonacci", "4"], "n = 4"),
        (&["rank1", "1"], "n = 1"),
    ];
    const HIDE: &[&[&str]] = &[
        &["--estimate"],
        &["--budget", "1e-9"],
        &["--budget-memory", "1e-12"],
    ];
    let (list_extra, filter_list_extra) = (select(LIST_EXTRA), select(FILTER_LIST_EXTRA));
    let (twice, bad_n, hide) = (select(TWICE), select(BAD_N), select(HIDE));
    prop_oneof![
        list_extra.prop_map(|e| {
            let w = if e[0].starts_with("--") {
                e[0]
            } else {
                "--list"
            };
            (vec![group(&["points", "--list"]), group(e)], w.to_string())
        }),
        filter_list_extra.prop_map(|e| {
            let w = if e[0].starts_with("--") {
                e[0]
            } else {
                "--list"
            };
            (vec![group(&["filter", "--list"]), group(e)], w.to_string())
        }),
        twice.prop_map(|(base, flag, key, a, b)| (
            vec![
                group(base),
                group(&[flag, &format!("{key}={a}")]),
                group(&[flag, &format!("{key}={b}")]),
            ],
            "twice".to_string()
        )),
        (
            deterministic,
            seed.clone(),
            select(&["points", "analyze"][..])
        )
            .prop_map(|(p, s, sub)| (
                vec![group(&[sub, p, "-n", "16"]), group(&["--seed", &s])],
                format!("--seed {s}")
            )),
        (random, seed).prop_map(|(p, s)| (
            vec![
                group(&[
                    "converge",
                    "--pattern",
                    p,
                    "--integrand",
                    "disk",
                    "--n",
                    "16"
                ]),
                group(&["--realizations", "2"]),
                group(&["--no-shift"]),
                group(&["--seed", &s]),
            ],
            "--no-shift".to_string()
        )),
        short_free.prop_map(|p| (
            vec![group(&["points", p, "-n", "16"]), group(&["--allow-fewer"])],
            "--allow-fewer".to_string()
        )),
        (bad_n, hide, select(&["points", "analyze"][..])).prop_map(|((pn, word), h, sub)| (
            vec![group(&[sub, pn[0], "-n", pn[1]]), group(h)],
            word.to_string()
        )),
    ]
    .prop_flat_map(|(groups, word)| {
        // The first group holds the subcommand; the others may come in any order.
        let first = groups[0].clone();
        let rest = groups[1..].to_vec();
        (Just(first), Just(rest).prop_shuffle(), Just(word))
    })
    .prop_map(|(first, rest, word)| {
        let mut args = first;
        args.extend(rest.into_iter().flatten());
        (args, word)
    })
}

#[test]
fn conflicting_and_pointless_options_are_refused_with_one_line_naming_them() {
    let dir = temp_dir("combos");
    runner(60, 13)
        .run(&invalid_combination(), |(args, word)| {
            let mut child = Command::new(env!("CARGO_BIN_EXE_samplescope"));
            child.args(&args).current_dir(&dir).stdin(Stdio::null());
            let o = child
                .output()
                .map_err(|e| TestCaseError::fail(e.to_string()))?;
            let err = String::from_utf8_lossy(&o.stderr);
            prop_assert_eq!(o.status.code(), Some(2), "{:?}: {}", args, err);
            prop_assert!(o.stdout.is_empty(), "{:?}: wrote to stdout", args);
            let first = err.lines().next().unwrap_or_default();
            prop_assert!(
                first.contains(&word),
                "{:?}: {:?} not in {:?}",
                args,
                word,
                first
            );
            prop_assert!(!err.contains("panicked"), "{:?}: {}", args, err);
            Ok(())
        })
        .unwrap();
    // Nothing was written by a refused command.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Where a generated output path leads.
#[derive(Debug, Clone, Copy, PartialEq)]
enum OutKind {
    New,
    Existing,
    Link,
    LinkToLink,
    Dangling,
    LinkToDevNull,
    DevNull,
    Dash,
    Fifo,
    Directory,
    MissingDir,
    LinkToDir,
}

const OUT_KINDS: &[OutKind] = &[
    OutKind::New,
    OutKind::Existing,
    OutKind::Link,
    OutKind::LinkToLink,
    OutKind::Dangling,
    OutKind::LinkToDevNull,
    OutKind::DevNull,
    OutKind::Dash,
    OutKind::Fifo,
    OutKind::Directory,
    OutKind::MissingDir,
    OutKind::LinkToDir,
];

/// Commands that write one output: the arguments before the path, and its flag.
const WRITERS: &[(&[&str], &str)] = &[
    (&["points", "grid", "-n", "16"], "--out"),
    (&["points", "sobol", "-n", "64", "--sphere"], "--out"),
    (&["filter", "box"], "--response"),
    (&["analyze", "grid", "-n", "64"], "--raps"),
    (&["analyze", "jitter", "-n", "64"], "--spectrum"),
    (
        &[
            "converge",
            "--pattern",
            "random",
            "--integrand",
            "disk",
            "--n",
            "16",
            "--realizations",
            "4",
        ],
        "--csv",
    ),
    (&["recon", "-n", "256", "--size", "32"], "--out"),
];

/// Makes the output of `kind` in `dir`: the path to pass, and the regular file it should
/// write when it writes one.
#[cfg(unix)]
fn make_output(dir: &std::path::Path, kind: OutKind) -> (String, Option<PathBuf>) {
    use std::os::unix::fs::symlink;
    let target = dir.join("target.out");
    match kind {
        OutKind::New => ("target.out".into(), Some(target)),
        OutKind::Existing => {
            std::fs::write(&target, "old").unwrap();
            ("target.out".into(), Some(target))
        }
        OutKind::Link => {
            std::fs::write(&target, "old").unwrap();
            symlink("target.out", dir.join("link")).unwrap();
            ("link".into(), Some(target))
        }
        OutKind::LinkToLink => {
            std::fs::write(&target, "old").unwrap();
            symlink("target.out", dir.join("link")).unwrap();
            symlink(dir.join("link"), dir.join("link2")).unwrap();
            ("link2".into(), Some(target))
        }
        OutKind::Dangling => {
            symlink("target.out", dir.join("link")).unwrap();
            ("link".into(), None)
        }
        OutKind::LinkToDevNull => {
            symlink("/dev/null", dir.join("link")).unwrap();
            ("link".into(), None)
        }
        OutKind::DevNull => ("/dev/null".into(), None),
        OutKind::Dash => ("-".into(), None),
        OutKind::Fifo => {
            let ok = Command::new("mkfifo")
                .arg(dir.join("fifo"))
                .status()
                .unwrap();
            assert!(ok.success());
            ("fifo".into(), None)
        }
        OutKind::Directory => {
            std::fs::create_dir(dir.join("sub")).unwrap();
            ("sub".into(), None)
        }
        OutKind::MissingDir => ("no/such/dir/out".into(), None),
        OutKind::LinkToDir => {
            std::fs::create_dir(dir.join("sub")).unwrap();
            symlink("sub", dir.join("link")).unwrap();
            ("link".into(), None)
        }
    }
}

/// Links, FIFOs, devices, `-`, directories and missing directories as the output of every
/// command that writes one: the command succeeds or fails with 1 or 2, a link stays a link
/// (its target written), a FIFO stays a FIFO (its reader gets the data), a device stays a
/// device, and no partial file is ever left.
#[cfg(unix)]
#[test]
fn generated_outputs_through_links_fifos_and_devices_never_replace_them() {
    use std::os::unix::fs::FileTypeExt;
    let base = temp_dir("outputs");
    let case = std::cell::Cell::new(0);
    runner(48, 23)
        .run(
            &(
                proptest::sample::select(WRITERS),
                proptest::sample::select(OUT_KINDS),
            ),
            |((args, flag), kind)| {
                case.set(case.get() + 1);
                let dir = base.join(case.get().to_string());
                std::fs::create_dir_all(&dir).unwrap();
                let (path, file) = make_output(&dir, kind);
                // A FIFO's reader, released at the end if the command never opened it.
                let reader = (kind == OutKind::Fifo).then(|| {
                    let fifo = dir.join("fifo");
                    std::thread::spawn(move || std::fs::read(fifo).map(|b| b.len()).unwrap_or(0))
                });
                let mut cmd: Vec<String> = args.iter().map(|s| s.to_string()).collect();
                cmd.extend([flag.to_string(), path.clone()]);
                let (code, err) = run(&dir, &cmd, Duration::from_secs(60))
                    .map_err(|e| TestCaseError::fail(format!("{cmd:?}: {e}")))?;
                let read = reader.map(|r| {
                    use std::os::unix::fs::OpenOptionsExt;
                    // O_NONBLOCK: opens only if the reader still waits, and so releases it.
                    let _ = std::fs::OpenOptions::new()
                        .write(true)
                        .custom_flags(0o4000)
                        .open(dir.join("fifo"));
                    r.join().unwrap()
                });
                prop_assert!(
                    matches!(code, Some(0) | Some(1) | Some(2)),
                    "{cmd:?}: {code:?} {err}"
                );
                prop_assert!(!err.contains("panicked"), "{cmd:?}: {err}");
                let expected_ok = !matches!(
                    kind,
                    OutKind::Dangling
                        | OutKind::Directory
                        | OutKind::MissingDir
                        | OutKind::LinkToDir
                );
                prop_assert_eq!(
                    code == Some(0),
                    expected_ok,
                    "{:?} {:?}: {}",
                    cmd,
                    kind,
                    err
                );
                if !expected_ok {
                    prop_assert_eq!(code, Some(1), "{:?}: {}", cmd, err);
                    prop_assert!(err.lines().count() == 1 && err.contains(flag), "{err}");
                }
                for l in ["link", "link2"] {
                    let p = dir.join(l);
                    if p.exists() || std::fs::symlink_metadata(&p).is_ok() {
                        prop_assert!(std::fs::symlink_metadata(&p)
                            .unwrap()
                            .file_type()
                            .is_symlink());
                    }
                }
                if let Some(f) = &file {
                    let len = std::fs::metadata(f).map(|m| m.len()).unwrap_or(0);
                    prop_assert!(len > 3, "{cmd:?}: {} holds {len} bytes", f.display());
                }
                if kind == OutKind::Dangling {
                    prop_assert!(!dir.join("target.out").exists(), "no target made");
                }
                if let Some(n) = read {
                    prop_assert!(n > 0, "{cmd:?}: the FIFO's reader got nothing");
                    let t = std::fs::symlink_metadata(dir.join("fifo"))
                        .unwrap()
                        .file_type();
                    prop_assert!(t.is_fifo());
                }
                prop_assert!(std::fs::metadata("/dev/null")
                    .unwrap()
                    .file_type()
                    .is_char_device());
                let partial: Vec<String> = walk(&dir)
                    .into_iter()
                    .filter(|n| n.ends_with(".partial"))
                    .collect();
                prop_assert!(partial.is_empty(), "{cmd:?}: {partial:?}");
                Ok(())
            },
        )
        .unwrap();
    let _ = std::fs::remove_dir_all(&base);
}

/// The exit code of `child` if it ends within `limit`; else it is killed and `None`.
fn wait_at_most(mut child: std::process::Child, limit: Duration) -> Option<Option<i32>> {
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(s)) => return Some(s.code()),
            Ok(None) if start.elapsed() <= limit => std::thread::sleep(Duration::from_millis(10)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                return None;
            }
        }
    }
}

/// Every file name under `dir`, recursively (links not followed).
fn walk(dir: &std::path::Path) -> Vec<String> {
    let mut out = Vec::new();
    if let Ok(rd) = std::fs::read_dir(dir) {
        for e in rd.flatten() {
            out.push(e.file_name().to_string_lossy().into_owned());
            if e.file_type().is_ok_and(|t| t.is_dir()) {
                out.extend(walk(&e.path()));
            }
        }
    }
    out
}

/// Long commands, each stopped by SIGTERM or SIGINT after a generated delay: every one ends
/// within a few seconds of the signal with 143 or 130, and leaves no file (whole or partial)
/// in its directory. The families: a read blocked on a FIFO (a point file, a scene's point
/// file), a long generation, a long reconstruction, a long render (figures being drawn).
#[cfg(unix)]
#[test]
fn generated_signals_end_every_long_command_promptly_with_no_file() {
    const LONG: &[&[&str]] = &[
        &["analyze", "--points", "fifo", "--raps", "r.csv"],
        &["render", "fifo.ron", "--out", "figs"],
        &["points", "best-candidate", "-n", "40000", "--out", "o.csv"],
        &[
            "recon", "-n", "2000000", "--size", "2048", "--filter", "lanczos", "--out", "o.png",
        ],
        &[
            "render",
            "big.ron",
            "--out",
            "figs",
            "--scale",
            "4",
            "--format",
            "png,svg,pdf",
            "--no-cache",
        ],
    ];
    let base = temp_dir("signals");
    let case = std::cell::Cell::new(0);
    runner(10, 31)
        .run(
            &(
                proptest::sample::select(LONG),
                proptest::sample::select(&[("TERM", 143), ("INT", 130)][..]),
                100u64..1500,
            ),
            |(args, (sig, status), delay)| {
                case.set(case.get() + 1);
                let dir = base.join(case.get().to_string());
                std::fs::create_dir_all(&dir).unwrap();
                let ok = Command::new("mkfifo")
                    .arg(dir.join("fifo"))
                    .status()
                    .unwrap();
                prop_assert!(ok.success());
                std::fs::write(
                    dir.join("fifo.ron"),
                    "(columns: [(points: Some((path: \"fifo\")))], n: 16)",
                )
                .unwrap();
                std::fs::write(
                    dir.join("big.ron"),
                    "(columns: [(pattern: (kind: \"random\"))], n: 1048576, \
                     panels: (pattern: true, spectrum: false, zoneplate: false, filter: false))",
                )
                .unwrap();
                let before = walk(&dir);
                let child = Command::new(env!("CARGO_BIN_EXE_samplescope"))
                    .args(["--budget", "100000"])
                    .args(args)
                    .current_dir(&dir)
                    .env("SAMPLESCOPE_CACHE_DIR", dir.join("cache"))
                    .stdin(Stdio::null())
                    .stdout(Stdio::null())
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap();
                std::thread::sleep(Duration::from_millis(delay));
                let sent = Instant::now();
                let kill = Command::new("kill")
                    .args([format!("-{sig}"), child.id().to_string()])
                    .status()
                    .is_ok_and(|s| s.success());
                let Some(code) = wait_at_most(child, Duration::from_secs(10)) else {
                    return Err(TestCaseError::fail(format!(
                        "{args:?}: running 10 s after SIG{sig}"
                    )));
                };
                prop_assert!(kill, "kill -{sig} failed");
                let took = sent.elapsed();
                prop_assert_eq!(
                    code,
                    Some(status),
                    "{:?} SIG{} after {} ms",
                    args,
                    sig,
                    delay
                );
                prop_assert!(
                    took < Duration::from_secs(3),
                    "{args:?}: ended {took:?} after"
                );
                let mut after = walk(&dir);
                after.retain(|n| !n.starts_with("cache") && !n.ends_with(".sscache"));
                let mut before = before;
                before.retain(|n| !n.starts_with("cache"));
                after.sort();
                before.sort();
                prop_assert_eq!(after, before, "{:?}: files left", args);
                Ok(())
            },
        )
        .unwrap();
    let _ = std::fs::remove_dir_all(&base);
}

/// Scene text fields of generated lengths and alphabets (words, one long word, multi-byte
/// and combining characters): within its documented limit a field loads and its title lays
/// out in two lines that fit, quickly; beyond it the scene is refused with one line naming
/// the field, its length and the limit.
#[test]
fn generated_long_scene_text_is_laid_out_quickly_or_refused_in_one_line() {
    use samplescope::scene::limits;
    const ALPHABETS: &[&str] = &["word ", "x", "é", "e\u{301}", "Φ_p1 ", "\u{200b}"];
    let fields: &[(&str, usize)] = &[
        ("title", limits::TITLE_CHARS),
        ("notes", limits::NOTES_CHARS),
        ("label", limits::LABEL_CHARS),
    ];
    runner(60, 41)
        .run(
            &(
                proptest::sample::select(fields),
                proptest::sample::select(ALPHABETS),
                prop_oneof![0usize..4, 0usize..=1, Just(100_000usize)],
                -2i64..3,
            ),
            |((field, max), alphabet, pick, delta)| {
                let len = match pick {
                    100_000 => 100_000,
                    0 | 1 => (max as i64 + delta).max(0) as usize,
                    _ => (max as i64 * (pick as i64 + 1) + delta).max(0) as usize,
                };
                let text: String = alphabet.chars().cycle().take(len).collect();
                let chars = text.chars().count();
                let ron = match field {
                    "label" => format!("(columns: [(label: \"{text}\")])"),
                    f => format!("({f}: \"{text}\")"),
                };
                let start = Instant::now();
                let loaded = Scene::from_ron(&ron, "long.ron");
                match &loaded {
                    Ok(scene) => {
                        prop_assert!(chars <= max, "{field}: {chars} characters accepted");
                        let lines = samplescope::export::figure::wrap(&scene.title, 1600, 32.0, 2);
                        prop_assert!(lines.len() <= 2);
                        for l in &lines {
                            prop_assert!(samplescope::export::figure::text_width(l, 32.0) <= 1600);
                        }
                    }
                    Err(e) => {
                        let msg = e.to_string();
                        prop_assert!(chars > max, "{field}: {chars} characters refused: {msg}");
                        prop_assert!(msg.starts_with("long.ron:1:"), "{msg}");
                        prop_assert!(
                            msg.contains(&format!("must be at most {max} characters")),
                            "{msg}"
                        );
                        prop_assert!(!msg.contains('\n') && msg.len() < 200, "{msg}");
                    }
                }
                prop_assert!(
                    start.elapsed() < Duration::from_secs(2),
                    "{field} of {chars}: {:?}",
                    start.elapsed()
                );
                Ok(())
            },
        )
        .unwrap();
}

/// A point file in one of the formats peers write, then mutated: `.npy` files with their
/// header edited, a byte flipped, the header length changed or the data cut; PSA `.rps` cut at
/// any byte; text rows with mixed separators (comma, spaces, tabs, semicolons), pmj-cpp's
/// `(x, y),` wrappers, headers and count lines, under any extension.
fn mutated_point_file() -> impl Strategy<Value = (String, Vec<u8>)> {
    const HEADER_TOKENS: &[&str] = &[
        "'<f8'",
        "'<f4'",
        "'>f8'",
        "'<i8'",
        "'|u1'",
        "True",
        "False",
        "(16, 2)",
        "(3,)",
        "(16, 2, 1)",
        "()",
        "(99999999999999999999, 2)",
        "(-1, 2)",
        "'shape'",
        "'descr'",
        "'fortran_order'",
        "{",
        "}",
        ",",
        ":",
        "'",
        "\0",
        "é",
    ];
    const NUMBERS: &[&str] = &[
        "0",
        "0.5",
        "0.25",
        "1",
        "1.0",
        "1.0000000000000002",
        "-0",
        "-0.0",
        "0.999999999999",
        "1e-300",
        "nan",
        "inf",
        "-1",
        "2",
        "abc",
        "",
        "0x1",
        "5e-324",
    ];
    const SEPARATORS: &[&str] = &[",", " ", "\t", ", ", " ,", ";", "  ", ",,", " \t "];
    const FIRST_LINES: &[&str] = &[
        "",
        "x,y\n",
        "x y\n",
        "X\tY\n",
        "\"x\",\"y\"\n",
        "# comment\n",
        "3\n",
        "2\n",
        "x,y,z\n",
        "\u{feff}x,y\n",
        "(x, y)\n",
    ];
    let npy = (
        proptest::collection::vec((0.0f64..1.0, 0.0f64..1.0), 1..20),
        any::<bool>(),
        any::<bool>(),
        1u8..4,
        proptest::collection::vec(
            (
                0usize..400,
                0usize..12,
                0usize..4,
                proptest::sample::select(HEADER_TOKENS),
            ),
            0..3,
        ),
    )
        .prop_map(|(points, f32s, fortran, version, edits)| {
            let descr = if f32s { "<f4" } else { "<f8" };
            let header = format!(
                "{{'descr': '{descr}', 'fortran_order': {}, 'shape': ({}, 2), }}",
                if fortran { "True" } else { "False" },
                points.len()
            );
            let mut bytes = b"\x93NUMPY".to_vec();
            bytes.extend_from_slice(&[version, 0]);
            if version == 1 {
                bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
            } else {
                bytes.extend_from_slice(&(header.len() as u32).to_le_bytes());
            }
            let header_start = bytes.len();
            bytes.extend_from_slice(header.as_bytes());
            let values: Vec<f64> = if fortran {
                points
                    .iter()
                    .map(|p| p.0)
                    .chain(points.iter().map(|p| p.1))
                    .collect()
            } else {
                points.iter().flat_map(|p| [p.0, p.1]).collect()
            };
            for v in values {
                if f32s {
                    bytes.extend_from_slice(&(v as f32).to_le_bytes());
                } else {
                    bytes.extend_from_slice(&v.to_le_bytes());
                }
            }
            for (at, len, op, token) in edits {
                match op {
                    // Replace a span of the header by a token.
                    0 => {
                        let end = (header_start + header.len()).min(bytes.len());
                        let a = (header_start + at % header.len()).min(end);
                        let b = (a + len).min(end);
                        bytes.splice(a..b, token.bytes());
                    }
                    // Flip a byte anywhere.
                    1 => {
                        let a = at % bytes.len();
                        bytes[a] ^= 1 << (len % 8);
                    }
                    // Cut the file.
                    2 => bytes.truncate(at % (bytes.len() + 1)),
                    // Change the header length.
                    _ => {
                        if bytes.len() > 9 {
                            bytes[8] = (at % 256) as u8;
                        }
                    }
                }
            }
            ("f.npy".to_string(), bytes)
        });
    let rps = (
        proptest::collection::vec(
            prop_oneof![
                0.0f32..1.0,
                Just(1.0f32),
                Just(f32::NAN),
                Just(-0.0f32),
                Just(1.5f32),
                Just(f32::INFINITY)
            ],
            0..40,
        ),
        0usize..400,
    )
        .prop_map(|(values, cut)| {
            let mut bytes: Vec<u8> = values.iter().flat_map(|v| v.to_le_bytes()).collect();
            bytes.truncate(cut.min(bytes.len()));
            ("f.rps".to_string(), bytes)
        });
    let text = (
        proptest::sample::select(FIRST_LINES),
        proptest::collection::vec(
            (
                proptest::sample::select(NUMBERS),
                proptest::sample::select(SEPARATORS),
                proptest::sample::select(NUMBERS),
                0usize..4,
                proptest::sample::select(&["\n", "\r\n", "\n\n", "\n# c\n"][..]),
            ),
            0..12,
        ),
        proptest::sample::select(&["txt", "csv", "tsv", "dat", "npy", "rps", ""][..]),
    )
        .prop_map(|(first, rows, ext)| {
            let mut s = first.to_string();
            for (x, sep, y, wrap, end) in rows {
                let row = format!("{x}{sep}{y}");
                s += &match wrap {
                    0 => row,
                    1 => format!("({row}),"),
                    2 => format!("[{row}]"),
                    _ => format!("({row}"),
                };
                s += end;
            }
            (format!("f.{ext}"), s.into_bytes())
        });
    prop_oneof![npy, rps, text]
}

#[test]
fn mutated_point_files_in_peer_formats_read_or_fail_in_one_line() {
    use samplescope::core::pointset::{read_points_named, OutOfRange};
    let read = std::cell::Cell::new(0);
    let refused = std::cell::Cell::new(0);
    runner(1500, 13)
        .run(
            &(mutated_point_file(), any::<bool>()),
            |((name, bytes), normalize)| {
                let mode = if normalize {
                    OutOfRange::NormalizeToBoundingBox
                } else {
                    OutOfRange::Reject
                };
                let start = Instant::now();
                match read_points_named(&bytes[..], std::path::Path::new(&name), mode) {
                    Ok(r) => {
                        read.set(read.get() + 1);
                        prop_assert!(!r.points.is_empty());
                        prop_assert!(
                            r.points
                                .iter()
                                .all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)),
                            "{name}: {:?}",
                            r.points
                        );
                    }
                    Err(e) => {
                        refused.set(refused.get() + 1);
                        let msg = e.to_string();
                        prop_assert!(!msg.contains('\n'), "{name}: one line: {msg:?}");
                        prop_assert!(!msg.is_empty());
                    }
                }
                prop_assert!(start.elapsed() < Duration::from_secs(2));
                Ok(())
            },
        )
        .unwrap();
    assert!(
        read.get() > 100 && refused.get() > 300,
        "read {}, refused {}",
        read.get(),
        refused.get()
    );
}
