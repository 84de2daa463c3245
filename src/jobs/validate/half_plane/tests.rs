use super::*;

/// The panel-mean of f over panel i (f sampled at 8 points), to compare piecewise-constant
/// tractions with a closed form without a midpoint bias.
fn mean(state: &HalfPlaneState, i: usize, f: &dyn Fn(f64) -> f64) -> f64 {
    let h = state.width;
    (0..8)
        .map(|k| f(state.x[i] - 0.5 * h + (k as f64 + 0.5) * h / 8.0))
        .sum::<f64>()
        / 8.0
}

#[test]
fn half_plane_cattaneo_at_beta_zero() {
    let (mu, ratio) = (0.6, 0.5);
    let s = coupled_partial_slip(0.0, mu, ratio, 400).unwrap();
    let c = (1.0f64 - ratio).sqrt();
    println!(
        "stick [{:.5}, {:.5}] vs ±{c:.5}; contact [{:.5}, {:.5}]",
        s.stick_left, s.stick_right, s.contact_left, s.contact_right
    );
    // 2e-3 a is a third of a panel (Δ = 0.00625a at N = 400): the edge fit's scatter.
    assert!((s.stick_right - c).abs() < 2e-3 && (s.stick_left + c).abs() < 2e-3);
    // β = 0 is exactly symmetric, also discretely.
    assert!(s.stick_centre().abs() < 1e-9);
    assert!((s.contact_right - 1.0).abs() < 2e-3 && (s.contact_left + 1.0).abs() < 2e-3);
    assert!((s.load - ratio * mu * LOAD).abs() < 1e-10);
    let exact = |x: f64| {
        let outer = (1.0 - x * x).max(0.0).sqrt();
        let inner = c * (1.0 - x * x / (c * c)).max(0.0).sqrt();
        -mu * (outer - inner)
    };
    let worst = (0..s.x.len())
        .map(|i| (s.shear[i] - mean(&s, i, &exact)).abs())
        .fold(0.0, f64::max);
    println!("max |q − Cattaneo| = {:.2e} μp₀", worst / mu);
    // Panel-mean comparison; the error sits at the √ edges: 3.2e-3 μp₀ at N = 400.
    assert!(worst < 0.01 * mu);
}

#[test]
fn half_plane_no_shear_no_coupling() {
    // Q = 0: the stage changes nothing, whatever β; the pressure is (discrete) Hertz.
    let s = coupled_partial_slip(0.3, 0.6, 0.0, 400).unwrap();
    let grid = Panels::new(400, window(0.3, 0.6));
    let h = hertz(&grid, 0.3).unwrap();
    let moved = (0..s.x.len())
        .map(|i| (s.pressure[i] - h.p[i]).abs() + s.shear[i].abs())
        .fold(0.0, f64::max);
    assert!(moved < 1e-10, "{moved:e}");
    assert!(s.stick.iter().zip(&h.p).all(|(&st, &p)| st == (p > 0.0)));
    let hertz = |x: f64| (1.0 - x * x).max(0.0).sqrt();
    let worst = (0..s.x.len())
        .map(|i| (s.pressure[i] - mean(&s, i, &hertz)).abs())
        .fold(0.0, f64::max);
    println!("max |p − Hertz| = {worst:.2e} p₀");
    // 4.1e-3 p₀ at N = 400, at the edge panels (p ∝ √ there).
    assert!(worst < 0.01);
    assert!((s.contact_right - 1.0).abs() < 2e-3 && (s.contact_left + 1.0).abs() < 2e-3);
}

#[test]
fn half_plane_full_sliding_is_bufler() {
    for (beta, mu) in [(0.3, 0.6), (-0.2, 0.5), (0.5, 0.8)] {
        let s = full_sliding(beta, mu, 400).unwrap();
        let (left, right, exact) = bufler(beta, mu);
        let worst = (0..s.x.len())
            .map(|i| (s.pressure[i] - mean(&s, i, &exact)).abs())
            .fold(0.0, f64::max);
        println!(
            "β {beta} μ {mu}: contact [{:.5}, {:.5}] vs Bufler [{left:.5}, {right:.5}], \
             max |p − Bufler| = {worst:.2e} p₀",
            s.contact_left, s.contact_right
        );
        // Edges to half a panel (Δ ≈ 0.0066a); the pressure's error sits at the edge
        // panels, where p ∝ distance^(1/2 − |γ|) is steeper than √ (1.8e-2 p₀ at most).
        assert!((s.contact_left - left).abs() < 3e-3);
        assert!((s.contact_right - right).abs() < 3e-3);
        assert!(worst < 0.03);
        // The shift is to +x for βμ > 0: body 1 (more compliant if β > 0) slides along +x.
        let centre = 0.5 * (s.contact_left + s.contact_right);
        assert!(centre * beta > 0.0);
    }
}

