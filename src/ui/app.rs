//! The application: scene, engine, controls, and where each part of the window goes. It owns
//! the state the panels and components are lent each frame; nothing below it imports it.

use super::animated::GifSaver;
use super::columns::{self, Columns};
use super::dropped::{self, PointImport};
use super::figures::{self, FigureRequests};
use super::gpu;
use super::lecture;
use super::panels::{Cell, Panel, PanelCx, Picture};
use super::playback::Playback;
use super::results::{ColumnResults, CompleteResults, Shown};
use super::view::{ViewState, LECTURE_SCALE_RANGE};
use super::widgets::image::ImageView;
use super::widgets::params;
use crate::engine::Engine;
use crate::model::Colormap;
use crate::scene::{limits, ReconMode, Scene, BUILTIN, MAX_COLUMNS};
use eframe::egui;
use std::collections::HashMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The samplescope GUI application.
pub struct SamplescopeApp {
    /// The scene being shown.
    pub scene: Scene,
    /// Name of the scene (file name or built-in name).
    scene_name: String,
    /// The engine evaluating the scene.
    pub engine: Engine,
    /// Latest results per column (possibly of different generations while recomputing).
    pub results: Vec<ColumnResults>,
    /// Each column's plain data made from `results` (with each node's status) whenever they
    /// change: what the panels read.
    pub data: Vec<crate::model::ColumnData>,
    /// The results of the latest generation that finished: one consistent snapshot (saved
    /// figures come from it while a recompute runs).
    complete: Option<CompleteResults>,
    /// Display state (ranges, zoom, overlays).
    pub view: ViewState,
    /// Last scene error (loading a malformed scene), shown in the UI.
    scene_error: Option<String>,
    /// Path typed into the "open scene" box.
    open_path: String,
    submitted: Option<Scene>,
    /// The cost budget every scene is checked against before it is computed (the CLI's
    /// default: 60 s and 4 GiB on the reference machine).
    pub budget: crate::core::budget::Budget,
    /// Why the scene shown is not being computed: its estimated cost is beyond [`Self::budget`]
    /// (the message names the costliest node and the limit). "Compute anyway" clears it.
    pub over_budget: Option<String>,
    /// A scene the user chose to compute although it is over budget.
    allowed_over_budget: Option<Scene>,
    frame_time: Duration,
    last_frame: Option<Instant>,
    /// Draws the panels' images (GPU when the wgpu pipelines are installed, else CPU).
    images: ImageView,
    /// The column panels and where each column was drawn.
    columns: Columns,
    /// The panels docked below the columns (the panel table's docked rows, in its order).
    docks: Vec<Box<dyn Panel>>,
    /// Playback of a scene with motion (frame shown, playing or not).
    playback: Playback,
    /// Point files brought into columns (the last failure, with its retry button).
    import: PointImport,
    applied_style: Option<lecture::AppliedStyle>,
    /// The figure requests of the frame (from menus, panels and shortcuts).
    figures: FigureRequests,
    /// Renders and writes requested figures off the UI thread.
    pub saver: figures::Saver,
    /// Makes the animated GIF of an animated scene off the UI thread.
    pub gif: GifSaver,
    /// The pictures the column panels drew in the last frame.
    pictures: Vec<Picture>,
    /// What the window still has to do once shown: fit the monitor, go full screen.
    window_start: WindowStart,
}

/// The window's first moves, made once it is shown (window systems ignore them for a hidden
/// window) and the monitor is known: full screen for `--lecture`, then — on a first run and
/// after asking for full screen — a check that the window uses the screen. Where it does not
/// (no window manager, e.g. a bare X server: maximize and full-screen requests are only hints
/// to one, though winit reports them as granted), the window is given the monitor's size at
/// the screen's top-left corner ([`window_fit`]).
#[derive(Debug, Clone, Copy, Default)]
struct WindowStart {
    /// Check that the window uses the screen (a first run, no window state stored; or after
    /// full screen was asked for).
    fit_monitor: bool,
    /// `--lecture`: full screen.
    fullscreen: bool,
    /// When the app was made, or the last move was sent.
    since: Option<Instant>,
}

/// What the window's first check finds ([`window_fit`]).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Fit {
    /// The monitor or the window's rectangle is not known (yet).
    Unknown,
    /// The window covers at least [`USES_SCREEN`] of the monitor both ways.
    Uses,
    /// It does not: give it this inner size (the monitor's, in points).
    Resize(egui::Vec2),
}

