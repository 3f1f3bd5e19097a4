//! What one publication of a scene's figures draws: every column's context and data, the
//! figures each column lists, its composite and the comparison.

use super::{ColumnData, FigureContext, FigureKind};

/// A scene's figures as plain data, made by the scene side (`scene::figure::publication`)
/// and published by `export::publish`: the figures of a panel, a column, the comparison or
/// all of them, in any format.
#[derive(Debug, Clone, Default)]
pub struct Publication {
    /// The scene's name in the comparison's file name (the columns name it in theirs).
    pub name: String,
    /// The scene's N (the comparison's file name).
    pub n: usize,
    /// Every column's figure context and data, in the scene's order.
    pub columns: Vec<(FigureContext, ColumnData)>,
    /// The figures each column lists (one file each per format).
    pub figures: Vec<Vec<FigureKind>>,
    /// The figures of each column's composite.
    pub composites: Vec<Vec<FigureKind>>,
    /// The figures of the comparison (the same in every column's row).
    pub comparison: Vec<FigureKind>,
}
