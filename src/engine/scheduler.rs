//! The scheduler: turns a scene's plan into jobs on the rayon pool and results for the UI.
//!
//! It is a state machine driven by events (a new scene; a job's coarse result; a job's end)
//! on one thread — the engine's coordinator thread, or the caller of
//! [`super::Evaluator::evaluate`]. Each job runs on a thread of its own, so independent nodes
//! (of different columns, and within a column the response, reference, spectrum and samples)
//! run concurrently, and their parallel loops share rayon's pool piece by piece.
//!
//! Invariants:
//! - a node whose inputs are ready is started at once, unless a job for its key is running;
//! - a new scene cancels exactly the running jobs whose keys left the plan; a job whose key
//!   stayed keeps running and its result is used;
//! - every completed result is cached (in memory, bounded by bytes; reference images also on
//!   disk), even one that finishes after its key left the plan; a cancelled job caches nothing;
//! - each result is delivered, per column, with the generation and the scene snapshot of the
//!   plan it belongs to.

use super::cache::MemoryCache;
use super::disk_cache::DiskCache;
use crate::core::cancel::Cancel;
use crate::core::progress::Steps;
use crate::scene::graph::{NodeKey, NodeKind, NodeResult, Plan};
use crate::scene::node::{JobCtx, NodeError, Partial};
use crate::scene::Scene;
use std::collections::HashMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::Sender;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// A node result for one column of one generation.
#[derive(Clone)]
pub struct Update {
    pub generation: u64,
    pub column: usize,
    pub kind: NodeKind,
    /// The node's key (`None` when its key could not be made; the result is that error).
    pub key: Option<NodeKey>,
    /// The scene the result was computed for (labels and figures use it, never a newer one).
    pub scene: Arc<Scene>,
    pub result: Arc<NodeResult>,
    /// `Some` for a result published while the node works (a coarse one, or its final value
    /// before its readout, see `value_final`); `None` for the final result.
    pub progress: Option<Steps>,
    /// Whether the value is the node's final value, bit for bit: true for the final result and
    /// for a final value published before its accuracy readout (the spectrum before its
    /// measured error); false for a coarse result.
    pub value_final: bool,
}

/// What drives the scheduler.
pub(crate) enum Event {
    Submit {
        generation: u64,
        scene: Arc<Scene>,
        /// The scene's plan, made once by whoever submits (who also estimated its cost).
        plan: Arc<Plan>,
    },
    Progress {
        key: NodeKey,
        partial: Partial,
        wall: Duration,
    },
    Done {
        job: u64,
        key: NodeKey,
        /// `None` when the job was cancelled (nothing to keep).
        result: Option<NodeResult>,
    },
    /// Stops the coordinator (the engine is dropped).
    Shutdown,
    /// Makes the coordinator panic (tests of the failure banner).
    #[doc(hidden)]
    Crash,
}

/// Where the scheduler sends what it has.
pub(crate) trait Sink {
    fn node(&mut self, update: Update);
    fn finished(&mut self, generation: u64, elapsed: Duration);
}

/// State shared by the scheduler and its jobs: caches and evaluation counters.
pub(crate) struct Shared {
    pub cache: Mutex<MemoryCache>,
    pub disk: Option<DiskCache>,
    pub counts: [AtomicUsize; NodeKind::ALL.len()],
}

impl Shared {
    pub fn new(budget: usize, disk: Option<DiskCache>) -> Self {
        Shared {
            cache: Mutex::new(MemoryCache::new(budget)),
            disk,
            counts: Default::default(),
        }
    }

    pub fn cache(&self) -> std::sync::MutexGuard<'_, MemoryCache> {
        self.cache.lock().unwrap_or_else(|e| e.into_inner())
    }
}

struct Running {
    job: u64,
    cancel: Cancel,
}

/// A node of the active plan (unique by key; `columns` lists every column that shows it).
struct Planned {
    key: NodeKey,
    kind: NodeKind,
    columns: Vec<usize>,
    deps: Vec<(NodeKind, NodeKey)>,
}

struct Active {
    generation: u64,
    scene: Arc<Scene>,
    started: Instant,
    nodes: Vec<Planned>,
    index: HashMap<NodeKey, usize>,
    ready: HashMap<NodeKey, Arc<NodeResult>>,
    finished: bool,
}

pub(crate) struct Scheduler {
    shared: Arc<Shared>,
    events: Sender<Event>,
    running: HashMap<NodeKey, Running>,
    next_job: u64,
    active: Option<Active>,
}

impl Scheduler {
    pub fn new(shared: Arc<Shared>, events: Sender<Event>) -> Self {
        Scheduler {
            shared,
            events,
            running: HashMap::new(),
            next_job: 0,
            active: None,
        }
    }

    /// Whether the active plan has all its results.
    pub fn is_finished(&self) -> bool {
        self.active.as_ref().is_none_or(|a| a.finished)
    }

    /// Cancels every running job.
    pub fn cancel_all(&mut self) {
        for r in self.running.values() {
            r.cancel.cancel();
        }
        self.running.clear();
    }

