//! An independent reference for the coupled partial slip of two dissimilar elastic half-planes
//! (plane strain): a cylinder-on-flat profile pressed by P without friction, then loaded
//! tangentially by Q < μP with P held — the problem of Nowell, Hills & Sackfield (1988, J. Mech.
//! Phys. Solids 36, "Contact of dissimilar elastic cylinders under normal and tangential
//! loading"). It shares nothing with the FE code: half-plane influence functions on equal
//! panels, solved by an active-set iteration.
//!
//! # Conventions
//!
//! * x along the interface; h(x) = x²/(2R) is the initial gap (the pad's profile; which body
//!   carries the curvature, and which lies on top, does not matter: only the relative profile
//!   enters, and reflecting y leaves every equation below unchanged). What matters is which
//!   body is "1" — the one whose traction q and load Q are meant, and whose constants are
//!   material 1 in β — and the direction of x.
//! * p(x) ≥ 0 the contact pressure; q(x) the shear traction ON BODY 1 (exerted by body 2),
//!   positive along +x. The tangential load Q acts on body 1 along +x, so ∫q dx = −Q:
//!   for Q > 0 the shear on body 1 is negative, body 1 slips along +x against body 2 where it
//!   slips, and friction there is q = −μp. This is the FE code's convention
//!   (`partial_slip`: forces on body 1 along +τ, Σ F + Q = 0).
//! * Dundurs' β = [(κ₁−1)/μ₁ − (κ₂−1)/μ₂] / [(κ₁+1)/μ₁ + (κ₂+1)/μ₂] (μᵢ shear moduli,
//!   κ = 3 − 4ν), the same as [Γ(κ₁−1) − (κ₂−1)] / [Γ(κ₁+1) + (κ₂+1)] with Γ = μ₂/μ₁.
//!   β > 0 when body 1 is the more compliant one (for equal ν): body 1 → rubber-like, body 2 →
//!   rigid gives β → (1 − 2ν₁)/(2(1 − ν₁)) > 0.
//! * A = 2[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] = 2/E*, with which Hertz reads p₀ = a/(RA) = aE*/(2R),
//!   a² = 4PR/(πE*), P = πap₀/2. (Written with A = 4/E* the Hertz check would fail by 2.)
//!
//! # Equations
//!
//! From the surface displacements of a half-plane (Johnson, Contact Mechanics, eq. 2.25: with
//! z into the solid, u_z′ = −(2(1−ν²)/πE)∫p/(x−s) + ((1−2ν)(1+ν)/E) q and
//! u_x′ = −((1−2ν)(1+ν)/E) p − (2(1−ν²)/πE)∫q/(x−s)), applied to each body with its own
//! traction (p, q on body 1; p, −q on body 2), and with H(f)(x) = (1/π) PV∫ f(s)/(x − s) ds:
//!
//! * contact (gap closed): h′(x)/A = H(p)(x) − β q(x);
//! * tangential: g′(x)/A = H(q)(x) + β p(x), g = u_x2 − u_x1 (body 2 against body 1); body 1's
//!   slip against body 2 is s = −g + a rigid shift δ.
//!
//! Signs checked from first principles: a normal load draws the surface towards itself (the
//! −(1−2ν)(1+ν)p/E term), so by Betti's theorem a tangential load depresses the surface ahead
//! of it and raises it behind. Body 1 pushed along +x carries friction along −x: its surface
//! rises towards body 2 at +x; body 2, dragged along +x, sinks at +x. If body 1 is the more
//! compliant (β > 0) the first wins: the interference grows at +x and the pressure moves to
//! +x, the direction in which the more compliant body moves relative to the other. In full
//! sliding (q = −μp) the contact equation is H(p) + βμ p = x/(RA), whose bounded solution
//! (Bufler; Plemelj with X(z) = (z − b)^(1/2−γ)(z + b)^(1/2+γ)) is, with t = x − e,
//!
//!   p = p₀ cos(πγ) (b − t)^(1/2−γ) (b + t)^(1/2+γ) / a,  tan(πγ) = βμ,
//!   b = a/√(1 − 4γ²),  e = 2γb,
//!
//! so for βμ > 0 both the contact (by e) and the peak shift to +x; [`full_sliding`] is checked
//! against it.
//!
//! # Discretisation
//!
//! Units: x in a, tractions in p₀, displacements divided by A in p₀a (so that h/A = x²/2 and
//! P = π/2). N equal panels on [−L, L], L = 1.25 + 2.5γ (γ of full sliding, so the window
//! holds every contact of the loading), piecewise-constant p and q, collocation at the
//! centres. The displacements themselves, not their gradients, are collocated, so that the
//! rigid approach d and the rigid shift δ are unknowns fixed by ∫p = P and ∫q = −Q:
//!
//!   gap_i/A = x_i²/2 − d − (1/π)Σ_j L_ij p_j + (β/2)Σ_j S_ij q_j,
//!   w_i     =            −(1/π)Σ_j L_ij q_j − (β/2)Σ_j S_ij p_j,   s_i/A = δ + w_i − w_i⁰,
//!
//! with L_ij = ∫_panel j ln|x_i − s| ds (in closed form, F(u) = u ln|u| − u) and
//! S_ij = ∫_panel j sgn(x_i − s) ds = Δ sgn(i − j): the "local" β terms of the gradient
//! equations, integrated (their constants go into d and δ). s_i is body 1's slip against body
//! 2 over the stage, measured from the stage's start (w⁰).
//!
//! # Loading
//!
//! 1. P without friction (q = 0): discrete Hertz, independent of β.
//! 2. One stage from there to Q (P held), as the FE model does: contact free (gap ≥ 0, p ≥ 0,
//!    complementary), each contact point sticks (s_i = 0, |q_i| ≤ μp_i) or slips
//!    (q_i = −μp_i sign s_i), the pressure answering the shear through −βq and the slip the
//!    pressure through −βp. Solved by a primal–dual active-set iteration on (contact, stick,
//!    slip direction), each iteration one dense solve of the contact pressures, the stick
//!    shears, d and δ, until no set changes.
//! 3. Optionally a second stage back to Q′ < Q ([`coupled_unloading`]), its stick condition on
//!    its own slip.
//!
//! Edges are located below the panel size: near a stick edge the margin μp − |q| ∝
//! √(distance), near a contact edge that slips p ∝ distance^(1/2 ∓ γ) (Bufler's exponents,
//! tan(πγ) = βμ), so margin² or p^(1/(1/2 ∓ γ)), fitted by a line through the three
//! outermost panels inside, is extrapolated to zero (and kept between the last panel inside
//! and the first outside).
//!
//! # Accuracy
//!
//! `cargo test --release half_plane -- --ignored --nocapture` prints these tables.
//! β = 0.2, μ = 0.6, Q/μP = 0.5, edges in a (window ±1.345a):
//!
//! | N   | Δ/a     | stick left | stick right | offset  | contact left | contact right |
//! |-----|---------|------------|-------------|---------|--------------|---------------|
//! | 100 | 0.0269  | −0.66135   | 0.75883     | 0.04874 | −0.95710     | 1.04261       |
//! | 200 | 0.0135  | −0.66020   | 0.76012     | 0.04996 | −0.95664     | 1.04418       |
//! | 400 | 0.0067  | −0.66023   | 0.75890     | 0.04934 | −0.95738     | 1.04585       |
//! | 800 | 0.0034  | −0.66042   | 0.75935     | 0.04947 | −0.95694     | 1.04463       |
//!
//! The edges do not converge monotonically: they scatter by about ±1.5 × 10⁻³ a (a fifth
//! to a half of a panel at N = 400–800) as the panel grid slides past the edges, so the
//! reference is good to ~2 × 10⁻³ a in the edges and ~1 × 10⁻³ a in the stick zone's offset.
//! At β = 0 (N = 400): stick half-width 0.70691 against Cattaneo's 0.70711 (Q/μP = 0.5),
//! shear within 3.2 × 10⁻³ μp₀ of μp₀[√(1 − x²) − c√(1 − x²/c²)], contact ±0.99949,
//! pressure within 4.1 × 10⁻³ p₀ of Hertz, the zone that does not slip back on unloading
//! 0.89414 against Mindlin–Deresiewicz's 0.89443. Full sliding (N = 400): contact edges
//! within 1.2 × 10⁻³ a of Bufler's, pressure within 1.8 × 10⁻² p₀ (at the edge panels).
//! Loading in 20 stages instead of one changes no edge in the fourth decimal: the monotonic
//! loading is, to this accuracy, path-independent.

