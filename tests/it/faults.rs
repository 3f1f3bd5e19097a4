//! Faults at the edges of the command line: outputs through links, FIFOs, devices and `-`;
//! SIGTERM and SIGINT during blocked reads, long computations and figures; scene text that
//! grows without bound; outputs checked before any work; the GUI's arguments checked before
//! the display.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("samplescope-faults-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).expect("temp dir");
    d
}

fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_samplescope"));
    c.env(
        "SAMPLESCOPE_CACHE_DIR",
        std::env::temp_dir().join("samplescope-faults-cache"),
    );
    c
}

fn run_in(dir: &Path, args: &[&str]) -> Output {
    bin()
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("run samplescope")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every file name in `dir` (hidden ones too), sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .map(|r| {
            r.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

fn is_link(p: &Path) -> bool {
    fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_symlink())
}

#[cfg(unix)]
fn mkfifo(p: &Path) {
    let ok = Command::new("mkfifo").arg(p).status().expect("mkfifo");
    assert!(ok.success());
}

#[cfg(unix)]
fn signal(child: &Child, name: &str) {
    let ok = Command::new("kill")
        .args([&format!("-{name}"), &child.id().to_string()])
        .status()
        .expect("kill");
    assert!(ok.success());
}

/// Waits for `child` at most `limit`; `None` (and the child killed) if it runs longer.
fn wait_at_most(mut child: Child, limit: Duration) -> Option<Output> {
    let start = Instant::now();
    loop {
        if child.try_wait().expect("wait").is_some() {
            return Some(child.wait_with_output().expect("output"));
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Starts `args` in `dir`, sends `sig` after `after`, and returns the output and how long
/// the process took to end after the signal.
#[cfg(unix)]
fn interrupted(dir: &Path, args: &[&str], sig: &str, after: Duration) -> (Output, Duration) {
    let child = bin()
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    std::thread::sleep(after);
    let t = Instant::now();
    signal(&child, sig);
    let o = wait_at_most(child, Duration::from_secs(20))
        .unwrap_or_else(|| panic!("{args:?}: still running 20 s after SIG{sig}"));
    (o, t.elapsed())
}

// ---- Item 3: outputs through links, FIFOs, devices and `-` --------------------------------

#[cfg(unix)]
#[test]
fn a_link_to_standard_output_writes_there_and_stays_a_link() {
    let dir = temp_dir("link-stdout");
    let link = dir.join("L");
    std::os::unix::fs::symlink("/proc/self/fd/1", &link).unwrap();
    let f = dir.join("f.csv");
    let o = bin()
        .args(["points", "random", "-n", "3", "--out", "L"])
        .current_dir(&dir)
        .stdout(fs::File::create(&f).unwrap())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(is_link(&link), "L is still a link");
    let text = fs::read_to_string(&f).unwrap();
    assert_eq!(text.lines().count(), 4, "{text}");
    assert!(text.starts_with("x,y\n"));
    for out in ["-", "/dev/stdout"] {
        let o = run_in(&dir, &["points", "random", "-n", "3", "--out", out]);
        assert_eq!(o.status.code(), Some(0), "{out}: {}", stderr(&o));
        assert_eq!(
            String::from_utf8_lossy(&o.stdout).lines().count(),
            4,
            "{out}"
        );
    }
    let o = run_in(&dir, &["filter", "box", "--response", "-"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("omega,magnitude,phase"));
    assert_eq!(names(&dir), ["L", "f.csv"]);
    let _ = fs::remove_dir_all(&dir);
}

#[cfg(unix)]
#[test]
fn links_are_written_through_and_a_dangling_link_is_refused() {
    let dir = temp_dir("links");
    fs::write(dir.join("t.csv"), "old").unwrap();
    std::os::unix::fs::symlink("t.csv", dir.join("l1")).unwrap();
    std::os::unix::fs::symlink(dir.join("l1"), dir.join("l2")).unwrap();
    let o = run_in(&dir, &["points", "grid", "-n", "4", "--out", "l2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(is_link(&dir.join("l1")) && is_link(&dir.join("l2")));
    assert_eq!(
        fs::read_to_string(dir.join("t.csv"))
            .unwrap()
            .lines()
            .count(),
        5
    );

    std::os::unix::fs::symlink("missing.csv", dir.join("dangling")).unwrap();
    let o = run_in(&dir, &["points", "grid", "-n", "4", "--out", "dangling"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("--out dangling") && err.contains("dangling link"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        !dir.join("missing.csv").exists(),
        "the target is not created"
    );
    assert_eq!(names(&dir), ["dangling", "l1", "l2", "t.csv"]);
    let _ = fs::remove_dir_all(&dir);
}

#[cfg(unix)]
#[test]
fn a_fifo_output_is_written_through_and_stays_a_fifo() {
    use std::os::unix::fs::FileTypeExt;
    let dir = temp_dir("fifo-out");
    let fifo = dir.join("p");
    mkfifo(&fifo);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || fs::read_to_string(fifo).unwrap())
    };
    let o = run_in(&dir, &["points", "grid", "-n", "9", "--out", "p"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(reader.join().unwrap().lines().count(), 10);
    assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    assert_eq!(names(&dir), ["p"]);
    let _ = fs::remove_dir_all(&dir);
}

// ---- Item 4: signals ---------------------------------------------------------------------

#[cfg(unix)]
#[test]
fn a_read_blocked_on_a_fifo_ends_on_the_first_signal() {
    let dir = temp_dir("fifo-in");
    mkfifo(&dir.join("pts"));
    for (sig, status) in [("TERM", 143), ("INT", 130)] {
        let (o, took) = interrupted(
            &dir,
            &["analyze", "--points", "pts", "--raps", "r.csv"],
            sig,
            Duration::from_millis(400),
        );
        assert_eq!(o.status.code(), Some(status), "SIG{sig}: {}", stderr(&o));
        assert!(
            took < Duration::from_secs(3),
            "SIG{sig}: ended {took:?} after"
        );
        assert_eq!(stderr(&o).trim(), "interrupted");
    }
    // A scene naming a point file that is a FIFO blocks the same way.
    let scene = "(title: \"fifo\", columns: [(points: Some((path: \"pts\")))], n: 16, \
                 panels: (pattern: true, spectrum: false, zoneplate: false, filter: false))";
    fs::write(dir.join("s.ron"), scene).unwrap();
    let (o, took) = interrupted(
        &dir,
        &["render", "s.ron", "--out", "figs"],
        "TERM",
        Duration::from_millis(400),
    );
    assert_eq!(o.status.code(), Some(143), "{}", stderr(&o));
    assert!(took < Duration::from_secs(3), "ended {took:?} after");
    assert_eq!(names(&dir), ["pts", "s.ron"]);
    let _ = fs::remove_dir_all(&dir);
}

#[cfg(unix)]
#[test]
fn sigterm_ends_a_long_generation_with_143_and_no_file() {
    let dir = temp_dir("term-points");
    let (o, took) = interrupted(
        &dir,
        &[
            "points",
            "best-candidate",
            "-n",
            "40000",
            "--out",
            "bc.csv",
            "--budget",
            "10000",
        ],
        "TERM",
        Duration::from_millis(500),
    );
    assert_eq!(o.status.code(), Some(143), "{}", stderr(&o));
    assert!(took < Duration::from_secs(3), "ended {took:?} after");
    assert_eq!(names(&dir), Vec::<String>::new());
    let _ = fs::remove_dir_all(&dir);
}

/// A render whose time goes into drawing figures: 2^20 points in the pattern figure, in PNG,
/// SVG and PDF at scale 4.
#[cfg(unix)]
#[test]
fn sigterm_ends_a_long_render_with_143_and_no_file() {
    let dir = temp_dir("term-render");
    let scene = "(title: \"many points\", columns: [(pattern: (kind: \"random\"), seed: 1), \
                 (pattern: (kind: \"random\"), seed: 2)], n: 1048576, \
                 panels: (pattern: true, spectrum: false, zoneplate: false, filter: false))";
    fs::write(dir.join("big.ron"), scene).unwrap();
    for after in [300, 3000] {
        let (o, took) = interrupted(
            &dir,
            &[
                "render",
                "big.ron",
                "--out",
                "figs",
                "--scale",
                "4",
                "--format",
                "png,svg,pdf",
                "--budget",
                "10000",
                "--no-cache",
            ],
            "TERM",
            Duration::from_millis(after),
        );
        assert_eq!(
            o.status.code(),
            Some(143),
            "after {after} ms: {}",
            stderr(&o)
        );
        assert!(
            took < Duration::from_secs(3),
            "ended {took:?} after the signal"
        );
        assert_eq!(names(&dir), ["big.ron"], "no output, partial or whole");
    }
    let _ = fs::remove_dir_all(&dir);
}

// ---- Item 5: text that grows without bound ------------------------------------------------

#[test]
fn scene_text_beyond_its_limit_is_refused_with_its_location() {
    use samplescope::scene::{limits, Scene};
    let base = "(\n    title: \"T\",\n    notes: \"N\",\n    columns: [(label: \"L\")],\n)";
    let cases = [
        ("title: \"T\"", "title", limits::TITLE_CHARS, 2),
        ("notes: \"N\"", "notes", limits::NOTES_CHARS, 3),
        ("label: \"L\"", "columns[0].label", limits::LABEL_CHARS, 4),
    ];
    for (from, field, max, line) in cases {
        let key = from.split(':').next().unwrap();
        // At the limit (multi-byte characters count once) it loads; one more is refused.
        let ok = base.replace(from, &format!("{key}: \"{}\"", "é".repeat(max)));
        assert!(
            Scene::from_ron(&ok, "s.ron").is_ok(),
            "{field} at its limit"
        );
        let long = base.replace(from, &format!("{key}: \"{}\"", "a ".repeat(max / 2 + 1)));
        let e = Scene::from_ron(&long, "s.ron").unwrap_err().to_string();
        assert!(
            e.starts_with(&format!("s.ron:{line}:"))
                && e.contains(&format!(
                    "{field} = {} characters: must be at most {max} characters",
                    max + 2
                )),
            "{e}"
        );
        assert!(!e.contains('\n') && e.len() < 200, "{e}");
    }
    // A 5 MB title is refused in well under a second, through the command line too (exit 2).
    let dir = temp_dir("long-title");
    let huge = base.replace(
        "title: \"T\"",
        &format!("title: \"{}\"", "x".repeat(5 << 20)),
    );
    fs::write(dir.join("huge.ron"), huge).unwrap();
    let t = Instant::now();
    let o = run_in(&dir, &["render", "huge.ron", "--out", "figs"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("huge.ron:2:"), "{}", stderr(&o));
    assert!(t.elapsed() < Duration::from_secs(5), "{:?}", t.elapsed());
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn a_title_at_its_limit_renders_quickly_with_bounded_metadata() {
    let dir = temp_dir("title-limit");
    let title = "word ".repeat(samplescope::scene::limits::TITLE_CHARS / 5);
    let scene = format!(
        "(title: \"{title}\", columns: [(label: \"{}\"), (seed: 2)], n: 256, \
         panels: (pattern: true, spectrum: false, zoneplate: false, filter: false))",
        "é".repeat(samplescope::scene::limits::LABEL_CHARS)
    );
    fs::write(dir.join("t.ron"), scene).unwrap();
    let o = run_in(
        &dir,
        &["render", "t.ron", "--out", "figs", "--format", "png"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for name in names(&dir.join("figs")) {
        let bytes = fs::read(dir.join("figs").join(&name)).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap();
        let info = reader.info();
        let text: usize = info
            .uncompressed_latin1_text
            .iter()
            .map(|t| t.text.len())
            .chain(info.utf8_text.iter().map(|t| t.get_text().unwrap().len()))
            .sum();
        assert!(text < 16 * 1024, "{name}: {text} bytes of metadata");
    }
    let _ = fs::remove_dir_all(&dir);
}

// ---- Item 6: outputs checked before any work ----------------------------------------------

#[test]
fn an_unwritable_output_is_found_before_any_file_is_written() {
    let dir = temp_dir("unwritable");
    let o = run_in(
        &dir,
        &[
            "analyze",
            "jitter",
            "-n",
            "64",
            "--spectrum",
            "a.png",
            "--spectrum-data",
            "b.csv",
            "--raps",
            "/proc/x.csv",
        ],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(err.starts_with("error: --raps /proc/x.csv"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert_eq!(
        names(&dir),
        Vec::<String>::new(),
        "a.png and b.csv are not written"
    );

    fs::create_dir(dir.join("d")).unwrap();
    for args in [
        &["points", "grid", "-n", "4", "--out", "d"][..],
        &["points", "grid", "-n", "4", "--out", "no/such/dir/x.csv"],
        &["filter", "box", "--response", "/proc/x.csv"],
        &["recon", "-n", "64", "--size", "32", "--out", "/proc/x.png"],
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
            "--csv",
            "/proc/x.csv",
        ],
        &["render", "none.ron", "--out", "/proc/figs"],
    ] {
        let o = run_in(&dir, args);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        let flag = args[args.len() - 2];
        assert!(
            stderr(&o).starts_with(&format!("error: {flag} ")),
            "{args:?}: {}",
            stderr(&o)
        );
    }
    assert_eq!(names(&dir), ["d"]);
    assert_eq!(names(&dir.join("d")), Vec::<String>::new());
    let _ = fs::remove_dir_all(&dir);
}

#[cfg(unix)]
#[test]
fn two_outputs_that_are_the_same_file_are_a_conflict() {
    let dir = temp_dir("same");
    fs::write(dir.join("x.csv"), "mine").unwrap();
    std::os::unix::fs::symlink("x.csv", dir.join("lx")).unwrap();
    for second in ["x.csv", "./x.csv", "lx"] {
        let o = run_in(
            &dir,
            &[
                "analyze", "jitter", "-n", "64", "--raps", "x.csv", "--rdf", second,
            ],
        );
        assert_eq!(o.status.code(), Some(2), "{second}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(
            err.contains("--raps x.csv") && err.contains(&format!("--rdf {second}")),
            "{err}"
        );
        assert!(err.contains("same file"), "{err}");
    }
    assert_eq!(names(&dir), ["lx", "x.csv"]);
    assert_eq!(
        fs::read_to_string(dir.join("x.csv")).unwrap(),
        "mine",
        "untouched"
    );
    // Devices may take several outputs.
    let o = run_in(
        &dir,
        &[
            "analyze",
            "jitter",
            "-n",
            "64",
            "--raps",
            "/dev/null",
            "--rdf",
            "/dev/null",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let _ = fs::remove_dir_all(&dir);
}

// ---- Item 11: the GUI's arguments before the display ---------------------------------------

#[test]
fn the_gui_reports_a_bad_scene_or_point_file_before_the_missing_display() {
    let dir = temp_dir("gui-args");
    fs::write(dir.join("bad.ron"), "(\n    n: 0,\n)").unwrap();
    fs::write(dir.join("good.ron"), samplescope::scene::BUILTIN[0].1).unwrap();
    fs::write(dir.join("bad.csv"), "x,y\n0.5,oops\n").unwrap();
    fs::write(dir.join("good.csv"), "x,y\n0.5,0.5\n").unwrap();
    let gui = |args: &[&str]| {
        let o = bin()
            .args(args)
            .current_dir(&dir)
            .env_remove("DISPLAY")
            .env_remove("WAYLAND_DISPLAY")
            .env_remove("WAYLAND_SOCKET")
            .stdin(Stdio::null())
            .output()
            .unwrap();
        (o.status.code(), stderr(&o))
    };
    let (code, err) = gui(&["--scene", "bad.ron"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("bad.ron:2:") && !err.contains("display"),
        "{err}"
    );
    let (code, err) = gui(&["--points", "bad.csv"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("bad.csv") && !err.contains("display"), "{err}");
    // A bad scene is reported the same with --lecture.
    let (code, err) = gui(&["--lecture", "--scene", "bad.ron"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("bad.ron:2:"), "{err}");
    // A file that is not there is bad input (2), as for every command.
    let (code, err) = gui(&["--scene", "missing.ron"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("missing.ron") && !err.contains("display"),
        "{err}"
    );
    // `--lecture` parses with or without a scene; it then needs the display like any window.
    for args in [
        &["--scene", "good.ron"][..],
        &["--points", "good.csv"],
        &[],
        &["--lecture"],
        &["--lecture", "--scene", "good.ron"],
    ] {
        let (code, err) = gui(args);
        assert_eq!(code, Some(1), "{args:?}: {err}");
        assert!(err.contains("no display"), "{args:?}: {err}");
    }
    let _ = fs::remove_dir_all(&dir);
}
