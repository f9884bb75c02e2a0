//! The structures of this crate by name: one line per structure in `structures!`.
//!
//! Code that must work with a structure chosen at run time (the CLI) implements
//! [`StructureVisitor`] and calls [`visit`]; the visitor's generic method is monomorphised for
//! each structure, so nothing goes through `dyn`.

use crate::core::topology::MeshTopology;
use crate::{
    CheL0, CheL1, CheL2, CheL3, ExplicitStorage, HeightField, IndexHalfEdge, PointerHalfEdge,
    RegularGrid, VertexList,
};

/// Code generic over a structure, run for a structure named at run time.
pub trait StructureVisitor {
    /// What the visit returns.
    type Output;
    /// Runs with the structure `M`.
    fn visit<M: MeshTopology>(self) -> Self::Output;
}

macro_rules! structures {
    ($($ty:ty),* $(,)?) => {
        /// Names of every structure of this crate, in report order.
        pub const NAMES: &[&str] = &[$(<$ty as MeshTopology>::NAME),*];

        /// Runs `visitor` with the structure called `name`; `None` if there is none.
        pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Option<V::Output> {
            $(
                if name == <$ty as MeshTopology>::NAME {
                    return Some(visitor.visit::<$ty>());
                }
            )*
            None
        }
    };
}

structures!(
    ExplicitStorage,
    VertexList,
    crate::EdgeList,
    crate::WingedEdge,
    PointerHalfEdge,
    IndexHalfEdge,
    RegularGrid,
    HeightField,
    CheL0,
    CheL1,
    CheL2,
    CheL3
);

/// Builds `M` from the soup and validates it.
struct BuildAndValidate<'a>(&'a crate::PolygonSoup);
impl StructureVisitor for BuildAndValidate<'_> {
    type Output = crate::Result<()>;
    fn visit<M: MeshTopology>(self) -> Self::Output {
        M::from_soup(self.0)?.validate()
    }
}

/// Builds every structure from `soup` and runs its `validate()`: per structure, in [`NAMES`]
/// order, its name and the outcome (a typed refusal for input it cannot store).
pub fn build_each(soup: &crate::PolygonSoup) -> Vec<(&'static str, crate::Result<()>)> {
    NAMES
        .iter()
        .map(|&name| {
            (
                name,
                visit(name, BuildAndValidate(soup)).expect("registered"),
            )
        })
        .collect()
}
