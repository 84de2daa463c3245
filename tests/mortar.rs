//! Mortar contact on meshes made independently: Hertz line contact against the closed form
//! (and where a coarse partner's own discretisation ripples the pressure), the contact patch
//! test, the flat punch with an evenly spaced strip against the matched mesh (and its
//! convergence as the strip is refined), and the pin example's first contact.

use wearfem::complementarity::{ContactSolution, ContactSolver, Direction, Method, Status};
use wearfem::contact::CondensedContact;
use wearfem::overrides::Override;
use wearfem::problem::Problem;

/// Mesh lines (as fractions of [lo, hi]) with cells of `h` mm over [−span, span] shifted by
/// `offset`, and the coarse lines `outer` (mm, ascending, outside the span) added.
fn lines(lo: f64, hi: f64, h: f64, span: f64, offset: f64, outer: &[f64]) -> String {
    let mut x: Vec<f64> = outer.to_vec();
    let mut k = (-(span - offset) / h).floor() as i64;
    loop {
        let v = offset + k as f64 * h;
        if v > span {
            break;
        }
        if v >= -span {
            x.push(v);
        }
        k += 1;
    }
    x.push(lo);
    x.push(hi);
    x.sort_by(f64::total_cmp);
    let f: Vec<String> = x
        .iter()
        .map(|v| format!("{:.12}", (v - lo) / (hi - lo)))
        .collect();
    format!("[{}]", f.join(", "))
}

/// The built-in example `hertz` (plane strain or stress) with both blocks remeshed near the
/// contact: body 1 with `h1` mm elements for |x| < 5 mm, body 2 with `h2` mm elements for
/// |x| < 13 mm whose lines are shifted by `shift` mm.
fn hertz(kind: &str, h1: f64, h2: f64, shift: f64, discretisation: &str) -> Problem {
    example_hertz(&hertz_sets(kind, h1, h2, shift, discretisation))
}

/// The overrides of [`hertz`].
fn hertz_sets(kind: &str, h1: f64, h2: f64, shift: f64, discretisation: &str) -> Vec<String> {
    let u1 = lines(-20.0, 20.0, h1, 5.0, 0.0, &[-12.0, -7.0, 7.0, 12.0]);
    let u2 = lines(-100.0, 100.0, h2, 13.0, shift, &[-50.0, -25.0, 25.0, 50.0]);
    vec![
        format!("analysis.kind={kind}"),
        format!("bodies[0].blocks[0].u={u1}"),
        format!("bodies[1].blocks[0].u={u2}"),
        format!("contact.discretisation={discretisation}"),
    ]
}

/// The built-in example `hertz` with `sets` (KEY=VALUE) applied, body 2 meshed as given: these
/// tests judge the coupling of two independent meshes, so body 2 gets no lines under body 1's
/// element ends (`contact.align_target_mesh`, tested on its own below).
fn example_hertz(sets: &[String]) -> Problem {
    let overrides: Vec<Override> = std::iter::once("contact.align_target_mesh=false")
        .chain(sets.iter().map(String::as_str))
        .map(|s| Override::parse(s).unwrap())
        .collect();
    let text = wearfem::examples::example("hertz").unwrap();
    Problem::with_overrides(text, "hertz", &overrides).unwrap()
}

/// Hertz's half-width a (mm) and peak pressure p0 (MPa) of the example (Johnson, Contact
/// Mechanics, §4.3): two equal bodies, 1/E* = 2/E', a = √(4 F R / (π E*)), p0 = 2F / (π a),
/// F = 38.825 MPa × 40 mm per mm of thickness, R = 500 mm.
fn hertz_closed_form(kind: &str) -> (f64, f64) {
    let force = 38.825 * 40.0;
    let (e, nu) = (2.0e5f64, 0.3f64);
    let e_one = if kind == "plane_strain" {
        e / (1.0 - nu * nu)
    } else {
        e
    };
    let e_star = e_one / 2.0;
    let a = (4.0 * force * 500.0 / (std::f64::consts::PI * e_star)).sqrt();
    (a, 2.0 * force / (std::f64::consts::PI * a))
}

fn solve(problem: &Problem) -> (CondensedContact, ContactSolution) {
    let (contact, _, _) = CondensedContact::build(problem).unwrap();
    let (sol, info) = ContactSolver::new(&contact, Method::ActiveSet)
        .solve(&contact.points.initial_gap, Direction::Plus);
    assert_eq!(info.status, Status::Solved);
    (contact, sol)
}

/// Largest distance of a pressure from the least-squares parabola through it and its two
/// neighbours on each side: a smooth profile sits on it, a point-to-point zigzag does not.
fn oscillation(x: &[f64], p: &[f64], keep: impl Fn(f64) -> bool) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 2..p.len().saturating_sub(2) {
        if !(i - 2..=i + 2).all(|j| keep(p[j])) {
            continue;
        }
        // Fit c0 + c1 ξ + c2 ξ² (ξ = x − x_i) by the normal equations (3 × 3, Cramer).
        let mut m = [[0.0; 3]; 3];
        let mut r = [0.0; 3];
        for j in i - 2..=i + 2 {
            let xi = x[j] - x[i];
            let basis = [1.0, xi, xi * xi];
            for a in 0..3 {
                r[a] += basis[a] * p[j];
                for b in 0..3 {
                    m[a][b] += basis[a] * basis[b];
                }
            }
        }
        let det = |m: &[[f64; 3]; 3]| {
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        };
        let d = det(&m);
        let mut c = [0.0; 3];
        for (a, ca) in c.iter_mut().enumerate() {
            let mut ma = m;
            for (row, rv) in ma.iter_mut().zip(r) {
                row[a] = rv;
            }
            *ca = det(&ma) / d;
        }
        for j in i - 2..=i + 2 {
            let xi = x[j] - x[i];
            worst = worst.max((p[j] - (c[0] + c[1] * xi + c[2] * xi * xi)).abs());
        }
    }
    worst
}