use faer::linalg::solvers::Solve;
use faer::Mat;
use std::f64::consts::PI;

/// The normal load per unit thickness in units of p₀a: Hertz's P = πap₀/2.
pub const LOAD: f64 = PI / 2.0;

/// A solved state of the half-plane contact, dimensionless: lengths in the Hertz half-width
/// a, tractions in the Hertz peak pressure p₀, displacements divided by A = 2/E* in p₀a.
#[derive(Clone, Debug)]
pub struct HalfPlaneState {
    /// Panel centres, a.
    pub x: Vec<f64>,
    /// Panel width, a.
    pub width: f64,
    /// Contact pressure on each panel, p₀ (0 outside the contact).
    pub pressure: Vec<f64>,
    /// Shear traction on body 1 along +x, p₀ (negative under Q > 0: ∫q dx = −Q).
    pub shear: Vec<f64>,
    /// Whether each panel sticks over the stage (false where it slips or is out of contact).
    pub stick: Vec<bool>,
    /// Body 1's slip against body 2 over the stage, along +x, in A p₀ a (0 where it sticks).
    pub slip: Vec<f64>,
    /// Left edge of the stick zone, a (NaN if nothing sticks).
    pub stick_left: f64,
    /// Right edge of the stick zone, a (NaN if nothing sticks).
    pub stick_right: f64,
    /// Left edge of the contact, a.
    pub contact_left: f64,
    /// Right edge of the contact, a.
    pub contact_right: f64,
    /// Rigid approach of body 1 towards body 2, in A p₀ a, up to the constant that the
    /// half-plane's logarithmic displacement leaves free (differences between states count).
    pub approach: f64,
    /// Body 1's rigid shift along +x over the stage, in A p₀ a (same proviso).
    pub shift: f64,
    /// The tangential load on body 1 along +x, p₀a (= −∫q dx).
    pub load: f64,
    /// Active-set iterations of the last stage.
    pub iterations: usize,
}

