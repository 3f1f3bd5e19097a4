//! Bad input never hurts: binary, endless and malformed files are refused quickly with an
//! error naming the file and the first bad line or byte.

use samplescope::core::pointset::{read_points_file, OutOfRange, PointsFileError};
use samplescope::scene::{Scene, SceneError};
use std::path::Path;
use std::time::{Duration, Instant};

fn quick<T>(f: impl FnOnce() -> T) -> T {
    let t = Instant::now();
    let out = f();
    // Generous for a loaded CI machine; an unbounded read of /dev/zero takes minutes.
    assert!(
        t.elapsed() < Duration::from_secs(5),
        "took {:?}",
        t.elapsed()
    );
    out
}

#[test]
fn scene_from_dev_zero_and_dev_urandom_is_refused_at_the_first_block() {
    for (dev, what) in [("/dev/zero", "NUL byte"), ("/dev/urandom", "")] {
        let e = quick(|| Scene::load(Path::new(dev))).unwrap_err();
        match &e {
            // Not a scene's text: bad input (exit status 2), not an environment failure.
            SceneError::File { path, message } => {
                assert!(!e.is_environment());
                assert_eq!(path, dev);
                assert!(
                    message.contains(what) && message.contains("byte"),
                    "{message}"
                );
                assert!(message.contains("not a scene file"), "{message}");
            }
            other => panic!("{dev}: {other:?}"),
        }
    }
}

#[test]
fn scene_with_a_character_split_across_read_blocks_loads() {
    // A 64 KiB block boundary inside a two-byte character (é) must not be taken for bad UTF-8.
    let base = samplescope::scene::BUILTIN[0].1;
    let pad = 64 * 1024 - 1 - base.len() % (64 * 1024);
    let text = format!("{base}\n//{}é\n", "x".repeat(pad.saturating_sub(3)));
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bad_input");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("split-char.ron");
    std::fs::write(&path, &text).unwrap();
    Scene::load(&path).unwrap();
    // The same file cut inside the character is refused, naming the byte.
    let cut = &text.as_bytes()[..text.len() - 2];
    std::fs::write(&path, cut).unwrap();
    match Scene::load(&path) {
        Err(SceneError::File { message, .. }) => {
            assert!(message.contains("ends inside"), "{message}")
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn point_files_from_dev_zero_and_dev_urandom_are_refused_at_once() {
    let e = quick(|| read_points_file(Path::new("/dev/zero"), OutOfRange::Reject)).unwrap_err();
    assert!(
        matches!(e, PointsFileError::LineTooLong { line: 1, .. }),
        "{e:?}"
    );
    let e = quick(|| read_points_file(Path::new("/dev/urandom"), OutOfRange::Reject)).unwrap_err();
    assert!(
        matches!(
            e,
            PointsFileError::NotUtf8 { .. }
                | PointsFileError::LineTooLong { .. }
                | PointsFileError::Malformed { .. }
        ),
        "{e:?}"
    );
}

/// The printing commands, each with arguments that print something.
const PRINTING: &[&[&str]] = &[
    &["analyze", "jitter", "-n", "64", "--size", "32"],
    &["filter", "box"],
    &["filter", "--list"],
    &["points", "--list"],
    &["points", "jitter", "-n", "64"],
    &["recon", "--pattern", "jitter", "-n", "64", "--size", "32"],
];

#[test]
fn a_closed_pipe_ends_every_printing_command_quietly() {
    for args in PRINTING {
        // The reading end is closed as soon as the command starts, long before it prints
        // (it parses its arguments and computes first).
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
            .args(*args)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(stderr.trim().is_empty(), "{args:?}: {stderr}");
    }
}

#[test]
fn a_full_disk_is_one_line_and_status_1() {
    for args in PRINTING {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
            .args(*args)
            .stdout(full)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert_eq!(stderr.trim().lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains("No space left"), "{args:?}: {stderr}");
    }
}

/// The error a bad file gives, on one line: scene errors name the file themselves, point-file
/// errors get it prefixed as every caller does.
fn error_of(path: &Path) -> String {
    let name = path.to_str().unwrap();
    if name.ends_with(".ron") {
        match Scene::load(path) {
            Ok(_) => "loaded".into(),
            Err(e) => e.to_string(),
        }
    } else {
        match read_points_file(path, OutOfRange::Reject) {
            Ok(p) => format!("loaded {} points", p.len()),
            Err(e) => format!("{name}: {e}"),
        }
    }
}

/// `tests/data/bad/`: malformed scene and point files, each beside `<file>.err`, the one-line
/// error it must give. `UPDATE_BAD_CORPUS=1` rewrites the `.err` files (review the diff).
#[test]
fn corpus_of_bad_files_gives_the_expected_one_line_errors() {
    let dir = Path::new("tests/data/bad");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e != "err"))
        .collect();
    files.sort();
    assert!(files.len() >= 15, "the corpus holds {} files", files.len());
    let update = std::env::var_os("UPDATE_BAD_CORPUS").is_some();
    let mut failures = Vec::new();
    for f in &files {
        let got = quick(|| error_of(f));
        assert!(!got.starts_with("loaded"), "{}: {got}", f.display());
        assert_eq!(got.lines().count(), 1, "{}: {got}", f.display());
        let err = f.with_extension(format!("{}.err", f.extension().unwrap().to_str().unwrap()));
        if update {
            std::fs::write(&err, format!("{got}\n")).unwrap();
            continue;
        }
        let want = std::fs::read_to_string(&err)
            .unwrap_or_else(|_| panic!("{} is missing", err.display()));
        if want.trim_end() != got {
            failures.push(format!(
                "{}:\n  want {}\n  got  {got}",
                f.display(),
                want.trim_end()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn options_without_effect_in_a_combination_are_refused_with_status_2() {
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "analyze",
                "jitter",
                "-n",
                "64",
                "--exact",
                "--tolerance",
                "1e-3",
            ],
            "--exact",
        ),
        (
            &["analyze", "jitter", "-n", "64", "--tolerance", "NaN"],
            "tolerance = NaN",
        ),
        (
            &["analyze", "jitter", "-n", "64", "--tolerance", "2"],
            "[1e-12, 1e-2]",
        ),
        (
            &["analyze", "jitter", "-n", "64", "--normalize"],
            "--normalize",
        ),
        (
            &[
                "analyze",
                "--points",
                "tests/data/csv-with-header.csv",
                "--seed",
                "3",
            ],
            "--seed",
        ),
        (
            &[
                "analyze",
                "--points",
                "tests/data/csv-with-header.csv",
                "--set",
                "amount=0",
            ],
            "--set",
        ),
        (&["recon", "--spp", "4", "-n", "1024"], "-n"),
    ];
    for (args, needle) in cases {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_samplescope"))
            .args(*args)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(needle), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}