/// The share of the monitor's width and height a window must cover to count as using the
/// screen: a window manager's maximized window loses at most its title bar and the desktop's
/// panels (a 1920×1080 screen with a 30-px title bar and a 48-px panel: 93 % of the height),
/// the 1600×1000 first-run size on a 1920×1080 screen without one covers 83 % of the width.
const USES_SCREEN: f32 = 0.9;

/// Whether a window whose inner rectangle is `inner` uses a monitor of `monitor` (both in
/// points, as egui's `ViewportInfo` gives them), and if not the size to give it.
fn window_fit(monitor: Option<egui::Vec2>, inner: Option<egui::Rect>) -> Fit {
    let (Some(m), Some(r)) = (monitor, inner) else {
        return Fit::Unknown;
    };
    if !(m.x > 0.0 && m.y > 0.0) {
        return Fit::Unknown;
    }
    if r.width() >= USES_SCREEN * m.x && r.height() >= USES_SCREEN * m.y {
        Fit::Uses
    } else {
        Fit::Resize(m)
    }
}

impl WindowStart {
    /// How long after start (or after asking for full screen) the window's state is read (a
    /// window manager maximizes it once it is mapped).
    const SETTLE: Duration = Duration::from_millis(300);
    /// How long the monitor and the window's rectangle are waited for (never known on
    /// Wayland: its compositor places and sizes the window itself).
    const GIVE_UP: Duration = Duration::from_secs(3);

    /// Sends the pending moves once the window has settled and the monitor is known.
    fn apply(&mut self, ctx: &egui::Context) {
        if !self.fit_monitor && !self.fullscreen {
            return;
        }
        let since = *self.since.get_or_insert_with(Instant::now);
        if since.elapsed() < Self::SETTLE {
            ctx.request_repaint_after(Self::SETTLE - since.elapsed());
            return;
        }
        if self.fullscreen {
            ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(true));
            self.fullscreen = false;
            // Then check that it took.
            self.fit_monitor = true;
            self.since = Some(Instant::now());
            ctx.request_repaint_after(Self::SETTLE);
            return;
        }
        let (monitor, inner) = ctx.input(|i| {
            let v = i.viewport();
            (v.monitor_size, v.inner_rect)
        });
        match window_fit(monitor, inner) {
            Fit::Unknown if since.elapsed() < Self::GIVE_UP => {
                ctx.request_repaint_after(Self::SETTLE);
            }
            Fit::Unknown | Fit::Uses => self.fit_monitor = false,
            Fit::Resize(size) => {
                ctx.send_viewport_cmd(egui::ViewportCommand::OuterPosition(egui::Pos2::ZERO));
                ctx.send_viewport_cmd(egui::ViewportCommand::InnerSize(size));
                self.fit_monitor = false;
            }
        }
    }
}

/// The controls' first width on screen, in pixels at one pixel per point.
const CONTROLS_WIDTH: f32 = 300.0;

/// Keys under which eframe persists the window's state.
const STORAGE_SCENE: &str = "samplescope.scene";
const STORAGE_VIEW: &str = "samplescope.view";
const STORAGE_SCENE_NAME: &str = "samplescope.scene_name";

impl SamplescopeApp {
    /// Creates the app; installs the wgpu pipelines when a wgpu renderer is present. Opens
    /// `scene_path` if given, else the persisted scene, else the built-in default scene.
    pub fn new(cc: &eframe::CreationContext<'_>, scene_path: Option<&std::path::Path>) -> Self {
        let ctx = cc.egui_ctx.clone();
        let engine = Engine::new(Arc::new(move || ctx.request_repaint()));
        Self::with_engine(cc, scene_path, engine)
    }

