//! Whether a result lies inside the model's own assumptions: checks that no solver residual
//! can see, because the equations were solved exactly and it is the equations that stop
//! describing the problem.
//!
//! - *Quasi-static half periods.* The half-period scheme, and the steady states built on it,
//!   hold the contact pressure at one value over a half period (paper §4: the wear of one
//!   half period is small against the elastic response). With a large β̃, or b = 3 at a
//!   high pressure, one half period's wear already moves the pressure: an independent
//!   integration with 200 sub-steps per half period found the periodic state of punch-b40
//!   with β̃ × 1000 8.5 % of the peak away from `wearfem steady`, which reported "Solved"
//!   (review of 2026-11-24). [`half_period_pressure_change`] measures that directly: the
//!   change of the pressure that one half period's wear causes, by two contact solves per
//!   direction.
//! - *Fixed geometry.* The bodies' meshes are never updated; wear enters only as a gap. A
//!   worn depth that is not small against the worn body's blocks at the contact (a run of
//!   k = 10⁶ wore 240 mm off a 40 mm punch; a 1 mm pad lost 1.8 mm) is outside the model
//!   ([`wear_depth_warnings`], for each body by its own wear).
//! - *Small displacements.* Linear elasticity: a plate motion that is not small against body 1
//!   (E = 10⁻³ MPa moved the punch 690 m) is outside it ([`displacement_warning`]), and so
//!   are strains that are not small ([`largest_strain`], [`contact_strain_warnings`]).

mod strain;
pub use strain::{contact_strain_warnings, largest_strain, strain_warning, STRAIN_LIMIT};

use super::codes::warning;
use crate::complementarity::{ContactSolver, Direction, Status};
use crate::contact::CondensedContact;
use crate::problem::Problem;
use crate::wear::{WearHistory, WearIntegrator};

/// Largest change of the pressure over one half period, relative to the peak, that passes
/// without a warning. Holding the pressure at its end-of-half-period value errs by about half
/// the change; 2 % keeps that near the 1 % the steady check asks of a run.
pub const HALF_PERIOD_CHANGE_LIMIT: f64 = 0.02;

/// Largest worn depth of a body, as a fraction of the extent along the contact normal of
/// the blocks that carry its contact edge; largest plate translation, as a fraction of body
/// 1's extent along the normal; largest plate rotation, in rad: beyond these a warning.
pub const GEOMETRY_LIMIT: f64 = 0.1;

/// The largest change of the contact pressure that the wear of one half period (one step
/// under monotonic sliding) causes, relative to the peak pressure: for each direction d with
/// pressure p_d, the pressure of direction d at `shape` and at `shape` + ΔW(p_d). A direction
/// without pressure wears nothing and changes nothing. `Err` says why the change could not be
/// measured (a check solve failed, or the wear is not finite): exactly where the wear is large
/// enough to break the solve, so the caller must say so, not drop the check.
/// `pressures` are (direction, pressure in MPa).
pub fn half_period_pressure_change(
    solver: &mut ContactSolver,
    integrator: &WearIntegrator,
    shape: &[f64],
    pressures: &[(Direction, &[f64])],
) -> Result<f64, String> {
    let terms = integrator.wear_terms();
    let mut worn = shape.to_vec();
    let mut change: f64 = 0.0;
    for &(direction, pressure) in pressures {
        let d = direction.symbol();
        for (i, ((w, g), p)) in worn.iter_mut().zip(shape).zip(pressure).enumerate() {
            *w = g + terms
                .at(i)
                .iter()
                .map(|(c, b)| c * p.max(0.0).powf(*b))
                .sum::<f64>();
        }
        if worn.iter().any(|w| !w.is_finite()) {
            return Err(format!(
                "the wear of one '{d}' half period is not finite (β̃ and the pressure overflow)"
            ));
        }
        let (before, info_before) = solver.solve(shape, direction);
        if info_before.status != Status::Solved {
            return Err(format!(
                "the contact solve of the '{d}' half cycle at the reported shape failed (complementarity residual {:.3e})",
                info_before.complementarity
            ));
        }
        let (after, info_after) = solver.solve(&worn, direction);
        if info_after.status != Status::Solved {
            return Err(format!(
                "the contact solve of the '{d}' half cycle at the shape worn by one more half period failed (complementarity residual {:.3e}): that wear is too large for the contact to carry the load as before",
                info_after.complementarity
            ));
        }
        let peak = before.pressure.iter().cloned().fold(0.0, f64::max);
        if peak <= 0.0 {
            continue;
        }
        let largest = before
            .pressure
            .iter()
            .zip(&after.pressure)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        if !largest.is_finite() {
            return Err(format!(
                "the '{d}' pressure at the worn shape is not finite"
            ));
        }
        change = change.max(largest / peak);
    }
    Ok(change)
}

