//! Point sets in the unit cube [0,1)^d: [`CubePoints`], `n` points of `dims` coordinates each,
//! stored row-major in one `Vec<f64>`, with the limits every d-dimensional sampler, reader and
//! measure checks ([`MAX_DIMS`], [`MAX_COORDS`]) and [`CubePoints::project`], which takes any
//! pair of dimensions to the 2D point set every 2D analysis reads.
//!
//! A 2D point set is the case `dims = 2` ([`CubePoints::from_2d`], [`CubePoints::to_2d`]); the
//! 2D patterns and analyses keep their `&[DVec2]` signatures.

use glam::DVec2;

/// The most dimensions any sampler, reader or measure takes.
pub const MAX_DIMS: usize = 1024;

/// The most coordinates (`n · dims`) one point set holds: 2²⁵, 268 MB as f64 (the same as
/// [`crate::core::pattern::MAX_N`] points in 2D; 2²⁰ points in 32 dimensions).
pub const MAX_COORDS: usize = 1 << 25;

/// Why a d-dimensional point set cannot be made, read or projected. Every variant names the
/// field and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CubeError {
    /// `dims` is zero or above the limit.
    #[error("dims = {dims}: must be an integer in 1..={max}")]
    InvalidDims { dims: usize, max: usize },
    /// `n · dims` is above [`MAX_COORDS`].
    #[error("n = {n} with dims = {dims}: n · dims must be at most {max} ({max_n} points in {dims} dimensions)", max_n = max / dims)]
    TooMany { n: usize, dims: usize, max: usize },
    /// The coordinate count is not a multiple of `dims`.
    #[error("{len} coordinates: not a whole number of points of dims = {dims}")]
    Ragged { len: usize, dims: usize },
    /// A projection names a dimension that is not there, or the same dimension twice.
    #[error("project = {i},{j}: must be two different dimensions in 0..={}", .dims - 1)]
    Projection { i: usize, j: usize, dims: usize },
    /// A coordinate is NaN or outside [0, 1).
    #[error("point {index}, x{dim} = {value}: must be a number in [0, 1)")]
    OutsideCube {
        index: usize,
        dim: usize,
        value: f64,
    },
}

/// Checks `1 ≤ dims ≤ max`.
pub fn check_dims(dims: usize, max: usize) -> Result<(), CubeError> {
    if dims == 0 || dims > max {
        return Err(CubeError::InvalidDims { dims, max });
    }
    Ok(())
}

/// Checks that `n` points of `dims` coordinates fit in [`MAX_COORDS`] (and `dims` in [`MAX_DIMS`]).
pub fn check_size(n: usize, dims: usize) -> Result<(), CubeError> {
    check_dims(dims, MAX_DIMS)?;
    if n.checked_mul(dims).is_none_or(|c| c > MAX_COORDS) {
        return Err(CubeError::TooMany {
            n,
            dims,
            max: MAX_COORDS,
        });
    }
    Ok(())
}

/// `n` points in [0,1)^dims, row-major: point i is `coords[i·dims .. (i+1)·dims]`.
#[derive(Debug, Clone, PartialEq)]
pub struct CubePoints {
    dims: usize,
    coords: Vec<f64>,
}

impl CubePoints {
    /// The point set with these coordinates, checked: `dims` in 1..=[`MAX_DIMS`], a whole
    /// number of points, at most [`MAX_COORDS`] coordinates, each in [0, 1).
    pub fn new(dims: usize, coords: Vec<f64>) -> Result<Self, CubeError> {
        check_dims(dims, MAX_DIMS)?;
        if coords.len() % dims != 0 {
            return Err(CubeError::Ragged {
                len: coords.len(),
                dims,
            });
        }
        check_size(coords.len() / dims, dims)?;
        if let Some(k) = coords.iter().position(|v| !(0.0..1.0).contains(v)) {
            return Err(CubeError::OutsideCube {
                index: k / dims,
                dim: k % dims,
                value: coords[k],
            });
        }
        Ok(CubePoints { dims, coords })
    }

    /// A 2D point set as a cube point set (`dims = 2`); the points are taken as they are.
    pub fn from_2d(points: &[DVec2]) -> Self {
        CubePoints {
            dims: 2,
            coords: points.iter().flat_map(|p| [p.x, p.y]).collect(),
        }
    }

    /// The number of points.
    pub fn n(&self) -> usize {
        self.coords.len() / self.dims
    }