/// Where the 1 % bound on the oscillation holds: partner elements no larger than body 1's
/// (ratios 1.3 : 1 and 2.7 : 1), or, with body 1 the finer side (1 : 1.3 and 1 : 2.7), a
/// contact zone 2a ≈ 6 mm spanning about nine partner elements (0.65 and 0.675 mm). Five
/// positions of body 2's lines each (shifted by 0.1 … 0.6 mm), so that no lucky alignment
/// passes the check. Coarser partners: `hertz_ripple_from_a_coarse_partner_is_the_partners`.
#[test]
fn hertz_line_contact_on_non_matching_meshes() {
    for kind in ["plane_strain", "plane_stress"] {
        let (a, p0) = hertz_closed_form(kind);
        for (h1, h2) in [(0.5, 0.65), (0.25, 0.675), (1.3, 1.0), (2.7, 1.0)] {
            for shift in [0.1, 0.3, 0.37, 0.45, 0.6] {
                let (contact, sol) = solve(&hertz(kind, h1, h2, shift, "mortar"));
                let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
                let a_fit = wearfem::validate::hertz_half_width(&contact, &sol);
                let case = format!("{kind} {h1}:{h2} shifted {shift}");
                // 2 %: the issue's bound; the finite bodies (2a ≈ 6 mm against 40 and 100 mm)
                // change the closed form by well under that.
                assert!(
                    (peak - p0).abs() < 0.02 * p0,
                    "{case}: peak {peak:.3} MPa, Hertz {p0:.3}"
                );
                assert!(
                    (a_fit - a).abs() < 0.02 * a,
                    "{case}: half-width {a_fit:.4} mm, Hertz {a:.4}"
                );
                // Point-to-point oscillation, judged where the profile is smooth (|x| < 0.8 a,
                // p > 0.6 p0): nearer the edges the square-root fall of the pressure is not a
                // polynomial inside an element, on matched meshes as well. 1 %: the issue's
                // bound; the measure gives < 0.03 % on the closed form itself (test below).
                let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
                let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
                assert!(
                    osc < 0.01 * peak,
                    "{case}: oscillation {osc:.3} MPa, peak {peak:.3}"
                );
                // The same meshes with one partner point per contact point oscillate by more: the
                // check above can see the defect mortar removes.
                let (_, sol) = solve(&hertz(kind, h1, h2, shift, "collocation"));
                let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
                assert!(
                    osc > 0.01 * peak,
                    "{case}: collocation oscillation only {osc:.3} MPa"
                );
            }
        }
    }
}

/// With body 1 finer than body 2 and only two to four partner elements across the contact, the
/// pressure ripples by more than 1 % (1 : 2.7 with 1 mm elements: up to 4 %). The cause is
/// body 2's discretisation, not the coupling: body 2's trace is a polynomial of degree p on
/// each of its elements, one of which holds the square-root edge of the pressure; its slope
/// jumps at its element ends, and body 1, fine enough to follow a kink, does so with a local
/// spike of pressure (the half-plane's answer to a slope jump). Shown here on the example's
/// own meshes and two variants.
#[test]
fn hertz_ripple_from_a_coarse_partner_is_the_partners() {
    let kind = "plane_strain";
    let (a, p0) = hertz_closed_form(kind);
    let smooth = |p: f64| p > 0.6 * p0;
    // The measure sees no natural curvature: the closed form at the 1 mm mesh's points
    // (spacing ≥ 0.05 mm) deviates from its local parabolas by 2.4e-4 p0 (the cubic term of
    // the square root over a 0.5 mm window); 5e-4 p0 bounds that floor of the measure, far
    // below the 1 % it is used to judge.
    let (contact, example) = solve(&example_hertz(&[]));
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let exact: Vec<f64> = x
        .iter()
        .map(|&x| p0 * (1.0 - (x / a).powi(2)).max(0.0).sqrt())
        .collect();
    let natural = oscillation(&x, &exact, smooth);
    assert!(natural < 5e-4 * p0, "closed form: {natural:.3e} MPa");
    // The example's meshes share their lines (1 mm elements for |x| < 6 mm), so the contact
    // edges x = ±3 mm lie on body 2's lines: the pressure is smooth (0.04 %).
    let peak = example.pressure.iter().cloned().fold(0.0, f64::max);
    let osc = oscillation(&x, &example.pressure, smooth);
    assert!(osc < 0.005 * peak, "example: oscillation {osc:.3} MPa");
    // Body 2 with 2 mm elements (lines at 0, ±2, ±4, ±6 mm, still shared with body 1's): its
    // trace is a polynomial on each of body 1's elements, so mortar is collocation (to
    // round-off: 5e-10 of the peak, the two traces' different sums through a condensed problem
    // whose points lie 0.05 mm apart; 1e-8 allowed), yet the contact edges now lie
    // mid-element in body 2 and the pressure ripples by ~4 % of the peak: no coupling is
    // involved.
    let coarse_block = "bodies[1].blocks[0].u=[0.0, 0.25, 0.4, 0.44, 0.47, 0.48, 0.49, 0.5, \
                        0.51, 0.52, 0.53, 0.56, 0.6, 0.75, 1.0]";
    let with = |discretisation: &str| {
        let sets = [
            coarse_block.to_string(),
            format!("contact.discretisation={discretisation}"),
        ];
        solve(&example_hertz(&sets)).1
    };
    let (collocation, mortar) = (with("collocation"), with("mortar"));
    let (max, _) = differences(&mortar.pressure, &collocation.pressure, 0);
    assert!(
        max < 1e-8 * peak,
        "mortar and collocation differ by {max:.3e} MPa"
    );
    let osc = oscillation(&x, &collocation.pressure, smooth);
    assert!(
        osc > 0.02 * peak,
        "2 mm body 2: oscillation only {osc:.3} MPa"
    );
    // Oscillation of the mortar solution with body 1 of 1 mm elements and body 2 of `h2` mm
    // elements shifted by `shift`, at that model's own points.
    let osc_of = |h2: f64, shift: f64| {
        let (contact, sol) = solve(&hertz(kind, 1.0, h2, shift, "mortar"));
        let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
        oscillation(&x, &sol.pressure, smooth)
    };
    // Body 2's lines at the contact edges (3 mm elements, lines at 0 and ±3 mm): every
    // partner element is smooth inside the contact and the ripple is gone (0.18 %; 0.5 %, half
    // the issue's bound, tells "gone" from "just under the bound").
    let at_edges = osc_of(3.0, 0.0);
    assert!(
        at_edges < 0.005 * peak,
        "lines at the edges: oscillation {at_edges:.3} MPa"
    );
    // Refining body 2 alone (2.7 → 0.54 mm, lines shifted by 0.37 mm) removes it; body 1 is
    // unchanged, so the ripple was body 2's (1.73 % → 0.20 %).
    let (coarse, fine) = (osc_of(2.7, 0.37), osc_of(0.54, 0.37));
    assert!(
        coarse > 0.01 * peak && fine < 0.005 * peak,
        "body 2 of 2.7 mm: {coarse:.3} MPa, of 0.54 mm: {fine:.3} MPa"
    );
}

