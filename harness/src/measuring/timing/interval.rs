//! How sure a median is: the distribution-free interval of a median from order statistics.
//!
//! The rounds of a cell are independent draws of everything that moves a number from one run
//! to the next (where the arrays landed, what the machine was doing, which queries were drawn).
//! Their median's interval is read off the sorted round values: the `k`-th smallest and the
//! `k`-th largest contain the true median with probability `1 - 2 P(B ≤ k - 1)`, `B` binomial
//! with `n` trials of ½, whatever the distribution. The interval is the narrowest of these
//! whose coverage is at least [`LEVEL`]; with five rounds or fewer none reaches it, and the
//! interval is the smallest to the largest value, with its lower coverage said.

/// The coverage an interval aims at.
pub const LEVEL: f64 = 0.95;

/// Where a median lies, with the probability that it does.
#[derive(Copy, Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Interval {
    /// Its low end.
    pub low: f64,
    /// Its high end.
    pub high: f64,
    /// The probability that it holds the median (at least [`LEVEL`] from six values on).
    pub coverage: f64,
}

impl Interval {
    /// The interval of the median of `values` (any order; at least one, all finite), or `None`.
    pub fn of_median(values: &[f64]) -> Option<Interval> {
        if values.is_empty() || values.iter().any(|x| !x.is_finite()) {
            return None;
        }
        let mut v = values.to_vec();
        v.sort_by(f64::total_cmp);
        let n = v.len();
        // The largest k whose interval [v(k), v(n+1-k)] still covers LEVEL; at least 1.
        let mut k = 1;
        while k < n.div_ceil(2) && coverage(n, k + 1) >= LEVEL {
            k += 1;
        }
        Some(Interval {
            low: v[k - 1],
            high: v[n - k],
            coverage: coverage(n, k),
        })
    }

    /// Whether two intervals share no value: the one change a comparison of two runs may claim.
    pub fn separates(&self, other: &Interval) -> bool {
        self.high < other.low || other.high < self.low
    }

    /// Whether `x` lies in it.
    pub fn holds(&self, x: f64) -> bool {
        self.low <= x && x <= self.high
    }

    /// Its width relative to `center` (0 for a point).
    pub fn relative_width(&self, center: f64) -> f64 {
        if center > 0.0 {
            (self.high - self.low) / center
        } else {
            f64::INFINITY
        }
    }

    /// The interval divided by `d` (a per-run value made per item).
    pub fn scaled(self, d: f64) -> Interval {
        Interval {
            low: self.low / d,
            high: self.high / d,
            coverage: self.coverage,
        }
    }
}

/// The probability that the `k`-th smallest and the `k`-th largest of `n` draws hold the
/// median: `1 - 2 P(B ≤ k - 1)` with `B ~ Binomial(n, ½)`.
pub fn coverage(n: usize, k: usize) -> f64 {
    let mut tail = 0.0;
    let mut choose = 1.0f64; // C(n, 0)
    for i in 0..k {
        if i > 0 {
            choose *= (n - i + 1) as f64 / i as f64;
        }
        tail += choose;
    }
    (1.0 - 2.0 * tail * 0.5f64.powi(n as i32)).max(0.0)
}

/// The fewest values whose interval reaches [`LEVEL`] (six: the smallest and largest of six
/// hold the median with probability 1 - 2/64).
pub const ROUNDS_FOR_LEVEL: usize = 6;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coverage_of_order_statistics() {
        // Smallest and largest of n: 1 - 2^(1-n).
        assert!((coverage(5, 1) - (1.0 - 2.0 / 32.0)).abs() < 1e-12);
        assert!((coverage(6, 1) - (1.0 - 2.0 / 64.0)).abs() < 1e-12);
        // n = 9, k = 2: 1 - 2 (1 + 9) / 512.
        assert!((coverage(9, 2) - (1.0 - 20.0 / 512.0)).abs() < 1e-12);
        assert!(coverage(5, 1) < LEVEL && coverage(ROUNDS_FOR_LEVEL, 1) >= LEVEL);
    }

    #[test]
    fn the_narrowest_interval_that_reaches_the_level() {
        let v: Vec<f64> = (1..=9).map(f64::from).rev().collect();
        let i = Interval::of_median(&v).unwrap();
        // Nine values: the second smallest and second largest (96.1%); the third would be 82%.
        assert_eq!((i.low, i.high), (2.0, 8.0));
        assert!(i.coverage >= LEVEL && i.holds(5.0) && !i.holds(9.0));
        // Few values: the whole range, its coverage said.
        let few = Interval::of_median(&[3.0, 1.0, 2.0]).unwrap();
        assert_eq!((few.low, few.high, few.coverage), (1.0, 3.0, 0.75));
        assert_eq!(Interval::of_median(&[]), None);
        assert_eq!(Interval::of_median(&[1.0, f64::NAN]), None);
        let one = Interval::of_median(&[4.0]).unwrap();
        assert_eq!((one.low, one.high, one.coverage), (4.0, 4.0, 0.0));
        // Twenty-one values: k = 6 (97.3%), k = 7 would be 92.2%.
        let v: Vec<f64> = (0..21).map(f64::from).collect();
        let i = Interval::of_median(&v).unwrap();
        assert_eq!((i.low, i.high), (5.0, 15.0));
    }

    #[test]
    fn intervals_separate_only_when_they_share_nothing() {
        let a = Interval {
            low: 1.0,
            high: 2.0,
            coverage: 0.95,
        };
        let b = Interval {
            low: 2.0,
            high: 3.0,
            ..a
        };
        let c = Interval {
            low: 2.5,
            high: 3.0,
            ..a
        };
        assert!(!a.separates(&b) && a.separates(&c) && c.separates(&a));
        assert_eq!(a.scaled(2.0).high, 1.0);
        assert!((a.relative_width(1.5) - 1.0 / 1.5).abs() < 1e-12);
    }
}
