//! Whether body 2's mesh resolves the contact zone: a partner coarser than body 1 where a
//! contact zone ends.
//!
//! Body 2's trace is a polynomial on each of its elements. Where a contact zone ends inside
//! one of them (the square-root edge of a Hertz pressure, the slope jump at the end of a
//! worn zone, a punch corner's singularity), that polynomial cannot follow the kink of the
//! deformed surface, and body 1, if finer, answers the partner's smoothed kink with a local
//! ripple of pressure. This is body 2's discretisation error, and no coupling removes it
//! (docs/validation.md, "Mortar contact on independent meshes"): it is a few percent of the
//! peak pressure with two to five partner elements across the zone, and below 1 % when body 2
//! is no coarser than body 1 there, when a line of body 2 lies at the zone's end, or when
//! about eight or more of body 2's elements span the zone.
//!
//! So a zone is reported as under-resolved when, at one of its ends, body 2's element is
//! coarser than body 1's by more than [`COARSER`] and the end lies inside that element
//! (farther from its ends than body 1's point spacing there), and too few of body 2's elements
//! span the zone (∫ ds / h₂ over the zone, a fractional count): fewer than [`RESOLVED_ACROSS`]
//! where the zone ends inside the contact edge, where the pressure falls to zero smoothly,
//! and fewer than [`RESOLVED_ACROSS_CORNER`] where it reaches an end of the edge (a corner:
//! there the pressure stops abruptly or is singular, which is harder to follow). These
//! thresholds are read off the studies of docs/validation.md; `tests/mortar.rs` checks that
//! the cases whose pressure is more than 1 % off are reported and the resolved ones are not.

use super::mortar::{ChainElement, SurfaceMisfit};
use super::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::quadrature::gauss_legendre;

/// Body 2's elements must be coarser than body 1's by more than this ratio to ripple: the
/// studies of docs/validation.md had 1.3 : 1 ripple and 1 : 1 not.
pub const COARSER: f64 = 1.1;

/// A zone that ends smoothly inside the contact edge is resolved when this many elements of
/// body 2 or more span it: in the Hertz studies 4.4 and 4.6 elements rippled by 1.2–2.3 %
/// of the peak, 8.9 and 9.2 by less than 0.9 %, and the pin example's 6.8 by 0.17 %.
pub const RESOLVED_ACROSS: f64 = 6.0;

/// A zone that reaches a corner (an end of the contact edge, where the pressure stops
/// abruptly or is singular) needs more: the flat punch on an even strip was 1.6–2.9 % off
/// with 7.2 elements across, the brake shoe 2.7 % with 6.0; the pin's worn cap 0.48 % with 14.
pub const RESOLVED_ACROSS_CORNER: f64 = 8.0;

/// Fewer points in contact than this do not resolve a contact zone: a pressure profile needs
/// a few points to have a shape (one point carries the whole load as its mean; a review's
/// cylinder pair at p = 1 had three points in contact and its peak 42 % high).
pub const MIN_POINTS: usize = 5;

/// A zone that ends inside one of body 1's elements longer than this fraction of the zone's
/// width is not resolved by body 1. A review's meshes graded towards the zone's centre, whose
/// zone ends fell inside elements 1.8–3 times the zone's width (10.8 and 18 mm against Hertz's
/// 6 mm), were 12–82 % of the peak off, inside the zone too. The limit was one zone width
/// until a red team's Hertz pair (zone 8.3 mm, body 2 fine) with uniform body 1 elements of
/// 0.6–0.97 of the zone came out 4–9.5 % off at the centre, unreported, and not better at
/// higher p. Scanning element length, line position and p = 6–16 on that pair (pointwise error
/// inside 0.8 a): 0.12 and 0.18 of the zone ≤ 1.1 %, 0.24 ≤ 1.3 %, 0.30–0.48 up to 2.3 %,
/// 0.60 up to 4.1 %, 0.73 up to 9.5 %. The limit is a quarter of the zone, the advice the
/// warning gives (tests/mortar.rs checks the report against the error it stands for).
pub const OWN_ELEMENT_FRACTION: f64 = 0.25;

