//! A column's data as the panels and the figures read it: every node's data with its status.

use super::{IntegrationPlot, NodeRow, Slot};
use std::sync::Arc;

/// Expands the node list (`scene::compute::node_list!`, a macro that carries only names and
/// `model` types) into [`ColumnData`]'s slots and their [`InColumn`] impls: one per node that
/// panels and figures read (its entry's `column`).
macro_rules! column_data {
    (
        kinds: $kinds:tt
        table: $table:tt
        columns: [$($(#[$doc:meta])* $kind:ident($ty:ty) $field:ident;)*]
    ) => {
        /// The data of one column, as the compute graph produced it: each node's [`Slot`] (its
        /// data with its status, its error, or missing where it was not computed: hidden
        /// panel, effect off, still running). The scene side fills it from a column's node
        /// results, once, where the results are held (`scene::figure::column_data`); the GUI's
        /// panels and the figures read the same data.
        #[derive(Debug, Clone, Default)]
        pub struct ColumnData {
            $($(#[$doc])* pub $field: Slot<$ty>,)*
            /// Every column's study, for the integration figure (column 0 only; filled by
            /// `scene::figure::columns_data`).
            pub integration_plot: Option<Arc<IntegrationPlot>>,
            /// Every node's status, in the node table's order (the cost view).
            pub nodes: Vec<NodeRow>,
        }

        $(
            impl InColumn for $ty {
                fn slot(data: &ColumnData) -> &Slot<Self> {
                    &data.$field
                }
            }
        )*
    };
}

crate::scene::compute::node_list!(column_data);

/// A node's data type and its place in [`ColumnData`]: what a panel asks for by type
/// (`PanelCx::get::<SpectrumData>()`).
pub trait InColumn: Sized + 'static {
    /// Its slot in the column's data.
    fn slot(data: &ColumnData) -> &Slot<Self>;
}

impl ColumnData {
    /// The `T` node's slot.
    pub fn get<T: InColumn>(&self) -> &Slot<T> {
        T::slot(self)
    }
}