    /// Like [`SamplescopeApp::new`], on a given engine (tests pass
    /// [`Engine::new_in_memory`] to stay off the user's disk cache).
    pub fn with_engine(
        cc: &eframe::CreationContext<'_>,
        scene_path: Option<&std::path::Path>,
        engine: Engine,
    ) -> Self {
        let gpu = match cc.wgpu_render_state.as_ref() {
            Some(rs) => match gpu::install(rs) {
                Ok(()) => true,
                Err(e) => {
                    eprintln!("{e}; falling back to CPU colour mapping");
                    false
                }
            },
            None => false,
        };
        let mut app = SamplescopeApp {
            scene: Scene::builtin_default(),
            scene_name: BUILTIN[0].0.to_string(),
            engine,
            results: Vec::new(),
            data: Vec::new(),
            complete: None,
            view: ViewState::default(),
            scene_error: None,
            budget: crate::core::budget::Budget::default(),
            over_budget: None,
            allowed_over_budget: None,
            open_path: String::new(),
            submitted: None,
            frame_time: Duration::ZERO,
            last_frame: None,
            images: ImageView::new(gpu),
            columns: Columns::default(),
            docks: columns::placed(crate::scene::panels::Place::Dock),
            playback: Playback::default(),
            import: PointImport::default(),
            applied_style: None,
            figures: FigureRequests::default(),
            saver: figures::Saver::default(),
            gif: GifSaver::default(),
            pictures: Vec::new(),
            window_start: WindowStart {
                // eframe stores the window's size and state under "window" (persist_window).
                fit_monitor: cc.storage.is_some_and(|s| s.get_string("window").is_none()),
                ..WindowStart::default()
            },
        };
        if let Some(storage) = cc.storage {
            if scene_path.is_none() {
                if let Some(scene) = eframe::get_value::<Scene>(storage, STORAGE_SCENE) {
                    if scene.validate("saved state").is_ok() {
                        app.scene = scene;
                        // The name the scene had when it was saved (figure file names use it).
                        app.scene_name = eframe::get_value::<String>(storage, STORAGE_SCENE_NAME)
                            .unwrap_or_else(|| "restored".into());
                    }
                }
            }
            if let Some(view) = eframe::get_value::<ViewState>(storage, STORAGE_VIEW) {
                app.view = view;
            }
        }
        if let Some(path) = scene_path {
            app.open_file(path);
        }
        app
    }

    /// Opens a scene file; on error keeps the current scene and shows the error.
    pub fn open_file(&mut self, path: &std::path::Path) {
        match Scene::load(path) {
            Ok(scene) => {
                self.set_scene(scene, path.display().to_string());
            }
            Err(e) => self.scene_error = Some(e.to_string()),
        }
    }

    /// Replaces the scene.
    pub fn set_scene(&mut self, scene: Scene, name: String) {
        self.scene = scene;
        self.scene_name = name;
        self.scene_error = None;
        self.results.clear();
        self.data.clear();
        self.complete = None;
        self.playback.reset();
    }

    /// Lecture mode with the controls hidden, and the window full screen once shown
    /// (`samplescope --lecture`).
    pub fn start_lecture(&mut self) {
        self.view.lecture = true;
        self.view.controls_hidden = true;
        self.window_start.fullscreen = true;
    }

    /// Adds a column (a copy of the last one with the next seed).
    pub fn add_column(&mut self) {
        columns::add_column(&mut self.scene);
    }

    /// Shows the points of `path` in `column` (0-based; a column is added when it is the next
    /// one). On error the current scene stays and the failure is shown.
    pub fn import_points(&mut self, column: usize, path: &std::path::Path, normalize: bool) {
        if let Err(e) = self.import.import(&mut self.scene, column, path, normalize) {
            self.scene_error = Some(e);
        }
    }

    /// The column a file dropped at `x` goes to (see [`dropped::column_at`]), with the columns
    /// as drawn in the last frame; `central` is the columns' area.
    pub fn column_at(&self, central: egui::Rect, x: f32) -> usize {
        dropped::column_at(self.columns.rects(), self.scene.columns.len(), central, x)
    }

    /// Each column's screen rectangle in the last frame, in column order.
    pub fn column_rects(&self) -> &[egui::Rect] {
        self.columns.rects()
    }

    /// Each column panel's cell in the last frame (the width the grid gave it, the rectangle
    /// it took).
    pub fn panel_cells(&self) -> &[columns::DrawnCell] {
        self.columns.cells()
    }

    /// The frame of a scene with motion that is shown (0 for a still scene).
    pub fn motion_frame(&self) -> i64 {
        self.playback.frame()
    }

