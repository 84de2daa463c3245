//! Where a profile that vanishes like a square root reaches zero: d = D √(1 − x²/c²) (Hertz's
//! pressure at the edge of its zone, Cattaneo's μp − |q| at the edge of a stick zone) has d²
//! linear in x², zero at x² = c², so the least-squares line of d² against x² through samples
//! inside the zone gives c between the points, to a fraction of their spacing. The checks
//! against closed forms (tests, `wearfem validate`) measure zone edges this way.

/// c (mm) from samples (x in mm, d in any unit) inside the zone; NaN for fewer than two
/// distinct x², or a line that does not fall to zero at positive x².
pub fn square_root_edge(samples: impl IntoIterator<Item = (f64, f64)>) -> f64 {
    line_zero(samples.into_iter().map(|(x, d)| (x * x, d * d))).sqrt()
}

/// Where the least-squares line through (u, v) reaches v = 0.
fn line_zero(points: impl Iterator<Item = (f64, f64)>) -> f64 {
    let (mut su, mut sv, mut suu, mut suv, mut count) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (u, v) in points {
        su += u;
        sv += v;
        suu += u * u;
        suv += u * v;
        count += 1.0;
    }
    let slope = (count * suv - su * sv) / (count * suu - su * su);
    -(sv - slope * su) / count / slope
}

/// The edge (mm) of a zone on one side, where a margin d vanishes like the square root of the
/// distance (d² linear in x near an edge that is not at the origin: an off-centre stick zone),
/// from samples (x in mm, d in any unit) next to it: the least-squares line of d² against x,
/// its zero. NaN for fewer than two distinct x.
pub fn square_root_edge_one_sided(samples: impl IntoIterator<Item = (f64, f64)>) -> f64 {
    line_zero(samples.into_iter().map(|(x, d)| (x, d * d)))
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_square_root_profile_gives_its_edge() {
        // Exact samples of 3 √(1 − x²/4): the line is exact, c = 2 to round-off.
        let samples = [0.3, 0.9, 1.2, 1.7].map(|x: f64| (x, 3.0 * (1.0 - x * x / 4.0).sqrt()));
        assert!((super::square_root_edge(samples) - 2.0).abs() < 1e-12);
    }

    #[test]
    fn a_one_sided_square_root_gives_its_edge() {
        // Exact samples of 2 √(0.7 − x) below x = 0.7: d² is a line, its zero 0.7.
        let samples = [0.5, 0.6, 0.65].map(|x: f64| (x, 2.0 * (0.7 - x).sqrt()));
        assert!((super::square_root_edge_one_sided(samples) - 0.7).abs() < 1e-12);
    }
}