    /// Handles one event; returns `false` on shutdown.
    pub fn handle(&mut self, event: Event, sink: &mut dyn Sink) -> bool {
        match event {
            Event::Submit {
                generation,
                scene,
                plan,
            } => self.submit(generation, scene, &plan, sink),
            Event::Progress { key, partial, wall } => self.progress(key, partial, wall, sink),
            Event::Done { job, key, result } => self.done(job, key, result, sink),
            Event::Shutdown => {
                self.cancel_all();
                return false;
            }
            Event::Crash => panic!("engine coordinator crash requested"),
        }
        true
    }

    fn submit(&mut self, generation: u64, scene: Arc<Scene>, plan: &Plan, sink: &mut dyn Sink) {
        let mut nodes: Vec<Planned> = Vec::new();
        let mut index = HashMap::new();
        let mut errors = Vec::new();
        for (c, column) in plan.iter().enumerate() {
            for n in &column.nodes {
                match &n.key {
                    Ok(key) => match index.get(key) {
                        Some(&i) => {
                            let p: &mut Planned = &mut nodes[i];
                            p.columns.push(c);
                        }
                        None => {
                            index.insert(*key, nodes.len());
                            nodes.push(Planned {
                                key: *key,
                                kind: n.kind,
                                columns: vec![c],
                                deps: n.deps.clone(),
                            });
                        }
                    },
                    Err(e) => errors.push((c, n.kind, NodeError::Key(e.clone()))),
                }
            }
        }
        // Cancel only the jobs whose keys left the plan; the others keep running.
        self.running.retain(|key, r| {
            let keep = index.contains_key(key);
            if !keep {
                r.cancel.cancel();
            }
            keep
        });
        let mut ready = HashMap::new();
        {
            let mut cache = self.shared.cache();
            for p in &nodes {
                if let Some(r) = cache.get(&p.key) {
                    ready.insert(p.key, r);
                }
            }
            cache.trim();
        }
        let active = Active {
            generation,
            scene: scene.clone(),
            started: Instant::now(),
            nodes,
            index,
            ready,
            finished: false,
        };
        for (c, kind, e) in errors {
            sink.node(Update {
                generation,
                column: c,
                kind,
                key: None,
                scene: scene.clone(),
                result: Arc::new(NodeResult::error(e)),
                progress: None,
                value_final: true,
            });
        }
        for p in &active.nodes {
            if let Some(r) = active.ready.get(&p.key) {
                deliver(&active, p, r.clone(), None, true, sink);
            }
        }
        self.active = Some(active);
        self.launch(sink);
    }

    /// Starts every node whose inputs are ready; a node whose input failed fails without
    /// running.
    fn launch(&mut self, sink: &mut dyn Sink) {
        let Some(active) = self.active.as_mut() else {
            return;
        };
        loop {
            let mut changed = false;
            for i in 0..active.nodes.len() {
                let p = &active.nodes[i];
                if active.ready.contains_key(&p.key) || self.running.contains_key(&p.key) {
                    continue;
                }
                let deps: Option<HashMap<NodeKind, Arc<NodeResult>>> = p
                    .deps
                    .iter()
                    .map(|(kind, key)| active.ready.get(key).map(|r| (*kind, r.clone())))
                    .collect();
                let Some(deps) = deps else {
                    continue;
                };
                if let Some(e) = failed_input(p.deps.iter().map(|(k, _)| (k, &deps[k]))) {
                    let r = Arc::new(NodeResult::error(e));
                    active.ready.insert(p.key, r.clone());
                    deliver(active, &active.nodes[i], r, None, true, sink);
                    changed = true;
                    continue;
                }
                self.next_job += 1;
                let job = self.next_job;
                let cancel = Cancel::new();
                self.running.insert(
                    p.key,
                    Running {
                        job,
                        cancel: cancel.clone(),
                    },
                );
                spawn_job(
                    self.shared.clone(),
                    self.events.clone(),
                    job,
                    p.key,
                    active.scene.clone(),
                    p.columns[0],
                    deps,
                    cancel,
                );
            }
            if !changed {
                break;
            }
        }
        self.check_finished(sink);
    }

    fn check_finished(&mut self, sink: &mut dyn Sink) {
        if let Some(a) = self.active.as_mut() {
            if !a.finished && a.nodes.iter().all(|p| a.ready.contains_key(&p.key)) {
                a.finished = true;
                sink.finished(a.generation, a.started.elapsed());
            }
        }
    }

    fn progress(&mut self, key: NodeKey, partial: Partial, wall: Duration, sink: &mut dyn Sink) {
        let Some(active) = self.active.as_ref() else {
            return;
        };
        let Some(&i) = active.index.get(&key) else {
            return;
        };
        if active.ready.contains_key(&key) || !self.running.contains_key(&key) {
            return;
        }
        let r = Arc::new(NodeResult {
            value: Ok(partial.value),
            wall,
            accuracy: partial.accuracy,
        });
        let value_final = partial.value_final;
        deliver(
            active,
            &active.nodes[i],
            r,
            Some(partial.progress),
            value_final,
            sink,
        );
    }

