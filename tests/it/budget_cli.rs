//! The cost budget of the CLI: work estimated beyond it is refused at once (status 2, naming
//! the operation and the limit); `--budget` and `--budget-memory` move the limits; work inside
//! them runs; a scene beyond the budget is refused by `render`; Ctrl-C stops cleanly.

use std::path::PathBuf;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn samplescope(args: &[&str]) -> (Output, Duration) {
    let t = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(args)
        .env("SAMPLESCOPE_NO_CACHE", "1")
        .output()
        .expect("run samplescope");
    (out, t.elapsed())
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("budget_cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Refused at once: status 2 within a second, one line naming `operation` and the limit.
fn assert_refused(args: &[&str], operation: &str, limit: &str) {
    let (o, took) = samplescope(args);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
    assert!(took < Duration::from_secs(1), "{args:?} took {took:?}");
    assert!(e.contains(operation), "{args:?}: {e}");
    assert!(e.contains(limit), "{args:?}: {e}");
    assert_eq!(e.trim().lines().count(), 1, "{args:?}: {e}");
}

#[test]
fn the_measured_failures_are_refused_at_once() {
    let limit = "the limit is 60 s (raise it with --budget SECONDS)";
    // Θ(m N²) candidates: ≥ 15 min measured at 200 000 points, far more at the pattern limit.
    assert_refused(
        &["points", "best-candidate", "-n", "200000"],
        "best-candidate n = 200000, m = 1: about 2e10 candidates, about",
        limit,
    );
    assert_refused(
        &[
            "points",
            "best-candidate",
            "-n",
            "16777216",
            "--set",
            "m=1000",
        ],
        "best-candidate n = 16777216, m = 1000",
        limit,
    );
    // Through `recon` and `analyze` too.
    assert_refused(
        &["recon", "--pattern", "best-candidate", "-n", "200000"],
        "best-candidate n = 200000",
        limit,
    );
    assert_refused(
        &["analyze", "best-candidate", "-n", "200000"],
        "best-candidate n = 200000",
        limit,
    );
    // Supersampling: 2.7·10⁸ samples each.
    assert_refused(
        &["recon", "--spp", "16", "--size", "4096"],
        "supersampling 4096×4096 at 16 spp",
        limit,
    );
    assert_refused(
        &["recon", "--spp", "256", "--size", "1024"],
        "supersampling 1024×1024 at 256 spp",
        limit,
    );
    // Once refused only after 43 s and 1.6 GB; now about 30 s of work, so refused at once
    // under a budget below that.
    assert_refused(
        &["recon", "--size", "8192", "--spp", "1", "--budget", "10"],
        "supersampling 8192×8192 at 1 spp",
        "the limit is 10 s (raise it with --budget SECONDS)",
    );
    // 256 exact 2048² periodograms.
    assert_refused(
        &[
            "analyze",
            "jitter",
            "-n",
            "4096",
            "--size",
            "2048",
            "--exact",
            "--realizations",
            "256",
        ],
        "spectrum 2048×2048 of 4096 points, K = 256, exact DFT",
        limit,
    );
}

#[test]
fn memory_has_a_limit_of_its_own() {
    // Measured peak 2.4 GB: within the default 4 GiB, refused below it.
    assert_refused(
        &[
            "recon",
            "--size",
            "8192",
            "-n",
            "16777216",
            "--budget-memory",
            "1",
        ],
        "scattered reconstruction of 16777216 samples on 8192×8192",
        "the memory limit is 1 GiB (raise it with --budget-memory GIB)",
    );
}

#[test]
fn budget_moves_the_limit_and_work_inside_it_runs() {
    let dir = temp_dir("inside");
    let out = dir.join("bc.csv");
    let out_s = out.to_str().expect("utf-8 path");
    // About 0.05 s estimated (4.5·10⁶ candidates): refused under a 0.02 s budget...
    let args = ["points", "best-candidate", "-n", "3000", "--out", out_s];
    let tight: Vec<&str> = args.iter().copied().chain(["--budget", "0.02"]).collect();
    assert_refused(
        &tight,
        "best-candidate n = 3000, m = 1",
        "the limit is 0.02 s",
    );
    assert!(!out.exists());
    // ...and run just inside a budget of a few times its estimate.
    let roomy: Vec<&str> = args.iter().copied().chain(["--budget", "0.5"]).collect();
    let (o, _) = samplescope(&roomy);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).expect("written");
    assert_eq!(text.lines().count(), 3001);
    assert!(!dir.join(".bc.csv.partial").exists());
    // A limit is a positive number.
    let (o, _) = samplescope(&["points", "random", "-n", "4", "--budget", "0"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("must be a positive number"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn estimate_prints_the_plan_and_computes_nothing() {
    let dir = temp_dir("estimate");
    let out = dir.join("r.png");
    let (o, took) = samplescope(&[
        "recon",
        "--spp",
        "256",
        "--size",
        "1024",
        "--out",
        out.to_str().expect("utf-8 path"),
        "--estimate",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(took < Duration::from_secs(1));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("supersampling 1024×1024 at 256 spp"),
        "{text}"
    );
    assert!(text.contains("reference image 1024×1024"), "{text}");
    // `--out` is the reconstruction figure (its base size), not a bare 1024² image.
    assert!(text.contains("PNG 480×510"), "{text}");
    assert!(
        text.lines()
            .last()
            .unwrap_or("")
            .starts_with("total: about "),
        "{text}"
    );
    assert!(!out.exists());
}

const HEAVY_SUPERSAMPLING: &str = r#"(
    title: "heavy supersampling",
    columns: [(pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 1)],
    n: 1024,
    recon: (mode: supersample(spp: 1024), size: 2048),
    panels: (pattern: false, spectrum: false, zoneplate: true, filter: false, cost: false),
    effects: (reconstruction: true, error: false, convergence: false, statistics: false),
)
"#;

const HEAVY_SPECTRUM: &str = r#"(
    title: "heavy spectrum",
    columns: [(pattern: (kind: "jitter", cols: 0, amount: 1.0), seed: 1)],
    n: 4096,
    spectrum: (size: 2048, tolerance: 1e-6, exact: true, realizations: 256, mask_dc: true),
    panels: (pattern: true, spectrum: true, zoneplate: false, filter: false, cost: false),
)
"#;

#[test]
fn render_refuses_a_scene_beyond_the_budget() {
    let dir = temp_dir("scene");
    for (name, text, operation) in [
        (
            "ss.ron",
            HEAVY_SUPERSAMPLING,
            "supersampling 2048×2048 at 1024 spp",
        ),
        (
            "spec.ron",
            HEAVY_SPECTRUM,
            "spectrum 2048×2048 of 4096 points, K = 256",
        ),
    ] {
        let scene = dir.join(name);
        std::fs::write(&scene, text).expect("scene");
        let out = dir.join(format!("{name}-out"));
        assert_refused(
            &[
                "render",
                scene.to_str().expect("utf-8 path"),
                "--out",
                out.to_str().expect("utf-8 path"),
            ],
            operation,
            "the limit is 60 s",
        );
        assert!(
            stderr(&samplescope(&["render", scene.to_str().unwrap_or(""), "--out", "x"]).0)
                .starts_with(&format!("error: {}", scene.display()))
        );
        assert!(!out.exists(), "nothing is written");
    }
}

#[cfg(unix)]
#[test]
fn ctrl_c_stops_with_status_130_and_leaves_no_file() {
    let dir = temp_dir("interrupt");
    let out = dir.join("bc.csv");
    // About 10 s of best candidate: interrupted after half a second.
    let child = Command::new(env!("CARGO_BIN_EXE_samplescope"))
        .args(["points", "best-candidate", "-n", "22000", "--out"])
        .arg(&out)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("spawn");
    std::thread::sleep(Duration::from_millis(500));
    let t = Instant::now();
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill");
    assert!(kill.success());
    let o = child.wait_with_output().expect("wait");
    assert_eq!(o.status.code(), Some(130), "{}", stderr(&o));
    assert!(t.elapsed() < Duration::from_secs(2), "stopped promptly");
    assert_eq!(stderr(&o).trim(), "interrupted");
    let left: Vec<_> = std::fs::read_dir(&dir).expect("dir").collect();
    assert!(left.is_empty(), "no file, partial or not: {left:?}");
}

#[cfg(unix)]
#[test]
fn an_output_that_is_a_device_is_written_through() {
    use std::os::unix::fs::FileTypeExt;
    let (o, _) = samplescope(&["points", "random", "-n", "10", "--out", "/dev/null"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let meta = std::fs::metadata("/dev/null").expect("/dev/null");
    assert!(meta.file_type().is_char_device(), "still the device");
    assert!(!std::path::Path::new("/dev/.null.partial").exists());
}