/// The meshes at one contact point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointResolution {
    /// Length of body 1's element(s) holding the point (the longer at a shared node), mm.
    pub element_length: f64,
    /// Length of body 2's element facing the point along its normal, mm (None: no partner).
    pub partner_element_length: Option<f64>,
    /// Distance along body 2's edge from the partner point to the nearer end of its element, mm.
    pub partner_line_distance: f64,
    /// Whether the point is an end of one of body 1's elements.
    pub on_element_end: bool,
    /// max(1, p₁/p₂): body 2's elements count this many times longer in the comparisons, as a
    /// lower degree resolves less per element (Hertz with p₂ = 1 under p₁ = 8: peak 9 % high,
    /// review of 2026-11-24). A higher degree on body 2 is not counted as finer: it does not
    /// follow a pressure corner inside its element (docs/validation.md, Mortar contact).
    pub partner_degree_ratio: f64,
}

/// A contact zone that body 2's mesh does not resolve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoarseZone {
    /// First and last contact point of the zone (indices).
    pub points: [usize; 2],
    /// Their positions [x, z], mm.
    pub from: Point,
    /// See `from`.
    pub to: Point,
    /// Number of body 2's elements across the zone (fractional).
    pub partner_elements_across: f64,
    /// Body 2's element length at the worse end, mm.
    pub partner_element_length: f64,
    /// Body 1's element length there, mm.
    pub element_length: f64,
    /// Which mesh does not resolve the zone: 2 (body 2 coarser than body 1 where the zone
    /// ends) or 1 (body 1's own element at the zone's end is long against the zone).
    pub body: usize,
    /// Body 1's degree over body 2's (1 when body 2's is as high or higher): body 2's element
    /// lengths count this many times longer against body 1's, and its elements across the
    /// zone this many times fewer.
    pub partner_degree_ratio: f64,
}

/// Arc length of an element edge between parameters a and b (8-point Gauss: exact for
/// straight edges, and to far better than the comparison needs on arcs).
fn arc_length(body: &ElasticBody, element: usize, local: usize, a: f64, b: f64) -> f64 {
    // Made once: sliding pairs measure every point at every position of the stroke.
    static RULE: std::sync::OnceLock<crate::quadrature::Rule1d> = std::sync::OnceLock::new();
    let rule = RULE.get_or_init(|| gauss_legendre(8));
    let half = 0.5 * (b - a);
    rule.points
        .iter()
        .zip(&rule.weights)
        .map(|(&r, &w)| {
            let (tangent, _) = body.mesh.edge_frame(element, local, a + half * (r + 1.0));
            w * half * tangent[0].hypot(tangent[1])
        })
        .sum()
}

/// The meshes at every contact point (`x`, `normal` of body 1's points, in order).
pub(super) fn point_resolution(
    body1: &ElasticBody,
    chain: &[ChainElement],
    body2: &ElasticBody,
    edges2: &[(usize, usize)],
    x: &[Point],
    normal: &[Point],
) -> Vec<PointResolution> {
    let p = body1.dofs.p;
    let partner_degree_ratio = (p as f64 / body2.dofs.p as f64).max(1.0);
    let mut element_length = vec![0.0_f64; x.len()];
    for c in chain {
        let h = arc_length(body1, c.element, c.local, -1.0, 1.0);
        for k in 0..=p {
            if let Some(v) = element_length.get_mut(c.first_point + k) {
                *v = v.max(h);
            }
        }
    }
    x.iter()
        .zip(normal)
        .zip(element_length)
        .enumerate()
        .map(|(i, ((&xi, &ni), element_length))| {
            // The chain's points run element by element, p to an element.
            let on_element_end = i % p == 0;
            match super::locate_on_body2(body2, edges2, xi, ni) {
                Some((_, e, l, t)) => {
                    let before = arc_length(body2, e, l, -1.0, t);
                    let after = arc_length(body2, e, l, t, 1.0);
                    PointResolution {
                        element_length,
                        partner_element_length: Some(before + after),
                        partner_line_distance: before.min(after),
                        on_element_end,
                        partner_degree_ratio,
                    }
                }
                None => PointResolution {
                    element_length,
                    partner_element_length: None,
                    partner_line_distance: 0.0,
                    on_element_end,
                    partner_degree_ratio,
                },
            }
        })
        .collect()
}