/// The warning for a [`half_period_pressure_change`] above [`HALF_PERIOD_CHANGE_LIMIT`], or
/// for one that could not be measured (why, from its `Err`).
pub fn half_period_warning(problem: &Problem, change: Result<f64, String>) -> Option<String> {
    let change = match change {
        Ok(change) => change,
        Err(why) => {
            return Some(warning(
                "half-period-unchecked",
                &problem.file,
                format!("wear: could not check whether one half period's wear changes the contact pressure: {why}"),
            ))
        }
    };
    (change > HALF_PERIOD_CHANGE_LIMIT).then(|| warning(
        "half-period",
        &problem.file,
        format!(
            "wear: one half period's wear changes the contact pressure by {:.1} % of its peak, which the half-period scheme holds constant",
            100.0 * change
        ),
    ))
}

/// The mean normal of the contact points (unit), None without contact points.
fn mean_normal(contact: &CondensedContact) -> Option<[f64; 2]> {
    let n = contact
        .points
        .normal
        .iter()
        .fold([0.0, 0.0], |s, v| [s[0] + v[0], s[1] + v[1]]);
    let length = n[0].hypot(n[1]);
    (length > 0.0).then(|| [n[0] / length, n[1] / length])
}

/// Extent along `normal` of `points`, mm.
fn extent(points: impl Iterator<Item = [f64; 2]>, normal: [f64; 2]) -> f64 {
    let (lo, hi) = points
        .map(|p| p[0] * normal[0] + p[1] * normal[1])
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    hi - lo
}

/// For body `which` (0: body 1, 1: body 2) of the contact: its name, and the depth of the
/// blocks that carry its contact edge, mm: along each element's contact side
/// (nine places, its ends included), the distance through its block to the
/// block's opposite side along the edge's normal there, the least of them. A pad modelled
/// as a block of its own is measured by itself, not by the whole body; a ring sector by its
/// radial thickness (its corners, projected on the mean normal, called a bush 15 mm thick
/// 7.5 mm: red team F).
pub fn worn_blocks_depth(problem: &Problem, which: usize) -> Option<(String, f64)> {
    let c = problem.spec.contact.as_ref()?;
    let (name, edge) = if which == 0 {
        (&c.body, &c.edge)
    } else {
        (&c.target_body, &c.target_edge)
    };
    let b = problem.body_index(name).ok()?;
    let mesh = problem.mesh(b).ok()?;
    // A Gmsh body's blocks are its elements: measure through the body instead.
    let from_gmsh = problem.spec.bodies[b].gmsh.is_some();
    let depth = mesh
        .named_edges
        .get(edge)?
        .iter()
        .map(|&(e, local)| {
            if from_gmsh {
                depth_through_body(&mesh, e, local)
            } else {
                depth_across_block(&mesh, e, local)
            }
        })
        .fold(f64::INFINITY, f64::min);
    depth.is_finite().then(|| (name.clone(), depth))
}

/// How many places along each contact element's side the block's depth is measured at, its
/// ends included: a pad tapered to 1 mm at one end of a single 60 mm element was measured
/// 10.5 mm deep at the element's middle alone, and its wear through 98 % of the thin end was
/// silent (red team K).
const DEPTH_SAMPLES: usize = 9;