impl HalfPlaneState {
    /// The middle of the stick zone, a: its offset from the profile's axis.
    pub fn stick_centre(&self) -> f64 {
        0.5 * (self.stick_left + self.stick_right)
    }
}

/// The panels and the influence coefficients that depend only on i − j.
struct Panels {
    n: usize,
    width: f64,
    x: Vec<f64>,
    /// L(k) = ∫ ln|kΔ − u| du over a panel centred at 0, at index k + n − 1.
    log: Vec<f64>,
}

impl Panels {
    fn new(n: usize, half: f64) -> Self {
        let width = 2.0 * half / n as f64;
        let x = (0..n).map(|i| -half + (i as f64 + 0.5) * width).collect();
        // ∫ ln|u| du = u ln|u| − u, finite at u = 0.
        let f = |u: f64| if u == 0.0 { 0.0 } else { u * u.abs().ln() - u };
        let log = (0..2 * n - 1)
            .map(|k| {
                let d = (k as f64 - (n as f64 - 1.0)) * width;
                f(d + 0.5 * width) - f(d - 0.5 * width)
            })
            .collect();
        Panels { n, width, x, log }
    }

    /// L_ij = ∫_panel j ln|x_i − s| ds.
    fn l(&self, i: usize, j: usize) -> f64 {
        self.log[i + self.n - 1 - j]
    }

