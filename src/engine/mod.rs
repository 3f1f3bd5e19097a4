//! Evaluating scenes: parallel, per-node cancellation, progressive results, bounded caches.
//!
//! The UI submits the whole scene after every change with its plan (the node table of
//! [`crate::scene::graph`]; [`Engine::submit_planned`]: planned once, for the cost check and
//! the engine; [`Engine::submit`] plans it itself). The engine's coordinator starts every node
//! whose inputs are ready as a job on rayon's pool (independent nodes run concurrently),
//! and sends each result back as soon as it is ready, calling `repaint` so the UI wakes up.
//! See [`scheduler`] for the invariants: a new scene cancels only the running jobs whose keys
//! left the plan, a job whose key stayed keeps running and its result is used, and every
//! completed result is cached ([`cache::MemoryCache`], bounded by bytes, least recently used
//! first out; reference images also on disk, [`disk_cache::DiskCache`]).
//!
//! Slow nodes publish coarse results first (with their [`Steps`]): the UI shows them with
//! "refining i/n" and their error estimate; the final result is the node's plain result, bit
//! for bit. Every [`Update`] carries the generation and the scene snapshot it was computed
//! for, so a panel or a saved figure never mixes one scene's labels with another's data.
//! If the coordinator cannot start or dies, [`Engine::failure`] says so (the UI shows a banner)
//! and [`Engine::is_idle`] is true: nothing waits forever.
//!
//! [`Evaluator::evaluate`] runs the same scheduler to completion on the calling thread
//! (`samplescope render`, tests, benchmarks).

pub mod allocator;
pub mod animation;
pub mod cache;
mod disk;
pub mod disk_cache;
pub mod scheduler;

use crate::core::cancel::Cancel;
pub use crate::core::progress::Steps;
use crate::scene::graph::{self, NodeKey, NodeKind, NodeResult, Plan};
use crate::scene::Scene;
pub use scheduler::Update;
use scheduler::{Event, Scheduler, Shared, Sink};
use std::collections::HashMap;
use std::sync::atomic::Ordering;
use std::sync::mpsc::{channel, Receiver, RecvTimeoutError, Sender, TryRecvError};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Default size bound of the on-disk cache of reference images: 1 GiB.
pub const DISK_CACHE_BYTES: u64 = 1 << 30;

/// Allowed memory budgets, MiB.
pub const MEMORY_MIB: std::ops::RangeInclusive<usize> = 16..=1 << 20;

/// The memory cache budget in bytes from the value of `SAMPLESCOPE_MEMORY_MIB` (MiB, in
/// [`MEMORY_MIB`]); [`cache::DEFAULT_BUDGET`] when unset.
pub fn memory_budget(value: Option<&str>) -> Result<usize, String> {
    let Some(v) = value else {
        return Ok(cache::DEFAULT_BUDGET);
    };
    match v.trim().parse::<usize>() {
        Ok(m) if MEMORY_MIB.contains(&m) => Ok(m << 20),
        _ => Err(format!(
            "SAMPLESCOPE_MEMORY_MIB = {v:?}: must be an integer in {}..={} (MiB)",
            MEMORY_MIB.start(),
            MEMORY_MIB.end()
        )),
    }
}

/// The on-disk cache of reference images at [`disk_cache::DiskCache::default_dir`] (the
/// platform cache directory, or `$SAMPLESCOPE_CACHE_DIR`), bounded by [`DISK_CACHE_BYTES`];
/// `None` when `SAMPLESCOPE_NO_CACHE` is set or no directory can be used (a warning says why).
pub fn default_disk_cache() -> Option<disk_cache::DiskCache> {
    if std::env::var_os("SAMPLESCOPE_NO_CACHE").is_some() {
        return None;
    }
    let dir = disk_cache::DiskCache::default_dir()?;
    match disk_cache::DiskCache::open(dir, DISK_CACHE_BYTES) {
        Ok(d) => Some(d),
        Err(e) => {
            eprintln!("samplescope: disk cache off: {e}");
            None
        }
    }
}

/// Node caches and evaluation counters, shared by every evaluation that uses them.
#[derive(Clone)]
pub struct Evaluator {
    shared: Arc<Shared>,
}