    /// Submits the scene to the engine if it changed, and takes results that arrived.
    pub fn sync_engine(&mut self) {
        // A scene with motion is submitted as it is at the frame shown.
        let moved = self.playback.moved_scene(&self.scene);
        let shown = moved.as_ref().unwrap_or(&self.scene);
        if self.submitted.as_ref() != Some(shown) {
            // Planned once: the same estimates as the CLI's guard (a scene beyond the budget is
            // not started), and the plan the engine runs.
            let plan = Arc::new(crate::scene::graph::plan(shown));
            let over = crate::scene::cost::check_plan(shown, &plan, &self.budget).err();
            self.submitted = Some(shown.clone());
            self.results
                .resize_with(self.scene.columns.len(), HashMap::new);
            self.results.truncate(self.scene.columns.len());
            if let (Some(e), false) = (
                &over,
                self.allowed_over_budget.as_ref() == Some(&self.scene),
            ) {
                self.over_budget = Some(format!("Not computed: {e}."));
                return;
            }
            self.over_budget = None;
            self.engine.submit_planned(shown, plan);
            self.results
                .resize_with(self.scene.columns.len(), HashMap::new);
            self.results.truncate(self.scene.columns.len());
        }
        let mut changed = self.data.len() != self.results.len();
        for u in self.engine.poll() {
            if let Some(col) = self.results.get_mut(u.column) {
                col.insert(u.kind, Shown::from(u));
                changed = true;
            }
        }
        let generation = self.engine.generation();
        if self.engine.is_idle()
            && self.engine.failure().is_none()
            && self.complete.as_ref().map(|c| c.generation) != Some(generation)
        {
            // Every node of the finished generation was delivered again (cache hits too),
            // so the results now all belong to it; drop any leftovers of older ones.
            for col in &mut self.results {
                col.retain(|_, r| r.generation == generation);
            }
            let scene = self
                .results
                .iter()
                .flat_map(|c| c.values())
                .map(|r| r.scene.clone())
                .next()
                .unwrap_or_else(|| Arc::new(shown_scene(&self.scene, self.submitted.as_ref())));
            self.complete = Some(CompleteResults {
                scene,
                generation,
                columns: self.results.clone(),
            });
            changed = true;
        }
        if changed {
            self.data = crate::scene::figure::columns_data(&self.scene, &self.results);
        }
    }