/// Two blocks 10 mm wide, meshed independently (3 and 4 uneven elements across), the upper
/// one (ν = 0, so that the plate clamping its top edge does not restrain it) pressed with
/// `load` MPa on the lower one (ν = 0.3, on rollers: base held in z, left side in x).
/// `align`: whether the lower block gets lines under the upper one's element ends.
fn patch(discretisation: &str, p: usize, align: bool) -> Problem {
    let text = format!(
        r#"
[analysis]
kind = "plane_stress"
thickness = 2.0
p = {p}

[materials.soft]
young = 7.0e4
poisson = 0.0
[materials.steel]
young = 2.0e5
poisson = 0.3

[[bodies]]
name = "upper"
[[bodies.blocks]]
corners = [[0.0, 10.0], [10.0, 10.0], [10.0, 16.0], [0.0, 16.0]]
u = [0.0, 0.23, 0.61, 1.0]
v = 2
material = "soft"
names = {{ bottom = "contact", top = "top" }}
[[bodies.tractions]]
edge = "top"
normal = 10.0

[[bodies]]
name = "lower"
[[bodies.blocks]]
corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
u = [0.0, 0.17, 0.45, 0.52, 1.0]
v = 3
material = "steel"
names = {{ bottom = "base", top = "surface", left = "side" }}
[[bodies.supports]]
edge = "base"
fix = ["z"]
[[bodies.supports]]
edge = "side"
fix = ["x"]

[contact]
body = "upper"
edge = "contact"
target_body = "lower"
target_edge = "surface"
discretisation = "{discretisation}"
align_target_mesh = {align}

[plate]
edge = "top"
motion = "vertical"
"#
    );
    Problem::from_toml(&text, "patch").unwrap()
}

#[test]
fn patch_test_uniform_pressure_crosses_non_matching_meshes() {
    // The exact solution is a uniform stress σ_zz = −10 MPa in both blocks, a linear
    // displacement: inside every finite element space, so a consistent contact discretisation
    // must reproduce it to round-off. 1e-8: the issue's bound (round-off is ~1e-12 here).
    for (p, align) in [(2, false), (5, false), (8, false), (8, true)] {
        let (_, sol) = solve(&patch("mortar", p, align));
        let worst = sol
            .pressure
            .iter()
            .map(|v| (v - 10.0).abs())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-8 * 10.0,
            "p = {p}: pressure off by {worst:.3e} MPa"
        );
    }
    // Collocation loads body 2 with point forces at the partner points, which are not the
    // consistent loads of a uniform pressure across body 2's element ends: it fails the test.
    let (_, sol) = solve(&patch("collocation", 8, false));
    let worst = sol
        .pressure
        .iter()
        .map(|v| (v - 10.0).abs())
        .fold(0.0, f64::max);
    assert!(
        worst > 1e-4 * 10.0,
        "collocation passes the patch test ({worst:.3e} MPa)"
    );
}

/// The strip's mesh lines of punch-b40: at the punch corners and its element ends (7.5 mm).
const MATCHED_STRIP: &str =
    "u = [0.0, 0.2, 0.35, 0.3875, 0.425, 0.4625, 0.5, 0.5375, 0.575, 0.6125, 0.65, 0.8, 1.0]";

/// How the strip of punch-b40 is meshed along x.
#[derive(Clone, Copy)]
enum Strip {
    /// As shipped, lines matched to the punch's elements.
    Matched,
    /// As shipped with every element under the punch cut into this many.
    MatchedCut(usize),
    /// This many even elements over its 200 mm (never 20 or a multiple: those meet 1070).
    Even(usize),
}

/// punch-b40 with the strip meshed as `strip`, its lines as given (`align` false) or with lines
/// added under the punch's element ends (the default).
fn punch_with(strip: Strip, discretisation: &str, align: bool) -> Problem {
    let lines = match strip {
        Strip::Matched => MATCHED_STRIP.to_string(),
        Strip::MatchedCut(k) => {
            let x: Vec<String> = [0.0, 0.2]
                .into_iter()
                .chain((0..=8 * k).map(|i| 0.35 + 0.3 * i as f64 / (8 * k) as f64))
                .chain([0.8, 1.0])
                .map(|v| format!("{v:?}"))
                .collect();
            format!("u = [{}]", x.join(", "))
        }
        Strip::Even(n) => format!("u = {n}"),
    };
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace(MATCHED_STRIP, &lines)
        .replace(
            "discretisation = \"collocation\"",
            &format!("discretisation = \"{discretisation}\"\nalign_target_mesh = {align}"),
        );
    Problem::from_toml(&text, "punch-b40").unwrap()
}

/// punch-b40 with the strip meshed as `strip`, as given.
fn punch(strip: Strip, discretisation: &str) -> Problem {
    punch_with(strip, discretisation, false)
}

/// Largest difference at the points that are not among the first or last `skip`, and the
/// root-mean-square difference over all points.
fn differences(a: &[f64], b: &[f64], skip: usize) -> (f64, f64) {
    let n = a.len();
    let max = (skip..n - skip)
        .map(|i| (a[i] - b[i]).abs())
        .fold(0.0, f64::max);
    let rms = (a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>() / n as f64).sqrt();
    (max, rms)
}

/// The issue's case as a user meets it: the strip's 12 elements spaced evenly, every default
/// on. Body 2 then gets lines under the punch's element ends (`contact.align_target_mesh`),
/// and the results meet the issue's bounds against the matched mesh: the first solve within
/// 2 % of its peak away from the two edge points, the steady and 1700-step p⁺ within 1 % of
/// 2p̃ at every point. (As given, the same strip misses them: the test below.)
#[test]
fn punch_on_an_evenly_meshed_strip_matches_the_matched_mesh() {
    let even = || punch_with(Strip::Even(12), "mortar", true);
    let (contact, matched) = solve(&punch(Strip::Matched, "collocation"));
    let (_, first) = solve(&even());
    let peak = matched.pressure.iter().cloned().fold(0.0, f64::max);
    // Measured 0.75 % at the second point, next to the singular corner, and 0.02 % from the
    // fifth on (as given: 6.3 % and 1.1 %).
    let (max, _) = differences(&first.pressure, &matched.pressure, 1);
    assert!(
        max < 0.02 * peak,
        "first solve: {max:.3} MPa off, peak {peak:.3}"
    );
    assert_eq!(contact.len(), 65);
    let two_p = 33.333; // 2p̃ = 2F₀/(l t), MPa
    let st_matched = wearfem::driver::steady(&punch(Strip::Matched, "collocation"))
        .unwrap()
        .0;
    let st_even = wearfem::driver::steady(&even()).unwrap().0;
    // p⁺ + p⁻ = 2p̃ on any mesh (paper eq. 23a), to the steady solver's tolerance.
    let sum: Vec<f64> = st_even
        .p_plus
        .iter()
        .zip(&st_even.p_minus)
        .map(|(a, b)| a + b)
        .collect();
    let (max, _) = differences(&sum, &vec![two_p; sum.len()], 0);
    assert!(max < 1e-3 * two_p, "steady p⁺ + p⁻ off 2p̃ by {max:.3e} MPa");
    // 0.09 % measured for both; 1 % is the issue's bound.
    let (max, _) = differences(&st_even.p_plus, &st_matched.p_plus, 0);
    assert!(max < 0.01 * two_p, "steady p⁺: max {max:.3} MPa");
    let run = |p: &Problem| wearfem::driver::wear(p, None, |_| {}).unwrap().history;
    let (h_matched, h_even) = (run(&punch(Strip::Matched, "collocation")), run(&even()));
    let (max, _) = differences(&h_even.p_plus, &h_matched.p_plus, 0);
    assert!(max < 0.01 * two_p, "run p⁺: max {max:.3} MPa");
}

