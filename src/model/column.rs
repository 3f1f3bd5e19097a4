//! A column's data as the figures read it.

use super::{
    ConvergencePoint, ErrorData, IntegrationData, IntegrationPlot, PointsData, ReconData,
    ReferenceData, ResponseData, SpectrumData, TheoremView,
};
use std::sync::Arc;

/// The data of one column, as the compute graph produced it; `None` where a node was not
/// computed (hidden panel, effect off, still running or failed). The scene side fills it
/// from a column's node results (`scene::figure::column_data`).
#[derive(Debug, Clone, Default)]
pub struct ColumnData {
    /// The points (pattern figure).
    pub points: Option<Arc<PointsData>>,
    /// The periodogram and its radial average (spectrum and RAPS figures).
    pub spectrum: Option<Arc<SpectrumData>>,
    /// The reconstructed signal.
    pub reconstruction: Option<Arc<ReconData>>,
    /// The signal's reference image.
    pub reference: Option<Arc<ReferenceData>>,
    /// |reconstruction − reference| with RMSE and PSNR.
    pub error: Option<Arc<ErrorData>>,
    /// The filter's kernel and frequency response.
    pub response: Option<Arc<ResponseData>>,
    /// RMSE against samples per pixel (its timings are never drawn).
    pub convergence: Option<Arc<Vec<ConvergencePoint>>>,
    /// The 1D sampling-theorem view (column 0 only, when the scene shows the theorem panel).
    pub theorem: Option<Arc<TheoremView>>,
    /// This column's integration-error study.
    pub integration: Option<Arc<IntegrationData>>,
    /// Every column's study, for the integration figure (column 0 only; filled by
    /// `scene::figure::columns_data`).
    pub integration_plot: Option<Arc<IntegrationPlot>>,
}
