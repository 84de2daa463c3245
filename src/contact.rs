//! Contact geometry and condensation: the contact points on body 1, body 2's side of each
//! (mortar traces weighted over the overlapping segments, [`mortar`]'s docs give the method;
//! or one partner point, "collocation"), the rigid loading plate, and the flexibility (Green)
//! matrices that reduce both finite element models to the contact points once and for all.
//! Contact zones cut by the end of the named edge are found by [`zone`]'s rules, zones that
//! body 2's mesh does not resolve by [`resolution`]'s.
//!
//! Sign conventions (paper eq. 2–3, 42): n_c is body 1's outward normal (into body 2), τ is n_c
//! turned by +90° (τ = +e_x under a flat punch). The force of body 2 on body 1 at point i is
//! F_i = P_i (−n_c + s μ τ), P_i = p_i w_i t ≥ 0 (N), s = ±1 the half-cycle sign. The gap is
//! d = u_n⁽²⁾ − u_n⁽¹⁾ + g, which condenses to d = A_s P + R λ + g with
//! A_s = A_nn − s μ A_nt, A_nn(i,j) = n_iᵀ(G¹+G²)_ij n_j, A_nt(i,j) = n_iᵀ(G¹+G²)_ij τ_j.
//! Body 1 = rigid plate motion Σ λ_k φ_k + elastic part with the plate edge clamped; the plate's
//! equilibrium (paper eq. 8) is E P + L = 0 with E(k,j) = φ_k(x_j)·(−n_j + s μ τ_j).

use crate::basis::shape_1d;
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::loads::trace_dofs;
use crate::problem::{Problem, ProblemError};
use crate::quadrature::gauss_lobatto;

mod flexibility;
pub mod mortar;
mod plate;
pub mod resolution;
mod spec;
pub mod track;
pub mod zone;
use flexibility::add_flexibility;
pub use flexibility::DofFlexibility;
pub use mortar::SurfaceMisfit;
use mortar::{mortar_traces, ChainElement};
use plate::plate_modes;
pub use resolution::{CoarseZone, PointResolution, SizeJump, UnmatchedLine};
pub use spec::{check_settings, CircleShape, ContactSpec, PlateSpec, MAX_POSITIONS};
pub use zone::EdgeEnd;

/// Contact points of body 1 with their partners on body 2.
#[derive(Clone, Debug)]
pub struct ContactPoints {
    /// Coordinates [x, z] of the points on body 1, mm, ordered along the edge (x rising).
    pub x: Vec<Point>,
    /// Integration weight of each point, mm: the Lobatto weight × edge Jacobian (collocation),
    /// or D_ii = ∫ N_i ds (mortar; the same on straight edges). Contact area = weight × t.
    /// Bodies of revolution: the ring's area 2πr × that, mm², with t = 1.
    pub weight: Vec<f64>,
    /// Unit normal n_c (into body 2).
    pub normal: Vec<Point>,
    /// Unit tangent τ = n_c turned by +90°.
    pub tangent: Vec<Point>,
    /// Initial geometric gap along n_c plus any initial shape, mm.
    pub initial_gap: Vec<f64>,
    /// Partner point [x, z] of each contact point on body 2's contact edge, mm.
    pub partner: Vec<Point>,
}

/// One constraint's displacement as a combination of a body's global dofs (the boundary dofs
/// of [`crate::elasticity::Displacement`]): (x dof, z dof, coefficient).
pub type Trace = Vec<([usize; 2], f64)>;

/// A contact point on the axis of a body of revolution. Its ring has no area (∫ L_i 2πr ds is
/// zero for the nodal interpolation on the axis), so the point force the solve puts there
/// says nothing of the pressure, and a point force on the axis is a 3D point load, far more
/// compliant than its neighbours' rings: it takes almost none. The pressure there is read
/// from the three nearest points' instead, by the parabola through them (p is even in r on
/// the axis, and Hertz's ball is then within 1e-4 of p₀).
#[derive(Clone, Debug)]
pub struct AxisPoint {
    /// Index of the point on the axis.
    pub point: usize,
    /// The nearest points along the edge and their weights in the parabola's value there.
    pub from: [(usize, f64); 3],
}

impl AxisPoint {
    /// The pressure on the axis (MPa) from `pressure` at the other points: the parabola's
    /// value, not below zero, and zero where the nearest point carries none.
    pub fn pressure(&self, pressure: &[f64]) -> f64 {
        if pressure[self.from[0].0] <= 0.0 {
            return 0.0;
        }
        self.from
            .iter()
            .map(|&(i, c)| c * pressure[i])
            .sum::<f64>()
            .max(0.0)
    }
}

