//! Memory estimates against the measured peak: the maximum resident set of the command (its
//! `VmHWM`) minus that of the binary at rest, within 2× of the `--estimate` peak, for the
//! cases that were furthest off.
//!
//! Before (release build, `/usr/bin/time -v`, resident set over `points random -n 1`'s):
//! `points lloyd -n 100000 --set iterations=40` 141 MiB against an estimate of 14 MiB (glibc's
//! dynamic mmap threshold let the heap fragment, growing with the iterations, and the
//! triangulation's model missed half of its buffers); `points sot -n 65536` 14 MiB against
//! 4 MiB (the batch of displacements in flight); `converge --pattern lloyd … --n 4096,16384`
//! 52 MiB against 4.7 MiB; `points gbn -n 4096` 2.2 MiB against 288 KiB (the worker threads).
//! After: 24.7 / 30, 13.8 / 14, 10.1 / 12, 2.3 / 2.3 MiB. The sizes here are smaller so that
//! the test build (opt-level 1) runs them in seconds; the allocations do not depend on it.

#![cfg(all(target_os = "linux", target_env = "gnu"))]

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The child's peak resident set in bytes: the largest `VmHWM` of `/proc/<pid>/status`, read
/// every millisecond until it exits (the high-water mark of its own address space; the
/// `ru_maxrss` that `wait4` reports would include the test process's own resident set, which
/// the spawned child shares until it executes the binary). With `hold`, the child's standard
/// input is a pipe kept open for that long, then closed.
fn peak_rss(args: &[&str], hold: Option<Duration>) -> f64 {
    let mut child = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .stdin(if hold.is_some() {
            Stdio::piped()
        } else {
            Stdio::null()
        })
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let status = format!("/proc/{}/status", child.id());
    let start = Instant::now();
    let mut peak = 0.0f64;
    loop {
        if let Ok(text) = std::fs::read_to_string(&status) {
            if let Some(kb) = text
                .lines()
                .find_map(|l| l.strip_prefix("VmHWM:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
            {
                peak = peak.max(kb * 1024.0);
            }
        }
        if hold.is_some_and(|h| start.elapsed() > h) {
            drop(child.stdin.take());
        }
        if child.try_wait().unwrap().is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(1));
    }
    assert!(peak > 0.0, "{args:?}: no VmHWM read");
    peak
}

/// The `--estimate` table's peak ("total: about … here, 30 MiB at most"), in bytes.
fn estimate(args: &[&str]) -> f64 {
    let mut with = args.to_vec();
    with.push("--estimate");
    let out = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(&with)
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let total = text.lines().find(|l| l.starts_with("total:")).unwrap();
    let words: Vec<&str> = total.split_whitespace().collect();
    let at = words.iter().position(|w| *w == "most").unwrap();
    let value: f64 = words[at - 3].parse().unwrap();
    let unit = match words[at - 2] {
        "KiB" => 1024.0,
        "MiB" => 1024.0 * 1024.0,
        "GiB" => 1024.0 * 1024.0 * 1024.0,
        u => panic!("unit {u} in {total}"),
    };
    value * unit
}

#[test]
fn memory_estimates_are_within_twice_the_measured_peak_for_the_worst_cases() {
    // The binary at rest: blocked reading points from standard input (nothing computed).
    let base = peak_rss(
        &["analyze", "--points", "/dev/stdin"],
        Some(Duration::from_millis(200)),
    );
    let dir =
        std::env::temp_dir().join(format!("samplescope-budget-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("jitter.csv").display().to_string();
    let made = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(["points", "jitter", "-n", "262144", "--out", &file])
        .status()
        .unwrap();
    assert!(made.success());
    let cases: &[&[&str]] = &[
        &["points", "lloyd", "-n", "30000", "--set", "iterations=12"],
        &["points", "sot", "-n", "65536", "--set", "iterations=2"],
        &[
            "converge",
            "--pattern",
            "lloyd",
            "--set",
            "iterations=12",
            "--integrand",
            "disk",
            "--n",
            "4096,16384",
            "--realizations",
            "2",
        ],
        &["points", "gbn", "-n", "4096", "--set", "iterations=20"],
        &[
            "recon", "-n", "4096", "--filter", "lanczos", "--size", "1024",
        ],
        // analyze runs its nodes at the same time beside the points it holds (2^18 points:
        // estimated 18 MiB, measured 37 MiB before the nodes' memory was added up).
        &["analyze", "jitter", "-n", "262144"],
        &["analyze", "--points", &file],
    ];
    let mut report = Vec::new();
    for args in cases {
        let est = estimate(args);
        let net = peak_rss(args, None) - base;
        let ratio = est / net;
        report.push(format!(
            "{args:?}: measured {:.1} MiB, estimated {:.1} MiB (×{ratio:.2})",
            net / 1048576.0,
            est / 1048576.0
        ));
        assert!((0.5..=2.0).contains(&ratio), "{}", report.last().unwrap());
    }
    let _ = std::fs::remove_dir_all(&dir);
    eprintln!("{}", report.join("\n"));
}