    /// S_ij = ∫_panel j sgn(x_i − s) ds.
    fn s(&self, i: usize, j: usize) -> f64 {
        match i.cmp(&j) {
            std::cmp::Ordering::Greater => self.width,
            std::cmp::Ordering::Less => -self.width,
            std::cmp::Ordering::Equal => 0.0,
        }
    }

    /// The elastic part of the gap per A, (u_y1 − u_y2)/A with y pointing from body 2 into
    /// body 1, up to a constant: −(1/π)Σ L p + (β/2)Σ S q.
    fn normal(&self, beta: f64, p: &[f64], q: &[f64]) -> Vec<f64> {
        (0..self.n)
            .map(|i| {
                (0..self.n)
                    .map(|j| -self.l(i, j) * p[j] / PI + 0.5 * beta * self.s(i, j) * q[j])
                    .sum()
            })
            .collect()
    }

    /// The gap per A: x²/2 − d + the elastic part.
    fn gap(&self, beta: f64, p: &[f64], q: &[f64], approach: f64) -> Vec<f64> {
        let v = self.normal(beta, p, q);
        (0..self.n)
            .map(|i| 0.5 * self.x[i] * self.x[i] - approach + v[i])
            .collect()
    }

    /// Body 1's tangential displacement against body 2 per A, without the rigid shift:
    /// w = −(1/π)Σ L q − (β/2)Σ S p.
    fn tangential(&self, beta: f64, p: &[f64], q: &[f64]) -> Vec<f64> {
        (0..self.n)
            .map(|i| {
                (0..self.n)
                    .map(|j| -self.l(i, j) * q[j] / PI - 0.5 * beta * self.s(i, j) * p[j])
                    .sum()
            })
            .collect()
    }
}

/// Solve the dense system `a` x = `b` (row-major n × n) by faer's LU with partial pivoting.
fn solve_dense(n: usize, a: &[f64], b: &[f64]) -> Vec<f64> {
    let m = Mat::<f64>::from_fn(n, n, |i, j| a[i * n + j]);
    let mut rhs = Mat::<f64>::from_fn(n, 1, |i, _| b[i]);
    m.partial_piv_lu().solve_in_place(rhs.as_mut());
    (0..n).map(|i| rhs[(i, 0)]).collect()
}

/// The half-width of the panel window for β and μ: the full-sliding contact (the widest and
/// most shifted of the loading, b + e ≈ 1 + 2γ) with a quarter of a to spare.
fn window(beta: f64, mu: f64) -> f64 {
    let gamma = (beta * mu).atan().abs() / PI;
    1.25 + 2.5 * gamma
}

const MAX_ITERATIONS: usize = 200;

/// The contact problem with the shear tied to the pressure, q = −`ms` p (`ms` = μ × the slip
/// direction; 0 without friction): active set on the contact alone. Returns p, q and d.
fn tied_normal(
    panels: &Panels,
    beta: f64,
    ms: f64,
) -> Result<(Vec<f64>, Vec<f64>, f64, usize), String> {
    let n = panels.n;
    let mut contact: Vec<bool> = panels.x.iter().map(|x| x.abs() < 1.0).collect();
    for iteration in 1..=MAX_ITERATIONS {
        let c: Vec<usize> = (0..n).filter(|&i| contact[i]).collect();
        let m = c.len() + 1;
        let mut a = vec![0.0; m * m];
        let mut b = vec![0.0; m];
        for (r, &i) in c.iter().enumerate() {
            for (k, &j) in c.iter().enumerate() {
                a[r * m + k] = -panels.l(i, j) / PI - 0.5 * beta * panels.s(i, j) * ms;
            }
            a[r * m + m - 1] = -1.0;
            b[r] = -0.5 * panels.x[i] * panels.x[i];
        }
        for k in 0..c.len() {
            a[(m - 1) * m + k] = panels.width;
        }
        b[m - 1] = LOAD;
        let sol = solve_dense(m, &a, &b);
        let mut p = vec![0.0; n];
        for (k, &j) in c.iter().enumerate() {
            p[j] = sol[k];
        }
        let q: Vec<f64> = p.iter().map(|p| -ms * p).collect();
        let approach = sol[m - 1];
        let gap = panels.gap(beta, &p, &q, approach);
        let mut changed = false;
        for i in 0..n {
            if contact[i] && p[i] < 0.0 {
                contact[i] = false;
                changed = true;
            } else if !contact[i] && gap[i] < -1e-12 {
                contact[i] = true;
                changed = true;
            }
        }
        if !changed {
            return Ok((p, q, approach, iteration));
        }
    }
    Err("the contact set did not settle".into())
}

