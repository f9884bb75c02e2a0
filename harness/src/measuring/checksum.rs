//! Structure-independent checksums of operator answers.
//!
//! Every timed kernel folds its answers into a `u64` with [`mix`] and a wrapping sum, so the
//! order in which a structure reports answers does not matter, while a missing, extra or wrong
//! answer changes the sum. Edges enter by their end vertices ([`edge_key`]) because edge ids
//! are each structure's own. Baselines written in C++ (the OpenMesh shim) implement the same
//! two functions bit for bit:
//!
//! ```text
//! mix(a, b)      = h ^ (h >> 31)  where  h = (a * 0x9E3779B97F4A7C15 + b) * 0xBF58476D1CE4E5B9   (wrapping u64)
//! edge_key(a, b) = (min(a, b) << 32) | max(a, b)
//! ```
//!
//! Per operator, the sweep checksum is (sums wrapping, over all elements):
//!
//! | operator | checksum |
//! |---|---|
//! | r00 | Σ_v Σ_{w ∈ R00(v)} mix(v, w) |
//! | r01 | Σ_v Σ_{e ∈ R01(v)} mix(v, edge_key(e)) |
//! | r02 | Σ_v Σ_{f ∈ R02(v)} mix(v, f) |
//! | r10 | Σ_e mix(min(a, b), max(a, b)) for R10(e) = (a, b) |
//! | r11 | Σ_e Σ_{x ∈ R11(e)} mix(edge_key(e), edge_key(x)) |
//! | r12 | Σ_e Σ_{f ∈ R12(e)} mix(edge_key(e), f) |
//! | r20 | Σ_f Σ_{v ∈ R20(f)} mix(f, v) |
//! | r21 | Σ_f Σ_{e ∈ R21(f)} mix(f, edge_key(e)) |
//! | r22 | Σ_f Σ_{g ∈ R22(f)} mix(f, g) |
//! | boundary-vertex | Σ_{v on the boundary} mix(v, 1) |
//! | boundary-edge | Σ_{e on the boundary} mix(edge_key(e), 1) |
//! | boundary-curves | Σ_curves Σ_{e ∈ curve} mix(len(curve), edge_key(e)) |
//! | edge-successor | Σ_f Σ_{e ∈ R21(f)} mix(edge_key(e), edge_key(successor(e, f))) |
//! | edge-predecessor | Σ_f Σ_{e ∈ R21(f)} mix(edge_key(e), edge_key(predecessor(e, f))) |
//!
//! A sampled kernel uses the same terms, summed over the sampled query elements only.
//!
//! Where a boundary touches itself at a vertex (two holes meeting at a corner), splitting the
//! boundary edges into curves is not unique, so two correct structures may give different
//! boundary-curves checksums; the report measures that operator on generated meshes only.

/// Mixes two numbers into one, asymmetrically (see the module docs for the formula).
#[inline(always)]
pub const fn mix(a: u64, b: u64) -> u64 {
    let h = a
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add(b)
        .wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^ (h >> 31)
}

/// Whether two workload results (sums of coordinates) agree: within 1e-6 relative, and
/// absolute below 1, since summing in another order (each structure walks a vertex's
/// neighbours from its own start) changes the last bits, and a closed mesh's coordinates sum
/// to nearly 0, where tens of millions of terms differ by more than 1e-9.
pub fn sums_agree(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1.0)
}

/// An undirected edge as one number: smaller end vertex in the high half.
#[inline(always)]
pub const fn edge_key(a: u32, b: u32) -> u64 {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    ((lo as u64) << 32) | hi as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mix_is_asymmetric_and_edge_key_symmetric() {
        assert_ne!(mix(1, 2), mix(2, 1));
        assert_eq!(edge_key(7, 3), edge_key(3, 7));
        assert_eq!(edge_key(1, 2), (1 << 32) | 2);
        // A fixed value, so that the C++ shim can check its copy against it.
        assert_eq!(mix(3, 5), 0x4015_9a6e_5620_edf9);
    }
}

/// What a changed mesh is compared by.
#[derive(Copy, Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct MeshChecksum {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Σ over faces of the face's vertices folded with [`mix`], each face read from its
    /// smallest vertex on (wrapping sum: face order does not matter, orientation does).
    pub face_hash: u64,
}

/// The [`MeshChecksum`] of `m` (through R20).
pub fn mesh_checksum<M: topolab_structures::MeshTopology>(m: &M) -> MeshChecksum {
    let mut face_hash = 0u64;
    let mut face = Vec::new();
    for f in 0..m.num_faces() {
        face.clear();
        m.face_vertices(topolab_structures::FaceId::new(f), |v| face.push(v.0));
        let k = face.len();
        let first = (0..k).min_by_key(|&i| face[i]).unwrap_or(0);
        let mut h = k as u64;
        for i in 0..k {
            h = mix(h, face[(first + i) % k] as u64);
        }
        face_hash = face_hash.wrapping_add(h);
    }
    MeshChecksum {
        vertices: m.num_vertices(),
        edges: m.num_edges(),
        faces: m.num_faces(),
        face_hash,
    }
}
