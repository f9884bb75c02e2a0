//! The studies a run makes beside the size sweep, each measuring one question on the
//! structures with the [`crate::measuring`] machinery: the changing workloads of the
//! Surface_mesh benchmark ([`changing`]), decimation and its reconstruction ([`decimate`]),
//! the 3D convex hull against n and beside Qhull and CGAL ([`hull`]), and the container reads
//! of every query counted ([`reads`]).

pub mod changing;
pub mod decimate;
pub mod hull;
pub mod reads;
