//! Saving figures from the GUI: any panel, a whole column or the whole comparison, as PNG at
//! 1×, 2× or 3×, as SVG or as CSV, or copied to the clipboard.
//!
//! The figures are the ones `samplescope render` writes (the same publishing path,
//! [`crate::export::publish`], and names), drawn on the CPU from the data the panels show, so a saved figure never depends on the
//! window's size, theme or GPU. Panels and menus only *request* a figure (into the app's
//! [`FigureRequests`]); the app renders requests on a background thread and reports each file
//! written, or the error, in the top bar.

use crate::export::figure::{self, FileFormat};
use crate::export::publish::{self, Format};
use crate::model::{Colormap, ColumnData, FigureContext, FigureKind, Publication};
use crate::scene::panels::PanelKind;
use crate::scene::{self, Scene};
use eframe::egui;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{channel, Receiver, Sender};

/// The frame the GUI's composites are laid out to fill: a 16:9 slide.
const SLIDE: figure::Aspect = figure::Aspect::SLIDE;

/// What a figure request covers: a panel's figure, a column or the comparison (the GUI never
/// asks for [`Target::All`]).
pub use crate::export::publish::Target;

/// What to produce.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    Png { scale: u32 },
    Svg { scale: u32 },
    Pdf { scale: u32 },
    Csv,
    Clipboard { scale: u32 },
}

/// A queued figure request.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Request {
    /// What the figure covers.
    pub target: Target,
    /// What to produce.
    pub output: Output,
}

/// A panel's screen rectangle this frame, for the keyboard shortcuts (Ctrl+S saves the panel
/// under the pointer).
#[derive(Debug, Clone, Copy)]
struct PanelRect {
    rect: egui::Rect,
    column: usize,
    kind: FigureKind,
}

/// The figure requests of one frame, and where each panel was drawn: owned by the app, lent to
/// the panels and menus, which only *request* figures; the app takes the requests after the
/// panels were drawn and hands them to the [`Saver`].
#[derive(Debug, Default)]
pub struct FigureRequests {
    queue: Vec<Request>,
    /// The scale of an animated GIF of the comparison asked for (the app's
    /// [`super::animated::GifSaver`] makes it).
    gif: Option<u32>,
    panels: Vec<PanelRect>,
}

impl FigureRequests {
    /// Queues a request.
    pub fn request(&mut self, r: Request) {
        self.queue.push(r);
    }

    /// Takes every queued request.
    pub fn take(&mut self) -> Vec<Request> {
        std::mem::take(&mut self.queue)
    }

    /// Takes the animated GIF asked for (its scale), if any.
    pub fn take_gif(&mut self) -> Option<u32> {
        self.gif.take()
    }

    /// Records where a panel of figure `kind` was drawn this frame.
    pub fn panel_drawn(&mut self, rect: egui::Rect, column: usize, kind: FigureKind) {
        self.panels.push(PanelRect { rect, column, kind });
    }

    /// The panel under `pos` among those drawn this frame; clears the list for the next frame.
    fn panel_at(&mut self, pos: Option<egui::Pos2>) -> Option<(usize, FigureKind)> {
        let rects = std::mem::take(&mut self.panels);
        let pos = pos?;
        rects
            .iter()
            .find(|r| r.rect.contains(pos))
            .map(|r| (r.column, r.kind))
    }

    /// A small "Save" menu for the figures of panel `panel` (those of its row of the panel
    /// table, in its order): PNG 1×/2×/3×, SVG, CSV, clipboard.
    pub fn panel_menu_ui(&mut self, ui: &mut egui::Ui, column: usize, panel: PanelKind) {
        let kinds = panel.spec().figures;
        ui.menu_button("Save", |ui| {
            for &(kind, _) in kinds {
                if kinds.len() > 1 {
                    ui.label(egui::RichText::new(kind.name()).strong());
                }
                let target = Target::Panel { column, kind };
                self.outputs_ui(ui, target, true);
            }
        })
        .response
        .on_hover_text(
            "Save this panel (Ctrl+S over it: PNG at the figure scale; Ctrl+Shift+C: copy)",
        );
    }