/// The start of a stage: tractions and body 1's tangential displacement (per A, elastic part).
struct Start {
    p: Vec<f64>,
    w: Vec<f64>,
}

/// One stage from `start` to the tangential load `load` (on body 1 along +x, p₀a), the normal
/// load held at [`LOAD`]; `direction` is the slip direction of the stage (+1 loading, −1
/// unloading).
///
/// The active sets are intervals of panels: the contact [cl, cr] and within it the stick zone
/// [sl, sr], the rest of the contact slipping along `direction` (a monotonic stage from a
/// symmetric start has one stick zone and slips one way). Each iteration moves each of the
/// four edges over the contiguous run of panels next to it that violate their conditions
/// (p < 0 or |q| > μp just inside, gap < 0 or slip against `direction` just outside).
/// Panel-by-panel sets, tried first, let the slipping contact edge of the coupled problem
/// chatter (alternate panels in and out) and never settled. The settled state is then checked
/// on every panel, so the interval assumption is verified, not imposed.
fn stage(
    panels: &Panels,
    beta: f64,
    mu: f64,
    start: &Start,
    load: f64,
    direction: f64,
) -> Result<HalfPlaneState, String> {
    let n = panels.n;
    let inside: Vec<usize> = (0..n).filter(|&i| start.p[i] > 0.0).collect();
    let (Some(&first), Some(&last)) = (inside.first(), inside.last()) else {
        return Err("no contact at the stage's start".into());
    };
    let (mut cl, mut cr) = (first, last);
    let (mut sl, mut sr) = (first, last);
    // The shear of a slipping panel is tied to its pressure: q = −μσp.
    let tie = -mu * direction;
    for iteration in 1..=MAX_ITERATIONS {
        let nc = cr - cl + 1;
        let ns = sr - sl + 1;
        let stick = |j: usize| (sl..=sr).contains(&j);
        // Unknowns: p on the contact (cl..=cr), q on the stick zone (sl..=sr), d, δ.
        let m = nc + ns + 2;
        let (id, idelta) = (nc + ns, nc + ns + 1);
        let mut a = vec![0.0; m * m];
        let mut b = vec![0.0; m];
        for (r, i) in (cl..=cr).enumerate() {
            let row = &mut a[r * m..(r + 1) * m];
            for (k, j) in (cl..=cr).enumerate() {
                row[k] += -panels.l(i, j) / PI;
                if !stick(j) {
                    row[k] += 0.5 * beta * panels.s(i, j) * tie;
                }
            }
            for (k, j) in (sl..=sr).enumerate() {
                row[nc + k] += 0.5 * beta * panels.s(i, j);
            }
            row[id] = -1.0;
            b[r] = -0.5 * panels.x[i] * panels.x[i];
        }
        for (r, i) in (sl..=sr).enumerate() {
            let row = &mut a[(nc + r) * m..(nc + r + 1) * m];
            for (k, j) in (cl..=cr).enumerate() {
                row[k] += -0.5 * beta * panels.s(i, j);
                if !stick(j) {
                    row[k] += -panels.l(i, j) / PI * tie;
                }
            }
            for (k, j) in (sl..=sr).enumerate() {
                row[nc + k] += -panels.l(i, j) / PI;
            }
            row[idelta] = 1.0;
            b[nc + r] = start.w[i];
        }
        for (k, j) in (cl..=cr).enumerate() {
            a[id * m + k] = panels.width;
            if !stick(j) {
                a[idelta * m + k] = panels.width * tie;
            }
        }
        for k in 0..ns {
            a[idelta * m + nc + k] = panels.width;
        }
        b[id] = LOAD;
        b[idelta] = -load;
        let sol = solve_dense(m, &a, &b);
        let (mut p, mut q) = (vec![0.0; n], vec![0.0; n]);
        for (k, j) in (cl..=cr).enumerate() {
            p[j] = sol[k];
            q[j] = tie * sol[k];
        }
        for (k, j) in (sl..=sr).enumerate() {
            q[j] = sol[nc + k];
        }
        let (approach, shift) = (sol[id], sol[idelta]);
        let gap = panels.gap(beta, &p, &q, approach);
        let w = panels.tangential(beta, &p, &q);
        let slip: Vec<f64> = (0..n).map(|i| shift + w[i] - start.w[i]).collect();
        let negative = |i: usize| p[i] < 0.0;
        let overlap = |i: usize| gap[i] < -1e-12;
        let exceeds = |i: usize| q[i].abs() > mu * p[i] * (1.0 + 1e-12);
        let backwards = |i: usize| direction * slip[i] < 0.0;
        // New edges: shrink over violating runs inside, else grow over violating runs outside.
        let (mut ncl, mut ncr) = (cl, cr);
        if negative(cl) {
            while ncl < ncr && negative(ncl) {
                ncl += 1;
            }
        } else {
            while ncl > 0 && overlap(ncl - 1) {
                ncl -= 1;
            }
        }
        if negative(cr) {
            while ncr > ncl && negative(ncr) {
                ncr -= 1;
            }
        } else {
            while ncr + 1 < n && overlap(ncr + 1) {
                ncr += 1;
            }
        }
        let (mut nsl, mut nsr) = (sl, sr);
        if exceeds(sl) {
            while nsl < nsr && exceeds(nsl) {
                nsl += 1;
            }
        } else {
            while nsl > cl && backwards(nsl - 1) {
                nsl -= 1;
            }
        }
        if exceeds(sr) {
            while nsr > nsl && exceeds(nsr) {
                nsr -= 1;
            }
        } else {
            while nsr < cr && backwards(nsr + 1) {
                nsr += 1;
            }
        }
        if nsl == nsr && exceeds(nsl) {
            return Err("nothing sticks: the load is at or beyond the friction limit".into());
        }
        let (nsl, nsr) = (nsl.max(ncl), nsr.min(ncr));
        if nsl > nsr {
            return Err("the stick zone left the contact".into());
        }
        if (ncl, ncr, nsl, nsr) != (cl, cr, sl, sr) {
            (cl, cr, sl, sr) = (ncl, ncr, nsl, nsr);
            continue;
        }
        // Settled: every panel's conditions, not only those next to the edges.
        let stick: Vec<bool> = (0..n).map(|i| (sl..=sr).contains(&i)).collect();
        let contact: Vec<bool> = (0..n).map(|i| (cl..=cr).contains(&i)).collect();
        let violated = (0..n).find(|&i| {
            if contact[i] {
                negative(i) || (stick[i] && exceeds(i)) || (!stick[i] && backwards(i))
            } else {
                overlap(i)
            }
        });
        if let Some(i) = violated {
            return Err(format!(
                "the settled intervals violate the conditions at x = {:.4}",
                panels.x[i]
            ));
        }
        let margin: Vec<f64> = (0..n).map(|i| mu * p[i] - q[i].abs()).collect();
        let (stick_left, stick_right) = edges(&panels.x, &margin, &stick, (2.0, 2.0));
        let (contact_left, contact_right) =
            edges(&panels.x, &p, &contact, slip_powers(beta, mu, direction));
        let slip = (0..n)
            .map(|i| if stick[i] { 0.0 } else { slip[i] })
            .collect();
        let q_out: Vec<f64> = (0..n)
            .map(|i| if contact[i] { q[i] } else { 0.0 })
            .collect();
        let load = -q_out.iter().sum::<f64>() * panels.width;
        return Ok(HalfPlaneState {
            x: panels.x.clone(),
            width: panels.width,
            pressure: p,
            shear: q_out,
            stick,
            slip,
            stick_left,
            stick_right,
            contact_left,
            contact_right,
            approach,
            shift,
            load,
            iterations: iteration,
        });
    }
    Err("the contact and stick edges did not settle".into())
}

