//! [`Lab`]: every structure of this build as one [`Structures`] list.

use crate::registry::{self, StructureVisitor};
use topolab_structures::registry::Structures;

/// Every structure of this build of the lab (the [`registry`]: the structures of
/// `topolab-structures`, then the C++ baselines compiled in) as a [`Structures`] list, for
/// the report and the `cargo bench` groups of the harness.
#[derive(Copy, Clone, Debug)]
pub struct Lab;

impl Structures for Lab {
    fn names(out: &mut Vec<&'static str>) {
        out.extend_from_slice(registry::NAMES);
    }
    fn visit<V: StructureVisitor>(name: &str, visitor: V) -> Result<V::Output, V> {
        if registry::NAMES.contains(&name) {
            Ok(registry::visit(name, visitor).expect("a registered name visits its structure"))
        } else {
            Err(visitor)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Name;
    impl StructureVisitor for Name {
        type Output = &'static str;
        fn visit<M: topolab_structures::MeshTopology>(self) -> &'static str {
            M::NAME
        }
    }

    #[test]
    fn the_lab_is_every_registered_structure_and_only_those() {
        assert_eq!(
            topolab_structures::registry::names::<Lab>(),
            registry::NAMES
        );
        for &name in registry::NAMES {
            assert_eq!(Lab::visit(name, Name).ok(), Some(name));
        }
        assert!(Lab::visit("no-such-structure", Name).is_err());
    }
}
