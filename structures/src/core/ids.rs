//! Typed element handles.
//!
//! Every handle is a `u32` newtype made by one macro. Handles are plain indices: vertex `i` of
//! the input is `VertexId(i)` and face `j` is `FaceId(j)` in every structure, so answers can be
//! compared across structures. `EdgeId` and `HalfEdgeId` are each structure's own (its module
//! documents what they index); answers about edges are compared by the edge's two end vertices.
//!
//! The API uses `Option<Id>` for "no element"; the `INVALID` sentinel (`u32::MAX`) exists only
//! for structures that store absent links in `u32` arrays, and never leaks out of them.

macro_rules! define_id {
    ($(#[$doc:meta])* $name:ident, $short:literal) => {
        $(#[$doc])*
        #[derive(Copy, Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
        #[repr(transparent)]
        pub struct $name(pub u32);

        impl $name {
            /// The sentinel stored in `u32` link arrays for "no element"; never returned by the API.
            pub const INVALID: Self = Self(u32::MAX);

            /// The handle of index `i`.
            ///
            /// # Panics
            /// If `i` does not fit in `u32` (structures check sizes at construction, so this
            /// cannot happen for indices of a built structure).
            #[inline(always)]
            pub fn new(i: usize) -> Self {
                debug_assert!(i < u32::MAX as usize, "index {i} does not fit a u32 handle");
                Self(i as u32)
            }

            /// The index this handle stands for.
            #[inline(always)]
            pub const fn index(self) -> usize {
                self.0 as usize
            }

            /// `false` for the `INVALID` sentinel.
            #[inline(always)]
            pub const fn is_valid(self) -> bool {
                self.0 != u32::MAX
            }

            /// `None` for the sentinel, `Some(self)` otherwise: how stored links leave a structure.
            #[inline(always)]
            pub const fn valid(self) -> Option<Self> {
                if self.is_valid() {
                    Some(self)
                } else {
                    None
                }
            }
        }

        impl std::fmt::Debug for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                if self.is_valid() {
                    write!(f, concat!($short, "{}"), self.0)
                } else {
                    f.write_str(concat!($short, "-"))
                }
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                std::fmt::Debug::fmt(self, f)
            }
        }

        impl From<$name> for usize {
            #[inline(always)]
            fn from(id: $name) -> usize {
                id.index()
            }
        }
    };
}

define_id!(
    /// A vertex: index into the input's vertex list.
    VertexId,
    "v"
);
define_id!(
    /// An edge: each structure's own handle (documented in its module).
    EdgeId,
    "e"
);
define_id!(
    /// A half-edge (an oriented edge inside one face): each half-edge structure's own handle.
    HalfEdgeId,
    "h"
);
define_id!(
    /// A face: index into the input's face list.
    FaceId,
    "f"
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sentinel_is_not_valid_and_maps_to_none() {
        assert_eq!(VertexId::INVALID.valid(), None);
        assert_eq!(VertexId(3).valid(), Some(VertexId(3)));
        assert_eq!(format!("{:?} {}", FaceId(7), EdgeId::INVALID), "f7 e-");
        assert_eq!(HalfEdgeId::new(5).index(), 5);
    }
}