impl Default for Evaluator {
    /// An in-memory cache of [`cache::DEFAULT_BUDGET`] bytes and no disk cache.
    fn default() -> Self {
        Evaluator::new(cache::DEFAULT_BUDGET, None)
    }
}

impl Evaluator {
    /// An evaluator whose memory cache holds at most `budget` bytes, with an optional disk
    /// cache for reference images.
    pub fn new(budget: usize, disk: Option<disk_cache::DiskCache>) -> Self {
        Evaluator {
            shared: Arc::new(Shared::new(budget, disk)),
        }
    }

    /// How many times nodes of `kind` were started (cache hits do not count; a job that was
    /// cancelled does).
    pub fn count(&self, kind: NodeKind) -> usize {
        self.shared.counts[kind as usize].load(Ordering::Relaxed)
    }

    /// Every counter, by kind.
    pub fn counts(&self) -> Vec<(NodeKind, usize)> {
        NodeKind::ALL.iter().map(|&k| (k, self.count(k))).collect()
    }

    /// Resets every counter to zero.
    pub fn reset_counts(&self) {
        for c in &self.shared.counts {
            c.store(0, Ordering::Relaxed);
        }
    }

    /// A cached result, if any.
    pub fn cached(&self, key: &NodeKey) -> Option<Arc<NodeResult>> {
        self.shared.cache().peek(key)
    }

    /// Bytes held by the memory cache now.
    pub fn cache_bytes(&self) -> usize {
        self.shared.cache().bytes()
    }

    /// The memory cache's budget in bytes.
    pub fn cache_budget(&self) -> usize {
        self.shared.cache().budget()
    }

    /// Evaluates every node the scene needs (in parallel) and calls `sink` on this thread with
    /// each final result, per column, as it becomes ready. Returns when all are ready, or as
    /// soon as `cancel` fires (running jobs are cancelled; completed ones stay cached).
    pub fn evaluate(
        &self,
        scene: &Scene,
        cancel: &Cancel,
        sink: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
    ) {
        self.evaluate_planned(scene, Arc::new(graph::plan(scene)), cancel, sink);
    }

    /// [`Self::evaluate`] with the scene's plan made by the caller (`graph::plan(scene)`,
    /// whose cost it has estimated): the scene is not planned again.
    pub fn evaluate_planned(
        &self,
        scene: &Scene,
        plan: Arc<Plan>,
        cancel: &Cancel,
        sink: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
    ) {
        self.evaluate_updates(scene, plan, cancel, &mut |u: Update| {
            if u.progress.is_none() {
                sink(u.column, u.kind, u.result);
            }
        });
    }

    /// [`Self::evaluate_planned`] that hands `sink` every [`Update`] as the app's engine sends
    /// them: results published while a node works (coarse ones, and final values before their
    /// readout: `value_final`) as well as the final ones (`progress` is `None`). Benchmarks
    /// time the complete picture with it.
    pub fn evaluate_updates(
        &self,
        scene: &Scene,
        plan: Arc<Plan>,
        cancel: &Cancel,
        sink: &mut dyn FnMut(Update),
    ) {
        if cancel.is_cancelled() {
            return;
        }
        self.evaluate_updates_shared(Arc::new(scene.clone()), plan, cancel, sink);
    }

    /// [`Self::evaluate_planned`] of a scene the caller already shares: not copied (a scene
    /// holding a million imported points is 16 MiB).
    pub fn evaluate_shared(
        &self,
        scene: Arc<Scene>,
        plan: Arc<Plan>,
        cancel: &Cancel,
        sink: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
    ) {
        self.evaluate_updates_shared(scene, plan, cancel, &mut |u: Update| {
            if u.progress.is_none() {
                sink(u.column, u.kind, u.result);
            }
        });
    }