    /// A "Save column" menu.
    pub fn column_menu_ui(&mut self, ui: &mut egui::Ui, column: usize) {
        ui.menu_button("Save column", |ui| {
            self.outputs_ui(ui, Target::Column { column }, false);
        });
    }

    /// A "Save comparison" menu; for an animated scene (`animation`: its frames and rate, as
    /// the GIF's hover text says them) also its animated GIF at 1× and 2×.
    pub fn comparison_menu_ui(&mut self, ui: &mut egui::Ui, animation: Option<(usize, f64)>) {
        ui.menu_button("Save comparison", |ui| {
            self.outputs_ui(ui, Target::Comparison, false);
            if let Some((frames, fps)) = animation {
                ui.separator();
                for scale in 1..=2 {
                    let r = ui
                        .button(format!("Animated GIF {scale}×"))
                        .on_hover_text(format!(
                            "The scene's animation ({frames} frames at {fps} fps, looping) as \
                         `render --format gif` writes it"
                        ));
                    if r.clicked() {
                        self.gif = Some(scale);
                        ui.close();
                    }
                }
            }
        })
        .response
        .on_hover_text("Every column as one figure (Ctrl+Shift+S)");
    }

    fn outputs_ui(&mut self, ui: &mut egui::Ui, target: Target, data: bool) {
        let mut pick = |ui: &mut egui::Ui, text: &str, output: Output| {
            if ui.button(text).clicked() {
                self.request(Request { target, output });
                ui.close();
            }
        };
        for scale in 1..=3 {
            pick(ui, &format!("PNG {scale}×"), Output::Png { scale });
        }
        pick(ui, "SVG", Output::Svg { scale: 1 });
        pick(ui, "PDF", Output::Pdf { scale: 1 });
        if data {
            pick(ui, "CSV (data)", Output::Csv);
        }
        pick(ui, "Copy to clipboard", Output::Clipboard { scale: 1 });
    }

    /// Keyboard shortcuts: Ctrl+S saves the panel under the pointer as PNG at `scale` (the
    /// whole comparison when the pointer is over no panel), Ctrl+Shift+S saves the comparison,
    /// Ctrl+Shift+C copies the panel under the pointer. Call once per frame after the panels
    /// were drawn (it clears the panels' rectangles for the next frame).
    pub fn shortcuts(&mut self, ctx: &egui::Context, scale: u32) {
        use egui::{Key, KeyboardShortcut, Modifiers};
        let save_all = KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::S);
        let copy = KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::C);
        let save = KeyboardShortcut::new(Modifiers::COMMAND, Key::S);
        let (all, copy, save, pos) = ctx.input_mut(|i| {
            (
                i.consume_shortcut(&save_all),
                i.consume_shortcut(&copy),
                i.consume_shortcut(&save),
                i.pointer.hover_pos(),
            )
        });
        let under = self.panel_at(pos);
        let png = Output::Png { scale };
        if all {
            self.request(Request {
                target: Target::Comparison,
                output: png,
            });
        }
        if let Some((column, kind)) = under {
            let target = Target::Panel { column, kind };
            if save {
                self.request(Request {
                    target,
                    output: png,
                });
            }
            if copy {
                self.request(Request {
                    target,
                    output: Output::Clipboard { scale },
                });
            }
        } else if save {
            self.request(Request {
                target: Target::Comparison,
                output: png,
            });
        }
    }
}

/// What finished: a file written, an image for the clipboard, or an error.
pub enum Done {
    Written(PathBuf),
    Clipboard(egui::ColorImage, String),
    Failed(String),
}

/// Everything a background job needs to draw a figure: the scene, its name and each column's
/// data, plus the display choices of the GUI.
#[derive(Clone)]
pub struct Snapshot {
    pub scene: Scene,
    pub scene_name: String,
    pub columns: Vec<ColumnData>,
    pub spectrum_range: Option<(f32, f32)>,
    pub colormap: Colormap,
    pub response_db: bool,
    /// The shared elementary-interval overlay of the pattern panels (a column's own
    /// `elementary_k` takes precedence, as on screen).
    pub elementary_k: Option<u32>,
    /// The strata overlay of the pattern panels (a column's own `strata` draws them anyway).
    pub strata: bool,
}