    fn shortcuts(&mut self, ctx: &egui::Context) {
        use egui::{Key, Modifiers};
        let (lecture, controls, fullscreen) = ctx.input_mut(|i| {
            (
                i.consume_key(Modifiers::NONE, Key::F5),
                i.consume_key(Modifiers::NONE, Key::F9),
                i.consume_key(Modifiers::NONE, Key::F11),
            )
        });
        if lecture {
            self.view.lecture = !self.view.lecture;
        }
        if controls {
            self.view.controls_hidden = !self.view.controls_hidden;
        }
        if fullscreen {
            let is_full = ctx.input(|i| i.viewport().fullscreen.unwrap_or(false));
            ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(!is_full));
        }
        let (add, dup, remove, toggle_spec, toggle_cost, reseed, lock) = ctx.input_mut(|i| {
            (
                i.consume_key(Modifiers::CTRL, Key::N),
                i.consume_key(Modifiers::CTRL, Key::D),
                i.consume_key(Modifiers::CTRL, Key::W),
                i.consume_key(Modifiers::NONE, Key::F2),
                i.consume_key(Modifiers::NONE, Key::F4),
                i.consume_key(Modifiers::CTRL, Key::R),
                i.consume_key(Modifiers::CTRL, Key::L),
            )
        });
        if add || dup {
            self.add_column();
        }
        if remove && self.scene.columns.len() > 1 {
            self.scene.columns.pop();
        }
        if toggle_spec {
            self.scene.panels.spectrum = !self.scene.panels.spectrum;
        }
        if toggle_cost {
            self.scene.panels.cost = !self.scene.panels.cost;
        }
        if reseed {
            for c in &mut self.scene.columns {
                c.seed = c.seed.wrapping_add(1);
            }
        }
        if lock {
            self.view.lock_scales = !self.view.lock_scales;
        }
    }

    /// The tool bar, the scene's title and notes, the playback and the messages; with the
    /// controls hidden only the title line (with "Show controls") and what follows it, so that
    /// the pictures get the height.
    fn top_bar(&mut self, ui: &mut egui::Ui) {
        if self.view.controls_hidden {
            ui.horizontal_wrapped(|ui| {
                ui.label(egui::RichText::new(&self.scene.title).strong());
                if ui.button("Show controls").on_hover_text("F9").clicked() {
                    self.view.controls_hidden = false;
                }
                if !self.engine.is_idle() {
                    ui.spinner();
                }
            });
        } else {
            self.tool_bar(ui);
            ui.label(egui::RichText::new(&self.scene.title).strong());
        }
        self.top_messages(ui);
    }

    /// The tool bar: scenes, columns, lecture mode, figures and the frame time. In lecture
    /// mode one row that scrolls sideways, so that its larger text costs the pictures no more
    /// than one row's height; else rows wrapped to the window.
    fn tool_bar(&mut self, ui: &mut egui::Ui) {
        if self.view.lecture {
            egui::ScrollArea::horizontal()
                .id_salt("samplescope-tool-bar")
                .show(ui, |ui| ui.horizontal(|ui| self.tool_bar_items(ui)));
        } else {
            ui.horizontal_wrapped(|ui| self.tool_bar_items(ui));
        }
    }

    /// The tool bar's widgets, in order.
    fn tool_bar_items(&mut self, ui: &mut egui::Ui) {
        {
            if self.view.lecture {
                // In the one sideways-scrolling row, the presentation switches first.
                self.presentation_ui(ui);
                ui.separator();
            }
            ui.heading("samplescope");
            ui.separator();
            let mut chosen = None;
            egui::ComboBox::from_label("Scene")
                .selected_text(self.scene_name.clone())
                .show_ui(ui, |ui| {
                    for (name, text) in BUILTIN {
                        if ui
                            .selectable_label(self.scene_name == *name, *name)
                            .clicked()
                        {
                            chosen = Some((*name, *text));
                        }
                    }
                });
            if let Some((name, text)) = chosen {
                match Scene::from_ron(text, name) {
                    Ok(s) => self.set_scene(s, name.to_string()),
                    Err(e) => self.scene_error = Some(e.to_string()),
                }
            }
            ui.add(
                egui::TextEdit::singleline(&mut self.open_path)
                    .hint_text("path/to/scene.ron")
                    .desired_width(180.0),
            );
            if ui.button("Open").clicked() {
                if self.open_path.trim().is_empty() {
                    self.scene_error =
                        Some("Open: type the path of a scene file (.ron) in the box first".into());
                } else {
                    let p = std::path::PathBuf::from(self.open_path.trim());
                    self.open_file(&p);
                }
            }
            ui.separator();
            if ui.button("Add column").on_hover_text("Ctrl+N").clicked() {
                self.add_column();
            }
            ui.checkbox(&mut self.view.lock_scales, "Lock scales")
                .on_hover_text("Same display range in every column (Ctrl+L)");
            ui.separator();
            if !self.view.lecture {
                self.presentation_ui(ui);
                ui.separator();
            }
            self.figures_ui(ui);
            ui.separator();
            if self.view.show_timings {
                ui.label(format!(
                    "frame {:.1} ms · update {}",
                    self.frame_time.as_secs_f64() * 1e3,
                    match self.engine.last_update_time {
                        Some(t) if self.engine.is_idle() =>
                            format!("{:.1} ms", t.as_secs_f64() * 1e3),
                        _ => "computing…".into(),
                    }
                ));
            }
            if !self.engine.is_idle() {
                ui.spinner();
            }
        }
    }

    /// The scene's notes, the playback and the messages under the title.
    fn top_messages(&mut self, ui: &mut egui::Ui) {
        if !self.scene.notes.is_empty() {
            ui.label(&self.scene.notes);
        }
        self.playback.transport_ui(ui, &mut self.scene);
        if let Err(e) = self.import.failure_ui(ui, &mut self.scene) {
            self.scene_error = Some(e);
        }
        if let Some(e) = &self.scene_error {
            ui.colored_label(egui::Color32::from_rgb(200, 40, 40), e);
        }
        if let Some(e) = &self.over_budget {
            ui.horizontal_wrapped(|ui| {
                ui.colored_label(egui::Color32::from_rgb(200, 40, 40), e);
                if ui
                    .button("Compute anyway")
                    .on_hover_text(
                        "start this scene although its estimated cost is over the budget",
                    )
                    .clicked()
                {
                    self.allowed_over_budget = Some(self.scene.clone());
                    self.submitted = None;
                }
            });
        }
        if let Some(e) = self.engine.failure() {
            ui.colored_label(
                egui::Color32::from_rgb(200, 40, 40),
                format!("Engine failure: {e}"),
            );
        }
    }

    /// The panels: the docked ones (cost, integration, theorem) below, the columns in the middle
    /// taking the rest of the window, each drawn from one context lent for the frame.
    fn panels_ui(&mut self, ui: &mut egui::Ui) {
        let SamplescopeApp {
            scene,
            engine,
            data,
            view,
            images,
            columns,
            docks,
            figures,
            pictures,
            ..
        } = self;
        let mut cx = PanelCx {
            scene,
            column: 0,
            data,
            view,
            images,
            figures,
            evaluator: engine.evaluator(),
            cell: Cell::default(),
        };
        for dock in docks {
            if dock.is_shown(&cx.scene.panels) {
                let id = format!("samplescope-{}", dock.kind().spec().name);
                egui::Panel::bottom(id)
                    .resizable(true)
                    .default_size(dock.dock_size())
                    .show(ui, |ui| dock.ui(ui, &mut cx));
            }
        }
        // The margin keeps its size on screen in lecture mode (the zoom enlarges text, not
        // the space around the pictures).
        let margin = lecture::unzoomed_margin(ui.ctx(), 8);
        egui::CentralPanel::default()
            .frame(egui::Frame::central_panel(ui.style()).inner_margin(margin))
            .show(ui, |ui| columns.ui(ui, &mut cx));
        *pictures = std::mem::take(&mut cx.cell.pictures);
    }

    /// The pictures (images and plots) the column panels drew in the last frame, with their
    /// screen rectangles in points: what the layout rule's tests measure.
    pub fn pictures(&self) -> &[Picture] {
        &self.pictures
    }

    /// What the figure writer needs: the scene, its name, every column's data and the
    /// display choices of the panels. Data and labels come from one generation: the latest
    /// that finished (while a recompute runs, the picture before it), else what is on screen.
    pub fn figure_snapshot(&self) -> figures::Snapshot {
        let (scene, columns) = match &self.complete {
            Some(c) => (c.scene.as_ref().clone(), &c.columns),
            None => (self.scene.clone(), &self.results),
        };
        let columns = crate::scene::figure::columns_data(&scene, columns);
        figures::Snapshot {
            scene,
            scene_name: figures::scene_stem(&self.scene_name),
            columns,
            spectrum_range: self
                .view
                .lock_scales
                .then_some((self.view.spectrum_lo, self.view.spectrum_hi)),
            colormap: self.view.colormap,
            response_db: self.view.response_db,
            elementary_k: self.view.elementary_k,
            strata: self.view.show_strata,
        }
    }

    /// The comparison's save menu, the figure folder and scale, and the last save's outcome.
    fn figures_ui(&mut self, ui: &mut egui::Ui) {
        let animation = self
            .scene
            .animates()
            .map(|_| (self.scene.animation.frames, self.scene.animation.fps));
        self.figures.comparison_menu_ui(ui, animation);
        let label = ui.label("into");
        ui.add(
            egui::TextEdit::singleline(&mut self.view.figure_dir)
                .desired_width(90.0)
                .hint_text("folder"),
        )
        .labelled_by(label.id)
        .on_hover_text("Folder for saved figures (created when needed)");
        egui::ComboBox::from_label("Ctrl+S scale")
            .selected_text(format!("{}×", self.view.figure_scale))
            .show_ui(ui, |ui| {
                for s in 1..=3 {
                    ui.selectable_value(&mut self.view.figure_scale, s, format!("{s}×"));
                }
            });
        if self.saver.busy() {
            ui.spinner();
        }
        if let Some(status) = &self.saver.status {
            ui.small(status);
        }
        self.gif.ui(ui);
    }

    /// Lecture mode, its scale, and the controls and full-screen toggles.
    fn presentation_ui(&mut self, ui: &mut egui::Ui) {
        ui.checkbox(&mut self.view.lecture, "Lecture mode")
            .on_hover_text("Light projector theme, large text, pictures never smaller (F5)");
        if self.view.lecture {
            let mut scale = lecture::clamp_scale(self.view.lecture_scale);
            // Applied when the drag ends: changing the zoom mid-drag would move the slider
            // under the pointer.
            let r = ui.add(
                egui::Slider::new(&mut scale, LECTURE_SCALE_RANGE)
                    .step_by(0.1)
                    .text("font scale"),
            );
            if r.drag_stopped() || (r.changed() && !r.dragged()) {
                self.view.lecture_scale = scale;
            }
        }
        let label = if self.view.controls_hidden {
            "Show controls"
        } else {
            "Hide controls"
        };
        if ui.button(label).on_hover_text("F9").clicked() {
            self.view.controls_hidden = !self.view.controls_hidden;
        }
        if ui.button("Full screen").on_hover_text("F11").clicked() {
            let is_full = ui.ctx().input(|i| i.viewport().fullscreen.unwrap_or(false));
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Fullscreen(!is_full));
        }
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        ui.heading("Sampling");
        ui.add(
            egui::Slider::new(&mut self.scene.n, limits::N)
                .logarithmic(true)
                .text("N"),
        );
        egui::CollapsingHeader::new("Panels")
            .default_open(true)
            .show(ui, |ui| {
                for row in &crate::scene::panels::PANELS {
                    ui.checkbox((row.switch)(&mut self.scene.panels), row.label);
                }
            });
        egui::CollapsingHeader::new("Effects")
            .default_open(true)
            .show(ui, |ui| {
                let e = &mut self.scene.effects;
                ui.checkbox(&mut e.reconstruction, "Reconstruction");
                ui.checkbox(&mut e.error, "Reference and error");
                ui.checkbox(&mut e.statistics, "Point statistics (overlays)");
                ui.checkbox(&mut e.convergence, "Convergence curve");
            });
        ui.separator();
        let ncols = self.scene.columns.len();
        let supersampling = matches!(self.scene.recon.mode, ReconMode::Supersample { .. });
        let n = self.scene.n;
        let mut remove = None;
        let mut duplicate = None;
        for (ci, column) in self.scene.columns.iter_mut().enumerate() {
            ui.push_id(ci, |ui| {
                ui.horizontal(|ui| {
                    ui.strong(format!("Column {}", ci + 1));
                    if ui.small_button("Duplicate").clicked() {
                        duplicate = Some(ci);
                    }
                    if ncols > 1 && ui.small_button("Remove").clicked() {
                        remove = Some(ci);
                    }
                });
                dropped::imported_column_ui(ui, column);
                params::pattern_ui(ui, column, n);
                if supersampling {
                    params::pixel_sampling_ui(ui, column);
                }
            });
            ui.separator();
        }
        if let Some(ci) = duplicate {
            if self.scene.columns.len() < MAX_COLUMNS {
                let c = self.scene.columns[ci].clone();
                self.scene.columns.insert(ci + 1, c);
            }
        }
        if let Some(ci) = remove {
            self.scene.columns.remove(ci);
            if ci < self.results.len() {
                self.results.remove(ci);
            }
            if ci < self.data.len() {
                self.data.remove(ci);
            }
        }
        ui.heading("Spectrum");
        let s = &mut self.scene.spectrum;
        egui::ComboBox::from_label("Size")
            .selected_text(format!("{}²", s.size))
            .show_ui(ui, |ui| {
                for m in [64, 128, 256, 512, 640, 1024] {
                    ui.selectable_value(&mut s.size, m, format!("{m}²"));
                }
            });
        params::setting_ui(ui, s, "exact", "Exact DFT");
        ui.add_enabled_ui(!s.exact, |ui| {
            params::setting_ui(ui, s, "tolerance", "tolerance")
        });
        params::setting_ui(ui, s, "realizations", "realizations K");
        params::setting_ui(ui, s, "mask_dc", "Mask DC");
        ui.heading("Reconstruction");
        params::signal_ui(ui, &mut self.scene.signal);
        let r = &mut self.scene.recon;
        egui::ComboBox::from_label("Output size")
            .selected_text(format!("{}²", r.size))
            .show_ui(ui, |ui| {
                for w in [128, 256, 512, 1024] {
                    ui.selectable_value(&mut r.size, w, format!("{w}²"));
                }
            });
        let mut supersample = matches!(r.mode, ReconMode::Supersample { .. });
        if ui
            .checkbox(&mut supersample, "Supersample (spp from the pattern)")
            .changed()
        {
            r.mode = if supersample {
                ReconMode::Supersample {
                    spp: crate::scene::DEFAULT_SPP,
                }
            } else {
                ReconMode::Scattered
            };
        }
        if let ReconMode::Supersample { .. } = r.mode {
            params::setting_ui(ui, &mut r.mode, "spp", "spp");
        }
        ui.heading("Filter");
        params::filter_ui(ui, &mut self.scene.filter);
        ui.heading("Display");
        egui::ComboBox::from_label("Colour map")
            .selected_text(self.view.colormap.name())
            .show_ui(ui, |ui| {
                for c in Colormap::ALL {
                    ui.selectable_value(&mut self.view.colormap, c, c.name());
                }
            });
        ui.add(egui::Slider::new(&mut self.view.spectrum_lo, -4.0..=2.0).text("log10 P min"));
        ui.add(egui::Slider::new(&mut self.view.spectrum_hi, -2.0..=4.0).text("log10 P max"));
        ui.add(egui::Slider::new(&mut self.view.zoom, 1..=8).text("zoom"));
    }
}

