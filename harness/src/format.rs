//! Formatting shared by every page the crate draws (the report, compare, scale, the plots):
//! escaping, times and sizes with their units, ratios beside their goals. Nothing here reads
//! the results: the pages pass the numbers in.

/// `s` with `&`, `<`, `>` and `"` escaped, for HTML text and quoted attribute values alike.
pub(crate) fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A time in nanoseconds with its unit (ns, µs, ms).
pub(crate) fn ns(x: f64) -> String {
    if x >= 1e6 {
        format!("{:.1} ms", x / 1e6)
    } else if x >= 1e3 {
        format!("{:.1} µs", x / 1e3)
    } else if x >= 10.0 {
        format!("{x:.0} ns")
    } else {
        format!("{x:.1} ns")
    }
}

/// A size in bytes with its unit (kB, MB, GB).
pub(crate) fn bytes(b: f64) -> String {
    if b >= 1e9 {
        format!("{:.2} GB", b / 1e9)
    } else if b >= 1e6 {
        format!("{:.1} MB", b / 1e6)
    } else {
        format!("{:.0} kB", b / 1e3)
    }
}

/// A ratio as the table shows it beside its goal: two decimals, more where two would read as
/// the goal itself while the ratio is not (1.2016 missing a goal of 1.2 reads 1.202×, not
/// 1.20×, beside its "no"; 1.1996 meeting it reads 1.1996×).
pub(crate) fn against_goal(ratio: f64, goal: f64) -> String {
    let digits = (2..6)
        .find(|&d| ratio == goal || format!("{ratio:.d$}") != format!("{goal:.d$}"))
        .unwrap_or(6);
    format!("{ratio:.digits$}×")
}

/// The table cell's class for a "met" column of "yes", "no" or "–".
pub(crate) fn class_of(met: &str) -> &'static str {
    match met {
        "yes" => "ok",
        "no" => "bad",
        _ => "skip",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ratio_beside_its_goal_never_rounds_to_it() {
        assert_eq!(against_goal(1.2016, 1.2), "1.202×");
        assert_eq!(against_goal(1.2004, 1.2), "1.2004×");
        assert_eq!(against_goal(1.1996, 1.2), "1.1996×");
        assert_eq!(against_goal(1.2, 1.2), "1.20×");
        assert_eq!(against_goal(1.27, 1.2), "1.27×");
        assert_eq!(against_goal(0.6449, 0.6), "0.64×");
    }
}