#[test]
fn on_matched_meshes_mortar_is_collocation() {
    // Where body 2's trace is a polynomial of degree p on each element of body 1 (same mesh
    // lines, same p, straight edges), biorthogonality returns its point values exactly, and
    // D_ii = ∫ N_i ds is the Lobatto weight: the two methods differ by round-off only.
    let (c_col, s_col) = solve(&punch(Strip::Matched, "collocation"));
    let (c_mor, s_mor) = solve(&punch(Strip::Matched, "mortar"));
    for (a, b) in c_col.points.weight.iter().zip(&c_mor.points.weight) {
        assert!((a - b).abs() < 1e-12 * a, "weights {a} / {b}");
    }
    let peak = s_col.pressure.iter().cloned().fold(0.0, f64::max);
    let (max, _) = differences(&s_mor.pressure, &s_col.pressure, 0);
    // Round-off of two different sums of ~1e3 terms through a 65 × 65 solve: 1e-9 of peak.
    assert!(max < 1e-9 * peak, "pressures differ by {max:.3e} MPa");
}

/// The differences of the 12-element strip as given (`align_target_mesh = false`) from the
/// matched one are the coarse strip's own discretisation error, not the coupling's. The steady p⁺ has slope jumps at the ends of its
/// zone (x ≈ 1077.1 and 1122.9 mm), which the matched strip has lines near (1077.5, 1122.5)
/// while a 16.7 mm even element holds them inside; the first solve is singular at the corner
/// 1070, inside an even element too. Refining the even strip (mortar on every mesh) brings all
/// three to the matched mesh, or to a strip four times finer under the punch where the matched
/// mesh is itself not converged (the first solve next to the corner).
#[test]
fn punch_on_an_even_strip_converges_to_the_matched_mesh() {
    let two_p = 33.333; // 2p̃ = 2F₀/(l t), the scale of the steady pressures, MPa
    let steady_p_plus = |s: Strip| {
        wearfem::driver::steady(&punch(s, "mortar"))
            .unwrap()
            .0
            .p_plus
    };
    let run_p_plus = |s: Strip| {
        wearfem::driver::wear(&punch(s, "mortar"), None, |_| {})
            .unwrap()
            .history
            .p_plus
    };
    // Whether each of the first solve, the steady state and the run is reported as
    // under-resolved by the strip (coarse_partner_zones).
    let reported = |s: Strip| {
        let (contact, first) = solve(&punch(s, "mortar"));
        let (state, _, _) = wearfem::driver::steady(&punch(s, "mortar")).unwrap();
        let run = wearfem::driver::wear(&punch(s, "mortar"), None, |_| {}).unwrap();
        let h = &run.history;
        [
            !contact.coarse_partner_zones(&[&first.pressure]).is_empty(),
            !contact
                .coarse_partner_zones(&[&state.p_plus, &state.p_minus])
                .is_empty(),
            !contact
                .coarse_partner_zones(&[&h.p_plus, &h.p_minus])
                .is_empty(),
        ]
    };
    let matched = (steady_p_plus(Strip::Matched), run_p_plus(Strip::Matched));
    // The matched mesh's own error in the steady p⁺: 0.33 % of 2p̃ against the finer strip, so
    // the issue's 1 % can tell a coarse strip from a fine one.
    let (own, _) = differences(&matched.0, &steady_p_plus(Strip::MatchedCut(4)), 0);
    assert!(
        own < 0.005 * two_p,
        "matched strip: {own:.3} MPa off the finer one"
    );
    let (_, first_finer) = solve(&punch(Strip::MatchedCut(4), "mortar"));
    let peak = first_finer.pressure.iter().cloned().fold(0.0, f64::max);
    // (elements, first solve off the finer strip, steady and run p⁺ off the matched one), as
    // fractions of the peak and of 2p̃. The first solve skips the two corner points, as the
    // issue does; pointwise everywhere else.
    let errors: Vec<(usize, f64, f64, f64)> = [12, 48, 96]
        .into_iter()
        .map(|n| {
            let (_, first) = solve(&punch(Strip::Even(n), "mortar"));
            let (first, _) = differences(&first.pressure, &first_finer.pressure, 1);
            let (steady, _) = differences(&steady_p_plus(Strip::Even(n)), &matched.0, 0);
            let (run, _) = differences(&run_p_plus(Strip::Even(n)), &matched.1, 0);
            (n, first / peak, steady / two_p, run / two_p)
        })
        .collect();
    // 12 elements as given miss the issue's bounds (first solve 4.2 %, steady 2.3 %, run
    // 2.6 %; with lines added under the punch's element ends they meet them, the test above)...
    let (_, first, steady, run) = errors[0];
    assert!(
        first > 0.02 && steady > 0.01 && run > 0.01,
        "12 elements: {errors:?}"
    );
    // ...and each of those results says so; the matched strip and 48 even elements do not.
    assert_eq!(reported(Strip::Even(12)), [true; 3]);
    assert_eq!(reported(Strip::Matched), [false; 3]);
    assert_eq!(reported(Strip::Even(48)), [false; 3]);
    // ...48 and 96 meet them (2 % and 1 %, the issue's bounds): at most 0.7 % and 0.3 %.
    for &(n, first, steady, run) in &errors[1..] {
        assert!(
            first < 0.02 && steady < 0.01 && run < 0.01,
            "{n} elements: first {first:.4}, steady {steady:.4}, run {run:.4}"
        );
    }
}