/// The least depth of element `element`'s block under its side `local` (on the block's
/// boundary), over [`DEPTH_SAMPLES`] places along the side: from each to the block's
/// opposite side along the parameter line across the block, projected on the side's normal
/// there, mm.
fn depth_across_block(mesh: &crate::mesh::Mesh, element: usize, local: usize) -> f64 {
    let el = &mesh.elements[element];
    let block = &mesh.blocks[el.block].block;
    (0..DEPTH_SAMPLES)
        .map(|k| {
            let t = k as f64 / (DEPTH_SAMPLES - 1) as f64;
            let (u, v) = (
                el.u[0] + t * (el.u[1] - el.u[0]),
                el.v[0] + t * (el.v[1] - el.v[0]),
            );
            // Local side e of an element on the block's boundary is the block's side e
            // (0 bottom, 1 right, 2 top, 3 left); the side's tangent is ∂x/∂u on sides 0
            // and 2, ∂x/∂v on 1 and 3.
            let (on_side, opposite, along_u) = match local {
                0 => ((u, 0.0), (u, 1.0), true),
                1 => ((1.0, v), (0.0, v), false),
                2 => ((u, 1.0), (u, 0.0), true),
                _ => ((0.0, v), (1.0, v), false),
            };
            depth_between(block, on_side, opposite, along_u)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The least depth of the body under side `local` of `element` (on the body's boundary), over
/// [`DEPTH_SAMPLES`] places along the side: the distance along the inward normal to where it
/// next crosses the body's boundary (each boundary edge taken as 16 chords), mm.
fn depth_through_body(mesh: &crate::mesh::Mesh, element: usize, local: usize) -> f64 {
    const CHORDS: usize = 16;
    let boundary: Vec<[crate::geometry::Point; 2]> = mesh
        .edges
        .iter()
        .filter(|e| e.elements.len() == 1)
        .flat_map(|e| {
            let (el, l) = e.elements[0];
            (0..CHORDS).map(move |k| {
                let t = |k: usize| -1.0 + 2.0 * k as f64 / CHORDS as f64;
                [
                    mesh.point_on_edge(el, l, t(k)),
                    mesh.point_on_edge(el, l, t(k + 1)),
                ]
            })
        })
        .collect();
    (0..DEPTH_SAMPLES)
        .map(|k| {
            let t = -1.0 + 2.0 * k as f64 / (DEPTH_SAMPLES - 1) as f64;
            let start = mesh.point_on_edge(element, local, t);
            let (tangent, normal) = mesh.edge_frame(element, local, t);
            let inward = [-normal[0], -normal[1]];
            // The ray leaves from its own edge (and its neighbours' at the side's ends), met
            // at s ≈ 0: crossings within 1e-6 of the side's length are those.
            let least = 1e-6 * tangent[0].hypot(tangent[1]);
            boundary
                .iter()
                .filter_map(|&[a, b]| ray_crossing(start, inward, a, b))
                .filter(|&s| s > least)
                .fold(f64::INFINITY, f64::min)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Where the ray x + s d (s ≥ 0) crosses the segment a b: its s, if it does.
fn ray_crossing(
    x: crate::geometry::Point,
    d: crate::geometry::Point,
    a: crate::geometry::Point,
    b: crate::geometry::Point,
) -> Option<f64> {
    let e = [b[0] - a[0], b[1] - a[1]];
    let denominator = d[0] * e[1] - d[1] * e[0];
    if denominator.abs() < 1e-300 {
        return None;
    }
    let w = [a[0] - x[0], a[1] - x[1]];
    let s = (w[0] * e[1] - w[1] * e[0]) / denominator;
    let along = (w[0] * d[1] - w[1] * d[0]) / denominator;
    ((0.0..=1.0).contains(&along) && s >= 0.0).then_some(s)
}

/// The distance from block parameters `on_side` to `opposite`, projected on the normal of
/// the side through `on_side` (whose tangent is ∂x/∂u when `along_u`, else ∂x/∂v), mm.
fn depth_between(
    block: &crate::geometry::Block,
    on_side: (f64, f64),
    opposite: (f64, f64),
    along_u: bool,
) -> f64 {
    let from = block.map(on_side.0, on_side.1);
    let to = block.map(opposite.0, opposite.1);
    let j = block.jacobian(on_side.0, on_side.1);
    let column = usize::from(!along_u);
    let tangent = [j[0][column], j[1][column]];
    let length = tangent[0].hypot(tangent[1]);
    if length <= 0.0 {
        // A side of zero length has no normal (the mesh checks refuse such blocks).
        return (to[0] - from[0]).hypot(to[1] - from[1]);
    }
    let normal = [-tangent[1] / length, tangent[0] / length];
    ((to[0] - from[0]) * normal[0] + (to[1] - from[1]) * normal[1]).abs()
}

/// A warning for each body whose worn depth ([`WearHistory::worn_depth`]) exceeds
/// [`GEOMETRY_LIMIT`] of the depth of the blocks that carry its contact edge
/// ([`worn_blocks_depth`]): the meshes are never updated, so such wear is outside the model.
pub fn wear_depth_warnings(problem: &Problem, history: &WearHistory) -> Vec<String> {
    (0..2)
        .filter(|&b| history.worn_depth[b] > 0.0)
        .filter_map(|b| {
            let depth = history.worn_depth[b];
            let (name, size) = worn_blocks_depth(problem, b)?;
            (depth > GEOMETRY_LIMIT * size).then(|| warning(
                "worn-deep",
                &problem.file,
                format!(
                    "the run wore up to {:.4e} mm off body {} (\"{name}\"), {} the {:.4} mm depth under its contact edge: outside the model, whose meshes are never updated",
                    depth,
                    b + 1,
                    share(depth / size),
                    size
                ),
            ))
        })
        .collect()
}

/// Warnings when the first contact solve's plate motion is not small: a translation λ_F
/// above [`GEOMETRY_LIMIT`] of body 1's extent along the contact normal, or a rotation λ_M
/// above [`GEOMETRY_LIMIT`] rad; or when the bodies' strains are not
/// ([`contact_strain_warnings`]). Linear elasticity assumes small displacements and
/// rotations; a long body may move far at a small strain, hence the body's own size.
pub fn displacement_warning(
    problem: &Problem,
    contact: &CondensedContact,
    solver: &mut ContactSolver,
    direction: Direction,
) -> Vec<String> {
    let (solution, info) = solver.solve(&contact.points.initial_gap, direction);
    if info.status != Status::Solved {
        return Vec::new();
    }
    let mut warnings: Vec<String> = plate_motion_warning(problem, contact, &solution.rigid)
        .into_iter()
        .collect();
    warnings.extend(contact_strain_warnings(
        problem, contact, &solution, direction,
    ));
    warnings
}

/// The warning of [`displacement_warning`] for a solved contact problem's plate unknowns
/// `rigid` (λ_F mm, λ_M rad, in `contact.rigid_names` order).
pub fn plate_motion_warning(
    problem: &Problem,
    contact: &CondensedContact,
    rigid: &[f64],
) -> Option<String> {
    let c = problem.spec.contact.as_ref()?;
    let mesh = problem.mesh(problem.body_index(&c.body).ok()?).ok()?;
    let size = extent(mesh.vertices.iter().copied(), mean_normal(contact)?);
    if size <= 0.0 {
        return None;
    }
    // The plate's rigid motion where it carries the contact, not λ_F itself: λ_F is the
    // motion of the pin, which may lie far from the punch (red team B: a pin 1 m away
    // reported 233 mm while the contact edge moved 0.014 mm).
    let translation = (0..contact.len())
        .map(|i| {
            let moved = (0..rigid.len()).fold([0.0, 0.0], |u, k| {
                let phi = contact.rigid_modes[k][i];
                [u[0] + rigid[k] * phi[0], u[1] + rigid[k] * phi[1]]
            });
            moved[0].hypot(moved[1])
        })
        .fold(0.0, f64::max);
    let rotation = contact
        .rigid_names
        .iter()
        .position(|n| *n == "lambda_M")
        .map_or(0.0, |i| rigid[i].abs());
    let what = if translation > GEOMETRY_LIMIT * size {
        format!(
            "moves body 1's contact edge by up to {translation:.4e} mm, {} body 1's {size:.4} mm along the contact normal,",
            share(translation / size)
        )
    } else if rotation > GEOMETRY_LIMIT {
        format!("turns by {rotation:.4e} rad,")
    } else {
        return None;
    };
    Some(warning(
        "large-motion",
        &problem.file,
        format!("under the load the plate {what} outside small displacements and rotations"),
    ))
}

/// A contact solver and wear integrator for the checks, made as the jobs make them.
fn tools(
    problem: &Problem,
    contact: &CondensedContact,
) -> Option<(ContactSolver, WearIntegrator, Direction)> {
    let spec = problem.spec.wear.as_ref()?;
    let mut integrator = WearIntegrator::new(spec).ok()?;
    let direction = problem.first_direction().ok()?;
    integrator.first_direction = direction;
    let solver = ContactSolver::new(contact, problem.contact_method().ok()?);
    Some((solver, integrator, direction))
}

/// The checks of this module for a finished `wearfem run`: its last cycle's pressures over a
/// half period, its worn depth and the first solve's displacements.
pub fn run_checks(problem: &Problem, contact: &CondensedContact, h: &WearHistory) -> Vec<String> {
    let Some((mut solver, integrator, first)) = tools(problem, contact) else {
        return Vec::new();
    };
    let mut warnings = Vec::new();
    if h.steady_distance.is_some() {
        // p_plus is the '+' pressure, p_minus the '−' one, whichever came first; under
        // monotonic sliding p_plus is the one direction's.
        let pressures = if integrator.is_monotonic() {
            vec![(first, &h.p_plus[..])]
        } else {
            vec![
                (Direction::Plus, &h.p_plus[..]),
                (Direction::Minus, &h.p_minus[..]),
            ]
        };
        let change = half_period_pressure_change(&mut solver, &integrator, &h.shape, &pressures);
        warnings.extend(half_period_warning(problem, change));
    }
    warnings.extend(wear_depth_warnings(problem, h));
    warnings.extend(displacement_warning(problem, contact, &mut solver, first));
    warnings
}

/// The checks of this module for a steady state: its pressures over a half period and the
/// first solve's displacements.
pub fn steady_checks(
    problem: &Problem,
    contact: &CondensedContact,
    state: &crate::steady::SteadyState,
) -> Vec<String> {
    let Some((_, integrator, first)) = tools(problem, contact) else {
        return Vec::new();
    };
    // The steady solver knows only exact contact: its checks use the same.
    let mut solver = ContactSolver::new(contact, crate::complementarity::Method::ActiveSet);
    let pressures = match state.sliding {
        crate::steady::SteadySliding::Monotonic(d) => vec![(d, &state.p_plus[..])],
        crate::steady::SteadySliding::Reciprocating => vec![
            (Direction::Plus, &state.p_plus[..]),
            (Direction::Minus, &state.p_minus[..]),
        ],
    };
    let change = half_period_pressure_change(&mut solver, &integrator, &state.shape, &pressures);
    let mut warnings: Vec<String> = half_period_warning(problem, change).into_iter().collect();
    if problem
        .spec
        .contact
        .as_ref()
        .is_some_and(|c| c.method == "penalty")
    {
        warnings.push(warning(
            "penalty-steady",
            &problem.file,
            "contact.method = \"penalty\" is not used by `steady`, which solves exact contact (its checks too); `run` and `contact` use the penalty",
        ));
    }
    warnings.extend(displacement_warning(problem, contact, &mut solver, first));
    warnings
}

/// "12 % of" for a ratio below 10, "3.2e5 times" above.
fn share(ratio: f64) -> String {
    if ratio < 10.0 {
        format!("{:.0} % of", 100.0 * ratio)
    } else {
        format!("{ratio:.2e} times")
    }
}