/// The left and right edges of the zone `inside` (a contiguous run is assumed), where
/// `margin` (∝ distance^(1/power) inside, 0 beyond) vanishes: the line through margin^power
/// of the three outermost panels inside, extrapolated to zero, kept between the outermost
/// centre inside and the first outside. NaN if the zone is empty.
fn edges(x: &[f64], margin: &[f64], inside: &[bool], powers: (f64, f64)) -> (f64, f64) {
    let (Some(first), Some(last)) = (
        inside.iter().position(|&b| b),
        inside.iter().rposition(|&b| b),
    ) else {
        return (f64::NAN, f64::NAN);
    };
    let width = if x.len() > 1 { x[1] - x[0] } else { 0.0 };
    let fit = |indices: Vec<usize>, outward: f64, power: f64| -> f64 {
        let e = indices[0];
        if indices.len() < 2 {
            return x[e] + 0.5 * outward * width;
        }
        // Least-squares line y = α + γ x through (x, margin²).
        let k = indices.len() as f64;
        let (mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0);
        for &i in &indices {
            let y = margin[i].max(0.0).powf(power);
            sx += x[i];
            sy += y;
            sxx += x[i] * x[i];
            sxy += x[i] * y;
        }
        let slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
        let intercept = (sy - slope * sx) / k;
        let root = -intercept / slope;
        let (lo, hi) = if outward > 0.0 {
            (x[e], x[e] + width)
        } else {
            (x[e] - width, x[e])
        };
        if root.is_finite() {
            root.clamp(lo, hi)
        } else {
            x[e] + 0.5 * outward * width
        }
    };
    let take = 3;
    let right: Vec<usize> = (0..take)
        .filter_map(|k| last.checked_sub(k))
        .filter(|&i| i >= first && inside[i])
        .collect();
    let left: Vec<usize> = (0..take)
        .map(|k| first + k)
        .filter(|&i| i <= last && inside[i])
        .collect();
    (fit(left, -1.0, powers.0), fit(right, 1.0, powers.1))
}