/// The pin example's first contact (Hertzian, a ≈ 4.6 mm) on a flat meshed independently but
/// not coarser than the pin (1.31 mm against 1.05 mm): no ripple. The issue found 70.1 → 37.4
/// MPa between neighbouring points with collocation, and 16 flat elements of 5 mm, whose lines
/// at 0 and ±5 mm put the contact edges inside flat elements, rippled by 5.3 % with mortar.
#[test]
fn pin_first_contact_is_smooth() {
    let text = wearfem::examples::example("pin").unwrap();
    let (contact, sol) = solve(&Problem::from_toml(text, "pin").unwrap());
    let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * peak);
    // 1 %: the issue's bound for Hertz (0.17 % here).
    assert!(
        osc < 0.01 * peak,
        "oscillation {osc:.3} MPa, peak {peak:.3}"
    );
    let coarse = |align: bool| {
        let sets = [
            Override::parse("bodies[1].blocks[0].u=16").unwrap(),
            Override::parse(&format!("contact.align_target_mesh={align}")).unwrap(),
        ];
        let (_, sol) = solve(&Problem::with_overrides(text, "pin", &sets).unwrap());
        oscillation(&x, &sol.pressure, |p| p > 0.6 * peak)
    };
    let osc = coarse(false);
    assert!(
        osc > 0.02 * peak,
        "5 mm flat: oscillation only {osc:.3} MPa"
    );
    // With lines added under the pin's element ends (the default) the same flat is smooth.
    let osc = coarse(true);
    assert!(
        osc < 0.005 * peak,
        "5 mm flat, aligned: oscillation {osc:.3} MPa"
    );
}

/// The coarse-partner report (`CondensedContact::coarse_partner_zones`) marks every Hertz mesh
/// whose pressure ripples by more than 1 % of the peak, and none of the meshes where body 2
/// is no coarser than body 1 or where about nine of its elements span the contact. Three
/// positions of body 2's lines each; the ripple is measured here, not taken from a table.
#[test]
fn a_coarse_partner_is_reported_where_it_ripples() {
    let (_, p0) = hertz_closed_form("plane_strain");
    let mut rippled = 0;
    for (h1, h2, resolved) in [
        (1.0, 1.3, false),
        (0.5, 1.35, false),
        (1.0, 2.7, false),
        (1.3, 1.0, true),
        (2.7, 1.0, true),
        (1.0, 0.9, true),
        (0.5, 0.65, true),
        (0.25, 0.675, true),
    ] {
        for shift in [0.1, 0.37, 0.6] {
            let (contact, sol) = solve(&hertz("plane_strain", h1, h2, shift, "mortar"));
            let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
            let ripple = oscillation(&x, &sol.pressure, |v| v > 0.6 * p0) / p0;
            // Body 2's report only: a zone end inside one of body 1's own elements long
            // against the zone (2.7 mm in a 6 mm zone) is reported as body 1's, whatever body 2.
            let reported = contact
                .coarse_partner_zones(&[&sol.pressure])
                .iter()
                .any(|z| z.body == 2);
            let case = format!(
                "{h1} : {h2} mm shifted {shift}: ripple {:.2} %",
                100.0 * ripple
            );
            if ripple > 0.01 {
                rippled += 1;
                assert!(reported, "{case}, not reported");
            }
            if resolved {
                assert!(!reported, "{case}, reported although resolved");
            }
        }
    }
    // The check above must have had something to catch.
    assert!(
        rippled >= 2,
        "only {rippled} meshes rippled by more than 1 %"
    );
}

/// Body 1's own report: a zone that ends inside one of body 1's elements long against the
/// zone is reported wherever its pressure is more than 1.5 % of the peak off Hertz inside the
/// zone, and never on elements of a fifth of the zone or less. Body 2 is fine (0.25 mm) so
/// that the error is body 1's; element lengths 0.17 to 0.75 of the zone, two positions of the
/// lines, p = 6, 8 and 12 (a red team's 6 mm elements under an 8.3 mm zone were 9.5 % off at
/// the centre at p = 6, unreported, with the old limit of one zone width).
#[test]
fn a_zone_end_inside_a_long_element_of_body_1_is_reported_where_it_is_off() {
    let kind = "plane_strain";
    let (a, p0) = hertz_closed_form(kind);
    let mut off = 0;
    for h1 in [1.0, 2.0, 3.0, 4.5] {
        for offset in [0.0, 0.5 * h1] {
            for p in [6, 8, 12] {
                let sets = [
                    format!("analysis.kind={kind}"),
                    format!("analysis.p={p}"),
                    format!(
                        "bodies[0].blocks[0].u={}",
                        lines(-20.0, 20.0, h1, 12.0, offset, &[])
                    ),
                    format!(
                        "bodies[1].blocks[0].u={}",
                        lines(-100.0, 100.0, 0.25, 13.0, 0.0, &[-50.0, -25.0, 25.0, 50.0])
                    ),
                ];
                let (contact, sol) = solve(&example_hertz(&sets));
                let error = contact
                    .points
                    .x
                    .iter()
                    .zip(&sol.pressure)
                    .filter(|(x, _)| x[0].abs() < 0.8 * a)
                    .map(|(x, p)| (p - p0 * (1.0 - (x[0] / a).powi(2)).sqrt()).abs() / p0)
                    .fold(0.0, f64::max);
                let reported = contact
                    .coarse_partner_zones(&[&sol.pressure])
                    .iter()
                    .any(|z| z.body == 1);
                let case = format!(
                    "h1 = {h1} mm from {offset}, p = {p}: {:.2} % off",
                    100.0 * error
                );
                if error > 0.015 {
                    off += 1;
                    assert!(reported, "{case}, not reported");
                }
                if h1 <= 0.2 * 2.0 * a {
                    assert!(
                        !reported,
                        "{case}, reported on elements of a fifth of the zone"
                    );
                }
            }
        }
    }
    assert!(off >= 2, "only {off} meshes were more than 1.5 % off");
}