impl Snapshot {
    fn context(&self, column: usize) -> Result<FigureContext, String> {
        let mut ctx = scene::figure::context(&self.scene, column, &self.scene_name)
            .map_err(|e| e.to_string())?;
        ctx.spectrum_range = self.spectrum_range;
        ctx.spectrum_colormap = self.colormap;
        ctx.response_db = self.response_db;
        ctx.elementary_k = ctx.elementary_k.or(self.elementary_k);
        ctx.strata = scene::figure::strata(&self.scene, column, self.strata);
        Ok(ctx)
    }

    fn data(&self, column: usize) -> Result<&ColumnData, String> {
        self.columns
            .get(column)
            .ok_or_else(|| format!("column {} has no results yet", column + 1))
    }

    /// What `target` draws: every column's context and data (the columns `target` covers
    /// must have results).
    fn publication(&self, target: Target) -> Result<Publication, String> {
        let covered = match target {
            Target::Panel { column, .. } | Target::Column { column } => column..column + 1,
            Target::Comparison | Target::All => 0..self.scene.columns.len(),
        };
        for c in covered {
            self.data(c)?;
        }
        let mut columns = Vec::with_capacity(self.scene.columns.len());
        for c in 0..self.scene.columns.len() {
            let data = self.columns.get(c).cloned().unwrap_or_default();
            columns.push((self.context(c)?, data));
        }
        Ok(scene::figure::publication(
            &self.scene,
            columns,
            &self.scene_name,
        ))
    }

    /// Renders `req` and writes it into `dir` (or returns the clipboard image).
    pub fn run(&self, req: Request, dir: &Path) -> Done {
        match self.try_run(req, dir) {
            Ok(d) => d,
            Err(e) => Done::Failed(e),
        }
    }

    fn try_run(&self, req: Request, dir: &Path) -> Result<Done, String> {
        let p = self.publication(req.target)?;
        let err = |e: crate::export::ExportError| e.to_string();
        let (format, scale) = match req.output {
            Output::Png { scale } => (Format::Picture(FileFormat::Png), scale),
            Output::Svg { scale } => (Format::Picture(FileFormat::Svg), scale),
            Output::Pdf { scale } => (Format::Picture(FileFormat::Pdf), scale),
            Output::Csv => (Format::Csv, 1),
            Output::Clipboard { scale } => {
                let (w, h, rgba, what) =
                    publish::picture(&p, req.target, scale, SLIDE).map_err(err)?;
                return Ok(Done::Clipboard(
                    egui::ColorImage::from_rgba_unmultiplied([w as usize, h as usize], &rgba),
                    what,
                ));
            }
        };
        let never = crate::core::cancel::Cancel::never();
        let made =
            publish::publish(&p, req.target, &[format], scale, SLIDE, &never).map_err(err)?;
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        let mut written = None;
        for (name, bytes) in made.files {
            let path = dir.join(name);
            // Written beside it and renamed (links followed): a failed write leaves no
            // partial figure.
            crate::core::output::write_atomic(&path, &bytes, &never).map_err(|e| e.to_string())?;
            written = Some(path);
        }
        written
            .map(Done::Written)
            .ok_or_else(|| "nothing to save".to_string())
    }
}

/// Runs figure requests off the UI thread and collects what they produced.
pub struct Saver {
    tx: Sender<Done>,
    rx: Receiver<Done>,
    pending: usize,
    /// The last outcome, shown in the top bar.
    pub status: Option<String>,
    /// Said after the files of the current save (e.g. that they show the last complete
    /// picture because a recompute was running).
    pub note: Option<String>,
}

impl Default for Saver {
    fn default() -> Self {
        let (tx, rx) = channel();
        Saver {
            tx,
            rx,
            pending: 0,
            status: None,
            note: None,
        }
    }
}

impl Saver {
    /// Starts `requests` on a background thread with `snapshot`'s data.
    pub fn start(
        &mut self,
        ctx: &egui::Context,
        snapshot: Snapshot,
        requests: Vec<Request>,
        dir: PathBuf,
    ) {
        if requests.is_empty() {
            return;
        }
        self.pending += requests.len();
        self.status = Some("saving figure…".into());
        let tx = self.tx.clone();
        let repaint = ctx.clone();
        let spawned = std::thread::Builder::new()
            .name("samplescope-figures".into())
            .spawn(move || {
                for r in requests {
                    let _ = tx.send(snapshot.run(r, &dir));
                    repaint.request_repaint();
                }
            });
        if let Err(e) = spawned {
            self.pending = 0;
            self.status = Some(format!("cannot start the figure thread: {e}"));
        }
    }