impl eframe::App for SamplescopeApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let now = Instant::now();
        if let Some(last) = self.last_frame {
            self.frame_time = now - last;
        }
        self.last_frame = Some(now);
        let ctx = ui.ctx().clone();
        self.window_start.apply(&ctx);
        self.shortcuts(&ctx);
        lecture::apply_style(&ctx, &self.view, &mut self.applied_style);
        egui::Panel::top("samplescope-top").show(ui, |ui| self.top_bar(ui));
        if !self.view.controls_hidden {
            // The controls keep their width on screen in lecture mode (their larger text wraps
            // or scrolls), so that the pictures keep theirs: a panel of its own, sized in the
            // zoomed points.
            let (id, zoom) = if self.view.lecture {
                (
                    "samplescope-controls-lecture",
                    lecture::clamp_scale(self.view.lecture_scale),
                )
            } else {
                ("samplescope-controls", 1.0)
            };
            egui::Panel::left(id)
                .resizable(true)
                .default_size(CONTROLS_WIDTH / zoom)
                .show(ui, |ui| {
                    egui::ScrollArea::both().show(ui, |ui| self.controls(ui));
                });
        }
        self.playback
            .advance(&ctx, &mut self.scene, self.engine.is_idle());
        let central = ui.available_rect_before_wrap();
        let drops = self
            .import
            .drops_ui(&ctx, central, self.columns.rects(), &mut self.scene);
        if let Err(e) = drops {
            self.scene_error = Some(e);
        }
        self.sync_engine();
        self.panels_ui(ui);
        self.figures.shortcuts(&ctx, self.view.figure_scale);
        let requests = self.figures.take();
        if !requests.is_empty() {
            let snapshot = self.figure_snapshot();
            self.saver.note = (!self.engine.is_idle() && self.complete.is_some())
                .then(|| "the last complete picture: a recompute is running".to_string());
            let dir = std::path::PathBuf::from(self.view.figure_dir.trim());
            self.saver.start(&ctx, snapshot, requests, dir);
        }
        self.saver.poll(&ctx);
        if let Some(scale) = self.figures.take_gif() {
            self.gif.start(
                &ctx,
                &self.scene,
                &figures::scene_stem(&self.scene_name),
                scale,
                crate::export::figure::Aspect::SLIDE,
                &self.budget,
                self.engine.evaluator().clone(),
                std::path::PathBuf::from(self.view.figure_dir.trim()),
            );
        }
        self.gif.poll();
        if !self.engine.is_idle() {
            ctx.request_repaint_after(Duration::from_millis(30));
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, STORAGE_SCENE, &self.scene);
        eframe::set_value(storage, STORAGE_VIEW, &self.view);
        eframe::set_value(storage, STORAGE_SCENE_NAME, &self.scene_name);
    }
}

