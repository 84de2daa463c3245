//! Each body's own wear: the depth worn off body 1 and off body 2 at every contact point, and
//! the volumes.
//!
//! The schemes integrate one quantity, the shape (the gap), whose change is the sum of both
//! bodies' wear: Δg = Δw⁽¹⁾ + Δw⁽²⁾ at each pair of points. How it divides follows from the
//! wear rule of each body, ẇ⁽ⁱ⁾ = β̃ᵢ pᵇⁱ |v|ᵃⁱ, which the integrator sums step by step
//! (k half periods of each step's pressure) beside the shape. The split takes the total from
//! the shape, so that both bodies' wear adds up to what the scheme integrated (Richardson
//! extrapolation and BDF2 included), and the shares from those sums. When both bodies' laws
//! have the same exponent b, each body's share β̃ᵢ sᵢ / Σ β̃ⱼ sⱼ (sᵢ = ∫|v|ᵃⁱ dτ) is the same
//! at every pressure, and the split is exact whatever the scheme; when the exponents differ,
//! the share depends on the pressure's history and the sums follow it step by step.
//!
//! With `wear.shape_zero_at` the shape is shifted after each cycle by a vertical rigid
//! translation of body 1, which removes no material: the translation's amount is recovered as
//! the multiple of that mode which brings the shape's change closest (least squares over the
//! contact length) to the summed wear.

use crate::contact::ContactPoints;

/// Each body's wear at each contact point (mm), from the change of the shape and the summed
/// wear of each body.
///
/// - `change`: the shape's change over the run (final minus initial shape), mm;
/// - `summed`: each body's wear summed step by step (k half periods of each step's pressure),
///   mm;
/// - `shifted`: whether the shape was shifted by `wear.shape_zero_at`;
/// - `fallback_share`: body 1's share where neither body wore (no pressure there, ever).
pub(super) fn split(
    points: &ContactPoints,
    change: &[f64],
    summed: &[Vec<f64>; 2],
    shifted: bool,
    fallback_share: f64,
) -> [Vec<f64>; 2] {
    let total: Vec<f64> = if shifted {
        unshift(points, change, summed)
    } else {
        change.to_vec()
    };
    let mut out = [vec![0.0; total.len()], vec![0.0; total.len()]];
    for (i, &removed) in total.iter().enumerate() {
        let both = summed[0][i] + summed[1][i];
        let share = if both > 0.0 {
            summed[0][i] / both
        } else {
            fallback_share
        };
        out[0][i] = share * removed;
        out[1][i] = removed - out[0][i];
    }
    out
}

/// The shape's change with the shifts of `wear.shape_zero_at` undone: plus the multiple α of
/// the shift's mode m_i = −n_z,i that brings it closest to the summed wear in the contact
/// length's least squares, α = Σ wᵢ mᵢ (sᵢ − Δgᵢ) / Σ wᵢ mᵢ².
fn unshift(points: &ContactPoints, change: &[f64], summed: &[Vec<f64>; 2]) -> Vec<f64> {
    let mode = |i: usize| -points.normal[i][1];
    let (mut numerator, mut denominator) = (0.0, 0.0);
    for (i, (&d, &w)) in change.iter().zip(&points.weight).enumerate() {
        let s = summed[0][i] + summed[1][i];
        numerator += w * mode(i) * (s - d);
        denominator += w * mode(i) * mode(i);
    }
    let alpha = if denominator > 0.0 {
        numerator / denominator
    } else {
        0.0
    };
    change
        .iter()
        .enumerate()
        .map(|(i, d)| d + alpha * mode(i))
        .collect()
}

/// The volume of `wear` (mm at each contact point) over the contact edge, mm³: t ∫ w ds by
/// the contact points' quadrature weights (mm) and the thickness `thickness` (mm).
pub fn worn_volume(points: &ContactPoints, wear: &[f64], thickness: f64) -> f64 {
    thickness
        * wear
            .iter()
            .zip(&points.weight)
            .map(|(w, l)| w * l)
            .sum::<f64>()
}