#[test]
fn half_plane_mirror_symmetry() {
    // Swapping the bodies (β → −β, q → −q, Q → −Q) and reflecting x (q → −q, Q → −Q)
    // maps the problem (β, Q) onto (−β, Q) mirrored: the discretisation must keep that.
    let a = coupled_partial_slip(0.25, 0.6, 0.5, 300).unwrap();
    let b = coupled_partial_slip(-0.25, 0.6, 0.5, 300).unwrap();
    assert!((a.stick_left + b.stick_right).abs() < 1e-9);
    assert!((a.stick_right + b.stick_left).abs() < 1e-9);
    assert!((a.contact_left + b.contact_right).abs() < 1e-9);
    let n = a.x.len();
    let worst = (0..n)
        .map(|i| (a.pressure[i] - b.pressure[n - 1 - i]).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-9);
}

#[test]
fn half_plane_mindlin_deresiewicz_at_beta_zero() {
    let (mu, peak, back) = (0.3, 0.6, 0.2);
    let (loaded, unloaded) = coupled_unloading(0.0, mu, peak, back, 400).unwrap();
    let c_back = (1.0f64 - (peak - back) / 2.0).sqrt();
    println!(
        "loaded stick ±{:.5} (Cattaneo {:.5}); unloaded ±{:.5} vs {c_back:.5}",
        loaded.stick_right,
        (1.0f64 - peak).sqrt(),
        unloaded.stick_right
    );
    // A third of a panel, as for Cattaneo's edge.
    assert!((unloaded.stick_right - c_back).abs() < 2e-3);
    assert!((unloaded.stick_left + c_back).abs() < 2e-3);
    assert!((unloaded.load - back * mu * LOAD).abs() < 1e-10);
    // The zone that slips back does so along −x.
    assert!(unloaded.slip.iter().all(|&s| s <= 0.0));
}

#[test]
fn half_plane_coupled_converges() {
    // β = 0.2, μ = 0.6, Q = 0.5 μP: the edges at N = 200 and 400 against N = 800.
    let fine = coupled_partial_slip(0.2, 0.6, 0.5, 800).unwrap();
    for n in [200, 400] {
        let s = coupled_partial_slip(0.2, 0.6, 0.5, n).unwrap();
        let d = (s.stick_left - fine.stick_left)
            .abs()
            .max((s.stick_right - fine.stick_right).abs())
            .max((s.contact_left - fine.contact_left).abs())
            .max((s.contact_right - fine.contact_right).abs());
        println!("N = {n}: largest edge change to N = 800: {d:.2e} a");
        // The edges scatter within a fraction of a panel (see the module's table).
        assert!(d < 0.5 * s.width);
    }
    // The coupling moves the stick zone to +x (β > 0, Q along +x).
    assert!(fine.stick_centre() > 0.0);
}

/// The table of the module's documentation and the coupled results of the report.
#[test]
#[ignore]
fn half_plane_tables() {
    println!("| N | stick left | stick right | contact left | contact right | iterations |");
    for n in [100, 200, 400, 800] {
        let s = coupled_partial_slip(0.2, 0.6, 0.5, n).unwrap();
        println!(
            "| {n} | {:.5} | {:.5} | {:.5} | {:.5} | {} |",
            s.stick_left, s.stick_right, s.contact_left, s.contact_right, s.iterations
        );
    }
    println!("| β | μ | Q/μP | stick left | stick right | offset | half-width | contact left | contact right |");
    for mu in [0.3, 0.6] {
        for ratio in [0.3, 0.5, 0.7] {
            for beta in [-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3] {
                let s = coupled_partial_slip(beta, mu, ratio, 800).unwrap();
                println!(
                    "| {beta:+.1} | {mu} | {ratio} | {:.4} | {:.4} | {:+.4} | {:.4} | {:.4} | {:.4} |",
                    s.stick_left,
                    s.stick_right,
                    s.stick_centre(),
                    0.5 * (s.stick_right - s.stick_left),
                    s.contact_left,
                    s.contact_right
                );
            }
        }
    }
    println!("one stage against 20 stages, N = 400:");
    for (beta, mu, ratio) in [(0.3, 0.6, 0.5), (0.3, 0.6, 0.7), (0.2, 0.3, 0.5)] {
        let one = coupled_partial_slip(beta, mu, ratio, 400).unwrap();
        let many = coupled_partial_slip_in_steps(beta, mu, ratio, 400, 20).unwrap();
        println!(
            "β {beta} μ {mu} Q/μP {ratio}: stick [{:.4}, {:.4}] vs [{:.4}, {:.4}], contact [{:.4}, {:.4}] vs [{:.4}, {:.4}]",
            one.stick_left, one.stick_right, many.stick_left, many.stick_right,
            one.contact_left, one.contact_right, many.contact_left, many.contact_right
        );
    }
}