/// With the default `contact.align_target_mesh`, body 2 gets lines under body 1's element
/// ends: the meshes that rippled above (body 2 1.3 to 2.7 times coarser than body 1, three
/// positions of its lines) then meet the issue's bounds, 2 % on the peak and half-width and
/// 1 % on the ripple, and the coarse-partner report is quiet.
#[test]
fn lines_under_body_1s_element_ends_remove_the_coarse_partners_ripple() {
    let kind = "plane_strain";
    let (a, p0) = hertz_closed_form(kind);
    for (h1, h2) in [(1.0, 1.3), (0.5, 1.35), (1.0, 2.7)] {
        for shift in [0.1, 0.37, 0.6] {
            let u1 = lines(-20.0, 20.0, h1, 5.0, 0.0, &[-12.0, -7.0, 7.0, 12.0]);
            let u2 = lines(-100.0, 100.0, h2, 13.0, shift, &[-50.0, -25.0, 25.0, 50.0]);
            let sets: Vec<Override> = [
                format!("bodies[0].blocks[0].u={u1}"),
                format!("bodies[1].blocks[0].u={u2}"),
            ]
            .iter()
            .map(|s| Override::parse(s).unwrap())
            .collect();
            let text = wearfem::examples::example("hertz").unwrap();
            let problem = Problem::with_overrides(text, "hertz", &sets).unwrap();
            let (_, added) = problem.target_alignment(1).unwrap().unwrap();
            let (contact, sol) = solve(&problem);
            let case = format!("{h1} : {h2} mm shifted {shift}, {added} lines added");
            assert!(added > 0, "{case}");
            let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
            let a_fit = wearfem::validate::hertz_half_width(&contact, &sol);
            assert!(
                (peak - p0).abs() < 0.02 * p0,
                "{case}: peak {peak:.3}, {p0:.3}"
            );
            assert!((a_fit - a).abs() < 0.02 * a, "{case}: a {a_fit:.4}, {a:.4}");
            let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
            let ripple = oscillation(&x, &sol.pressure, |v| v > 0.6 * p0);
            assert!(ripple < 0.01 * p0, "{case}: ripple {ripple:.3} MPa");
            assert!(
                contact.coarse_partner_zones(&[&sol.pressure]).is_empty(),
                "{case}: reported"
            );
        }
    }
}

/// Collocation needs body 2's lines on body 1's element ends: a line inside an element in
/// contact is reported (there the pressure oscillates, measured here), lines that match are
/// not; mortar reports it too where `contact.align_target_mesh = false` left it (the Hertz
/// meshes of these tests: a ripple of under 1 % here, 5.8 % of the peak on a ball in a cup,
/// red team F), and not once aligned. And a load so small that one point carries it is
/// reported as unresolved.
#[test]
fn collocation_off_the_lines_and_a_one_point_contact_are_reported() {
    let (_, p0) = hertz_closed_form("plane_strain");
    let (contact, sol) = solve(&hertz("plane_strain", 0.5, 0.65, 0.37, "collocation"));
    let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
    let ripple = oscillation(&x, &sol.pressure, |v| v > 0.6 * p0) / p0;
    assert!(ripple > 0.02, "ripple {ripple}");
    assert!(contact
        .unmatched_line_in_contact(&[&sol.pressure])
        .is_some());
    let (contact, sol) = solve(&hertz("plane_strain", 0.5, 0.65, 0.37, "mortar"));
    assert!(contact
        .unmatched_line_in_contact(&[&sol.pressure])
        .is_some());
    let mut aligned = hertz_sets("plane_strain", 0.5, 0.65, 0.37, "mortar");
    aligned.push("contact.align_target_mesh=true".into());
    let (contact, sol) = solve(&example_hertz(&aligned));
    assert!(contact
        .unmatched_line_in_contact(&[&sol.pressure])
        .is_none());
    // The shipped example: body 2's lines on body 1's.
    let (contact, sol) = solve(&example_hertz(&[
        "contact.discretisation=collocation".into()
    ]));
    assert!(contact
        .unmatched_line_in_contact(&[&sol.pressure])
        .is_none());
    assert_eq!(contact.too_few_points_in_contact(&[&sol.pressure]), None);
    // Hertz's half-width goes as √F: 1e-8 of the load gives a = 0.3 µm, inside one point's
    // share of a 1 mm element.
    let (contact, sol) = solve(&example_hertz(&[
        "bodies[0].tractions[0].normal=38.825e-8".into()
    ]));
    assert_eq!(contact.too_few_points_in_contact(&[&sol.pressure]), Some(1));
}

/// A review's mesh graded towards the contact's centre: body 1's elements of 18 mm hold the
/// ends of Hertz's 6 mm zone, and the pressures are far off (measured here against the closed
/// form). It is reported, as body 1's; the shipped 1 mm mesh is not.
#[test]
fn a_zone_ending_inside_a_long_element_of_body_1_is_reported() {
    let (a, p0) = hertz_closed_form("plane_strain");
    let graded = example_hertz(&[
        "bodies[0].blocks[0].u=[0.0, 0.45, 0.4999, 0.5, 0.5001, 0.55, 1.0]".into(),
    ]);
    let (contact, sol) = solve(&graded);
    let worst = contact
        .points
        .x
        .iter()
        .zip(&sol.pressure)
        .map(|(x, p)| {
            let exact = if x[0].abs() < a {
                p0 * (1.0 - (x[0] / a).powi(2)).sqrt()
            } else {
                0.0
            };
            (p - exact).abs()
        })
        .fold(0.0, f64::max);
    assert!(worst > 0.1 * p0, "worst {worst} MPa");
    let zones = contact.coarse_partner_zones(&[&sol.pressure]);
    assert_eq!(zones.len(), 1, "{zones:?}");
    assert_eq!(zones[0].body, 1);
    assert!((zones[0].element_length - 18.0).abs() < 1e-9);
    let (contact, sol) = solve(&example_hertz(&[]));
    assert!(contact.coarse_partner_zones(&[&sol.pressure]).is_empty());
}