    /// The number of coordinates per point.
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// Every coordinate, row-major.
    pub fn coords(&self) -> &[f64] {
        &self.coords
    }

    /// The coordinates, row-major, taken out.
    pub fn into_coords(self) -> Vec<f64> {
        self.coords
    }

    /// Point `i`'s coordinates.
    pub fn point(&self, i: usize) -> &[f64] {
        &self.coords[i * self.dims..(i + 1) * self.dims]
    }

    /// The points in order.
    pub fn rows(&self) -> std::slice::ChunksExact<'_, f64> {
        self.coords.chunks_exact(self.dims)
    }

    /// Dimension `j` of every point, in point order.
    pub fn column(&self, j: usize) -> impl Iterator<Item = f64> + '_ {
        self.coords.iter().skip(j).step_by(self.dims).copied()
    }

    /// The 2D point set `(x_i, x_j)`: a projection every 2D analysis takes as it is.
    pub fn project(&self, i: usize, j: usize) -> Result<Vec<DVec2>, CubeError> {
        if i >= self.dims || j >= self.dims || i == j {
            return Err(CubeError::Projection {
                i,
                j,
                dims: self.dims,
            });
        }
        Ok(self.rows().map(|p| DVec2::new(p[i], p[j])).collect())
    }

    /// The points as 2D points, when `dims = 2`.
    pub fn to_2d(&self) -> Option<Vec<DVec2>> {
        (self.dims == 2).then(|| self.project(0, 1).expect("dims = 2 has dimensions 0 and 1"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_columns_and_projections_index_the_same_coordinates() {
        // 3 points in 3 dims, coordinate (i, j) = (3i + j) / 10.
        let coords: Vec<f64> = (0..9).map(|k| k as f64 / 10.0).collect();
        let p = CubePoints::new(3, coords).unwrap();
        assert_eq!((p.n(), p.dims()), (3, 3));
        assert_eq!(p.point(1), &[0.3, 0.4, 0.5]);
        assert_eq!(p.column(2).collect::<Vec<_>>(), vec![0.2, 0.5, 0.8]);
        assert_eq!(
            p.project(2, 0).unwrap(),
            vec![
                DVec2::new(0.2, 0.0),
                DVec2::new(0.5, 0.3),
                DVec2::new(0.8, 0.6)
            ]
        );
        assert_eq!(p.to_2d(), None);
    }

    #[test]
    fn a_2d_set_round_trips() {
        let pts = vec![DVec2::new(0.25, 0.5), DVec2::new(0.75, 0.125)];
        let cube = CubePoints::from_2d(&pts);
        assert_eq!(cube.coords(), &[0.25, 0.5, 0.75, 0.125]);
        assert_eq!(cube.to_2d().unwrap(), pts);
    }

    #[test]
    fn bad_input_names_the_field_and_the_range() {
        let msg = |e: CubeError| e.to_string();
        assert_eq!(
            msg(CubePoints::new(0, vec![]).unwrap_err()),
            "dims = 0: must be an integer in 1..=1024"
        );
        assert_eq!(
            msg(CubePoints::new(MAX_DIMS + 1, vec![]).unwrap_err()),
            "dims = 1025: must be an integer in 1..=1024"
        );
        assert_eq!(
            msg(CubePoints::new(3, vec![0.0; 4]).unwrap_err()),
            "4 coordinates: not a whole number of points of dims = 3"
        );
        assert_eq!(
            msg(CubePoints::new(2, vec![0.0, 0.5, f64::NAN, 0.1]).unwrap_err()),
            "point 1, x0 = NaN: must be a number in [0, 1)"
        );
        assert_eq!(
            msg(CubePoints::new(2, vec![0.0, 1.0]).unwrap_err()),
            "point 0, x1 = 1: must be a number in [0, 1)"
        );
        let p = CubePoints::new(3, vec![0.0; 3]).unwrap();
        assert_eq!(
            msg(p.project(1, 3).unwrap_err()),
            "project = 1,3: must be two different dimensions in 0..=2"
        );
        assert_eq!(
            msg(p.project(1, 1).unwrap_err()),
            "project = 1,1: must be two different dimensions in 0..=2"
        );
        assert_eq!(
            msg(check_size(1 << 21, 32).unwrap_err()),
            "n = 2097152 with dims = 32: n · dims must be at most 33554432 (1048576 points in 32 dimensions)"
        );
        assert!(check_size(1 << 20, 32).is_ok());
        assert!(check_size(usize::MAX, 2).is_err());
    }
}
