//! The contact's heat as the reduction's inputs: a few smooth shapes along the contact
//! instead of one input per contact point.
//!
//! # Why shapes
//!
//! The reduction ([`crate::conduction::reduced`]) spans the responses (K + σC)⁻¹ B of its
//! inputs B at every shift, and costs N r m per block (N unknowns, r modes so far, m inputs):
//! with one input per contact point both m and r grow with the points (65 points, 305 modes
//! on punch-b40-heat), and the block Gram–Schmidt took most of the set-up. The frictional
//! flux μ p_i |v| is the pressure times the speed, and the pressure along the contact is a
//! smooth function of the position except at the contact's ends, where a flat punch's corners
//! concentrate it. Chebyshev polynomials T_0 … T_{m−1} of the position (the chord length
//! along the points, mapped onto [−1, 1]) resolve such a function best for their number:
//! their zeros cluster at the ends as 1/m², where the peaks are.
//!
//! # Why that is accurate enough
//!
//! Only the space is coarser: the modes still receive the run's real flux, one value per
//! point (the projection Φᵀ F of every point's input), and a flux outside the shapes' span is
//! answered by its Galerkin projection, not dropped. Measured by `examples/heat_reduction.rs`
//! against the full model (docs/convergence.md, "The reduced heat model"). With half as many
//! shapes as points (until 2026-11-30): on punch-b40-heat (65 points, 33 shapes) 202 modes
//! instead of 305, the contact temperature within 1.7e-3 of its rise (1.5e-3 with one input
//! per point) and the thermal gap within 6.9e-4 of its size (4.1e-4); on 16 elements (129
//! points, 65 shapes) 314 modes instead of 464, 1.8e-3 (1.9e-3) and 1.4e-3 (8.9e-4). With a
//! third as many and the reduction's seventh shift, 32/h ([`super::SHIFTS`]): 22 shapes, 165
//! modes, 1.2e-3 and 9.2e-4; on 16 elements 43 shapes, 278 modes, 5.3e-4 and 9.4e-4. The
//! shift at 32/h resolves the ripple within a half period that the fewer shapes would lose
//! (a third as many shapes at the six shifts before: 2.2e-3 and 1.1e-3), and costs no more
//! time: the eight factorisations run two at a time in four rounds, as the seven did. A
//! fixed number of shapes is not enough under refinement: the corner peaks sharpen as the
//! elements shrink (16 elements, half as many shapes as before: 40 shapes left 2.4e-3 of the
//! rise, 32 left 4.7e-3), so the number follows the points, a third of them and at least
//! [`FEWEST`].
//!
//! Nor is it enough for fast sliding: the heat of a half period h reaches √(a h) into the
//! body (a its diffusivity), 0.8 mm in punch-b40-heat's composite at ω = 10 rad/s, 0.15 mm at
//! 300, and a layer thinner than the flux's features answers each point's own heat. A review
//! found a third as many shapes 2.5e-2 of the rise off after one half period at ω = 100 and
//! 0.19 (in each body's largest temperature) over 300 steps at ω = 300, where one input per
//! point stays within 3e-4 and 2.5e-3 of a converged model. So the number is also at least
//! one per [`DEPTHS_PER_SHAPE`] thermal depths along the contact, and past half the points
//! the inputs are one per point (tests/heat.rs, `the_reduced_model_follows_the_full_one_at_
//! slow_and_fast_sliding`: at ω = 10, 30, 100 the contact temperature within 2.2e-3, 5.9e-4
//! and 4.0e-4 of its rise from the full model over six half periods; a third as many shapes
//! at ω = 30 was 6.2e-3 off).
//!
//! Under monotonic sliding the heat of a point enters material that carries it along the
//! contact in a thin layer (Péclet numbers up to 1800): the response of each point is its
//! own, and the inputs stay one per point (the caller decides: [`shapes`] is only asked for a
//! symmetric problem).

use crate::geometry::Point;
use faer::Mat;

/// The fewest shapes used: a contact of at most that many points keeps one input per point.
pub const FEWEST: usize = 16;

/// Diffusion lengths per shape: the contact's heat needs a shape per this many thermal
/// depths √(a h) along the contact (module docs).
pub const DEPTHS_PER_SHAPE: f64 = 4.0;

/// The shapes (points × m, dimensionless) of the contact's heat at the contact points `x`
/// (mm, ordered along the contact) whose heat of a half period reaches `depth` = √(a h) (mm;
/// a the smallest diffusivity at the contact, h the half period): Chebyshev polynomials of
/// the chord length L along them, m = max(⌈n/3⌉, ⌈L/(4 depth)⌉, [`FEWEST`]). None (one
/// input per point) when that is more than half the points, or the points do not span a
/// length.
pub fn shapes(x: &[Point], depth: f64) -> Option<Mat<f64>> {
    let n = x.len();
    let mut chord = Vec::with_capacity(n);
    chord.push(0.0);
    for i in 1..n {
        let step = (x[i][0] - x[i - 1][0]).hypot(x[i][1] - x[i - 1][1]);
        chord.push(chord[i - 1] + step);
    }
    let length = *chord.last()?;
    if length <= 0.0 || !length.is_finite() {
        return None;
    }
    let by_depth = (length / (DEPTHS_PER_SHAPE * depth)).ceil();
    if by_depth.is_nan() || by_depth >= n as f64 {
        // Also a depth of zero or NaN: one input per point.
        return None;
    }
    let m = n.div_ceil(3).max(FEWEST).max(by_depth as usize);
    // Past half the points the polynomials miss what they leave out in the contact's middle
    // (their zeros crowd at its ends), where a thin layer answers each point's own heat.
    if m >= n || 2 * m > n.max(2 * FEWEST) {
        return None;
    }
    // T_j(s) = cos(j arccos s) with s ∈ [−1, 1]: bounded by 1, and well conditioned as
    // columns (the Gram–Schmidt normalises them anyway).
    Some(Mat::from_fn(n, m, |i, j| {
        let s = (2.0 * chord[i] / length - 1.0).clamp(-1.0, 1.0);
        (j as f64 * s.acos()).cos()
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_third_as_many_chebyshev_shapes_as_points() {
        let points: Vec<Point> = (0..65)
            .map(|i| [1070.0 + i as f64 * 60.0 / 64.0, 100.0])
            .collect();
        // A deep thermal layer (1 mm over 60 mm: 15 shapes by depth): a third of the points.
        let t = shapes(&points, 1.0).unwrap();
        assert_eq!((t.nrows(), t.ncols()), (65, 22));
        // T_0 = 1, T_1 the position, T_2 = 2 s² − 1 at both ends and the middle.
        for i in [0, 32, 64] {
            let s = i as f64 / 32.0 - 1.0;
            assert!((t[(i, 0)] - 1.0).abs() < 1e-14);
            assert!((t[(i, 1)] - s).abs() < 1e-12);
            assert!((t[(i, 2)] - (2.0 * s * s - 1.0)).abs() < 1e-12);
        }
        // At least FEWEST shapes; at most FEWEST points: one input per point.
        assert_eq!(shapes(&points[..40], 1.0).unwrap().ncols(), FEWEST);
        assert!(shapes(&points[..FEWEST], 1.0).is_none());
        // A thin layer needs more: 0.5 mm, 30 shapes; 0.4 mm, 38, more than half the points:
        // one input per point.
        assert_eq!(shapes(&points, 0.5).unwrap().ncols(), 30);
        assert!(shapes(&points, 0.4).is_none());
        assert!(shapes(&points, 0.0).is_none());
        assert!(shapes(&points, f64::NAN).is_none());
    }
}