    fn done(&mut self, job: u64, key: NodeKey, result: Option<NodeResult>, sink: &mut dyn Sink) {
        if self.running.get(&key).is_some_and(|r| r.job == job) {
            self.running.remove(&key);
        }
        let Some(result) = result else {
            // Cancelled: if the key is (again) in the plan, a fresh job is needed.
            self.launch(sink);
            return;
        };
        let result = Arc::new(result);
        self.shared.cache().insert(key, result.clone());
        if let Some(active) = self.active.as_mut() {
            if let Some(&i) = active.index.get(&key) {
                if let std::collections::hash_map::Entry::Vacant(e) = active.ready.entry(key) {
                    e.insert(result.clone());
                    deliver(active, &active.nodes[i], result, None, true, sink);
                }
            }
        }
        self.launch(sink);
    }
}

fn deliver(
    active: &Active,
    p: &Planned,
    result: Arc<NodeResult>,
    progress: Option<Steps>,
    value_final: bool,
    sink: &mut dyn Sink,
) {
    for &c in &p.columns {
        sink.node(Update {
            generation: active.generation,
            column: c,
            kind: p.kind,
            key: Some(p.key),
            scene: active.scene.clone(),
            result: result.clone(),
            progress,
            value_final,
        });
    }
}

#[allow(clippy::too_many_arguments)]
fn spawn_job(
    shared: Arc<Shared>,
    events: Sender<Event>,
    job: u64,
    key: NodeKey,
    scene: Arc<Scene>,
    column: usize,
    deps: HashMap<NodeKind, Arc<NodeResult>>,
    cancel: Cancel,
) {
    // Each job drives its node on a thread of its own; the node's parallel loops run on
    // rayon's pool. (Jobs spawned *into* the pool would let a worker that waits inside one
    // node's parallel loop pick up a whole other node, delaying the first by that node's full
    // time; from outside the pool, nodes share the workers loop piece by loop piece.)
    let failed_events = events.clone();
    let spawned = std::thread::Builder::new()
        .name(format!("samplescope-{}", key.kind.name()))
        .spawn(move || {
            let start = Instant::now();
            let def = key.kind.def();
            if def.disk_cached {
                if let Some(r) = shared
                    .disk
                    .as_ref()
                    .and_then(|d| super::disk::load(d, &key))
                {
                    let _ = events.send(Event::Done {
                        job,
                        key,
                        result: Some(r),
                    });
                    return;
                }
            }
            // Counted once it really computes (a disk-cache hit is not an evaluation).
            shared.counts[key.kind as usize].fetch_add(1, Ordering::Relaxed);
            let progress_events = events.clone();
            let progress = move |partial: Partial| {
                let _ = progress_events.send(Event::Progress {
                    key,
                    partial,
                    wall: start.elapsed(),
                });
            };
            let ctx = JobCtx {
                scene: &scene,
                column,
                deps: &deps,
                cancel: &cancel,
                progress: &progress,
            };
            let result = run_job(key.kind, &ctx);
            if let (Some(r), Some(d)) = (&result, shared.disk.as_ref()) {
                if def.disk_cached {
                    super::disk::store(d, &key, r);
                }
            }
            let _ = events.send(Event::Done { job, key, result });
        });
    if let Err(e) = spawned {
        let _ = failed_events.send(Event::Done {
            job,
            key,
            result: Some(NodeResult::error(NodeError::Thread(e.to_string()))),
        });
    }
}

/// Runs the job of `kind` in `ctx`: its result with its wall time, a panic turned into an
/// error, or `None` when it stopped because `ctx.cancel` fired (a job that completed is kept
/// even if it was cancelled meanwhile).
pub(crate) fn run_job(kind: NodeKind, ctx: &JobCtx) -> Option<NodeResult> {
    let start = Instant::now();
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| (kind.def().run)(ctx)));
    let (value, accuracy) = match outcome {
        Err(_) | Ok(Err(_)) if ctx.cancel.is_cancelled() => return None,
        Ok(Ok((value, accuracy))) => (Ok(value), accuracy),
        Ok(Err(e)) => (Err(e), None),
        Err(panic) => (Err(NodeError::Panic(panic_message(panic))), None),
    };
    Some(NodeResult {
        value,
        wall: start.elapsed(),
        accuracy,
    })
}

/// The error of a node one of whose inputs failed ("<input> failed: <its error>", the first
/// failed input in the given order, which callers take from the node table), if any.
pub(crate) fn failed_input<'a>(
    inputs: impl IntoIterator<Item = (&'a NodeKind, &'a Arc<NodeResult>)>,
) -> Option<NodeError> {
    inputs.into_iter().find_map(|(k, r)| {
        r.value.as_ref().err().map(|e| NodeError::Input {
            input: *k,
            cause: Arc::new(e.clone()),
        })
    })
}

fn panic_message(panic: Box<dyn std::any::Any + Send>) -> String {
    let text = panic
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "unknown panic".into());
    text
}