    /// Whether figures are still being drawn.
    pub fn busy(&self) -> bool {
        self.pending > 0
    }

    /// Takes finished results: writes the status line and copies clipboard images.
    pub fn poll(&mut self, ctx: &egui::Context) {
        while let Ok(done) = self.rx.try_recv() {
            self.pending = self.pending.saturating_sub(1);
            let note = self
                .note
                .as_deref()
                .map(|n| format!(" ({n})"))
                .unwrap_or_default();
            self.status = Some(match done {
                Done::Written(p) => format!("saved {}{note}", p.display()),
                Done::Clipboard(img, what) => {
                    ctx.copy_image(img);
                    format!("copied {what} to the clipboard")
                }
                Done::Failed(e) => format!("figure not saved: {e}"),
            });
            if self.pending == 0 {
                self.note = None;
            }
        }
    }
}

/// The short scene name used in file names: the file stem of a path or built-in name.
pub fn scene_stem(name: &str) -> String {
    Path::new(name)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| name.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scene_stem_strips_folders_and_extension() {
        assert_eq!(scene_stem("assets/scenes/default.ron"), "default");
        assert_eq!(scene_stem("two-columns.ron"), "two-columns");
        assert_eq!(scene_stem("restored"), "restored");
    }

    #[test]
    fn unusable_folder_or_missing_data_fail_with_a_message_naming_them() {
        let snapshot = Snapshot {
            scene: Scene::default(),
            scene_name: "bad".into(),
            columns: vec![ColumnData::default()],
            spectrum_range: None,
            colormap: Colormap::Viridis,
            response_db: false,
            elementary_k: None,
            strata: false,
        };
        let png = Request {
            target: Target::Panel {
                column: 0,
                kind: FigureKind::Pattern,
            },
            output: Output::Png { scale: 1 },
        };
        // No points yet: refused before drawing, naming the figure.
        match snapshot.run(png, Path::new("unused")) {
            Done::Failed(e) => assert!(e.contains("pattern"), "{e}"),
            _ => panic!("drawn without data"),
        }
        // A column that does not exist.
        let r = Request {
            target: Target::Column { column: 3 },
            output: Output::Png { scale: 1 },
        };
        assert!(matches!(
            snapshot.run(r, Path::new("unused")),
            Done::Failed(_)
        ));
        // A folder that is a file: the error names the path.
        let file =
            std::env::temp_dir().join(format!("samplescope-not-a-dir-{}", std::process::id()));
        std::fs::write(&file, b"x").unwrap();
        let mut with_points = snapshot.clone();
        with_points.columns[0].points =
            crate::model::Slot::from(std::sync::Arc::new(crate::model::PointsData {
                points: vec![glam::DVec2::new(0.5, 0.5)],
                gpu: std::sync::Arc::new(vec![[0.5, 0.5]]),
                version: 1,
                note: None,
            }));
        match with_points.run(png, &file) {
            Done::Failed(e) => assert!(e.contains(&file.display().to_string()), "{e}"),
            _ => panic!("wrote into a file"),
        }
        let _ = std::fs::remove_file(&file);
    }

    #[test]
    fn shared_elementary_overlay_reaches_the_figure_unless_the_column_sets_its_own() {
        let mut scene = Scene::default();
        scene.columns = vec![crate::scene::Column::default(); 2];
        scene.columns[1].elementary_k = Some(3);
        let snapshot = Snapshot {
            scene,
            scene_name: "overlay".into(),
            columns: Vec::new(),
            spectrum_range: None,
            colormap: Colormap::Viridis,
            response_db: false,
            elementary_k: Some(1),
            strata: false,
        };
        assert_eq!(snapshot.context(0).unwrap().elementary_k, Some(1));
        assert_eq!(snapshot.context(1).unwrap().elementary_k, Some(3));
    }

    #[test]
    fn theorem_figures_save_from_column_zero_and_other_columns_composites_skip_them() {
        use crate::core::cancel::Cancel;
        use crate::engine::Evaluator;
        let text = r#"(title: "GUI theorem figures",
            columns: [(pattern: (kind: "random"), seed: 1), (pattern: (kind: "random"), seed: 2)],
            n: 16,
            panels: (pattern: true, spectrum: false, zoneplate: false, filter: false, cost: false, theorem: true),
            effects: (reconstruction: false, error: false, convergence: false, statistics: false))"#;
        let scene = Scene::from_ron(text, "gui-theorem.ron").unwrap();
        let mut results = vec![std::collections::HashMap::new(); 2];
        Evaluator::default().evaluate(&scene, &Cancel::never(), &mut |c, kind, r| {
            results[c].insert(kind, r);
        });
        let snapshot = Snapshot {
            scene,
            scene_name: "gui-theorem".into(),
            columns: results.iter().map(scene::figure::column_data).collect(),
            spectrum_range: None,
            colormap: Colormap::Viridis,
            response_db: false,
            elementary_k: None,
            strata: false,
        };
        let dir =
            std::env::temp_dir().join(format!("samplescope-gui-theorem-{}", std::process::id()));
        let written = |r: Request| match snapshot.run(r, &dir) {
            Done::Written(p) => p,
            Done::Failed(e) => panic!("{r:?}: {e}"),
            Done::Clipboard(..) => panic!("{r:?}: not a file"),
        };
        let p = written(Request {
            target: Target::Panel {
                column: 0,
                kind: FigureKind::TheoremSpectrum,
            },
            output: Output::Csv,
        });
        assert!(p.ends_with("gui-theorem_theorem-spectrum.csv"), "{p:?}");
        // Column 1 has no theorem view: its composite is its pattern alone.
        written(Request {
            target: Target::Column { column: 1 },
            output: Output::Png { scale: 1 },
        });
        // Column 0's composite holds the theorem figures; the comparison leaves them out.
        let p = written(Request {
            target: Target::Column { column: 0 },
            output: Output::Png { scale: 1 },
        });
        let bytes = std::fs::read(p).unwrap();
        let info = png::Decoder::new(std::io::Cursor::new(bytes))
            .read_info()
            .unwrap()
            .info()
            .clone();
        let kinds = scene::panels::composite_in(&snapshot.scene, 0);
        assert_eq!(kinds.len(), 4, "the pattern and three theorem figures");
        let want = figure::column_size(&kinds, 1, SLIDE);
        assert_eq!((info.width as u64, info.height as u64), want);
        written(Request {
            target: Target::Comparison,
            output: Output::Png { scale: 1 },
        });
        let e = match snapshot.run(
            Request {
                target: Target::Panel {
                    column: 1,
                    kind: FigureKind::TheoremSignal,
                },
                output: Output::Png { scale: 1 },
            },
            &dir,
        ) {
            Done::Failed(e) => e,
            _ => panic!("column 1 has no theorem figure"),
        };
        assert!(e.starts_with("theorem-signal"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn requests_queue_and_drain() {
        let mut requests = FigureRequests::default();
        let r = Request {
            target: Target::Comparison,
            output: Output::Png { scale: 2 },
        };
        requests.request(r);
        requests.request(r);
        assert_eq!(requests.take(), vec![r, r]);
        assert!(requests.take().is_empty());
    }

    #[test]
    fn the_panel_under_the_pointer_is_found_once_per_frame() {
        let mut requests = FigureRequests::default();
        let rect = egui::Rect::from_min_size(egui::pos2(10.0, 10.0), egui::vec2(100.0, 100.0));
        requests.panel_drawn(rect, 1, FigureKind::Spectrum);
        assert_eq!(requests.panel_at(None), None);
        requests.panel_drawn(rect, 1, FigureKind::Spectrum);
        assert_eq!(requests.panel_at(Some(egui::pos2(500.0, 50.0))), None);
        requests.panel_drawn(rect, 1, FigureKind::Spectrum);
        assert_eq!(
            requests.panel_at(Some(egui::pos2(50.0, 50.0))),
            Some((1, FigureKind::Spectrum))
        );
        // Cleared for the next frame.
        assert_eq!(requests.panel_at(Some(egui::pos2(50.0, 50.0))), None);
    }
}
