//! The nodes: one file each, holding everything the node is (its inputs: the nodes and scene
//! fields it reads; its job; its estimate), and [`node_list!`], the one list of them (kind,
//! data type, name, algorithm version, disk caching, heap bytes, file). The vocabulary
//! (`node::NodeKind`, `NodeValue`) and the node table (`graph::NODES`) are expanded from the
//! list. A new node is its file here with its `mod` line and its entry in the list (a panel
//! asks for it in its entry of the panel list; `analyze` asks by name).
//!
//! A job gets the scene, its column and the results of the inputs it declared, and returns
//! plain `model` data; these files import the graph's vocabulary (`node`), never the graph.

pub(super) mod convergence;
pub(super) mod error;
pub(super) mod integration;
pub(super) mod net_prefixes;
pub(super) mod points;
pub(super) mod psa;
pub(super) mod rdf;
pub(super) mod reconstruction;
pub(super) mod reference;
pub(super) mod response;
pub(super) mod samples;
pub(super) mod spectrum;
pub(super) mod statistics;
pub(super) mod theorem;

pub use convergence::{CONVERGENCE_SIZE, CONVERGENCE_SPP};
pub use integration::{integrand_thumbnail, INTEGRAND_THUMBNAIL};
pub use points::POINTS_PARTIAL_INTERVAL;
pub use reconstruction::{PREVIEW_DIVISOR, PREVIEW_SAMPLES};
pub use response::{RESPONSE_IMAGE_SIZE, RESPONSE_OMEGA_MAX};
pub use spectrum::spectrum_data;

/// The list of nodes, in an order where every node comes after its inputs (the evaluation
/// order). It calls `$then!` with one entry per node:
///
/// ```text
/// /// doc of the node
/// Kind(data type) {
///     name: "…",            // its display name (also part of its key)
///     version: n,           // its algorithm's version, part of the key: bump it whenever
///                           // the job computes other numbers for the same inputs, so that
///                           // no cache (the disk cache above all) serves the old ones
///     disk_cached: bool,    // whether its result is kept on disk across runs
///     bytes: |data| …,      // the approximate heap bytes of its data (the cache budget)
///     file: module,         // its file here: `inputs`, `run` (the job) and `estimate`
/// }
/// ```
macro_rules! node_list {
    ($then:path) => {
        $crate::scene::compute::node_project! {
            $then;
            Points(crate::model::PointsData) {
                name: "points",
                version: 1,
                disk_cached: false,
                bytes: |p| p.points.len() * 16 + p.gpu.len() * 8,
                file: points,
            }
            /// PSA's statistics (an input of `Statistics` for the N its overlay shows them at).
            Psa(crate::model::PsaData) {
                name: "PSA statistics",
                version: 1,
                disk_cached: false,
                bytes: |_| std::mem::size_of::<crate::model::PsaData>(),
                file: psa,
            }
            Statistics(crate::model::StatsData) {
                name: "statistics",
                version: 1,
                disk_cached: false,
                bytes: |s| {
                    std::mem::size_of::<crate::model::StatsData>() + s.full.timings.len() * 32
                },
                file: statistics,
            }
            Spectrum(crate::model::SpectrumData) {
                name: "spectrum",
                version: 1,
                disk_cached: false,
                bytes: |s| {
                    s.image.values.len() * 4
                        + (s.raps.len() + s.anisotropy.len()) * 16
                        + s.power.power.len() * 8
                },
                file: spectrum,
            }
            Samples(Vec<f64>) {
                name: "samples",
                version: 1,
                disk_cached: false,
                bytes: |v| v.len() * 8,
                file: samples,
            }
            Reconstruction(crate::model::ReconData) {
                name: "reconstruction",
                version: 1,
                disk_cached: false,
                // The f64 pixels and the zero-weight mask besides the display image.
                bytes: |r| r.image.values.len() * 4 + r.exact.pixels.len() * 9,
                file: reconstruction,
            }
            Reference(crate::model::ReferenceData) {
                name: "reference",
                // 2: separable quadrature for the zone plate and the chirp.
                version: 2,
                disk_cached: true,
                bytes: |r| r.image.values.len() * 4 + r.pixels.len() * 8,
                file: reference,
            }
            Error(crate::model::ErrorData) {
                name: "error",
                // 2: RMSE and PSNR over the f64 pixels (core's error report).
                version: 2,
                disk_cached: false,
                bytes: |e| e.image.values.len() * 4,
                file: error,
            }
            Response(crate::model::ResponseData) {
                name: "filter response",
                version: 1,
                disk_cached: false,
                bytes: |r| r.image.values.len() * 4 + (r.kernel.len() + r.magnitude.len()) * 16,
                file: response,
            }
            Convergence(Vec<crate::model::ConvergencePoint>) {
                name: "convergence",
                version: 1,
                disk_cached: false,
                bytes: |c| c.len() * std::mem::size_of::<crate::model::ConvergencePoint>(),
                file: convergence,
            }
            /// The 1D sampling-theorem view (column-independent: computed for column 0 only).
            Theorem(crate::model::TheoremView) {
                name: "sampling theorem",
                version: 1,
                disk_cached: false,
                bytes: |t| t.approx_bytes(),
                file: theorem,
            }
            /// The integration-error study of the column's pattern.
            Integration(crate::model::IntegrationData) {
                name: "integration error",
                version: 1,
                disk_cached: false,
                bytes: |i| {
                    i.study.rows.len() * std::mem::size_of::<crate::core::integration::StudyRow>()
                        + i.thumbnail.values.len() * 4
                },
                file: integration,
            }
            /// PSA's radial distribution function (read by `analyze --rdf`, by no panel).
            Rdf(crate::model::Rdf) {
                name: "RDF",
                version: 1,
                disk_cached: false,
                bytes: |r| r.values().len() * 8,
                file: rdf,
            }
            /// The (0,k,2)-net check of the power-of-two prefixes (read by `analyze`, by no
            /// panel).
            NetPrefixes(crate::model::NetPrefixes) {
                name: "net prefixes",
                version: 1,
                disk_cached: false,
                bytes: |p| {
                    p.prefixes.len() * std::mem::size_of::<crate::core::metrics::PrefixCheck>()
                },
                file: net_prefixes,
            }
        }
    };
}
pub(crate) use node_list;