/// The powers that make the pressure linear near the (left, right) edges of a contact whose
/// edges slip along `direction`: p ∝ distance^(1/2 ± γ), tan(πγ) = βμ (see [`bufler`]).
fn slip_powers(beta: f64, mu: f64, direction: f64) -> (f64, f64) {
    let gamma = (beta * mu * direction).atan() / PI;
    (1.0 / (0.5 + gamma), 1.0 / (0.5 - gamma))
}

/// The state after the frictionless normal load (discrete Hertz) on the panels of β, μ.
fn hertz(panels: &Panels, beta: f64) -> Result<Start, String> {
    let (p, q, _, _) = tied_normal(panels, beta, 0.0)?;
    let w = panels.tangential(beta, &p, &q);
    Ok(Start { p, w })
}

/// P (frictionless), then one stage to Q = `q_over_mu_p` μP on body 1 along +x, P held: the
/// coupled partial slip of two dissimilar half-planes with Dundurs' `beta` (body 1 the
/// profiled one, see the module's conventions), friction coefficient `mu`, on `panels` equal
/// panels. 0 ≤ `q_over_mu_p` < 1.
pub fn coupled_partial_slip(
    beta: f64,
    mu: f64,
    q_over_mu_p: f64,
    panels: usize,
) -> Result<HalfPlaneState, String> {
    coupled_partial_slip_in_steps(beta, mu, q_over_mu_p, panels, 1)
}

