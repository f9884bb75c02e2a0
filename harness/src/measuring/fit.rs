//! The measured complexity: the exponent of time per query against mesh size, fitted by
//! least squares on log-log axes, and its classification.

/// A fitted power law `t ≈ c · n^exponent`.
#[derive(Copy, Clone, Debug, serde::Serialize)]
pub struct PowerFit {
    /// The exponent.
    pub exponent: f64,
    /// How many sizes it was fitted on.
    pub points: usize,
}

/// Fits `ys ≈ c · xs^e` by least squares on `(ln x, ln y)`; `None` with fewer than two distinct sizes.
pub fn fit_exponent(points: &[(f64, f64)]) -> Option<PowerFit> {
    let pts: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    let n = pts.len() as f64;
    if pts.len() < 2 {
        return None;
    }
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / n,
        pts.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx < 1e-12 {
        return None;
    }
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    Some(PowerFit {
        exponent: sxy / sxx,
        points: pts.len(),
    })
}

/// Names an exponent: constant (≈ 0), sub-linear (≈ 0.5), linear (≈ 1), quadratic (≈ 2).
pub fn classify(exponent: f64) -> &'static str {
    match exponent {
        e if e < 0.3 => "constant",
        e if e < 0.75 => "sub-linear",
        e if e < 1.5 => "linear",
        _ => "quadratic",
    }
}

/// Does a fitted exponent agree with the one a cost predicts? Caches make O(1) queries slower
/// on larger meshes, so the tolerance is generous (0.4).
pub fn agrees(fitted: f64, expected: f64) -> bool {
    (fitted - expected).abs() <= 0.4
}

/// Fits every (structure, operator, kernel, family) with at least two measured sizes, and
/// compares with the structure's declared cost (the per-query exponent).
pub fn fit_all(
    measurements: &[crate::measuring::cells::Measurement],
    structures: &[crate::measuring::cells::StructureInfo],
) -> Vec<crate::measuring::cells::FitRow> {
    use crate::measuring::cells::Subject;
    use crate::measuring::kernels::Kernel;
    use std::collections::BTreeMap;
    use topolab_structures::{Cost, Operator};
    // (structure, operator, kernel, family) → (triangles, ns per query) points, in the order
    // of their names.
    type Key<'a> = (&'a str, &'static str, &'static str, &'a str);
    type Group = (Operator, Kernel, Vec<(f64, f64)>);
    let mut groups: BTreeMap<Key, Group> = BTreeMap::new();
    for m in measurements {
        let (crate::measuring::cells::Status::Measured, Some(ns)) = (m.status, m.ns_per_item)
        else {
            continue;
        };
        let (Subject::Query(op), kernel @ (Kernel::Sweep | Kernel::Sampled)) =
            (m.operator, m.kernel)
        else {
            continue;
        };
        // Real meshes differ in shape, not only size; orderings share one size.
        if m.family != "real" && m.family != "ordering" {
            groups
                .entry((&m.structure, op.name(), kernel.name(), &m.family))
                .or_insert_with(|| (op, kernel, Vec::new()))
                .2
                .push((m.triangles as f64, ns));
        }
    }
    let mut rows = Vec::new();
    for ((s, _, _, fam), (op, kernel, pts)) in groups {
        let Some(f) = fit_exponent(&pts) else {
            continue;
        };
        let Some(cost) = structures
            .iter()
            .find(|x| x.name == s)
            .and_then(|x| x.costs.iter().find(|c| c.operator == op))
        else {
            continue;
        };
        // O(∂n1) is constant on a closed mesh (no boundary) and grows like √n on a grid.
        let closed = fam == "torus" || fam == "sphere";
        let expected = if closed && cost.cost == Cost::Boundary {
            0.0
        } else {
            cost.expected_exponent
        };
        rows.push(crate::measuring::cells::FitRow {
            structure: s.into(),
            operator: op,
            kernel,
            family: fam.into(),
            exponent: f.exponent,
            class: classify(f.exponent).into(),
            theory: cost.cost,
            expected_exponent: expected,
            agrees: agrees(f.exponent, expected),
            points: f.points,
        });
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_exponents_of_exact_power_laws() {
        for e in [0.0, 0.5, 1.0, 2.0] {
            let pts: Vec<(f64, f64)> = [1e3, 4e3, 16e3, 64e3]
                .iter()
                .map(|&x: &f64| (x, 3.0 * x.powf(e)))
                .collect();
            let f = fit_exponent(&pts).unwrap();
            assert!((f.exponent - e).abs() < 1e-9, "{e}: {}", f.exponent);
        }
        assert_eq!(classify(0.1), "constant");
        assert_eq!(classify(1.1), "linear");
        assert!(fit_exponent(&[(10.0, 1.0)]).is_none());
        assert!(agrees(0.2, 0.0) && !agrees(1.0, 0.0));
    }
}
