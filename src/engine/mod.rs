//! The worker that evaluates scenes off the UI thread.
//!
//! The UI submits the whole scene after every change; the engine cancels the job in flight
//! (cooperatively: the hot loops check a [`Cancel`] token), evaluates the new scene on its worker
//! thread (rayon inside the nodes), and sends each node's result back over a channel as soon as
//! it is ready, calling `repaint` so the UI wakes up. Every request carries a generation number;
//! results of older generations are dropped. A panic inside a node becomes an error on that
//! node's panel; the worker keeps running.

use crate::core::cancel::Cancel;
use crate::scene::graph::{Evaluator, NodeKind, NodeResult};
use crate::scene::Scene;
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A node result for one column of one generation.
#[derive(Clone)]
pub struct Update {
    pub generation: u64,
    pub column: usize,
    pub kind: NodeKind,
    pub result: Arc<NodeResult>,
}

/// What the worker sends back.
enum Message {
    Node(Update),
    Finished { generation: u64, elapsed: Duration },
}

struct Request {
    generation: u64,
    scene: Scene,
    cancel: Cancel,
}

/// A callback that wakes the UI (egui's `request_repaint`).
pub type Repaint = Arc<dyn Fn() + Send + Sync>;

/// Owns the worker thread and the node cache.
pub struct Engine {
    requests: Sender<Request>,
    messages: Receiver<Message>,
    cancel: Cancel,
    generation: u64,
    finished_generation: u64,
    submitted_at: Option<Instant>,
    /// Time from the last submit until all of its nodes were ready.
    pub last_update_time: Option<Duration>,
    evaluator: Arc<Evaluator>,
}

impl Engine {
    /// Starts the worker thread. `repaint` is called whenever a result is ready.
    pub fn new(repaint: Repaint) -> Engine {
        let (req_tx, req_rx) = channel::<Request>();
        let (msg_tx, msg_rx) = channel::<Message>();
        let evaluator = Arc::new(Evaluator::default());
        let worker_eval = evaluator.clone();
        std::thread::Builder::new()
            .name("samplescope-engine".into())
            .spawn(move || worker(req_rx, msg_tx, worker_eval, repaint))
            .map_err(|e| eprintln!("cannot start the engine thread: {e}"))
            .ok();
        Engine {
            requests: req_tx,
            messages: msg_rx,
            cancel: Cancel::new(),
            generation: 0,
            finished_generation: 0,
            submitted_at: None,
            last_update_time: None,
            evaluator,
        }
    }

    /// Submits a scene; cancels the job in flight. Returns the new generation.
    pub fn submit(&mut self, scene: &Scene) -> u64 {
        self.cancel.cancel();
        self.cancel = Cancel::new();
        self.generation += 1;
        self.submitted_at = Some(Instant::now());
        let _ = self.requests.send(Request {
            generation: self.generation,
            scene: scene.clone(),
            cancel: self.cancel.clone(),
        });
        self.generation
    }

    /// The generation of the latest submit.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Whether the latest submit has finished.
    pub fn is_idle(&self) -> bool {
        self.finished_generation >= self.generation
    }

    /// Results that arrived since the last poll, of the current generation only.
    pub fn poll(&mut self) -> Vec<Update> {
        let mut out = Vec::new();
        while let Ok(m) = self.messages.try_recv() {
            self.accept(m, &mut out);
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
                Err(_) => break,
            }
        }
        out
    }

    /// The evaluator (node cache and evaluation counters).
    pub fn evaluator(&self) -> &Arc<Evaluator> {
        &self.evaluator
    }
}

impl Drop for Engine {
    fn drop(&mut self) {
        self.cancel.cancel();
    }
}

fn worker(
    requests: Receiver<Request>,
    messages: Sender<Message>,
    eval: Arc<Evaluator>,
    repaint: Repaint,
) {
    while let Ok(mut req) = requests.recv() {
        // Skip requests that a newer one already superseded.
        while let Ok(newer) = requests.try_recv() {
            req = newer;
        }
        let start = Instant::now();
        let generation = req.generation;
        eval.evaluate(&req.scene, &req.cancel, &mut |column, kind, result| {
            let _ = messages.send(Message::Node(Update {
                generation,
                column,
                kind,
                result,
            }));
            repaint();
        });
        if !req.cancel.is_cancelled() {
            let _ = messages.send(Message::Finished {
                generation,
                elapsed: start.elapsed(),
            });
            repaint();
        }
    }
}
