//! The vocabulary of the compute graph: node kinds, keys, values, results and errors, and
//! what a job sees. [`super::graph`] plans with it and [`super::compute`] fills it; neither
//! imports the other's types from the other.

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
use crate::model::{
    ConvergencePoint, ErrorData, ImageData, IntegrationData, NetPrefixes, PointsData, PsaData, Rdf,
    ReconData, ReferenceData, ResponseData, SpectrumData, StatsData,
};
use serde::Serialize;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::sync::Arc;
use std::time::Duration;

/// The kinds of node, in an order where every node comes after its inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum NodeKind {
    Points,
    /// PSA's statistics (an input of `Statistics` for the N its overlay shows them at).
    Psa,
    Statistics,
    Spectrum,
    Samples,
    Reconstruction,
    Reference,
    Error,
    Response,
    Convergence,
    /// The 1D sampling-theorem view (column-independent: computed for column 0 only).
    Theorem,
    /// The integration-error study of the column's pattern.
    Integration,
    /// PSA's radial distribution function (read by `analyze --rdf`, by no panel).
    Rdf,
    /// The (0,k,2)-net check of the power-of-two prefixes (read by `analyze`, by no panel).
    NetPrefixes,
}

impl NodeKind {
    /// Every kind, in dependency (evaluation) order.
    pub const ALL: [NodeKind; 14] = [
        NodeKind::Points,
        NodeKind::Psa,
        NodeKind::Statistics,
        NodeKind::Spectrum,
        NodeKind::Samples,
        NodeKind::Reconstruction,
        NodeKind::Reference,
        NodeKind::Error,
        NodeKind::Response,
        NodeKind::Convergence,
        NodeKind::Theorem,
        NodeKind::Integration,
        NodeKind::Rdf,
        NodeKind::NetPrefixes,
    ];

    /// Display name.
    pub fn name(self) -> &'static str {
        match self {
            NodeKind::Points => "points",
            NodeKind::Psa => "PSA statistics",
            NodeKind::Statistics => "statistics",
            NodeKind::Spectrum => "spectrum",
            NodeKind::Samples => "samples",
            NodeKind::Reconstruction => "reconstruction",
            NodeKind::Reference => "reference",
            NodeKind::Error => "error",
            NodeKind::Response => "filter response",
            NodeKind::Convergence => "convergence",
            NodeKind::Theorem => "sampling theorem",
            NodeKind::Integration => "integration error",
            NodeKind::Rdf => "RDF",
            NodeKind::NetPrefixes => "net prefixes",
        }
    }
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

/// The value of a node.
#[derive(Debug, Clone)]
pub enum NodeValue {
    Points(Arc<PointsData>),
    /// PSA's statistics, or why they were skipped.
    Psa(Arc<PsaData>),
    Statistics(Arc<StatsData>),
    Spectrum(Arc<SpectrumData>),
    Samples(Arc<Vec<f64>>),
    Reconstruction(Arc<ReconData>),
    Reference(Arc<ReferenceData>),
    Error(Arc<ErrorData>),
    Response(Arc<ResponseData>),
    Convergence(Arc<Vec<ConvergencePoint>>),
    /// The 1D sampling-theorem view.
    Theorem(Arc<crate::core::signal::theorem::TheoremView>),
    /// The integration-error study.
    Integration(Arc<IntegrationData>),
    /// PSA's radial distribution function.
    Rdf(Arc<Rdf>),
    /// The (0,k,2)-net check of the power-of-two prefixes.
    NetPrefixes(Arc<NetPrefixes>),
}

/// The results of a node's declared inputs, by kind.
pub type Deps = HashMap<NodeKind, Arc<NodeResult>>;

/// What a job returns: its value and the accuracy reached, or the error that stopped it.
pub type Output = Result<(NodeValue, Option<Accuracy>), NodeError>;

/// A coarse result a node publishes while it refines, `progress` of the way (the last step
/// is the node's final result and is returned, not published).
pub struct Partial {
    pub value: NodeValue,
    pub accuracy: Option<Accuracy>,
    pub progress: Steps,
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

impl NodeValue {
    /// Approximate heap bytes held by the value (what the cache budget counts).
    pub fn bytes(&self) -> usize {
        let img = |i: &ImageData| i.values.len() * 4;
        let pairs = |v: &Vec<[f64; 2]>| v.len() * 16;
        match self {
            NodeValue::Points(p) => p.points.len() * 16 + p.gpu.len() * 8,
            NodeValue::Psa(_) => std::mem::size_of::<PsaData>(),
            NodeValue::Statistics(s) => {
                std::mem::size_of::<StatsData>() + s.full.timings.len() * 32
            }
            NodeValue::Spectrum(s) => {
                img(&s.image) + pairs(&s.raps) + pairs(&s.anisotropy) + s.power.power.len() * 8
            }
            NodeValue::Samples(v) => v.len() * 8,
            // The f64 pixels and the zero-weight mask besides the display image.
            NodeValue::Reconstruction(r) => img(&r.image) + r.exact.pixels.len() * 9,
            NodeValue::Reference(r) => img(&r.image) + r.pixels.len() * 8,
            NodeValue::Error(e) => img(&e.image),
            NodeValue::Response(r) => img(&r.image) + pairs(&r.kernel) + pairs(&r.magnitude),
            NodeValue::Convergence(c) => c.len() * std::mem::size_of::<ConvergencePoint>(),
            NodeValue::Theorem(t) => t.approx_bytes(),
            NodeValue::Integration(i) => {
                i.study.rows.len() * std::mem::size_of::<crate::core::integration::StudyRow>()
                    + i.thumbnail.values.len() * 4
            }
            NodeValue::Rdf(r) => r.values().len() * 8,
            NodeValue::NetPrefixes(p) => {
                p.prefixes.len() * std::mem::size_of::<crate::core::metrics::PrefixCheck>()
            }
        }
    }
}
