//! Monotonic steady shapes (paper §6.1, eq. 38) and the averaged monotonic shape (eq. 39),
//! the paper's first guess of the periodic steady shape.
//!
//! For monotonic sliding in one direction the steady pressure is the minimiser of the wear
//! dissipation (uniform p̃ under a translating flat punch). Loading each body separately with
//! that pressure and its friction stress, with no rigid motion of the plate, the total gap must
//! vanish (eq. 38): d = g₀ + g + A_s P = 0, so g = −(g₀ + A_s P). The paper zeroes the shape of
//! leftward sliding at the left end of the contact (g(1070) = 0) and that of rightward sliding
//! at the right end (g(1130) = 0), and approximates the reciprocating shape by
//! Shape⁽ᵃ⁾ = shape⁽ˡ⁾ + shape⁽ʳ⁾ − 2 shape⁽ˡ⁾(mid) (eq. 39).
//!
//! The ordinates the paper prints for Example 1 (§6.2.1) are about half of that sum: they are
//! its mean, ½(shape⁽ˡ⁾ + shape⁽ʳ⁾) − shape⁽ˡ⁾(mid), and match only in plane strain (see
//! `docs/validation.md`). Both readings are offered, [`AveragedReading`].

use crate::complementarity::Direction;
use crate::contact::CondensedContact;
use crate::steady::{steady_state, SteadyError, SteadySliding, SteadyStatus};

/// How eq. 39 is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum AveragedReading {
    /// As printed: shape⁽ˡ⁾ + shape⁽ʳ⁾ − 2 shape⁽ˡ⁾(mid).
    Sum,
    /// The mean, ½(shape⁽ˡ⁾ + shape⁽ʳ⁾) − shape⁽ˡ⁾(mid): what the paper's printed ordinates of
    /// §6.2.1 are (default).
    #[default]
    Mean,
}

impl AveragedReading {
    /// Factor applied to the eq. 39 sum: 1 for `Sum`, ½ for `Mean`.
    pub fn factor(self) -> f64 {
        match self {
            AveragedReading::Sum => 1.0,
            AveragedReading::Mean => 0.5,
        }
    }
    /// "sum" or "mean", as written in summary.json and accepted by the CLI.
    pub fn name(self) -> &'static str {
        match self {
            AveragedReading::Sum => "sum",
            AveragedReading::Mean => "mean",
        }
    }
}

/// The steady shape of monotonic sliding in one direction (eq. 38).
#[derive(Clone, Debug)]
pub struct MonotonicShape {
    /// The sliding direction: `Plus` is the strip moving towards +x ("rightward"), friction
    /// +μp e_x on body 1; `Minus` is leftward.
    pub direction: Direction,
    /// Steady pressure of monotonic sliding, MPa, one per contact point.
    pub pressure: Vec<f64>,
    /// Wear gap g = −(g₀ + A_s P), mm, zeroed at the contact end the paper chooses (the left
    /// end for leftward, the right end for rightward sliding).
    pub shape: Vec<f64>,
    /// Status of the monotonic steady solve that gave the pressure.
    pub status: SteadyStatus,
}

/// The monotonic steady shape of `contact` for sliding in `direction` (eq. 38), with the
/// half-period wear `terms` of [`crate::wear::WearIntegrator::half_period_wear`] (for a
/// monotonic state only their exponents matter: the pressure minimises the wear dissipation).
pub fn monotonic_shape(
    contact: &CondensedContact,
    terms: &[(f64, f64)],
    direction: Direction,
) -> Result<MonotonicShape, SteadyError> {
    let state = steady_state(
        contact,
        terms,
        SteadySliding::Monotonic(direction),
        Default::default(),
    )?;
    let shape = shape_under_pressure(contact, &state.p_plus, direction);
    let zero = match direction {
        Direction::Minus => 0,
        Direction::Plus => contact.len() - 1,
    };
    let offset = shape[zero];
    Ok(MonotonicShape {
        direction,
        pressure: state.p_plus,
        shape: shape.iter().map(|g| g - offset).collect(),
        status: state.status,
    })
}

/// g = −(g₀ + A_s P) (eq. 38 with λ = 0): the gap each point needs so that it just touches
/// when the bodies carry the pressure `pressure` (MPa) and its friction in `direction`.
pub fn shape_under_pressure(
    contact: &CondensedContact,
    pressure: &[f64],
    direction: Direction,
) -> Vec<f64> {
    let n = contact.len();
    let a = contact.gap_matrix(direction.sign());
    let force: Vec<f64> = pressure
        .iter()
        .zip(contact.areas())
        .map(|(p, w)| p * w)
        .collect();
    (0..n)
        .map(|i| {
            let elastic: f64 = (0..n).map(|j| a[i * n + j] * force[j]).sum();
            -(contact.points.initial_gap[i] + elastic)
        })
        .collect()
}

/// Both monotonic shapes and their average (eq. 39).
#[derive(Clone, Debug)]
pub struct AveragedShape {
    /// Leftward sliding (`Minus`), zeroed at the left end.
    pub left: MonotonicShape,
    /// Rightward sliding (`Plus`), zeroed at the right end.
    pub right: MonotonicShape,
    /// Reading of eq. 39 used.
    pub reading: AveragedReading,
    /// Index of the contact point at mid contact, where the average is zero.
    pub mid: usize,
    /// Shape⁽ᵃ⁾, mm, one per contact point.
    pub shape: Vec<f64>,
}

/// The averaged monotonic shape (eq. 39) of `contact` under the `reading`; zero at the contact
/// point nearest the middle of the contact (x = 1100 in Example 1, the crown of the brake).
pub fn averaged_shape(
    contact: &CondensedContact,
    terms: &[(f64, f64)],
    reading: AveragedReading,
) -> Result<AveragedShape, SteadyError> {
    let left = monotonic_shape(contact, terms, Direction::Minus)?;
    let right = monotonic_shape(contact, terms, Direction::Plus)?;
    let mid = mid_point(contact);
    let shape = combine(&left.shape, &right.shape, mid, reading);
    Ok(AveragedShape {
        left,
        right,
        reading,
        mid,
        shape,
    })
}

/// eq. 39 (times ½ for the mean): left + right − 2 left(mid).
pub fn combine(left: &[f64], right: &[f64], mid: usize, reading: AveragedReading) -> Vec<f64> {
    left.iter()
        .zip(right)
        .map(|(l, r)| reading.factor() * (l + r - 2.0 * left[mid]))
        .collect()
}

/// Index of the contact point nearest to the middle of the contact's x range.
pub fn mid_point(contact: &CondensedContact) -> usize {
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let middle = 0.5 * (lo + hi);
    (0..x.len())
        .min_by(|&i, &j| (x[i] - middle).abs().total_cmp(&(x[j] - middle).abs()))
        .unwrap_or(0)
}