/// The contact problem condensed onto the contact points.
#[derive(Clone, Debug)]
pub struct CondensedContact {
    /// Geometry of the contact points.
    pub points: ContactPoints,
    /// Thickness t, mm.
    pub thickness: f64,
    /// Points on the axis of a body of revolution (empty in a plane analysis).
    pub axis_points: Vec<AxisPoint>,
    /// Whether the bodies are bodies of revolution (x is the radius r).
    pub axisymmetric: bool,
    /// Friction coefficient μ of the friction in the plane of the section (0 for bodies of
    /// revolution turning about their axis, whose friction is circumferential).
    pub friction: f64,
    /// Bodies of revolution turning about their axis (`contact.sliding_motion =
    /// "about_axis"`): the friction coefficient μ of their circumferential friction, which
    /// leaves the (r, z) problem untouched and sets the torque ∫ μ p r dA; None otherwise.
    pub friction_about_axis: Option<f64>,
    /// n_iᵀ G n_j, mm/N (N × N, row-major).
    pub a_nn: Vec<f64>,
    /// n_iᵀ G τ_j, mm/N (N × N, row-major).
    pub a_nt: Vec<f64>,
    /// Rigid modes: φ_k at each point (k-major: `phi[k][i]`).
    pub rigid_modes: Vec<Vec<Point>>,
    /// Names of the rigid unknowns ("lambda_F" mm, "lambda_M" rad).
    pub rigid_names: Vec<&'static str>,
    /// Generalised plate load L_k (N, N·mm).
    pub plate_load: Vec<f64>,
    /// Resultant [F_x, F_z] (N) of every load on body 1 (the plate edge's and any others) and
    /// its moment about the pin (N·mm).
    pub plate_resultant: (Point, f64),
    /// For the first and the last contact point: whether body 1's surface continues beyond
    /// that end of the named contact edge (see [`CondensedContact::edge_ends_in_contact`]).
    pub surface_continues: [bool; 2],
    /// Both meshes' element lengths at each contact point (see
    /// [`CondensedContact::coarse_partner_zones`]).
    pub resolution: Vec<PointResolution>,
    /// The lines of body 2 inside one of body 1's contact elements, with collocation (where
    /// one-point partners make the pressure oscillate) and with mortar on meshes left
    /// unaligned (`contact.align_target_mesh = false`, where the pressure ripples at body 1's
    /// element ends); empty for matched lines and for aligned mortar meshes.
    pub unmatched_lines: Vec<UnmatchedLine>,
    /// Vertices of body 1's contact edge where the element length jumps by more than
    /// [`resolution::SIZE_JUMP`] (see [`CondensedContact::size_jump_in_contact`]).
    pub size_jumps: Vec<SizeJump>,
    /// Mesh lines added to body 2 under body 1's element ends (`contact.align_target_mesh`,
    /// [`crate::mesh::Mesh::aligned_to`]), and body 2's element count with them.
    pub target_mesh: TargetMesh,
    /// Each constraint's displacement on body 1 and on body 2 (`[body 1, body 2]`, one
    /// [`Trace`] per contact point): the point value at a contact point and at its partner
    /// (collocation), or body 2's mortar average (1/D_ii) ∫ ψ_i N⁽²⁾. The flexibilities are
    /// built from these, so a contact force F_i acts on body b as the load F_i · trace_b,i
    /// ([`crate::deformation`]); a point force at the partner is not the same load on mortar.
    pub traces: [Vec<Trace>; 2],
    /// Mortar only: per contact element of body 1, where body 2's surface departs most from
    /// the polynomial through the constraints' gaps (see
    /// [`CondensedContact::surface_misfit_in_contact`]); empty for collocation.
    pub surface_misfits: Vec<SurfaceMisfit>,
}

/// What sliding pairs know before a position is condensed ([`track`]).
#[derive(Clone, Debug)]
pub struct KnownFlexibility {
    /// Body 1's part of A_nn and A_nt (row-major N × N), the same at every position.
    pub body1: [Vec<f64>; 2],
    /// Body 2's flexibility on the dofs of its track.
    pub body2: DofFlexibility,
}

/// What aligning body 2's mesh with body 1's element ends did to it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TargetMesh {
    /// Mesh lines added to body 2's blocks (0 when its lines already met body 1's ends, or
    /// with `align_target_mesh = false`).
    pub lines_added: usize,
    /// Body 2's elements, the added lines' included.
    pub elements: usize,
}

fn chain_edge(body: &ElasticBody, edges: &[(usize, usize)]) -> Vec<(usize, usize, bool)> {
    // Order the element edges end to end; `bool` = traverse with t decreasing.
    let ends = |&(e, l): &(usize, usize)| {
        let (a, b) = crate::mesh::EDGE_ENDPOINTS[l];
        (
            body.mesh.elements[e].vertices[a],
            body.mesh.elements[e].vertices[b],
        )
    };
    let mut left: Vec<(usize, usize)> = edges.to_vec();
    let mut chain: Vec<(usize, usize, bool)> = Vec::new();
    // Start at an edge whose start vertex is no other edge's vertex (an open end).
    let count = |v: usize| {
        edges
            .iter()
            .filter(|e| ends(e).0 == v || ends(e).1 == v)
            .count()
    };
    let start = left
        .iter()
        .position(|e| count(ends(e).0) == 1 || count(ends(e).1) == 1)
        .unwrap_or(0);
    let first = left.remove(start);
    let (a, b) = ends(&first);
    let reversed = count(a) != 1 && count(b) == 1;
    chain.push((first.0, first.1, reversed));
    let mut tip = if reversed { a } else { b };
    while !left.is_empty() {
        let Some(k) = left
            .iter()
            .position(|e| ends(e).0 == tip || ends(e).1 == tip)
        else {
            break;
        };
        let next = left.remove(k);
        let (a, b) = ends(&next);
        let reversed = b == tip;
        tip = if reversed { a } else { b };
        chain.push((next.0, next.1, reversed));
    }
    chain
}