/// Each body can have its own degree (`bodies[i].p`); mortar couples any two. Hertz on
/// non-matching meshes (body 1 twice as fine as body 2) with body 1 at p = 8 and body 2 at
/// p = 4 or 12, and the other way round: peak and half-width within the issue's 2 % of the
/// closed form, and no point-to-point ripple above 1 % of the peak, as with one degree.
#[test]
fn bodies_of_different_degrees_meet_hertz() {
    let kind = "plane_strain";
    let (a, p0) = hertz_closed_form(kind);
    for (p1, p2) in [(8, 4), (8, 12), (4, 8), (12, 6)] {
        let u1 = lines(-20.0, 20.0, 0.5, 5.0, 0.0, &[-12.0, -7.0, 7.0, 12.0]);
        let u2 = lines(-100.0, 100.0, 0.65, 13.0, 0.3, &[-50.0, -25.0, 25.0, 50.0]);
        let problem = example_hertz(&[
            format!("analysis.kind={kind}"),
            format!("bodies[0].blocks[0].u={u1}"),
            format!("bodies[1].blocks[0].u={u2}"),
            format!("bodies[0].p={p1}"),
            format!("bodies[1].p={p2}"),
        ]);
        let (contact, sol) = solve(&problem);
        // The degrees reached the bodies: body 1's points are its p1 + 1 Lobatto points per
        // element (shared ends), so the count along its edge is a multiple of p1, plus one.
        assert_eq!(
            (contact.len() - 1) % p1,
            0,
            "p1 = {p1}: {} points",
            contact.len()
        );
        let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
        let a_fit = wearfem::validate::hertz_half_width(&contact, &sol);
        let case = format!("p1 = {p1}, p2 = {p2}");
        assert!(
            (peak - p0).abs() < 0.02 * p0,
            "{case}: peak {peak:.3}, Hertz {p0:.3}"
        );
        assert!(
            (a_fit - a).abs() < 0.02 * a,
            "{case}: a {a_fit:.4}, Hertz {a:.4}"
        );
        let x: Vec<f64> = contact.points.x.iter().map(|p| p[0]).collect();
        let osc = oscillation(&x, &sol.pressure, |p| p > 0.6 * p0);
        assert!(osc < 0.01 * peak, "{case}: oscillation {osc:.3} MPa");
    }
}

/// Collocation samples body 2's trace at one partner point per contact point: on a trace of
/// another degree than body 1's the point forces ripple (p₂ = 12 against p₁ = 8: up to 16 %
/// of the pressure, review of 2026-11-24), so it is refused; mortar takes the same meshes.
#[test]
fn collocation_needs_equal_degrees() {
    let problem = example_hertz(&[
        "contact.discretisation=collocation".to_string(),
        "bodies[1].p=12".to_string(),
    ]);
    let error = CondensedContact::build(&problem).err().expect("refused");
    assert_eq!(error.key, "contact.discretisation");
    assert!(error.message.contains("same degree"), "{}", error.message);
    let mortar = example_hertz(&["bodies[1].p=12".to_string()]);
    assert!(CondensedContact::build(&mortar).is_ok());
}

/// A lower degree on body 2 resolves less per element: Hertz with body 2 at p = 1 under
/// body 1 at p = 8 (the example's meshes) has its peak 9 % above the closed form, and the
/// zone is reported; at p = 8 on both it is within 0.2 % and is not.
#[test]
fn a_lower_degree_on_body_2_is_reported_like_a_coarser_mesh() {
    let (_, p0) = hertz_closed_form("plane_strain");
    let low = example_hertz(&["bodies[1].p=1".to_string()]);
    let (contact, sol) = solve(&low);
    let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
    assert!(
        (peak - p0).abs() > 0.02 * p0,
        "p2 = 1: peak {peak}, Hertz {p0}"
    );
    let zones = contact.coarse_partner_zones(&[&sol.pressure]);
    assert!(!zones.is_empty());
    // The report says the degrees are what make body 2 coarse (8 against 1), so that its
    // element length, shorter than body 1's here, does not read as a contradiction.
    assert!(
        zones.iter().all(|z| z.partner_degree_ratio == 8.0),
        "{zones:?}"
    );
    let lines = wearfem::warnings::zone_warnings(&low, &contact, &[&sol.pressure]);
    assert!(
        lines
            .iter()
            .any(|l| l.contains("of a degree 8 times lower")),
        "{lines:?}"
    );
    let (contact, sol) = solve(&example_hertz(&[]));
    assert!(contact.coarse_partner_zones(&[&sol.pressure]).is_empty());
}

/// summary.json's `target_mesh` counts what the alignment did, from the geometry: the punch's
/// 9 element ends (1070 + 7.5 i) against 12 even strip lines (1000 + 16.67 k) share only 1100,
/// so 8 lines are added, and the strip's 4 rows then hold (12 + 8) × 4 elements. The matched
/// strip and `align_target_mesh = false` add none.
#[test]
fn the_summary_counts_the_lines_added_to_body_2() {
    let lines = |p: &Problem| {
        let (summary, ..) = wearfem::driver::contact(p).unwrap();
        let t = &summary["target_mesh"];
        (
            t["lines_added"].as_u64().unwrap(),
            t["elements"].as_u64().unwrap(),
        )
    };
    assert_eq!(lines(&punch_with(Strip::Even(12), "mortar", true)), (8, 80));
    assert_eq!(
        lines(&punch_with(Strip::Even(12), "mortar", false)),
        (0, 48)
    );
    assert_eq!(lines(&punch_with(Strip::Matched, "mortar", true)), (0, 48));
}

/// A groove in body 2's surface beside the Hertz zone (1 mm deep at 7.3 < x < 9.1 mm, inside
/// one of body 1's contact elements, |x| < 3 in contact) changes nothing the closed form
/// knows: the peak is Hertz's p₀ and nothing outside the zone carries pressure. The geometric
/// gap of a mortar constraint is the gap at its point: the ψ-weighted mean of the gap's 1 mm
/// jump was a false interference of about 0.1 mm, 14 000 MPa at x = 6 and the zone 99 % off
/// (red team A).
#[test]
fn a_groove_beside_the_zone_inside_an_element_of_body_1_changes_nothing() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/hertz-groove-beside.toml"
    ))
    .unwrap();
    let problem = Problem::with_overrides(&text, "groove", &[]).unwrap();
    let (contact, sol) = solve(&problem);
    let (a, p0) = hertz_closed_form("plane_strain");
    let peak = sol.pressure.iter().cloned().fold(0.0, f64::max);
    // 1 %: the example's own mesh is within 0.25 % of the closed form (tests/contact.rs).
    assert!(
        (peak - p0).abs() < 0.01 * p0,
        "peak {peak:.2}, Hertz {p0:.2}"
    );
    let outside = contact
        .points
        .x
        .iter()
        .zip(&sol.pressure)
        .filter(|(x, _)| x[0].abs() > 1.1 * a)
        .map(|(_, p)| *p)
        .fold(0.0, f64::max);
    assert!(
        outside == 0.0,
        "pressure {outside:.3e} MPa outside the zone"
    );
}

