//! A column's data as the panels and the figures read it: every node's data with its status.

use super::{
    ConvergencePoint, ErrorData, IntegrationData, IntegrationPlot, NodeRow, PointsData, ReconData,
    ReferenceData, ResponseData, Slot, SpectrumData, StatsData, TheoremView,
};
use std::sync::Arc;

/// The data of one column, as the compute graph produced it: each node's [`Slot`] (its data
/// with its status, its error, or missing where it was not computed: hidden panel, effect
/// off, still running). The scene side fills it from a column's node results, once, where
/// the results are held (`scene::figure::column_data`); the GUI's panels and the figures read
/// the same data.
#[derive(Debug, Clone, Default)]
pub struct ColumnData {
    /// The points (pattern and sphere figures and panels).
    pub points: Slot<PointsData>,
    /// The points' statistics (the pattern panel's overlay).
    pub statistics: Slot<StatsData>,
    /// The periodogram and its radial average (spectrum and RAPS figures).
    pub spectrum: Slot<SpectrumData>,
    /// The reconstructed signal.
    pub reconstruction: Slot<ReconData>,
    /// The signal's reference image.
    pub reference: Slot<ReferenceData>,
    /// |reconstruction − reference| with RMSE and PSNR.
    pub error: Slot<ErrorData>,
    /// The filter's kernel and frequency response.
    pub response: Slot<ResponseData>,
    /// RMSE against samples per pixel (its timings are never drawn).
    pub convergence: Slot<Vec<ConvergencePoint>>,
    /// The 1D sampling-theorem view (column 0 only, when the scene shows the theorem panel).
    pub theorem: Slot<TheoremView>,
    /// This column's integration-error study.
    pub integration: Slot<IntegrationData>,
    /// Every column's study, for the integration figure (column 0 only; filled by
    /// `scene::figure::columns_data`).
    pub integration_plot: Option<Arc<IntegrationPlot>>,
    /// Every node's status, in the node table's order (the cost view).
    pub nodes: Vec<NodeRow>,
}

/// A node's data type and its place in [`ColumnData`]: what a panel asks for by type
/// (`PanelCx::get::<SpectrumData>()`).
pub trait InColumn: Sized + 'static {
    /// Its slot in the column's data.
    fn slot(data: &ColumnData) -> &Slot<Self>;
}

macro_rules! in_column {
    ($($t:ty => $field:ident),* $(,)?) => {$(
        impl InColumn for $t {
            fn slot(data: &ColumnData) -> &Slot<Self> {
                &data.$field
            }
        }
    )*};
}

in_column! {
    PointsData => points,
    StatsData => statistics,
    SpectrumData => spectrum,
    ReconData => reconstruction,
    ReferenceData => reference,
    ErrorData => error,
    ResponseData => response,
    Vec<ConvergencePoint> => convergence,
    TheoremView => theorem,
    IntegrationData => integration,
}

impl ColumnData {
    /// The `T` node's slot.
    pub fn get<T: InColumn>(&self) -> &Slot<T> {
        T::slot(self)
    }
}