/// Whether the element edges `edges` of `body` close on themselves: every vertex they touch
/// is shared by two of them, so the chain has no end.
pub(crate) fn closed_loop(body: &ElasticBody, edges: &[(usize, usize)]) -> bool {
    let mut touches: std::collections::HashMap<usize, usize> = Default::default();
    for &(e, l) in edges {
        let (a, b) = crate::mesh::EDGE_ENDPOINTS[l];
        for v in [a, b] {
            *touches
                .entry(body.mesh.elements[e].vertices[v])
                .or_default() += 1;
        }
    }
    !edges.is_empty() && touches.values().all(|&n| n == 2)
}

impl ContactPoints {
    /// Gauss–Lobatto points (p + 1 per element edge, shared end points) along body 1's edge,
    /// with one trace per point for body 1.
    fn on_body1(
        body: &ElasticBody,
        edges: &[(usize, usize)],
    ) -> Option<(ContactPoints, Vec<Trace>, Vec<ChainElement>)> {
        let p = body.dofs.p;
        let rule = gauss_lobatto(p + 1);
        let chain = chain_edge(body, edges);
        if chain.len() != edges.len() {
            return None;
        }
        let mut pts = ContactPoints {
            x: vec![],
            weight: vec![],
            normal: vec![],
            tangent: vec![],
            initial_gap: vec![],
            partner: vec![],
        };
        let mut traces = Vec::new();
        let mut elements = Vec::new();
        let mut values = vec![0.0; p + 1];
        let mut derivs = vec![0.0; p + 1];
        for (ci, &(element, local, reversed)) in chain.iter().enumerate() {
            let dofs = trace_dofs(&body.dofs, &body.mesh, &body.basis, element, local);
            elements.push(ChainElement {
                element,
                local,
                reversed,
                first_point: ci * p,
            });
            for k in 0..rule.points.len() {
                let t = if reversed {
                    -rule.points[k]
                } else {
                    rule.points[k]
                };
                let (tan, normal) = body.mesh.edge_frame(element, local, t);
                let w = rule.weights[k] * tan[0].hypot(tan[1]);
                if k == 0 && ci > 0 {
                    // Shared end point: its weight collects both elements' shares.
                    *pts.weight.last_mut().unwrap() += w;
                    continue;
                }
                shape_1d(p, t, &mut values, &mut derivs);
                traces.push(
                    dofs.iter()
                        .zip(&values)
                        .map(|(&(g, s), &v)| (g, s * v))
                        .filter(|x| x.1 != 0.0)
                        .collect(),
                );
                pts.x.push(body.mesh.point_on_edge(element, local, t));
                pts.weight.push(w);
                pts.normal.push(normal);
                pts.tangent.push([-normal[1], normal[0]]);
            }
        }
        if pts.x.len() > 1 && pts.x[0][0] > pts.x[pts.x.len() - 1][0] {
            for v in [&mut pts.x, &mut pts.normal, &mut pts.tangent] {
                v.reverse();
            }
            pts.weight.reverse();
            traces.reverse();
            // Traverse each element the other way: its node k is then point N − 1 − (first + p − k).
            let last = pts.x.len() - 1;
            for c in &mut elements {
                c.reversed = !c.reversed;
                c.first_point = last - (c.first_point + p);
            }
        }
        Some((pts, traces, elements))
    }
}

/// Find the point of body 2's edge on the line x + s n: (s, element, local edge, t).
fn locate_on_body2(
    body: &ElasticBody,
    edges: &[(usize, usize)],
    x: Point,
    n: Point,
) -> Option<(f64, usize, usize, f64)> {
    body.mesh.cross_edges(edges, x, n)
}

/// Find the point of body 2's edge on the line x + s n and return (s, the point, trace).
fn project_on_body2(
    body: &ElasticBody,
    edges: &[(usize, usize)],
    x: Point,
    n: Point,
) -> Option<(f64, Point, Trace)> {
    let p = body.dofs.p;
    let (s, element, local, t) = locate_on_body2(body, edges, x, n)?;
    let partner = body.mesh.point_on_edge(element, local, t);
    let dofs = trace_dofs(&body.dofs, &body.mesh, &body.basis, element, local);
    let mut values = vec![0.0; p + 1];
    let mut derivs = vec![0.0; p + 1];
    shape_1d(p, t, &mut values, &mut derivs);
    Some((
        s,
        partner,
        dofs.iter()
            .zip(&values)
            .map(|(&(g, sg), &v)| (g, sg * v))
            .filter(|x| x.1 != 0.0)
            .collect(),
    ))
}