/// A ridge of body 2 (1 µm high, 0.2 mm wide) between two of body 1's contact points: the
/// constraints, which take the gap at their points, see none of it, so the job says so, with
/// the ridge's height as the misfit (the punch's face 1 µm above the strip, the ridge's top
/// touching it: exactly 1e-3 mm). With body 1's mesh lines at the ridge's ends the points see
/// it, it carries pressure, and nothing is said. The shipped mortar examples (smooth
/// surfaces, arcs) say nothing either.
#[test]
fn a_ridge_between_contact_points_is_reported() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/ridge-between-points.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    let misfit_warnings = |p: &Problem| -> Vec<String> {
        let (summary, ..) = wearfem::driver::contact(p).unwrap();
        summary["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w.as_str().unwrap().to_string())
            .filter(|w| w.contains("between body 1's contact points"))
            .collect()
    };
    let unresolved = Problem::with_overrides(&text, "ridge", &[]).unwrap();
    let (contact, sol) = solve(&unresolved);
    let m = contact
        .surface_misfit_in_contact(
            &[&sol.pressure],
            wearfem::warnings::contact_modulus(&unresolved).unwrap(),
        )
        .expect("a misfit in contact");
    // 1e-9 mm: round-off of the gaps (1e-3 mm) and of locating the ridge's top.
    assert!((m.misfit + 1e-3).abs() < 1e-9, "misfit {} mm", m.misfit);
    assert!(0.4 <= m.x[0] && m.x[0] <= 0.6, "at {:?}", m.x);
    assert_eq!(misfit_warnings(&unresolved).len(), 1);
    let lines = Override::parse("bodies[0].blocks[0].u=[0.0, 0.2, 0.4, 0.52, 0.53, 0.6, 0.8, 1.0]")
        .unwrap();
    let resolved = Problem::with_overrides(&text, "ridge", &[lines]).unwrap();
    assert!(misfit_warnings(&resolved).is_empty());
    let (contact, sol) = solve(&resolved);
    let on_ridge = contact
        .points
        .x
        .iter()
        .zip(&sol.pressure)
        .filter(|(x, _)| 0.4 < x[0] && x[0] < 0.6)
        .map(|(_, p)| *p)
        .fold(0.0, f64::max);
    assert!(on_ridge > 0.0, "the ridge carries nothing");
    for name in ["hertz", "pin", "brake-independent"] {
        let p = Problem::from_toml(wearfem::examples::example(name).unwrap(), name).unwrap();
        assert!(misfit_warnings(&p).is_empty(), "{name}");
    }
}

/// Mortar on meshes left unaligned (`contact.align_target_mesh = false`): body 2's element
/// ends inside body 1's contact elements kink its trace under a dual basis that cannot follow
/// the kink, and the pressure ripples near body 1's element ends (red team F: a ball in a
/// cup, 5.8 % of the peak, silent). The job says so; with the default alignment it does not,
/// and the two meshes' pressures differ by more than the alignment's own error (0.09 % of the
/// matched strip's, docs/validation.md), so the warning has something to warn of.
#[test]
fn an_unaligned_mortar_mesh_is_reported() {
    let strip =
        "u = [0.0, 0.2, 0.35, 0.3875, 0.425, 0.4625, 0.5, 0.5375, 0.575, 0.6125, 0.65, 0.8, 1.0]";
    let text = wearfem::examples::example("punch-b40")
        .unwrap()
        .replace(strip, "u = 12")
        .replace(
            "discretisation = \"collocation\"",
            "discretisation = \"mortar\"",
        );
    let solve_with = |align: &str| {
        let o = Override::parse(&format!("contact.align_target_mesh={align}")).unwrap();
        let p = Problem::with_overrides(&text, "unaligned", &[o]).unwrap();
        let (summary, ..) = wearfem::driver::contact(&p).unwrap();
        let pressure: Vec<f64> = summary["pressure"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let warned = summary["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().starts_with("warning[unaligned-line]"));
        (pressure, warned)
    };
    let (aligned, aligned_warned) = solve_with("true");
    let (unaligned, unaligned_warned) = solve_with("false");
    assert!(!aligned_warned && unaligned_warned);
    let peak = aligned.iter().cloned().fold(0.0, f64::max);
    let largest = aligned
        .iter()
        .zip(&unaligned)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(largest > 0.005 * peak, "{largest} of {peak}");
}

/// The misfit check judges where the surfaces can meet (red team G): a ridge beside a Hertz
/// zone, between body 1's contact points and in no element in contact, that the resolved mesh
/// finds carrying 27 % of the load (its own contact: the ridge's gap is below the gap the
/// deformation closed inside the zone) is reported; a groove outside the zone, in the open
/// part of an element in contact, which changes nothing (red team G: 0.96 % of the peak
/// against a resolved mesh, at the zone's other end), is not.
#[test]
fn a_ridge_that_makes_contact_beside_the_zone_is_reported_a_groove_in_the_open_is_not() {
    let warned = |name: &str| {
        let path = format!("{}/tests/problems/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(path).unwrap();
        let p = Problem::with_overrides(&text, name, &[]).unwrap();
        let (summary, ..) = wearfem::driver::contact(&p).unwrap();
        summary["warnings"].as_array().unwrap().iter().any(|w| {
            w.as_str()
                .unwrap()
                .contains("between body 1's contact points")
        })
    };
    assert!(warned("ridge-beside-hertz-zone.toml"));
    assert!(!warned("groove-beside-hertz-zone.toml"));
}

/// Two more features the misfit scan must not miss (red team H): a crown narrower than the
/// points' spacing (`contact.initial_shape` of radius 0.02 mm between two of punch-b40's
/// points: the punch stands on a 20 µm bump; its kinks now split the sampled pieces), and a
/// step whose fall in the open part of an element hid its rise inside the zone (the worst
/// rise and the worst fall are now kept apart).
#[test]
fn a_narrow_crown_and_a_step_at_the_zone_end_are_reported() {
    let warned = |p: &Problem| {
        let (summary, ..) = wearfem::driver::contact(p).unwrap();
        summary["warnings"].as_array().unwrap().iter().any(|w| {
            w.as_str()
                .unwrap()
                .contains("between body 1's contact points")
        })
    };
    let text = wearfem::examples::example("punch-b40").unwrap().replace(
        "discretisation = \"collocation\"",
        "discretisation = \"mortar\"",
    );
    let plain = Problem::with_overrides(&text, "punch", &[]).unwrap();
    assert!(!warned(&plain));
    let crown =
        Override::parse("contact.initial_shape={ radius = 0.02, center_x = 1101.0 }").unwrap();
    assert!(warned(
        &Problem::with_overrides(&text, "punch", &[crown]).unwrap()
    ));
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/problems/side-step-in-element.toml"
    );
    let text = std::fs::read_to_string(path).unwrap();
    assert!(warned(
        &Problem::with_overrides(&text, "step", &[]).unwrap()
    ));
}
