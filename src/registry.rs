//! Every structure of the lab by name: those of [`topolab_structures::registry`] plus the
//! OpenMesh baseline ([`crate::openmesh::OpenMesh`], name `openmesh`) when it is compiled in.
//! The CLI goes through this registry, so `topolab list` and `topolab info --structure
//! openmesh` include it.

use topolab_structures::registry as structures;
pub use topolab_structures::registry::StructureVisitor;

/// The name of the OpenMesh baseline (whether or not this build includes it).
pub const OPENMESH: &str = "openmesh";

/// The structures this package adds to `topolab_structures`'s.
const EXTRA: &[&str] = if cfg!(has_openmesh) { &[OPENMESH] } else { &[] };

/// Names of every structure, in report order: the crate's, then the baselines.
pub const NAMES: &[&str] = &concat::<{ structures::NAMES.len() + EXTRA.len() }>();

const fn concat<const N: usize>() -> [&'static str; N] {
    let mut out = [""; N];
    let mut i = 0;
    while i < structures::NAMES.len() {
        out[i] = structures::NAMES[i];
        i += 1;
    }
    while i < N {
        out[i] = EXTRA[i - structures::NAMES.len()];
        i += 1;
    }
    out
}

/// Runs `visitor` with the structure called `name`; `None` if there is none in this build.
pub fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Option<V::Output> {
    #[cfg(has_openmesh)]
    if name == <crate::openmesh::OpenMesh as topolab_structures::MeshTopology>::NAME {
        return Some(visitor.visit::<crate::openmesh::OpenMesh>());
    }
    structures::visit(name, visitor)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_extend_the_crate_registry() {
        assert_eq!(&NAMES[..structures::NAMES.len()], structures::NAMES);
        assert_eq!(NAMES.contains(&OPENMESH), crate::HAS_OPENMESH);
    }
}