/// Body 2's trace of every constraint, filling in the initial gaps (and, for mortar, the
/// weights D_ii) of `points`.
fn body2_traces(
    problem: &Problem,
    c: &ContactSpec,
    body1: &ElasticBody,
    chain: &[ChainElement],
    body2: &ElasticBody,
    edge2: &[(usize, usize)],
    points: &mut ContactPoints,
) -> Result<(Vec<Trace>, Vec<SurfaceMisfit>), ProblemError> {
    if c.initial_shape.is_some() {
        // The crown is a function of the global x: along an edge inclined by θ it would be a
        // cylinder of radius R/cos²θ (a review's Hertz turned by 30°: 13 % low), and nothing
        // along a vertical edge.
        if let Some((x, n)) = points
            .x
            .iter()
            .zip(&points.normal)
            .find(|(_, n)| n[0].abs() > 1e-9)
        {
            return Err(problem.error(
                "contact.initial_shape",
                format!("is a crown over the global x and needs a straight horizontal contact edge, but body 1's normal at ({:.4}, {:.4}) is inclined by {:.3}°; model a curved or inclined profile with arc edges of the blocks (`arcs`) instead", x[0], x[1], n[0].asin().abs().to_degrees()),
            ));
        }
    }
    let shape = |x: Point| {
        c.initial_shape.map_or(0.0, |sh| {
            let dx = x[0] - sh.center_x;
            sh.radius - (sh.radius * sh.radius - dx * dx).max(0.0).sqrt()
        })
    };
    let no_partner = |x: Point| {
        problem.error("contact.target_edge", format!("contact point ({:.4}, {:.4}) of body 1 has no partner on \"{}\" along its normal (a part of the edge that crosses the normal line and faces body 1)", x[0], x[1], c.target_edge))
    };
    match c.discretisation.as_str() {
        "collocation" => {
            spec::check_collocation_degrees(problem, body1.dofs.p, body2.dofs.p)?;
            let mut traces2 = Vec::with_capacity(points.x.len());
            for i in 0..points.x.len() {
                let (s, partner, tr) =
                    project_on_body2(body2, edge2, points.x[i], points.normal[i])
                        .ok_or_else(|| no_partner(points.x[i]))?;
                points.initial_gap.push(s + shape(points.x[i]));
                points.partner.push(partner);
                traces2.push(tr);
            }
            Ok((traces2, Vec::new()))
        }
        "mortar" => {
            let m = mortar_traces(body1, chain, body2, edge2, points.x.len(), shape)
                .map_err(no_partner)?;
            points.weight = m.weight;
            // The geometric gap of each constraint is the gap at its own point, g₀(x_i): the
            // ψ_i-weighted mean equals it for every g₀ that body 1's element polynomials
            // interpolate (biorthogonality, as for the wear), but ψ_i has negative lobes, and
            // across a step or groove of body 2's surface inside one of body 1's elements the
            // mean of a jump of 1 mm was a false interference of 0.1 mm: 14 000 MPa at a
            // point beside a Hertz zone (red team A). The point of body 2 facing each contact
            // point is also the partner for post-processing (the constraint itself couples
            // body 2 through the mortar trace). Where the normal line misses body 2's edge,
            // the mean stays and the contact point itself stands in as partner.
            let mut gap = m.gap;
            points.partner = (0..points.x.len())
                .map(
                    |i| match locate_on_body2(body2, edge2, points.x[i], points.normal[i]) {
                        Some((sigma, e, l, t)) => {
                            gap[i] = sigma + shape(points.x[i]);
                            body2.mesh.point_on_edge(e, l, t)
                        }
                        None => points.x[i],
                    },
                )
                .collect();
            points.initial_gap = gap;
            // The crown's kinks: its centre and where the cylinder meets its flanks.
            let kinks: Vec<Point> = c.initial_shape.map_or(Vec::new(), |sh| {
                let z = points.x.first().map_or(0.0, |x| x[1]);
                [-1.0, 0.0, 1.0]
                    .map(|k| [sh.center_x + k * sh.radius, z])
                    .to_vec()
            });
            let misfits = mortar::surface_misfits(
                body1,
                chain,
                body2,
                edge2,
                &points.initial_gap,
                (shape, &kinks),
            );
            Ok((m.traces, misfits))
        }
        other => Err(spec::unknown_discretisation(problem, other)),
    }
}

/// One element edge: (element, local edge).
pub(crate) type EdgeRef = (usize, usize);

/// Body 2's index and its named contact edge (element, local edge) on `body2`'s mesh,
/// checked: what the sliding pairs' track is made of.
pub(crate) fn target_edge<'m>(
    problem: &Problem,
    body2: &'m ElasticBody,
) -> Result<(usize, &'m [EdgeRef]), ProblemError> {
    let (c, _, b2) = spec::contact_section(problem)?;
    let edge = problem.named_edge(&body2.mesh, b2, &c.target_edge, "contact.target_edge")?;
    Ok((b2, edge))
}

/// The contact points with their normals and tangents turned back by `turn` (radians): the
/// directions in body 2's frame of assembly (see [`CondensedContact::condense`]).
fn body2_frame(points: &ContactPoints, turn: f64) -> ContactPoints {
    let mut frame = points.clone();
    if turn != 0.0 {
        let (sin, cos) = (-turn).sin_cos();
        let back = |v: Point| [cos * v[0] - sin * v[1], sin * v[0] + cos * v[1]];
        for (n, t) in frame.normal.iter_mut().zip(frame.tangent.iter_mut()) {
            *n = back(*n);
            *t = back(*t);
        }
    }
    frame
}

