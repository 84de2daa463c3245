//! `wear.shape_zero_at`: the shape shifted to zero at a chosen x by a vertical rigid
//! translation of body 1 (which the plate takes up), and the wear reported relative to it.

use crate::contact::ContactPoints;

/// Shift `shape` to zero at the interpolation point `weights` by a vertical rigid translation
/// of body 1. It changes the gap by n_c·(−e_z) at each point (1 under a flat punch, cos α on
/// an arc) and so leaves every pressure unchanged: the plate's λ_F takes it up.
pub(super) fn shift_to_zero(shape: &mut [f64], weights: &[(usize, f64)], points: &ContactPoints) {
    let mode = |i: usize| -points.normal[i][1];
    let at_ref: f64 = weights.iter().map(|&(i, w)| w * mode(i)).sum();
    if at_ref.abs() > 1e-12 {
        let offset = weights.iter().map(|&(i, w)| w * shape[i]).sum::<f64>() / at_ref;
        for (i, g) in shape.iter_mut().enumerate() {
            *g -= offset * mode(i);
        }
    }
}

/// Linear interpolation weights of the contact points at x = `x0` (nearest pair along x).
pub(super) fn interpolation_weights(points: &ContactPoints, x0: f64) -> Vec<(usize, f64)> {
    let xs: Vec<f64> = points.x.iter().map(|p| p[0]).collect();
    for i in 0..xs.len().saturating_sub(1) {
        let (a, b) = (xs[i], xs[i + 1]);
        if (a - x0) * (b - x0) <= 0.0 && a != b {
            let s = (x0 - a) / (b - a);
            return vec![(i, 1.0 - s), (i + 1, s)];
        }
    }
    let nearest = (0..xs.len())
        .min_by(|&i, &j| (xs[i] - x0).abs().total_cmp(&(xs[j] - x0).abs()))
        .unwrap_or(0);
    vec![(nearest, 1.0)]
}

/// The wear in `shape` (a shape of a run, mm): `shape` minus the initial gap (the bodies'
/// geometric gap and `contact.initial_shape`), positive where material was removed. With
/// `zero_at` (`wear.shape_zero_at`, mm) it is shifted by the same vertical rigid translation
/// of body 1 as the shape is, but so that the *wear* is zero at x₀: the shape's own shift
/// makes the shape zero there, which on a curved body leaves the wear at −g₀(x₀).
pub fn wear_of_shape(points: &ContactPoints, shape: &[f64], zero_at: Option<f64>) -> Vec<f64> {
    let mut wear: Vec<f64> = shape
        .iter()
        .zip(&points.initial_gap)
        .map(|(g, g0)| g - g0)
        .collect();
    if let Some(x0) = zero_at {
        shift_to_zero(&mut wear, &interpolation_weights(points, x0), points);
    }
    wear
}
