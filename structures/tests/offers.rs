//! A structure states the edits it offers by the functions it gives ([`Offers`]), so one that
//! keeps every default offers nothing it would refuse: enrolled in the editing suite with the
//! required methods of `MeshEdit` only, it offers the operations on positions and garbage
//! collection, and every other operation the suite draws is refused as not implemented.

use topolab_structures::{
    Cost, Deletion, EditOp, FaceId, MeshEdit, MeshTopology, Offers, Result, VertexId, VertexList,
};

/// The vertex list under another name, with nothing of `MeshEdit` but what it must write.
struct RequiredOnly(VertexList);

topolab_structures::delegate_topology!(RequiredOnly(VertexList), "required-only");

impl MeshEdit for RequiredOnly {
    const DELETION: Deletion = Deletion::Removed;

    fn edit_cost(_op: EditOp) -> Cost {
        Cost::Constant
    }
    fn set_position(&mut self, v: VertexId, p: topolab_structures::glam::DVec3) -> Result<()> {
        self.0.set_position(v, p)
    }
    fn is_deleted_vertex(&self, _v: VertexId) -> bool {
        false
    }
    fn is_deleted_face(&self, _f: FaceId) -> bool {
        false
    }
    fn garbage_collection(&mut self) {}
    fn reserve(&mut self, _vertices: usize, _edges: usize, _faces: usize) {}
}

topolab_structures::edit_conformance!(required_only, RequiredOnly, offered_operations);

#[test]
fn the_required_methods_alone_offer_the_operations_on_positions_and_nothing_else() {
    let offered: Vec<EditOp> = EditOp::ALL
        .into_iter()
        .filter(|&op| RequiredOnly::supports(op))
        .collect();
    assert_eq!(
        offered,
        [
            EditOp::GarbageCollection,
            EditOp::SetPosition,
            EditOp::Select,
            EditOp::RotateSelection,
            EditOp::ScaleSelection,
            EditOp::Smooth,
        ]
    );
    // The table it keeps is the one that says so.
    let nothing: Offers<RequiredOnly> = Offers::NOTHING;
    for op in EditOp::ALL {
        assert_eq!(nothing.offers(op), RequiredOnly::supports(op), "{op:?}");
    }
}

#[test]
fn the_vertex_list_inside_flips_an_edge_the_wrapper_refuses_as_not_implemented() {
    let soup = topolab_structures::meshes::annulus(8);
    let mut inside = VertexList::from_soup(&soup).unwrap();
    let mut wrapper = RequiredOnly(VertexList::from_soup(&soup).unwrap());
    let e = (0..inside.num_edges() as u32)
        .map(topolab_structures::EdgeId)
        .find(|&e| inside.flip_edge(e).is_ok())
        .expect("an annulus has an edge to flip");
    match wrapper.flip_edge(e) {
        Err(topolab_structures::Error::EditRefused {
            structure,
            op,
            reason,
        }) => {
            assert_eq!(structure, "required-only");
            assert_eq!(op, EditOp::FlipEdge);
            assert_eq!(reason, topolab_structures::Refusal::NotImplemented);
        }
        other => panic!("{other:?}"),
    }
    wrapper.validate().unwrap();
}