/// Reads the entries of [`node_list!`] (the one place their grammar is written) and hands
/// `$then!` two views of them: the vocabulary (`kinds`: doc, kind, data type, name, version,
/// bytes) and the table (`table`: kind, file, disk caching).
macro_rules! node_project {
    ($then:path; $(
        $(#[$doc:meta])*
        $kind:ident($ty:ty) {
            name: $name:literal,
            version: $version:literal,
            disk_cached: $disk:literal,
            bytes: $bytes:expr,
            file: $file:ident $(,)?
        }
    )*) => {
        $then! {
            kinds: [$($(#[$doc])* $kind($ty) $name $version ($bytes);)*]
            table: [$($kind $file $disk;)*]
        }
    };
}
pub(crate) use node_project;

/// What every node file uses.
mod prelude {
    pub(super) use super::{dep, ms, n_of, points_of};
    pub(super) use crate::core::budget::{self, Estimate};
    pub(super) use crate::core::progress::{Progress, Steps, Throttle};
    pub(super) use crate::core::recon::image_plane::{ImagePlaneProvider, ZSobolProvider};
    pub(super) use crate::core::recon::supersample::SampleProvider;
    pub(super) use crate::model::{
        next_version, Accuracy, ConvergencePoint, ErrorData, ImageData, IntegrationData,
        PointsData, PsaData, ReconData, ReferenceData, ResponseData, ResponseMetrics, SpectrumData,
        StatsData,
    };
    pub(super) use crate::scene::node::{Inputs, JobCtx, NodeError, NodeKind, NodeValue, Output};
    pub(super) use crate::scene::{PixelSampling, ReconMode, Scene};
    pub(super) use std::sync::Arc;
    pub(super) use std::time::Duration;
}

use crate::core::progress::Steps;
use crate::model::{Accuracy, PointsData};
use crate::scene::node::{Deps, JobCtx, NodeError, NodeKind, NodeValue, Partial};
use std::sync::Arc;
use std::time::Duration;

/// The number of points of column `c`: its imported set's, else the scene's N (known before
/// the points are).
fn n_of(s: &crate::scene::Scene, c: usize) -> usize {
    s.columns[c].points.as_ref().map_or(s.n, |p| p.points.len())
}

impl JobCtx<'_> {
    fn col(&self) -> &super::Column {
        &self.scene.columns[self.column]
    }

    /// Publishes a coarse value while the node refines, `progress` of the way (never the
    /// last step: the job returns that).
    fn publish(&self, value: NodeValue, accuracy: Option<Accuracy>, progress: Steps) {
        (self.progress)(Partial {
            value,
            accuracy,
            progress,
        })
    }
}

fn dep(done: &Deps, kind: NodeKind) -> Result<&NodeValue, NodeError> {
    match done.get(&kind).map(|r| &r.value) {
        Some(Ok(v)) => Ok(v),
        Some(Err(e)) => Err(NodeError::Input {
            input: kind,
            cause: Arc::new(e.clone()),
        }),
        None => Err(NodeError::Internal(format!(
            "the {} input is missing",
            kind.name()
        ))),
    }
}

fn points_of(done: &Deps) -> Result<Arc<PointsData>, NodeError> {
    match dep(done, NodeKind::Points)? {
        NodeValue::Points(p) => Ok(p.clone()),
        _ => Err(NodeError::Internal(
            "the points input has another kind".into(),
        )),
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

#[cfg(test)]
mod tests {
    use crate::scene::graph::{NodeKind, NODES};
    use crate::scene::{ReconMode, Scene};

    #[test]
    fn the_list_gives_each_node_its_row_a_unique_name_and_inputs_that_come_before_it() {
        for (i, d) in NODES.iter().enumerate() {
            assert_eq!(d.kind as usize, i);
            assert_eq!(NodeKind::ALL[i], d.kind);
            let same = NodeKind::ALL.iter().filter(|k| k.name() == d.kind.name());
            assert_eq!(same.count(), 1, "{}", d.kind.name());
        }
        let mut scenes = Vec::new();
        for mode in [
            ReconMode::Scattered,
            ReconMode::Resample { grid: 64 },
            ReconMode::Supersample { spp: 4 },
        ] {
            let mut s = Scene::default();
            s.recon.mode = mode;
            for n in [64, 5000] {
                s.n = n;
                scenes.push(s.clone());
            }
        }
        for s in &scenes {
            for d in &NODES {
                for input in (d.inputs)(s, 0).nodes {
                    assert!(input < d.kind, "{} reads {}", d.kind.name(), input.name());
                }
                assert!(!(d.estimate)(s, 0).is_empty() || d.kind == NodeKind::Points);
            }
        }
    }
}