/// The scene last submitted (the shown frame of a moving scene), else the edited one.
fn shown_scene(scene: &Scene, submitted: Option<&Scene>) -> Scene {
    submitted.unwrap_or(scene).clone()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_that_does_not_use_the_screen_gets_the_monitor_s_size() {
        let m = egui::vec2(1920.0, 1080.0);
        let rect = |w: f32, h: f32| {
            Some(egui::Rect::from_min_size(
                egui::pos2(0.0, 0.0),
                egui::vec2(w, h),
            ))
        };
        // No window manager: the first-run size stays (what a bare X server did).
        assert_eq!(window_fit(Some(m), rect(1600.0, 1000.0)), Fit::Resize(m));
        // Full screen, and maximized under a title bar and a panel: it uses the screen.
        assert_eq!(window_fit(Some(m), rect(1920.0, 1080.0)), Fit::Uses);
        assert_eq!(window_fit(Some(m), rect(1920.0, 1002.0)), Fit::Uses);
        // A window manager's side dock leaves the width a little short: still used.
        assert_eq!(window_fit(Some(m), rect(1850.0, 1080.0)), Fit::Uses);
        // Unknown monitor or window (Wayland gives no window rectangle).
        assert_eq!(window_fit(None, rect(800.0, 600.0)), Fit::Unknown);
        assert_eq!(window_fit(Some(m), None), Fit::Unknown);
        assert_eq!(
            window_fit(Some(egui::Vec2::ZERO), rect(800.0, 600.0)),
            Fit::Unknown
        );
    }
}