    /// [`Self::evaluate_updates`] of a scene the caller already shares.
    pub fn evaluate_updates_shared(
        &self,
        scene: Arc<Scene>,
        plan: Arc<Plan>,
        cancel: &Cancel,
        sink: &mut dyn FnMut(Update),
    ) {
        if cancel.is_cancelled() {
            return;
        }
        struct All<'a>(&'a mut dyn FnMut(Update));
        impl Sink for All<'_> {
            fn node(&mut self, u: Update) {
                (self.0)(u)
            }
            fn finished(&mut self, _: u64, _: Duration) {}
        }
        let mut sink = All(sink);
        let (tx, rx) = channel();
        let mut s = Scheduler::new(self.shared.clone(), tx);
        s.handle(
            Event::Submit {
                generation: 1,
                scene,
                plan,
            },
            &mut sink,
        );
        while !s.is_finished() {
            if cancel.is_cancelled() {
                s.cancel_all();
                return;
            }
            match rx.recv_timeout(Duration::from_millis(20)) {
                Ok(ev) => {
                    s.handle(ev, &mut sink);
                }
                Err(RecvTimeoutError::Timeout) => {}
                Err(RecvTimeoutError::Disconnected) => return,
            }
        }
    }
}

/// The final result of every node of an evaluated scene, per column.
pub type ColumnResults = Vec<HashMap<NodeKind, Arc<NodeResult>>>;

/// Why [`Evaluator::evaluate_columns`] returned no results.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ColumnsError {
    /// `cancel` fired.
    #[error("cancelled")]
    Cancelled,
    /// The first failed node, columns in order and in each column the kinds in
    /// [`NodeKind::ALL`]'s order: "column C (title): KIND node failed: ERROR", C from 1.
    #[error("{0}")]
    Failed(String),
}

impl ColumnsError {
    /// Node `kind` of column `c` (from 0) of `scene` failed with `error`.
    pub fn failed(scene: &Scene, c: usize, kind: NodeKind, error: &dyn std::fmt::Display) -> Self {
        ColumnsError::Failed(format!(
            "column {} ({}): {} node failed: {error}",
            c + 1,
            scene.columns[c].title(),
            kind.name()
        ))
    }
}

impl Evaluator {
    /// [`Self::evaluate_planned`] with every final result collected per column: the results,
    /// or the first failed node (one that failed through its inputs counts too), or
    /// [`ColumnsError::Cancelled`]. `samplescope render` and each frame of an animation.
    pub fn evaluate_columns(
        &self,
        scene: &Scene,
        plan: Arc<Plan>,
        cancel: &Cancel,
    ) -> Result<ColumnResults, ColumnsError> {
        let mut results: ColumnResults = vec![HashMap::new(); scene.columns.len()];
        self.evaluate_planned(scene, plan, cancel, &mut |c, kind, r| {
            if let Some(col) = results.get_mut(c) {
                col.insert(kind, r);
            }
        });
        if cancel.is_cancelled() {
            return Err(ColumnsError::Cancelled);
        }
        for (c, col) in results.iter().enumerate() {
            for kind in NodeKind::ALL {
                if let Some(Err(e)) = col.get(&kind).map(|r| &r.value) {
                    return Err(ColumnsError::failed(scene, c, kind, e));
                }
            }
        }
        Ok(results)
    }
}

impl Evaluator {
    /// The serial reference: every column's plan in order, one node after the other on this
    /// thread (no job runs beside another), with the same jobs and caches as
    /// [`Self::evaluate`]. Benchmarks time it against the parallel scheduler; tests check
    /// that both give the same bits. Stops at once when `cancel` fires.
    pub fn evaluate_serial(
        &self,
        scene: &Scene,
        cancel: &Cancel,
        sink: &mut dyn FnMut(usize, NodeKind, Arc<NodeResult>),
    ) {
        let never = |_: crate::scene::node::Partial| {};
        for (c, plan) in crate::scene::graph::plan(scene).into_iter().enumerate() {
            let mut done: std::collections::HashMap<NodeKind, Arc<NodeResult>> = Default::default();
            for n in plan.nodes {
                if cancel.is_cancelled() {
                    return;
                }
                let key = match n.key {
                    Ok(k) => k,
                    Err(e) => {
                        let r = Arc::new(NodeResult::error(crate::scene::node::NodeError::Key(e)));
                        done.insert(n.kind, r.clone());
                        sink(c, n.kind, r);
                        continue;
                    }
                };
                let cached = self.shared.cache().get(&key);
                let r = match cached {
                    Some(r) => r,
                    None => {
                        let deps: std::collections::HashMap<_, _> = n
                            .deps
                            .iter()
                            .filter_map(|(k, _)| done.get(k).map(|r| (*k, r.clone())))
                            .collect();
                        let declared = n.deps.iter().filter_map(|(k, _)| deps.get_key_value(k));
                        let r = match scheduler::failed_input(declared) {
                            Some(e) => NodeResult::error(e),
                            None => {
                                self.shared.counts[n.kind as usize].fetch_add(1, Ordering::Relaxed);
                                let ctx = crate::scene::node::JobCtx {
                                    scene,
                                    column: c,
                                    deps: &deps,
                                    cancel,
                                    progress: &never,
                                };
                                match scheduler::run_job(n.kind, &ctx) {
                                    Some(r) if !cancel.is_cancelled() => r,
                                    _ => return,
                                }
                            }
                        };
                        let r = Arc::new(r);
                        self.shared.cache().insert(key, r.clone());
                        r
                    }
                };
                done.insert(n.kind, r.clone());
                sink(c, n.kind, r);
            }
        }
    }
}

