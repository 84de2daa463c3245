//! Mesh lines along one direction of a block: equal divisions, or graded geometrically (each
//! element a fixed ratio of its neighbour) towards one end or both. The lines are block
//! parameters in [0, 1]; on a circular arc the parameter runs with the angle, so the grading is
//! the same in arc length as on a straight edge.

/// `n` equal divisions: n + 1 lines from 0 to 1.
pub fn equal_lines(n: usize) -> Vec<f64> {
    (0..=n).map(|i| i as f64 / n as f64).collect()
}

/// `n` divisions whose sizes grow geometrically by `ratio` from the start (ratio < 1: they
/// shrink, fine at the end), or, with `both_ends`, grow by `ratio` from both ends towards the
/// middle (a middle element of odd n is the largest, alone). The first and last lines are
/// exactly 0 and 1. `ratio` must be finite and positive; 1 gives equal divisions.
pub fn graded_lines(n: usize, ratio: f64, both_ends: bool) -> Vec<f64> {
    let sizes: Vec<f64> = if both_ends {
        // Element i from the nearer end has size ratio^i.
        (0..n)
            .map(|i| ratio.powi(i.min(n - 1 - i) as i32))
            .collect()
    } else {
        (0..n).map(|i| ratio.powi(i as i32)).collect()
    };
    let total: f64 = sizes.iter().sum();
    let mut lines = Vec::with_capacity(n + 1);
    let mut at = 0.0;
    lines.push(0.0);
    for size in &sizes[..n.saturating_sub(1)] {
        at += size / total;
        lines.push(at);
    }
    lines.push(1.0);
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn graded_lines_grow_by_the_ratio() {
        let lines = graded_lines(6, 1.5, false);
        assert_eq!((lines[0], lines[6]), (0.0, 1.0));
        for i in 1..6 {
            let (before, this) = (lines[i] - lines[i - 1], lines[i + 1] - lines[i]);
            assert!(
                (this / before - 1.5).abs() < 1e-12,
                "{i}: {}",
                this / before
            );
        }
        // The first element of a geometric series of 6 terms: (r − 1)/(r⁶ − 1).
        assert!((lines[1] - 0.5 / (1.5f64.powi(6) - 1.0)).abs() < 1e-15);
    }

    #[test]
    fn both_ends_are_fine_and_mirror_each_other() {
        for n in [1, 2, 5, 8] {
            let lines = graded_lines(n, 1.3, true);
            assert_eq!(lines.len(), n + 1);
            for i in 0..=n {
                assert!(
                    (lines[i] + lines[n - i] - 1.0).abs() < 1e-14,
                    "n = {n}, {i}"
                );
            }
        }
        let lines = graded_lines(8, 1.3, true);
        let size = |i: usize| lines[i + 1] - lines[i];
        assert!((size(1) / size(0) - 1.3).abs() < 1e-12);
        assert!(
            (size(3) / size(4) - 1.0).abs() < 1e-12,
            "the middle pair is equal"
        );
        assert!((size(6) / size(7) - 1.3).abs() < 1e-12);
    }

    #[test]
    fn ratio_one_is_equal_divisions() {
        let graded = graded_lines(7, 1.0, false);
        for (g, e) in graded.iter().zip(equal_lines(7)) {
            assert!((g - e).abs() < 1e-15);
        }
    }
}