impl CondensedContact {
    /// Build both bodies, condense them onto the contact points and evaluate the plate load.
    /// Returns the condensed problem and the two factorised bodies (for post-processing).
    pub fn build(
        problem: &Problem,
    ) -> Result<(CondensedContact, ElasticBody, ElasticBody), ProblemError> {
        let (body1, body2) = Self::bodies(problem)?;
        let contact = Self::from_bodies(problem, &body1, &body2)?;
        Ok((contact, body1, body2))
    }

    /// Assemble and factorise the two bodies; body 1 with its plate edge clamped.
    pub fn bodies(problem: &Problem) -> Result<(ElasticBody, ElasticBody), ProblemError> {
        let (_, b1, b2) = spec::contact_section(problem)?;
        let clamped: Vec<&str> = problem.spec.plate.iter().map(|p| p.edge.as_str()).collect();
        Ok((
            problem.elastic_body(b1, &clamped)?,
            problem.elastic_body(b2, &[])?,
        ))
    }

    /// Condense two factorised bodies (from [`CondensedContact::bodies`]) onto the contact
    /// points: 2N right-hand sides per body, no refactorisation.
    pub fn from_bodies(
        problem: &Problem,
        body1: &ElasticBody,
        body2: &ElasticBody,
    ) -> Result<CondensedContact, ProblemError> {
        Self::condense(problem, body1, body2, None, 0.0)
    }