/// As [`coupled_partial_slip`], the tangential load applied in `steps` equal stages, each
/// stage's stick condition on its own slip (one stage is the FE model's loading; many
/// approach the incremental, path-following solution).
pub fn coupled_partial_slip_in_steps(
    beta: f64,
    mu: f64,
    q_over_mu_p: f64,
    panels: usize,
    steps: usize,
) -> Result<HalfPlaneState, String> {
    let grid = Panels::new(panels, window(beta, mu));
    let mut start = hertz(&grid, beta)?;
    let mut state = None;
    for k in 1..=steps.max(1) {
        let load = q_over_mu_p * mu * LOAD * k as f64 / steps.max(1) as f64;
        let s = stage(&grid, beta, mu, &start, load, 1.0)?;
        start = Start {
            p: s.pressure.clone(),
            w: grid.tangential(beta, &s.pressure, &s.shear),
        };
        state = Some(s);
    }
    state.ok_or_else(|| "no stage".into())
}

/// P, then Q* = `peak` μP in one stage, then back to `back` μP (< `peak`) in a second stage:
/// the loaded and the unloaded states. In the unloaded state `stick` and `slip` are the second
/// stage's (the zone that does not slip back).
pub fn coupled_unloading(
    beta: f64,
    mu: f64,
    peak: f64,
    back: f64,
    panels: usize,
) -> Result<(HalfPlaneState, HalfPlaneState), String> {
    let grid = Panels::new(panels, window(beta, mu));
    let start = hertz(&grid, beta)?;
    let loaded = stage(&grid, beta, mu, &start, peak * mu * LOAD, 1.0)?;
    let start = Start {
        p: loaded.pressure.clone(),
        w: grid.tangential(beta, &loaded.pressure, &loaded.shear),
    };
    let unloaded = stage(&grid, beta, mu, &start, back * mu * LOAD, -1.0)?;
    Ok((loaded, unloaded))
}

/// Full sliding of body 1 along +x (q = −μp everywhere, Q = μP): the pressure and contact of
/// Bufler's solution, on `panels` panels. `stick` is all false.
pub fn full_sliding(beta: f64, mu: f64, panels: usize) -> Result<HalfPlaneState, String> {
    let grid = Panels::new(panels, window(beta, mu));
    let (p, q, approach, iterations) = tied_normal(&grid, beta, mu)?;
    let contact: Vec<bool> = p.iter().map(|&p| p > 0.0).collect();
    let (contact_left, contact_right) = edges(&grid.x, &p, &contact, slip_powers(beta, mu, 1.0));
    let load = -q.iter().sum::<f64>() * grid.width;
    Ok(HalfPlaneState {
        x: grid.x.clone(),
        width: grid.width,
        slip: vec![0.0; grid.n],
        stick: vec![false; grid.n],
        pressure: p,
        shear: q,
        stick_left: f64::NAN,
        stick_right: f64::NAN,
        contact_left,
        contact_right,
        approach,
        shift: 0.0,
        load,
        iterations,
    })
}

/// Bufler's full-sliding solution for body 1 sliding along +x (q = −μp): the contact's
/// (left, right) edges, a, and the pressure at x, p₀. tan(πγ) = βμ, b = 1/√(1 − 4γ²),
/// e = 2γb, p = cos(πγ)(b − t)^(1/2−γ)(b + t)^(1/2+γ), t = x − e.
pub fn bufler(beta: f64, mu: f64) -> (f64, f64, impl Fn(f64) -> f64) {
    let gamma = (beta * mu).atan() / PI;
    let b = 1.0 / (1.0 - 4.0 * gamma * gamma).sqrt();
    let e = 2.0 * gamma * b;
    let pressure = move |x: f64| {
        let t = x - e;
        if t.abs() >= b {
            0.0
        } else {
            (PI * gamma).cos() * (b - t).powf(0.5 - gamma) * (b + t).powf(0.5 + gamma)
        }
    };
    (e - b, e + b, pressure)
}

#[cfg(test)]
mod tests;
