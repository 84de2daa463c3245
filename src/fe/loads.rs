//! Edge tractions: consistent load vectors, resultants and the edge traces of the shape
//! functions (which the contact stage uses as well).

use crate::basis::shape_1d;
use crate::dofs::DofMap;
use crate::geometry::{bisect, Point};
use crate::material::Analysis;
use crate::mesh::Mesh;
use crate::quadrature::gauss_legendre;

/// Part of an edge selected by a coordinate range: `axis` 0 = x, 1 = z; `range` in mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// 0 for x, 1 for z.
    pub axis: usize,
    /// Lower and upper coordinate, mm.
    pub range: [f64; 2],
}

/// A distributed load on a named edge.
///
/// The traction vector is T = −p n + s τ, with n the outward unit normal and τ the
/// counter-clockwise unit tangent of the body's boundary (τ = n turned by +90°).
/// With a window, p and s vary linearly in the window coordinate from the first to the second
/// value and vanish outside it; without one they are the first value everywhere.
#[derive(Clone, Debug, PartialEq)]
pub struct Traction {
    /// Name of the loaded edge.
    pub edge: String,
    /// Normal pressure p at the window's lower and upper bound, MPa (positive pushes inwards).
    pub normal: [f64; 2],
    /// Shear s at the window's lower and upper bound, MPa.
    pub shear: [f64; 2],
    /// Optional coordinate window.
    pub window: Option<Window>,
}

/// Edge-trace dofs of one element edge: for each of the p + 1 trace functions (start vertex,
/// end vertex, degrees 2..=p, the order of [`shape_1d`]) the global x and z dofs and the sign.
pub fn trace_dofs(
    dofs: &DofMap,
    mesh: &Mesh,
    basis: &crate::basis::QuadBasis,
    element: usize,
    local: usize,
) -> Vec<([usize; 2], f64)> {
    let ed = dofs.element_dofs(mesh, element);
    basis
        .edge_trace(local)
        .into_iter()
        .map(|m| ([ed.global[2 * m], ed.global[2 * m + 1]], ed.sign[2 * m]))
        .collect()
}

/// Gauss points on the part of local edge `local` inside `window`: (t, ds) with t the edge
/// parameter and ds the arc-length weight (mm). `n` points on each piece of the edge inside
/// the window (a curved edge may enter and leave it more than once).
pub fn edge_quadrature(
    mesh: &Mesh,
    element: usize,
    local: usize,
    window: Option<Window>,
    n: usize,
) -> Vec<(f64, f64)> {
    let pieces = match window {
        None => vec![(-1.0, 1.0)],
        Some(w) => window_intervals(mesh, element, local, w),
    };
    let rule = gauss_legendre(n);
    let mut points = Vec::with_capacity(n * pieces.len());
    for (t0, t1) in pieces {
        let half = 0.5 * (t1 - t0);
        for (&r, &w) in rule.points.iter().zip(&rule.weights) {
            let t = t0 + half * (r + 1.0);
            let (tangent, _) = mesh.edge_frame(element, local, t);
            points.push((t, w * half * tangent[0].hypot(tangent[1])));
        }
    }
    points
}

/// Samples of the edge parameter searched for turning points of the window coordinate: an arc
/// turns its tangent by at most 2π, so two turning points (π apart in angle) never fall
/// between neighbouring samples of 64.
const TURNING_SAMPLES: usize = 64;

/// The sub-intervals of t in [-1, 1] where the window coordinate lies in its range. The
/// coordinate is monotone between its turning points (where the edge's tangent is
/// perpendicular to the window's axis: the apex of a crown under a z window), so the edge is
/// cut there and each monotone piece gives at most one interval. Reading the coordinate at
/// the element's ends only put an apex element's whole length in or out of a window (red
/// team 13: +188 % of a windowed load on a crowned plate edge, or a window refused as acting
/// nowhere).
fn window_intervals(mesh: &Mesh, element: usize, local: usize, w: Window) -> Vec<(f64, f64)> {
    let coord = |t: f64| mesh.point_on_edge(element, local, t)[w.axis];
    let slope = |t: f64| mesh.edge_frame(element, local, t).0[w.axis];
    let mut cuts = vec![-1.0];
    let sample = |k: usize| -1.0 + 2.0 * k as f64 / TURNING_SAMPLES as f64;
    for k in 0..TURNING_SAMPLES {
        // A turning point exactly on a sample (the apex of an arc at an element's centre, for
        // an odd number of equal elements) is a cut of its own: neither neighbouring interval
        // sees a strict change of sign there (red team 14: +125 % of an x window's load).
        if k > 0 && slope(sample(k)) == 0.0 {
            cuts.push(sample(k));
        }
        let (lo, hi) = (sample(k), sample(k + 1));
        if let Some(t) = sign_change(slope, lo, hi) {
            cuts.push(t);
        }
    }
    cuts.push(1.0);
    cuts.windows(2)
        .filter_map(|piece| monotone_interval(coord, piece[0], piece[1], w.range))
        .collect()
}