    /// [`CondensedContact::from_bodies`], with the flexibilities taken from `known` where it
    /// holds them (sliding pairs: body 1's part, the same at every position, and body 2's
    /// flexibility on its track's dofs). `body2_turn` (radians, counter-clockwise) is the
    /// angle by which body 2's mesh has been turned from the one its stiffness was assembled
    /// on: its dofs are components in the frame it was assembled in, so its displacement
    /// along a direction d of the turned body is its displacement along d turned back.
    pub(crate) fn condense(
        problem: &Problem,
        body1: &ElasticBody,
        body2: &ElasticBody,
        known: Option<&KnownFlexibility>,
        body2_turn: f64,
    ) -> Result<CondensedContact, ProblemError> {
        let (c, b1, b2) = spec::contact_section(problem)?;
        let plate = problem.spec.plate.clone();
        spec::check_plate_edge(problem, c)?;
        let edge1 = problem
            .named_edge(&body1.mesh, b1, &c.edge, "contact.edge")?
            .to_vec();
        let edge2 = problem
            .named_edge(&body2.mesh, b2, &c.target_edge, "contact.target_edge")?
            .to_vec();
        // A body of revolution integrates over the whole circle: its contact points' weights
        // become areas (below) and the thickness 1.
        let t = problem.analysis.thickness().unwrap_or(1.0);
        // A press fit's loop once gave its start twice, one copy with twice the pressure and
        // the other none, in silence (red team A).
        if closed_loop(body1, &edge1) {
            return Err(problem.error(
                "contact.edge",
                format!(
                    "edge \"{}\" of body 1 is a closed loop (a shaft or ring all round), but a contact edge needs two ends: its points are ordered from one end to the other, and a loop's start would be two contact points at one place. Name an open part of it (split the loop into two or more named edges: `names` of the blocks), and model the rest with symmetry supports or as a second problem",
                    c.edge
                ),
            ));
        }
        let (mut points, traces1, chain) =
            ContactPoints::on_body1(body1, &edge1).ok_or_else(|| {
                problem.error(
                    "contact.edge",
                    format!(
                        "edge \"{}\" of body 1 is not one connected line of element edges",
                        c.edge
                    ),
                )
            })?;
        let edge2 = match known {
            // Sliding pairs: body 2's edge is long against body 1's (the stroke's length
            // more), and each point's partner search scans it; the part under body 1 (its x
            // range and a tenth of it either side, the track being straight along x) holds
            // every partner. At the 160 positions of a 100 mm stroke over 210 elements the
            // whole edge's search was a third of the set-up.
            Some(_) => {
                let xs = points.x.iter().map(|p| p[0]);
                let (low, high) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                    (a.min(x), b.max(x))
                });
                let margin = 0.1 * (high - low);
                edge2
                    .into_iter()
                    .filter(|&(element, local)| {
                        let ends =
                            [-1.0, 1.0].map(|t| body2.mesh.point_on_edge(element, local, t)[0]);
                        ends[0].max(ends[1]) >= low - margin
                            && ends[0].min(ends[1]) <= high + margin
                    })
                    .collect()
            }
            None => edge2,
        };
        let (traces2, surface_misfits) =
            body2_traces(problem, c, body1, &chain, body2, &edge2, &mut points)?;
        if problem.analysis.is_axisymmetric() && c.friction != 0.0 && c.sliding_motion == "in_plane"
        {
            spec::along_axis_friction(problem, &points.tangent, "contact.friction", "friction")?;
        }
        let axis_points = if problem.analysis.is_axisymmetric() {
            let size = body1
                .mesh
                .vertices
                .iter()
                .fold(0.0f64, |a, v| a.max(v[0].abs()).max(v[1].abs()));
            axisymmetric_areas(&mut points, size)
        } else {
            Vec::new()
        };
        // Loads on the bodies themselves (all tractions but the plate's, which load the plate)
        // and prescribed support displacements move the contact points before any contact
        // force acts: their normal displacements enter the gap, d = u_n⁽²⁾ − u_n⁽¹⁾ + g.
        let plate_edge: Vec<&str> = plate.iter().map(|p| p.edge.as_str()).collect();
        let frame2 = body2_frame(&points, body2_turn);
        let frames = [&points.normal, &frame2.normal];
        for (k, (b, body, traces, sign)) in
            [(b1, body1, &traces1, -1.0), (b2, body2, &traces2, 1.0)]
                .into_iter()
                .enumerate()
        {
            let load = problem.load_vector(b, body, &plate_edge)?;
            if load.iter().any(|f| *f != 0.0) || body.has_prescribed() {
                let u = body
                    .solve(&load)
                    .map_err(|e| problem.error("bodies", e.to_string()))?
                    .boundary;
                for (i, tr) in traces.iter().enumerate() {
                    let n = frames[k][i];
                    let un: f64 = tr
                        .iter()
                        .map(|&(g, coef)| coef * (u[g[0]] * n[0] + u[g[1]] * n[1]))
                        .sum();
                    points.initial_gap[i] += sign * un;
                }
            }
        }
        let resolution =
            resolution::point_resolution(body1, &chain, body2, &edge2, &points.x, &points.normal);
        let size_jumps = resolution::size_jumps(body1, &chain, &points.x);
        // Mortar on meshes left unaligned: a line of body 2 inside one of body 1's elements
        // kinks body 2's trace under a dual basis that cannot follow it (red team F: a ball in
        // a cup, body 2 finer than body 1 but unaligned, dipped 5.8 % of the peak at body 1's
        // vertices, in silence).
        let unmatched_lines = if c.discretisation == "collocation" || !c.aligns_target_mesh() {
            resolution::unmatched_lines(body1, &chain, body2, &edge2)
        } else {
            Vec::new()
        };
        let n = points.x.len();
        let (mut a_nn, mut a_nt) = match known {
            Some(k) => (k.body1[0].clone(), k.body1[1].clone()),
            None => {
                let (mut a_nn, mut a_nt) = (vec![0.0; n * n], vec![0.0; n * n]);
                add_flexibility(problem, body1, &traces1, &points, &mut a_nn, &mut a_nt)?;
                (a_nn, a_nt)
            }
        };
        let from_known =
            known.is_some_and(|k| k.body2.add_to(&traces2, &frame2, &mut a_nn, &mut a_nt));
        if !from_known {
            add_flexibility(problem, body2, &traces2, &frame2, &mut a_nn, &mut a_nt)?;
        }
        let (rigid_modes, rigid_names, plate_load, plate_resultant) = match &plate {
            None => (vec![], vec![], vec![], ([0.0; 2], 0.0)),
            Some(pl) => plate_modes(problem, b1, body1, pl, &points)?,
        };
        let about_axis = c.sliding_motion == "about_axis";
        let contact = CondensedContact {
            points,
            thickness: t,
            axis_points,
            axisymmetric: problem.analysis.is_axisymmetric(),
            friction: if about_axis { 0.0 } else { c.friction },
            friction_about_axis: about_axis.then_some(c.friction),
            a_nn,
            a_nt,
            rigid_modes,
            rigid_names,
            plate_load,
            plate_resultant,
            surface_continues: zone::surface_continues(body1, &chain),
            resolution,
            target_mesh: TargetMesh {
                lines_added: body2.mesh.added_lines,
                elements: body2.mesh.elements.len(),
            },
            unmatched_lines,
            size_jumps,
            traces: [traces1, traces2],
            surface_misfits,
        };
        Ok(contact)
    }

    /// What every position of sliding pairs shares ([`KnownFlexibility`]): body 1's part of
    /// A_nn and A_nt, and body 2's flexibility on the dofs of its contact edge's elements
    /// that reach into x ∈ `reach` (mm, body 2 at rest).
    pub(crate) fn sliding_flexibility(
        problem: &Problem,
        body1: &ElasticBody,
        body2: &ElasticBody,
        reach: [f64; 2],
    ) -> Result<KnownFlexibility, ProblemError> {
        let (c, _, b2) = spec::contact_section(problem)?;
        let edge2 = problem.named_edge(&body2.mesh, b2, &c.target_edge, "contact.target_edge")?;
        let (points, traces1) = Self::body1_points(problem, body1)?;
        let n = points.x.len();
        let (mut a_nn, mut a_nt) = (vec![0.0; n * n], vec![0.0; n * n]);
        add_flexibility(problem, body1, &traces1, &points, &mut a_nn, &mut a_nt)?;
        let mut dofs = Vec::new();
        for &(element, local) in edge2 {
            let ends = [-1.0, 1.0].map(|t| body2.mesh.point_on_edge(element, local, t)[0]);
            if ends[0].max(ends[1]) < reach[0] || ends[0].min(ends[1]) > reach[1] {
                continue;
            }
            let element_dofs = trace_dofs(&body2.dofs, &body2.mesh, &body2.basis, element, local);
            dofs.extend(element_dofs.iter().flat_map(|&(g, _)| g));
        }
        dofs.sort_unstable();
        dofs.dedup();
        Ok(KnownFlexibility {
            body1: [a_nn, a_nt],
            body2: DofFlexibility::new(problem, body2, &dofs)?,
        })
    }

    /// Body 1's contact points and their traces, without body 2 (their partners and initial
    /// gaps are left empty).
    pub(crate) fn body1_points(
        problem: &Problem,
        body1: &ElasticBody,
    ) -> Result<(ContactPoints, Vec<Trace>), ProblemError> {
        let (c, b1, _) = spec::contact_section(problem)?;
        let edge1 = problem.named_edge(&body1.mesh, b1, &c.edge, "contact.edge")?;
        let (points, traces, _) = ContactPoints::on_body1(body1, edge1).ok_or_else(|| {
            problem.error(
                "contact.edge",
                format!(
                    "edge \"{}\" of body 1 is not one connected line of element edges",
                    c.edge
                ),
            )
        })?;
        Ok((points, traces))
    }

    /// Number of contact points N.
    pub fn len(&self) -> usize {
        self.points.x.len()
    }

    /// Contact area w_i t of each point, mm².
    pub fn areas(&self) -> Vec<f64> {
        self.points
            .weight
            .iter()
            .map(|w| w * self.thickness)
            .collect()
    }

    /// A_tt (mm/N, row-major N × N): τ_iᵀ G τ_j of both bodies, the relative tangential
    /// displacement of body 1 against body 2 along τ_i per unit force pair along τ_j (+τ_j on
    /// body 1, −τ_j on body 2); `body1`, `body2` the factorised bodies [`CondensedContact::build`]
    /// returns. Only the stick problem needs it ([`crate::partial_slip`]): made on demand.
    /// The fixed pairs' frame (body 2's traces face the points' own tangents).
    pub fn tangential_flexibility(
        &self,
        problem: &Problem,
        body1: &ElasticBody,
        body2: &ElasticBody,
    ) -> Result<Vec<f64>, ProblemError> {
        let n = self.len();
        let mut a_tt = vec![0.0; n * n];
        for (body, traces) in [(body1, &self.traces[0]), (body2, &self.traces[1])] {
            flexibility::add_tangential_flexibility(
                problem,
                body,
                traces,
                &self.points.tangent,
                &mut a_tt,
            )?;
        }
        Ok(a_tt)
    }

    /// A_s = A_nn − s μ A_nt (mm/N, row-major N × N): gap change per unit contact force in
    /// half-cycle sign s.
    pub fn gap_matrix(&self, s: f64) -> Vec<f64> {
        self.a_nn
            .iter()
            .zip(&self.a_nt)
            .map(|(nn, nt)| nn - s * self.friction * nt)
            .collect()
    }

    /// R (row-major N × m): R(i,k) = −n_i·φ_k(x_i), the gap change per unit rigid motion λ_k.
    pub fn rigid_gap_matrix(&self) -> Vec<f64> {
        let (n, m) = (self.len(), self.rigid_modes.len());
        let mut r = vec![0.0; n * m];
        for i in 0..n {
            for k in 0..m {
                let (phi, normal) = (self.rigid_modes[k][i], self.points.normal[i]);
                r[i * m + k] = -(normal[0] * phi[0] + normal[1] * phi[1]);
            }
        }
        r
    }

    /// E (row-major m × N): E(k,j) = φ_k(x_j)·(−n_j + s μ τ_j), the generalised plate force of a
    /// unit contact force; the plate's equilibrium is E P + L = 0.
    pub fn equilibrium_matrix(&self, s: f64) -> Vec<f64> {
        let (n, m) = (self.len(), self.rigid_modes.len());
        let pts = &self.points;
        let mut e = vec![0.0; m * n];
        for k in 0..m {
            for j in 0..n {
                let phi = self.rigid_modes[k][j];
                let dir = [
                    -pts.normal[j][0] + s * self.friction * pts.tangent[j][0],
                    -pts.normal[j][1] + s * self.friction * pts.tangent[j][1],
                ];
                e[k * n + j] = phi[0] * dir[0] + phi[1] * dir[1];
            }
        }
        e
    }

    /// The ends of the named contact edge that carry pressure where body 1's surface goes on
    /// beyond them: there the contact zone is cut by the model, not found by it. `pressures`
    /// are one or more pressure profiles (MPa, one value per point); an end counts when its
    /// pressure exceeds 1e-6 of the profile's peak (the solvers' round-off is far below).
    pub fn edge_ends_in_contact(&self, pressures: &[&[f64]]) -> Vec<EdgeEnd> {
        zone::ends_in_contact(self, pressures)
    }

    /// The contact zones of `pressures` (MPa, one value per point; a point is in contact above
    /// 1e-6 of the profile's peak) that end inside an element of body 2 coarser than body 1's,
    /// at a corner or with too few of body 2's elements across them: there the pressure can
    /// be off by a few percent of its peak (body 2's discretisation error; [`resolution`]).
    pub fn coarse_partner_zones(&self, pressures: &[&[f64]]) -> Vec<CoarseZone> {
        resolution::coarse_zones(self, pressures)
    }

    /// The fewest points in contact of any of `pressures` (MPa, one value per point), when it
    /// is below [`resolution::MIN_POINTS`]: the mesh does not resolve the contact zone.
    pub fn too_few_points_in_contact(&self, pressures: &[&[f64]]) -> Option<usize> {
        resolution::too_few_points(pressures)
    }

    /// A line of body 2 inside an element of body 1 that is in contact in any of `pressures`
    /// ([x, z], mm), where the pressure oscillates (collocation) or ripples (unaligned mortar).
    pub fn unmatched_line_in_contact(&self, pressures: &[&[f64]]) -> Option<Point> {
        resolution::unmatched_in_contact(&self.unmatched_lines, pressures)
    }

    /// A vertex of body 1's contact edge where the element length jumps by more than
    /// [`resolution::SIZE_JUMP`] and one of the two elements is in contact in any of
    /// `pressures`: a pressure there can dip far below its neighbours.
    pub fn size_jump_in_contact(&self, pressures: &[&[f64]]) -> Option<SizeJump> {
        resolution::size_jump_in_contact(&self.size_jumps, pressures)
    }

    /// Mortar only: the departure of body 2's surface from what the contact points see (the
    /// polynomial through their gaps, [`SurfaceMisfit`]) that matters most under `pressures`
    /// (MPa, one value per point), with `modulus` the contact modulus E* (MPa): a ridge,
    /// groove or step of body 2 narrower than the spacing of body 1's contact points, which
    /// the constraints do not see (see `resolution::misfit_in_contact` for when it matters).
    pub fn surface_misfit_in_contact(
        &self,
        pressures: &[&[f64]],
        modulus: f64,
    ) -> Option<SurfaceMisfit> {
        resolution::misfit_in_contact(
            &self.surface_misfits,
            pressures,
            (&self.points.x, &self.points.initial_gap),
            modulus,
        )
    }

    /// Whether every contact point's tangent runs along the axis (z), as on a pin or a ring
    /// in a bore: the one contact edge of bodies of revolution along which they can slide in
    /// the (r, z) plane.
    pub fn edge_along_axis(&self) -> bool {
        self.points
            .tangent
            .iter()
            .all(|t| t[0].abs() <= crate::material::AXIS_TOLERANCE)
    }

    /// The figures' label of the contact points' coordinate: "z (mm)" on bodies of
    /// revolution whose contact edge runs along the axis ([`CondensedContact::profile`]),
    /// "r (mm)" on other bodies of revolution, "x (mm)" otherwise.
    pub fn position_label(&self) -> &'static str {
        if self.axisymmetric && self.edge_along_axis() {
            "z (mm)"
        } else if self.axisymmetric {
            "r (mm)"
        } else {
            "x (mm)"
        }
    }

    /// The coordinate the contact's profiles are drawn against (mm): x (the radius on bodies
    /// of revolution), or z where the contact edge of bodies of revolution runs along the
    /// axis (a ring in a bore, where every point has the same r).
    pub fn profile(&self) -> Vec<f64> {
        let along_z = self.axisymmetric && self.edge_along_axis();
        let k = usize::from(along_z);
        self.points.x.iter().map(|p| p[k]).collect()
    }

    /// The z of the contact points (mm) where the profiles are drawn against it
    /// ([`CondensedContact::profile`]); None otherwise, where x is the profiles' coordinate.
    pub fn profile_z(&self) -> Option<Vec<f64>> {
        (self.axisymmetric && self.edge_along_axis())
            .then(|| self.points.x.iter().map(|p| p[1]).collect())
    }

    /// Whether there are no contact points.
    pub fn is_empty(&self) -> bool {
        self.points.x.is_empty()
    }
}

