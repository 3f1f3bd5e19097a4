//! The identities of the figures: what `render` writes, the GUI's Save menus list and a
//! `Figure` draws (a panel saves one or more of them), expanded from the panel list
//! (`scene::panels::panel_list!`, the one place a figure is named).

/// Expands the panel list into [`FigureKind`]: every figure of every panel, in the list's
/// order, with its name, whether a composite holds it and whether its panel depends on no
/// column.
macro_rules! figure_kinds {
    (
        figures: [$(
            $(#[$doc:meta])* $kind:ident $name:literal $composite:literal $free:literal;
        )*]
        $($rest:tt)*
    ) => {
        /// One figure of a column (a panel saves one or more).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum FigureKind {
            $($(#[$doc])* $kind,)*
        }

        impl FigureKind {
            /// Every kind, in the order `render` writes them (the panel list's).
            pub const ALL: [FigureKind; [$(FigureKind::$kind,)*].len()] =
                [$(FigureKind::$kind,)*];

            /// Name used in file names, menus and metadata.
            pub fn name(self) -> &'static str {
                match self {
                    $(FigureKind::$kind => $name,)*
                }
            }

            /// Whether a composite may hold each kind of [`FigureKind::ALL`].
            const IN_COMPOSITE: [bool; FigureKind::ALL.len()] = [$($composite,)*];

            /// Whether each kind's panel depends on no column (the 1D sampling theorem's):
            /// its data exists for column 0 only and its file name names no column.
            const COLUMN_FREE: [bool; FigureKind::ALL.len()] = [$($free,)*];
        }
    };
}

crate::scene::panels::panel_list!(figure_kinds);

/// The kinds of `ALL` whose flag in `keep` is set, in order (`N` of them).
const fn select<const N: usize>(keep: [bool; FigureKind::ALL.len()]) -> [FigureKind; N] {
    let mut out = [FigureKind::ALL[0]; N];
    let (mut i, mut j) = (0, 0);
    while i < FigureKind::ALL.len() {
        if keep[i] {
            out[j] = FigureKind::ALL[i];
            j += 1;
        }
        i += 1;
    }
    assert!(j == N, "the count of the selected kinds");
    out
}

/// How many flags of `keep` are set.
const fn count(keep: [bool; FigureKind::ALL.len()]) -> usize {
    let (mut i, mut n) = (0, 0);
    while i < FigureKind::ALL.len() {
        if keep[i] {
            n += 1;
        }
        i += 1;
    }
    n
}

impl FigureKind {
    /// The figures of the 1D sampling-theorem panel (the column-free one).
    pub const THEOREM: [FigureKind; count(FigureKind::COLUMN_FREE)] =
        select(FigureKind::COLUMN_FREE);

    /// The kinds a composite may hold, in its order: one per panel as the GUI first shows it
    /// (pattern, sphere, periodogram, reconstruction, kernel and response), then the theorem's
    /// signal, spectrum and reconstructed spectrum (not the transform pair).
    pub const COMPOSITE: [FigureKind; count(FigureKind::IN_COMPOSITE)] =
        select(FigureKind::IN_COMPOSITE);

    /// Whether this is a figure of the 1D sampling-theorem panel: its data does not depend
    /// on the column and exists for column 0 only.
    pub fn is_theorem(self) -> bool {
        FigureKind::COLUMN_FREE[self as usize]
    }
}