/// Where `f` changes sign strictly inside (lo, hi), found by bisection; None if it does not.
fn sign_change(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> Option<f64> {
    let (f_lo, f_hi) = (f(lo), f(hi));
    let scale = f_lo.abs().max(f_hi.abs());
    if scale == 0.0 || f_lo * f_hi >= 0.0 {
        return None;
    }
    Some(bisect(f, lo, hi, 60))
}

/// The sub-interval of [t0, t1], on which `coord` is monotone, where it lies in `range`.
fn monotone_interval(
    coord: impl Fn(f64) -> f64,
    t0: f64,
    t1: f64,
    range: [f64; 2],
) -> Option<(f64, f64)> {
    let (a, b) = (range[0], range[1]);
    let inside = |c: f64| c >= a - 1e-12 * (1.0 + a.abs()) && c <= b + 1e-12 * (1.0 + b.abs());
    let (c0, c1) = (coord(t0), coord(t1));
    if (c1 - c0).abs() <= 1e-12 * (1.0 + c0.abs()) {
        return (inside(c0) && t1 > t0).then_some((t0, t1));
    }
    let increasing = c1 > c0;
    // Only called for a target strictly between the piece's end values.
    let crossing = |target: f64| bisect(|t| coord(t) - target, t0, t1, 60);
    let (cmin, cmax) = (c0.min(c1), c0.max(c1));
    if cmax <= a || cmin >= b {
        return None;
    }
    let ta = if cmin < a {
        crossing(a)
    } else if increasing {
        t0
    } else {
        t1
    };
    let tb = if cmax > b {
        crossing(b)
    } else if increasing {
        t1
    } else {
        t0
    };
    let (lo, hi) = (ta.min(tb), ta.max(tb));
    (hi > lo).then_some((lo, hi))
}

impl Traction {
    /// Traction vector T (MPa) at point `x` with outward unit normal `normal`.
    pub fn vector(&self, x: Point, normal: Point) -> Point {
        let s = match self.window {
            Some(w) if w.range[1] > w.range[0] => {
                ((x[w.axis] - w.range[0]) / (w.range[1] - w.range[0])).clamp(0.0, 1.0)
            }
            _ => 0.0,
        };
        let p = self.normal[0] + s * (self.normal[1] - self.normal[0]);
        let q = self.shear[0] + s * (self.shear[1] - self.shear[0]);
        let tangent = [-normal[1], normal[0]];
        [
            -p * normal[0] + q * tangent[0],
            -p * normal[1] + q * tangent[1],
        ]
    }

    /// Visit every quadrature point of this traction: (element, local edge, t, x, T, dS times
    /// the analysis' weight at x: the thickness, or 2πr).
    pub fn for_each_point(
        &self,
        mesh: &Mesh,
        edges: &[(usize, usize)],
        p: usize,
        analysis: Analysis,
        mut visit: impl FnMut(usize, usize, f64, Point, Point, f64),
    ) {
        for &(element, local) in edges {
            for (t, ds) in edge_quadrature(mesh, element, local, self.window, p + 4) {
                let x = mesh.point_on_edge(element, local, t);
                let (_, normal) = mesh.edge_frame(element, local, t);
                visit(
                    element,
                    local,
                    t,
                    x,
                    self.vector(x, normal),
                    ds * analysis.weight(x),
                );
            }
        }
    }

    /// Resultant force (N) and its moment about `pivot` (N·mm, about +y: M = Δz F_x − Δx F_z).
    pub fn resultant(
        &self,
        mesh: &Mesh,
        edges: &[(usize, usize)],
        p: usize,
        analysis: Analysis,
        pivot: Point,
    ) -> (Point, f64) {
        let mut force = [0.0; 2];
        let mut moment = 0.0;
        self.for_each_point(mesh, edges, p, analysis, |_, _, _, x, t, w| {
            force[0] += t[0] * w;
            force[1] += t[1] * w;
            moment += ((x[1] - pivot[1]) * t[0] - (x[0] - pivot[0]) * t[1]) * w;
        });
        (force, moment)
    }

    /// Add the consistent nodal forces of this traction to `load` (N per global dof).
    pub fn add_to_load(
        &self,
        mesh: &Mesh,
        edges: &[(usize, usize)],
        dofs: &DofMap,
        basis: &crate::basis::QuadBasis,
        analysis: Analysis,
        load: &mut [f64],
    ) {
        let p = dofs.p;
        let mut values = vec![0.0; p + 1];
        let mut derivatives = vec![0.0; p + 1];
        type EdgeTrace = (usize, usize, Vec<([usize; 2], f64)>);
        let mut last: Option<EdgeTrace> = None;
        self.for_each_point(
            mesh,
            edges,
            p,
            analysis,
            |element, local, t, _, traction, w| {
                if last.as_ref().map(|l| (l.0, l.1)) != Some((element, local)) {
                    last = Some((
                        element,
                        local,
                        trace_dofs(dofs, mesh, basis, element, local),
                    ));
                }
                let trace = &last.as_ref().unwrap().2;
                shape_1d(p, t, &mut values, &mut derivatives);
                for (k, (g, sign)) in trace.iter().enumerate() {
                    for c in 0..2 {
                        load[g[c]] += sign * values[k] * traction[c] * w;
                    }
                }
            },
        );
    }
}