fn distance(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The zones of `pressures` (points with p > 1e-6 of the profile's peak, in runs) that body
/// 2's mesh does not resolve; each zone once.
pub(super) fn coarse_zones(contact: &CondensedContact, pressures: &[&[f64]]) -> Vec<CoarseZone> {
    let x = &contact.points.x;
    let cells = &contact.resolution;
    let n = x.len().min(cells.len());
    let mut zones: Vec<CoarseZone> = Vec::new();
    for p in pressures {
        let peak = p.iter().cloned().fold(0.0, f64::max);
        let active: Vec<bool> = (0..n)
            .map(|i| p.get(i).is_some_and(|&v| v > 1e-6 * peak))
            .collect();
        let mut i = 0;
        while i < n {
            if !active[i] {
                i += 1;
                continue;
            }
            let start = i;
            while i + 1 < n && active[i + 1] {
                i += 1;
            }
            if let Some(zone) = assess(x, cells, [start, i]) {
                // The two half cycles' zones of one contact differ by a point or so: once.
                let overlaps =
                    |z: &CoarseZone| z.points[0] <= zone.points[1] && zone.points[0] <= z.points[1];
                if !zones.iter().any(overlaps) {
                    zones.push(zone);
                }
            }
            i += 1;
        }
    }
    zones
}

/// The zone `ends` as a [`CoarseZone`] when body 2 does not resolve it.
fn assess(x: &[Point], cells: &[PointResolution], ends: [usize; 2]) -> Option<CoarseZone> {
    let [a, b] = ends;
    let last = x.len() - 1;
    let across: f64 = (a..b)
        .filter_map(|i| {
            let h =
                0.5 * (cells[i].partner_element_length? + cells[i + 1].partner_element_length?);
            Some(distance(x[i], x[i + 1]) / (h * cells[i].partner_degree_ratio))
        })
        .sum();
    // An end is inside a coarse partner element when no line of body 2 lies within body 1's
    // point spacing of it (towards the next point out, or in at the edge's ends). At the
    // edge's ends the pressure stops abruptly (a corner's singularity), and only a partner
    // as fine as body 1 follows it; inside the edge it falls to zero smoothly, and enough
    // partner elements across the zone do.
    let unresolved = |end: usize, outward: Option<usize>, inward: usize| {
        let cell = cells[end];
        let h2 = cell.partner_element_length?;
        let spacing = distance(x[end], x[outward.unwrap_or(inward)]);
        let inside_coarse = h2 * cell.partner_degree_ratio > COARSER * cell.element_length
            && cell.partner_line_distance > spacing;
        let needed = if outward.is_none() {
            RESOLVED_ACROSS_CORNER
        } else {
            RESOLVED_ACROSS
        };
        (inside_coarse && across < needed).then_some((h2, cell.element_length))
    };
    let partner = [
        unresolved(a, a.checked_sub(1), (a + 1).min(last)),
        unresolved(b, (b < last).then_some(b + 1), b.saturating_sub(1)),
    ]
    .into_iter()
    .flatten()
    .max_by(|u, v| (u.0 / u.1).total_cmp(&(v.0 / v.1)));
    // Body 1's own element: an end inside the contact edge that falls inside one element
    // (neither the end nor the next point out is an element end) too long for the zone.
    let width: f64 = (a..b).map(|i| distance(x[i], x[i + 1])).sum();
    let own = |end: usize, outward: Option<usize>| {
        let out = outward?;
        let inside = !cells[end].on_element_end && !cells[out].on_element_end;
        (inside && cells[end].element_length > OWN_ELEMENT_FRACTION * width)
            .then_some(cells[end].element_length)
    };
    let own_worst = [
        own(a, a.checked_sub(1)),
        own(b, (b < last).then_some(b + 1)),
    ]
    .into_iter()
    .flatten()
    .fold(None, |m: Option<f64>, h| Some(m.map_or(h, |m| m.max(h))));
    let (partner_element_length, element_length, body) = match (partner, own_worst) {
        (Some((h2, h1)), _) => (h2, h1, 2),
        (None, Some(h1)) => (cells[a].partner_element_length.unwrap_or(0.0), h1, 1),
        (None, None) => return None,
    };
    Some(CoarseZone {
        points: ends,
        from: x[a],
        to: x[b],
        partner_elements_across: across,
        partner_element_length,
        element_length,
        body,
        partner_degree_ratio: cells[a].partner_degree_ratio,
    })
}

/// The fewest points in contact of any of `pressures` (p > 1e-6 of its peak), when it is
/// positive and below [`MIN_POINTS`].
pub(super) fn too_few_points(pressures: &[&[f64]]) -> Option<usize> {
    pressures
        .iter()
        .map(|p| {
            let peak = p.iter().cloned().fold(0.0, f64::max);
            p.iter().filter(|&&v| v > 1e-6 * peak).count()
        })
        .filter(|&n| n > 0 && n < MIN_POINTS)
        .min()
}

/// Neighbouring contact elements of body 1 whose lengths differ by more than this factor are
/// reported where they are in contact: a review's punch with elements of 18, 0.6 and 11.4 mm
/// (30 : 1) had one point 57 % below its neighbours at p = 4 and 8, on any body 2 mesh, while
/// a 6 : 1 step showed nothing.
pub const SIZE_JUMP: f64 = 10.0;

/// Two neighbouring contact elements of body 1 of very different lengths.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SizeJump {
    /// Their shared vertex [x, z], mm.
    pub x: Point,
    /// The longer element's length over the shorter's.
    pub ratio: f64,
    /// The contact points of the two elements (first, last).
    pub points: [usize; 2],
}

/// The vertices of body 1's contact edge where the element length jumps by more than
/// [`SIZE_JUMP`].
pub(super) fn size_jumps(
    body1: &ElasticBody,
    chain: &[ChainElement],
    x: &[Point],
) -> Vec<SizeJump> {
    let p = body1.dofs.p;
    let lengths: Vec<f64> = chain
        .iter()
        .map(|c| arc_length(body1, c.element, c.local, -1.0, 1.0))
        .collect();
    chain
        .windows(2)
        .zip(lengths.windows(2))
        .filter_map(|(c, h)| {
            let ratio = h[0].max(h[1]) / h[0].min(h[1]);
            let shared = c[0].first_point.max(c[1].first_point);
            let first = c[0].first_point.min(c[1].first_point);
            (ratio > SIZE_JUMP).then(|| SizeJump {
                x: x.get(shared).copied().unwrap_or([f64::NAN; 2]),
                ratio,
                points: [first, shared + p],
            })
        })
        .collect()
}

/// The first of `jumps` in an element that is in contact in any of `pressures`.
pub(super) fn size_jump_in_contact(jumps: &[SizeJump], pressures: &[&[f64]]) -> Option<SizeJump> {
    jumps
        .iter()
        .find(|j| span_in_contact(j.points, pressures))
        .copied()
}

/// Share of the peak contact pressure above which a misfit's own pressure scale (see
/// [`super::CondensedContact::surface_misfit_in_contact`]) is reported.
pub const SURFACE_MISFIT_SHARE: f64 = 0.01;

/// The largest misfit that matters under `pressures` (MPa, the first profile's peak as the
/// scale), with `initial_gap` the points' gaps (mm) and `modulus` the contact modulus E* (MPa).
/// A misfit h over an element of length L presses, or relieves, the surfaces by about E* h / L
/// (a feature narrower than L by more: red team G, a bump 0.2 µm high and 0.1 mm wide put
/// 11 % of the peak beside it, below the elastic approach's 1 % by a factor 200); it matters
/// above [`SURFACE_MISFIT_SHARE`] of the peak, and where the surfaces can meet there: a ridge
/// (rise) on an element in contact, or anywhere its own gap is below the largest gap the
/// deformation closed at a point in contact (a ridge beside the zone that makes contact of
/// its own, red team G: 27 % of the load); a groove (fall) only between two points in contact
/// (one in the open part of an element changes nothing).
pub(super) fn misfit_in_contact(
    misfits: &[SurfaceMisfit],
    pressures: &[&[f64]],
    (points, initial_gap): (&[Point], &[f64]),
    modulus: f64,
) -> Option<SurfaceMisfit> {
    let first = pressures.first()?;
    let peak = first.iter().cloned().fold(0.0, f64::max);
    let touching = |i: usize| {
        pressures
            .iter()
            .any(|p| p.get(i).is_some_and(|&v| v > 1e-6 * peak))
    };
    let closed = (0..initial_gap.len())
        .filter(|&i| touching(i))
        .map(|i| initial_gap[i])
        .fold(f64::NEG_INFINITY, f64::max);
    // Whether `x` lies between points i and i + 1 (its projection on their chord).
    let between = |i: usize, x: Point| {
        let (p, q) = (points[i], points[i + 1]);
        let chord = [q[0] - p[0], q[1] - p[1]];
        let t = ((x[0] - p[0]) * chord[0] + (x[1] - p[1]) * chord[1])
            / (chord[0] * chord[0] + chord[1] * chord[1]);
        (0.0..=1.0).contains(&t)
    };
    misfits
        .iter()
        .filter(|m| modulus * m.misfit.abs() / m.element_length > SURFACE_MISFIT_SHARE * peak)
        .filter(|m| {
            if m.misfit < 0.0 {
                span_in_contact(m.points, pressures) || m.gap <= closed
            } else {
                let [a, b] = m.points;
                (a..b.min(points.len().saturating_sub(1)))
                    .any(|i| between(i, m.x) && touching(i) && touching(i + 1))
            }
        })
        .max_by(|a, b| a.misfit.abs().total_cmp(&b.misfit.abs()))
        .copied()
}

/// Whether any of the points `first..=last` carries pressure (above 1e-6 of the profile's
/// peak, which is round-off of the active-set solve) in any of `pressures`.
fn span_in_contact([first, last]: [usize; 2], pressures: &[&[f64]]) -> bool {
    pressures.iter().any(|p| {
        let peak = p.iter().cloned().fold(0.0, f64::max);
        (first..=last).any(|i| p.get(i).is_some_and(|&v| v > 1e-6 * peak))
    })
}

/// A line of body 2 inside one of body 1's contact elements, for collocation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UnmatchedLine {
    /// Its position on body 1's edge [x, z], mm.
    pub x: Point,
    /// The contact points of body 1's element it falls in (first, last).
    pub points: [usize; 2],
}