/// A body of revolution's contact points carry rings: point i's weight (its share of the
/// edge's length, the Lobatto weight times the edge's Jacobian) becomes the ring's area
/// 2π r_i w_i, mm², which is ∫ L_i 2πr ds exactly for the nodal interpolation of a pressure of
/// degree up to p − 2 (Lobatto quadrature is exact to degree 2p − 1). A point on the axis has
/// no ring: it stands for the disc of radius w_i about the axis, π w_i², so that its force has
/// a pressure (Hertz's ball: within 0.5 % of the centre's, tests/axisymmetric_contact.rs).
fn axisymmetric_areas(points: &mut ContactPoints, size: f64) -> Vec<AxisPoint> {
    let n = points.x.len();
    let mut axis = Vec::new();
    for (i, (w, x)) in points.weight.iter_mut().zip(&points.x).enumerate() {
        if !crate::material::on_axis(x[0], size) {
            *w *= std::f64::consts::TAU * x[0];
            continue;
        }
        *w = std::f64::consts::PI * *w * *w;
        // The three nearest points along the edge, on the side that has them.
        let from: Vec<usize> = if i + 3 < n {
            vec![i + 1, i + 2, i + 3]
        } else if i >= 3 {
            vec![i - 1, i - 2, i - 3]
        } else {
            continue;
        };
        let r: Vec<f64> = from.iter().map(|&k| points.x[k][0]).collect();
        // Lagrange weights of the parabola through (r_k, p_k), evaluated at r = 0.
        let weight = |k: usize| {
            let (a, b) = ((k + 1) % 3, (k + 2) % 3);
            r[a] * r[b] / ((r[k] - r[a]) * (r[k] - r[b]))
        };
        axis.push(AxisPoint {
            point: i,
            from: [
                (from[0], weight(0)),
                (from[1], weight(1)),
                (from[2], weight(2)),
            ],
        });
    }
    axis
}
