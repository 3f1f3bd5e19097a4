//! The vocabulary of the compute graph: node kinds and values (expanded from the node list,
//! `compute::node_list!`), keys and what they hash (`Inputs`), results, errors, and what a
//! job sees. [`super::graph`] plans with it and the nodes' files in [`super::compute`] fill
//! it; they never import the graph.

use super::Scene;
use crate::core::cancel::{Cancel, Cancelled};
use crate::core::filter::FilterError;
use crate::core::metrics::MetricsError;
use crate::core::pattern::PatternError;
use crate::core::progress::Steps;
use crate::core::recon::ReconError;
use crate::core::signal::theorem::TheoremError;
use crate::core::spectrum::SpectrumError;
use crate::model::Accuracy;
use serde::Serialize;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::sync::Arc;
use std::time::Duration;

/// Expands the node list (`compute::node_list!`) into [`NodeKind`] (with its order, names and
/// versions) and [`NodeValue`] (with its heap bytes).
macro_rules! vocabulary {
    (
        kinds: [$($(#[$doc:meta])* $kind:ident($ty:ty) $name:literal $version:literal ($bytes:expr);)*]
        $($rest:tt)*
    ) => {
        /// The kinds of node, in an order where every node comes after its inputs.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
        pub enum NodeKind {
            $($(#[$doc])* $kind,)*
        }

        impl NodeKind {
            /// Every kind, in dependency (evaluation) order.
            pub const ALL: [NodeKind; [$(NodeKind::$kind),*].len()] = [$(NodeKind::$kind),*];

            /// Display name.
            pub fn name(self) -> &'static str {
                match self {
                    $(NodeKind::$kind => $name,)*
                }
            }

            /// The version of the node's algorithm, part of its key.
            pub fn version(self) -> u32 {
                match self {
                    $(NodeKind::$kind => $version,)*
                }
            }
        }

        /// The value of a node.
        #[derive(Debug, Clone)]
        pub enum NodeValue {
            $($(#[$doc])* $kind(Arc<$ty>),)*
        }

        impl NodeValue {
            /// Approximate heap bytes held by the value (what the cache budget counts).
            pub fn bytes(&self) -> usize {
                match self {
                    $(NodeValue::$kind(v) => bytes_of(v.as_ref(), $bytes),)*
                }
            }
        }
    };
}

super::compute::node_list!(vocabulary);

/// `bytes(v)`: the list's byte count of a node's data, its closure typed by `T`.
fn bytes_of<T: ?Sized>(v: &T, bytes: impl Fn(&T) -> usize) -> usize {
    bytes(v)
}

/// A node's identity: its kind and the BLAKE3 hash of everything it depends on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct NodeKey {
    pub kind: NodeKind,
    pub hash: [u8; 32],
}

impl NodeKey {
    /// The hash as 64 lowercase hex digits (file names of the disk cache).
    pub fn hex(&self) -> String {
        let mut s = String::with_capacity(64);
        for b in self.hash {
            let _ = write!(s, "{b:02x}");
        }
        s
    }
}

/// Why a node's key could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind} node: its inputs cannot be keyed: {message}")]
pub struct KeyError {
    pub kind: &'static str,
    pub message: String,
}

/// A node's result: its value or the error that stopped it, what it cost, and its accuracy.
#[derive(Debug, Clone)]
pub struct NodeResult {
    pub value: Result<NodeValue, NodeError>,
    /// Wall time of this evaluation (of the original evaluation for cache hits).
    pub wall: Duration,
    /// Accuracy reached, where defined (e.g. the measured error of a fast spectrum).
    pub accuracy: Option<Accuracy>,
}

impl NodeResult {
    /// A result that is only an error.
    pub fn error(error: NodeError) -> Self {
        NodeResult {
            value: Err(error),
            wall: Duration::ZERO,
            accuracy: None,
        }
    }

    /// Approximate heap bytes held (the cache budget counts these).
    pub fn bytes(&self) -> usize {
        let base = std::mem::size_of::<Self>();
        base + match &self.value {
            Ok(v) => v.bytes(),
            Err(_) => std::mem::size_of::<NodeError>(),
        }
    }
}

/// Why a node has no value. Errors of `core` keep their own type (and message); the others
/// say which input failed, or what the scene asks that the node cannot do.
#[derive(Debug, Clone, thiserror::Error)]
pub enum NodeError {
    #[error(transparent)]
    Pattern(#[from] PatternError),
    #[error(transparent)]
    Filter(#[from] FilterError),
    #[error(transparent)]
    Metrics(#[from] MetricsError),
    #[error(transparent)]
    Recon(#[from] ReconError),
    #[error(transparent)]
    Spectrum(Arc<SpectrumError>),
    #[error(transparent)]
    Theorem(#[from] TheoremError),
    #[error(transparent)]
    Study(#[from] crate::core::integration::StudyError),
    /// The job stopped because its token was cancelled.
    #[error("cancelled")]
    Cancelled,
    /// The node's key could not be made (it never ran).
    #[error(transparent)]
    Key(#[from] KeyError),
    /// An input node failed, so this one did not run.
    #[error("{} failed: {cause}", input.name())]
    Input {
        input: NodeKind,
        cause: Arc<NodeError>,
    },
    /// A node that draws fresh samples in every pixel, on a column of imported points.
    #[error(
        "column {} shows imported points: {what} needs a pattern that generates new samples \
         for every pixel; use scattered reconstruction, or a pattern in this column",
        column + 1
    )]
    ImportedNeedsPattern { column: usize, what: &'static str },
    /// A node that draws fresh 2D samples in every pixel, on a column shown as a projection of
    /// its points in D dimensions.
    #[error(
        "column {} shows dims = {dims}, project {project:?}: {what} draws fresh 2D samples in \
         every pixel; use scattered reconstruction, or dims 2 with project (0, 1)",
        column + 1
    )]
    ProjectedNeedsPattern {
        column: usize,
        dims: usize,
        project: (usize, usize),
        what: &'static str,
    },
    /// The integration study on a column of imported points (they have one N).
    #[error(
        "column {} shows imported points: the integration study needs a pattern that makes \
         every N of its curve",
        column + 1
    )]
    ImportedNoStudy { column: usize },
    /// The scene's filter cannot reconstruct (H(0) = 0: band-pass, high-pass, cosc).
    #[error("{0}")]
    CannotReconstruct(String),
    /// The job panicked (a bug; the message is the panic's).
    #[error("internal error (panic): {0}")]
    Panic(String),
    /// The job's thread could not be started.
    #[error("cannot start a thread for the job: {0}")]
    Thread(String),
    /// An input the plan declares is absent or of another kind (a bug of the node table).
    #[error("internal error: {0}")]
    Internal(String),
}

impl From<SpectrumError> for NodeError {
    fn from(e: SpectrumError) -> Self {
        NodeError::Spectrum(Arc::new(e))
    }
}

impl From<Cancelled> for NodeError {
    fn from(_: Cancelled) -> Self {
        NodeError::Cancelled
    }
}

/// The results of a node's declared inputs, by kind.
pub type Deps = HashMap<NodeKind, Arc<NodeResult>>;

/// What a job returns: its value and the accuracy reached, or the error that stopped it.
pub type Output = Result<(NodeValue, Option<Accuracy>), NodeError>;

/// A result a node publishes before it returns, `progress` of the way (the last step is the
/// node's final result and is returned, not published): a coarse value while it refines, or
/// (`value_final`) its final value while only its accuracy readout is still being measured.
pub struct Partial {
    pub value: NodeValue,
    pub accuracy: Option<Accuracy>,
    pub progress: Steps,
    /// The value is the node's final value, bit for bit (the picture is complete); only the
    /// accuracy follows with the returned result (the spectrum before its measured error).
    pub value_final: bool,
}

/// Everything a job sees: the scene, its column, its declared inputs' results, its own
/// cancellation token, and where to publish coarse results.
pub struct JobCtx<'a> {
    pub scene: &'a Scene,
    pub column: usize,
    pub deps: &'a Deps,
    pub cancel: &'a Cancel,
    pub progress: &'a (dyn Fn(Partial) + Sync),
}

/// A `fmt::Write` that feeds BLAKE3 (RON text is streamed, never built in memory).
struct HashWriter(blake3::Hasher);

impl std::fmt::Write for HashWriter {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.0.update(s.as_bytes());
        Ok(())
    }
}

/// A hasher fed with a node's kind and the RON text of its scene fields.
fn fields_hasher(
    kind: NodeKind,
    fields: &(impl Serialize + ?Sized),
) -> Result<blake3::Hasher, KeyError> {
    let mut w = HashWriter(blake3::Hasher::new());
    w.0.update(b"samplescope-node-v1\0");
    w.0.update(kind.name().as_bytes());
    w.0.update(b"\0");
    w.0.update(&kind.version().to_le_bytes());
    ron::ser::to_writer(&mut w, fields).map_err(|e| KeyError {
        kind: kind.name(),
        message: e.to_string(),
    })?;
    w.0.update(b"\0");
    Ok(w.0)
}

fn finish_key(kind: NodeKind, mut h: blake3::Hasher, deps: &[NodeKey]) -> NodeKey {
    for d in deps {
        h.update(&d.hash);
    }
    NodeKey {
        kind,
        hash: *h.finalize().as_bytes(),
    }
}

/// The key of a `kind` node whose scene fields are `fields` and whose input nodes have `deps`.
pub fn key_of(
    kind: NodeKind,
    fields: &(impl Serialize + ?Sized),
    deps: &[NodeKey],
) -> Result<NodeKey, KeyError> {
    Ok(finish_key(kind, fields_hasher(kind, fields)?, deps))
}

/// What a node reads: the nodes it takes results from and its scene fields (hashed).
pub struct Inputs {
    pub nodes: Vec<NodeKind>,
    fields: Result<FieldsOf, KeyError>,
}

/// The scene fields of a node, already fed to the key's hasher.
struct FieldsOf {
    kind: NodeKind,
    hasher: blake3::Hasher,
}

impl Inputs {
    /// A `kind` node with input nodes `nodes` and scene fields `fields` (anything serialisable).
    pub fn new(kind: NodeKind, nodes: &[NodeKind], fields: impl Serialize) -> Self {
        Inputs {
            nodes: nodes.to_vec(),
            fields: fields_hasher(kind, &fields).map(|hasher| FieldsOf { kind, hasher }),
        }
    }

    pub(super) fn key(&self, deps: &[NodeKey]) -> Result<NodeKey, KeyError> {
        match &self.fields {
            Ok(f) => Ok(finish_key(f.kind, f.hasher.clone(), deps)),
            Err(e) => Err(e.clone()),
        }
    }
}