/// Collocation only: the lines of body 2 that fall inside one of body 1's contact elements,
/// where one-point partners make the pressure oscillate (docs/validation.md: 4–36 % of the
/// peak on the Hertz meshes); empty when body 2's lines meet body 1's element ends.
pub(super) fn unmatched_lines(
    body1: &ElasticBody,
    chain: &[ChainElement],
    body2: &ElasticBody,
    edges2: &[(usize, usize)],
) -> Vec<UnmatchedLine> {
    let p = body1.dofs.p;
    chain
        .iter()
        .flat_map(|c| {
            let breaks = super::mortar::break_points(body1, c, body2, edges2);
            // Ends of body 2's elements within 1e-6 of body 1's element ends count as matched.
            breaks
                .into_iter()
                .filter(|s| s.abs() < 1.0 - 1e-6)
                .map(move |s| {
                    let t = if c.reversed { -s } else { s };
                    UnmatchedLine {
                        x: body1.mesh.point_on_edge(c.element, c.local, t),
                        points: [c.first_point, c.first_point + p],
                    }
                })
        })
        .collect()
}

/// The first of `lines` inside an element of body 1 that is in contact in any of `pressures`.
pub(super) fn unmatched_in_contact(lines: &[UnmatchedLine], pressures: &[&[f64]]) -> Option<Point> {
    lines
        .iter()
        .find(|l| span_in_contact(l.points, pressures))
        .map(|l| l.x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points every `h1 / 8` mm from 0 to `length`, body 1's elements `h1` long, body 2's
    /// `h2` long with lines at multiples of `h2` shifted by `shift`.
    fn line(length: f64, h1: f64, h2: f64, shift: f64) -> (Vec<Point>, Vec<PointResolution>) {
        let n = (8.0 * length / h1).round() as usize + 1;
        let x: Vec<Point> = (0..n).map(|i| [i as f64 * h1 / 8.0, 0.0]).collect();
        let cells = x
            .iter()
            .map(|p| {
                let offset = (p[0] - shift).rem_euclid(h2);
                let own = p[0].rem_euclid(h1);
                PointResolution {
                    element_length: h1,
                    partner_element_length: Some(h2),
                    partner_line_distance: offset.min(h2 - offset),
                    on_element_end: own.min(h1 - own) < 1e-9,
                    partner_degree_ratio: 1.0,
                }
            })
            .collect();
        (x, cells)
    }

    #[test]
    fn a_zone_inside_the_edge_needs_six_partner_elements_a_corner_eight() {
        // Edge 0 … 40 mm, body 1 in 1 mm elements, body 2 in 2 mm ones (coarser) with lines
        // at odd millimetres: zone ends at whole millimetres are inside partner elements.
        let (x, cells) = line(40.0, 1.0, 2.0, 1.0);
        let at = |mm: f64| x.iter().position(|p| (p[0] - mm).abs() < 1e-9).unwrap();
        // Inside the edge, 10 mm wide: 5 partner elements across (< 6): reported.
        let zone = assess(&x, &cells, [at(10.0), at(20.0)]).expect("reported");
        assert!((zone.partner_elements_across - 5.0).abs() < 1e-9);
        assert_eq!(
            (zone.partner_element_length, zone.element_length),
            (2.0, 1.0)
        );
        // 14 mm wide: 7 across, enough inside the edge...
        assert!(assess(&x, &cells, [at(10.0), at(24.0)]).is_none());
        // ...not at a corner (the edge's first point), which needs 8.
        assert!(assess(&x, &cells, [0, at(14.0)]).is_some());
        assert!(assess(&x, &cells, [0, at(18.0)]).is_none());
        // Ends on partner lines (odd millimetres) are resolved whatever the width.
        assert!(assess(&x, &cells, [at(11.0), at(15.0)]).is_none());
        // A partner no coarser than body 1 is never reported.
        let (x, cells) = line(40.0, 1.0, 1.05, 0.5);
        assert!(assess(&x, &cells, [at(10.0), at(13.0)]).is_none());
    }

    #[test]
    fn fewer_than_five_points_in_contact_do_not_resolve_a_zone() {
        assert_eq!(too_few_points(&[&[0.0, 3.0, 0.0, 0.0]]), Some(1));
        assert_eq!(too_few_points(&[&[0.0, 3.0, 2.0, 1.0, 0.0]]), Some(3));
        assert_eq!(too_few_points(&[&[1.0, 3.0, 2.0, 1.0, 0.5, 0.0]]), None);
        // No contact at all is not "too few points" (nothing to resolve).
        assert_eq!(too_few_points(&[&[0.0; 4]]), None);
    }
}