/// What the coordinator sends to the UI.
enum Message {
    Node(Update),
    Finished { generation: u64, elapsed: Duration },
}

/// A callback that wakes the UI (egui's `request_repaint`).
pub type Repaint = Arc<dyn Fn() + Send + Sync>;

struct ToUi {
    messages: Sender<Message>,
    repaint: Repaint,
}

impl Sink for ToUi {
    fn node(&mut self, u: Update) {
        let _ = self.messages.send(Message::Node(u));
        (self.repaint)();
    }
    fn finished(&mut self, generation: u64, elapsed: Duration) {
        let _ = self.messages.send(Message::Finished {
            generation,
            elapsed,
        });
        (self.repaint)();
    }
}

/// Owns the coordinator thread; the UI's handle on evaluation.
pub struct Engine {
    events: Sender<Event>,
    messages: Receiver<Message>,
    generation: u64,
    finished_generation: u64,
    submitted_at: Option<Instant>,
    /// Time from the last submit until all of its nodes were ready.
    pub last_update_time: Option<Duration>,
    evaluator: Evaluator,
    failure: Option<String>,
}

impl Engine {
    /// Starts the coordinator with a fresh [`Evaluator`] (memory cache of the default budget;
    /// the disk cache at [`disk_cache::DiskCache::default_dir`] unless `SAMPLESCOPE_NO_CACHE`
    /// is set). `repaint` is called whenever a result is ready.
    pub fn new(repaint: Repaint) -> Engine {
        let budget = match memory_budget(std::env::var("SAMPLESCOPE_MEMORY_MIB").ok().as_deref()) {
            Ok(b) => b,
            Err(e) => {
                eprintln!("samplescope: {e}; using the default of 1024 MiB");
                cache::DEFAULT_BUDGET
            }
        };
        Engine::with_evaluator(Evaluator::new(budget, default_disk_cache()), repaint)
    }

    /// Starts the coordinator with a memory cache of the default budget and no disk cache:
    /// hermetic (tests and benchmarks neither read nor write the user's cache directory).
    pub fn new_in_memory(repaint: Repaint) -> Engine {
        Engine::with_evaluator(Evaluator::new(cache::DEFAULT_BUDGET, None), repaint)
    }

    /// Starts the coordinator on `evaluator`'s caches.
    pub fn with_evaluator(evaluator: Evaluator, repaint: Repaint) -> Engine {
        let (ev_tx, ev_rx) = channel::<Event>();
        let (msg_tx, msg_rx) = channel::<Message>();
        let shared = evaluator.shared.clone();
        let sched_tx = ev_tx.clone();
        let started = std::thread::Builder::new()
            .name("samplescope-engine".into())
            .spawn(move || {
                let mut s = Scheduler::new(shared, sched_tx);
                let mut sink = ToUi {
                    messages: msg_tx,
                    repaint,
                };
                while let Ok(ev) = ev_rx.recv() {
                    if !s.handle(ev, &mut sink) {
                        break;
                    }
                }
            });
        let failure = started
            .err()
            .map(|e| format!("the compute engine could not start: {e}"));
        Engine {
            events: ev_tx,
            messages: msg_rx,
            generation: 0,
            finished_generation: 0,
            submitted_at: None,
            last_update_time: None,
            evaluator,
            failure,
        }
    }

    /// Submits a scene. Nodes of the previous scene whose keys are not in this one are
    /// cancelled; the others keep running. Returns the new generation.
    pub fn submit(&mut self, scene: &Scene) -> u64 {
        self.submit_planned(scene, Arc::new(graph::plan(scene)))
    }

    /// [`Self::submit`] with the scene's plan made by the caller (`graph::plan(scene)`, whose
    /// cost the app has checked): the coordinator does not plan it again.
    pub fn submit_planned(&mut self, scene: &Scene, plan: Arc<Plan>) -> u64 {
        self.generation += 1;
        self.submitted_at = Some(Instant::now());
        if self
            .events
            .send(Event::Submit {
                generation: self.generation,
                scene: Arc::new(scene.clone()),
                plan,
            })
            .is_err()
        {
            self.died();
        }
        self.generation
    }

    /// The generation of the latest submit.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Whether the latest submit has finished (or the engine has failed: see [`Self::failure`]).
    pub fn is_idle(&self) -> bool {
        self.failure.is_some() || self.finished_generation >= self.generation
    }

    /// Why the engine is not working, if it is not (shown as a banner).
    pub fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    fn died(&mut self) {
        if self.failure.is_none() {
            self.failure = Some(
                "the compute engine stopped unexpectedly; results are no longer updated \
                 (restart samplescope)"
                    .into(),
            );
        }
    }

    /// Results that arrived since the last poll, of the current generation only.
    pub fn poll(&mut self) -> Vec<Update> {
        let mut out = Vec::new();
        loop {
            match self.messages.try_recv() {
                Ok(m) => self.accept(m, &mut out),
                Err(TryRecvError::Empty) => break,
                Err(TryRecvError::Disconnected) => {
                    self.died();
                    break;
                }
            }
        }
        out
    }

    fn accept(&mut self, m: Message, out: &mut Vec<Update>) {
        match m {
            Message::Node(u) if u.generation == self.generation => out.push(u),
            Message::Node(_) => {}
            Message::Finished {
                generation,
                elapsed,
            } => {
                if generation == self.generation {
                    self.finished_generation = generation;
                    self.last_update_time =
                        self.submitted_at.map(|t| t.elapsed()).or(Some(elapsed));
                }
            }
        }
    }

    /// Blocks until the current generation is finished (or `timeout`), returning its results.
    pub fn wait(&mut self, timeout: Duration) -> Vec<Update> {
        let deadline = Instant::now() + timeout;
        let mut out = Vec::new();
        while !self.is_idle() {
            let left = deadline.saturating_duration_since(Instant::now());
            if left.is_zero() {
                break;
            }
            match self.messages.recv_timeout(left) {
                Ok(m) => self.accept(m, &mut out),
                Err(RecvTimeoutError::Timeout) => break,
                Err(RecvTimeoutError::Disconnected) => self.died(),
            }
        }
        out
    }

    /// The evaluator (node cache and evaluation counters).
    pub fn evaluator(&self) -> &Evaluator {
        &self.evaluator
    }

    /// Makes the coordinator thread panic, as a bug would (tests of the failure banner).
    #[doc(hidden)]
    pub fn crash_for_test(&self) {
        let _ = self.events.send(Event::Crash);
    }
}

impl Drop for Engine {
    fn drop(&mut self) {
        let _ = self.events.send(Event::Shutdown);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn memory_budget_parses_mib_and_names_the_variable_and_range() {
        assert_eq!(super::memory_budget(None), Ok(super::cache::DEFAULT_BUDGET));
        assert_eq!(super::memory_budget(Some("64")), Ok(64 << 20));
        for bad in ["0", "15", "abc", "-5", "1e3", "", "1048577"] {
            let e = super::memory_budget(Some(bad)).unwrap_err();
            assert!(
                e.contains("SAMPLESCOPE_MEMORY_MIB") && e.contains("16..=1048576"),
                "{e}"
            );
        }
    }
}
