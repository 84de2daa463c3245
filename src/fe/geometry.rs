//! Exact 2D geometry in the x–z plane: blocks bounded by straight segments and circular arcs,
//! mapped from the unit square by the Gordon–Hall transfinite (blending-function) map, so
//! that curved boundaries are represented exactly. Lengths in mm, angles in radians.

use std::f64::consts::PI;

/// A point [x, z], mm.
pub type Point = [f64; 2];

/// Errors in a block's geometry.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum GeometryError {
    /// The corners run clockwise (or are collinear).
    #[error("block corners are not counter-clockwise (signed area {area} mm²)")]
    Clockwise {
        /// Signed polygon area of the four corners, mm².
        area: f64,
    },
    /// The two ends of an arc are not equally far from its centre.
    #[error(
        "arc on edge {edge}: corners are at distances {r_start} and {r_end} mm from the centre"
    )]
    ArcRadiusMismatch {
        /// Edge index 0..4.
        edge: usize,
        /// Distance of the start corner from the centre, mm.
        r_start: f64,
        /// Distance of the end corner from the centre, mm.
        r_end: f64,
    },
    /// An arc of zero (or non-finite) radius.
    #[error("arc on edge {edge} is degenerate (radius {radius} mm)")]
    DegenerateArc {
        /// Edge index 0..4.
        edge: usize,
        /// Radius, mm.
        radius: f64,
    },
    /// The arc's ends are diametrically opposite, so "the minor arc" does not say which way
    /// round it goes.
    #[error("arc on edge {edge} sweeps half a circle ({sweep} rad), so its side is ambiguous")]
    AmbiguousArc {
        /// Edge index 0..4.
        edge: usize,
        /// Sweep angle found, radians.
        sweep: f64,
    },
    /// The block map folds over.
    #[error("block map is not invertible: Jacobian determinant {det} at (u, v) = ({u}, {v})")]
    FoldedMap {
        /// Jacobian determinant, mm².
        det: f64,
        /// Parameter u where it was found.
        u: f64,
        /// Parameter v where it was found.
        v: f64,
    },
}

/// A boundary curve parametrised by t ∈ [0, 1] from `start()` to `end()`.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    /// Straight segment, traversed at constant speed.
    Line {
        /// First point, mm.
        start: Point,
        /// Last point, mm.
        end: Point,
    },
    /// Arc of a circle about `center`, radius `radius`, angle going linearly from
    /// `start_angle` to `end_angle` (radians; end < start means clockwise).
    Arc {
        /// Centre, mm.
        center: Point,
        /// Radius, mm.
        radius: f64,
        /// Polar angle of the first point about `center`, radians.
        start_angle: f64,
        /// Polar angle of the last point about `center`, radians.
        end_angle: f64,
    },
    /// Parabola through `start` (t = 0), `middle` (t = ½) and `end` (t = 1): the edge of a
    /// second-order element read from a mesh file, an approximation of the true boundary.
    Quadratic {
        /// First point, mm.
        start: Point,
        /// Point at t = ½, mm.
        middle: Point,
        /// Last point, mm.
        end: Point,
    },
}

impl Curve {
    /// Point at parameter t ∈ [0, 1], mm (any real t is accepted: the curve is extended
    /// smoothly, which the block map's Newton inverse relies on).
    pub fn point(&self, t: f64) -> Point {
        match *self {
            Curve::Line { start, end } => [
                start[0] + t * (end[0] - start[0]),
                start[1] + t * (end[1] - start[1]),
            ],
            Curve::Arc {
                center,
                radius,
                start_angle,
                end_angle,
            } => {
                let a = start_angle + t * (end_angle - start_angle);
                [center[0] + radius * a.cos(), center[1] + radius * a.sin()]
            }
            Curve::Quadratic { start, middle, end } => {
                // Lagrange basis on t = 0, ½, 1.
                let (l0, l1, l2) = (
                    (1.0 - t) * (1.0 - 2.0 * t),
                    4.0 * t * (1.0 - t),
                    t * (2.0 * t - 1.0),
                );
                std::array::from_fn(|d| l0 * start[d] + l1 * middle[d] + l2 * end[d])
            }
        }
    }

    /// Derivative d point / dt, mm.
    pub fn derivative(&self, t: f64) -> Point {
        match *self {
            Curve::Line { start, end } => [end[0] - start[0], end[1] - start[1]],
            Curve::Arc {
                radius,
                start_angle,
                end_angle,
                ..
            } => {
                let sweep = end_angle - start_angle;
                let a = start_angle + t * sweep;
                [-radius * sweep * a.sin(), radius * sweep * a.cos()]
            }
            Curve::Quadratic { start, middle, end } => {
                let (d0, d1, d2) = (4.0 * t - 3.0, 4.0 - 8.0 * t, 4.0 * t - 1.0);
                std::array::from_fn(|d| d0 * start[d] + d1 * middle[d] + d2 * end[d])
            }
        }
    }

    /// First point (t = 0), mm.
    pub fn start(&self) -> Point {
        self.point(0.0)
    }

    /// Last point (t = 1), mm.
    pub fn end(&self) -> Point {
        self.point(1.0)
    }

    /// The same curve traversed backwards.
    pub fn reversed(&self) -> Curve {
        let mut c = self.clone();
        match &mut c {
            Curve::Line { start, end } => std::mem::swap(start, end),
            Curve::Arc {
                start_angle,
                end_angle,
                ..
            } => std::mem::swap(start_angle, end_angle),
            Curve::Quadratic { start, end, .. } => std::mem::swap(start, end),
        }
        c
    }

    /// Length, mm.
    pub fn length(&self) -> f64 {
        match self {
            // Traversed at constant speed: the length is |d point / dt|.
            Curve::Line { .. } | Curve::Arc { .. } => {
                let d = self.derivative(0.0);
                d[0].hypot(d[1])
            }
            // |d point / dt| is the square root of a quadratic in t: 12 Gauss points leave
            // an error far below round-off for any edge that is not folded back on itself.
            Curve::Quadratic { .. } => {
                let rule = crate::quadrature::gauss_legendre(12);
                rule.points
                    .iter()
                    .zip(&rule.weights)
                    .map(|(&x, &w)| {
                        let d = self.derivative(0.5 * (x + 1.0));
                        0.5 * w * d[0].hypot(d[1])
                    })
                    .sum()
            }
        }
    }

    /// Minor arc (|sweep| < π) from `start` to `end` about `center` (all mm); `edge` only
    /// labels errors. Errors if the two radii differ by more than 1e-9 relative, if the
    /// radius is zero or not finite, or if the ends are diametrically opposite.
    pub fn arc_through(
        start: Point,
        end: Point,
        center: Point,
        edge: usize,
    ) -> Result<Curve, GeometryError> {
        let r_start = (start[0] - center[0]).hypot(start[1] - center[1]);
        let r_end = (end[0] - center[0]).hypot(end[1] - center[1]);
        // Checking both radii for finiteness first keeps a NaN from slipping through the
        // mismatch comparison below (NaN compares false).
        if !(r_start.is_finite() && r_end.is_finite()) || r_start <= 0.0 || r_end <= 0.0 {
            return Err(GeometryError::DegenerateArc {
                edge,
                radius: r_start.min(r_end),
            });
        }
        if (r_start - r_end).abs() > 1e-9 * r_start.max(r_end) {
            return Err(GeometryError::ArcRadiusMismatch {
                edge,
                r_start,
                r_end,
            });
        }
        let a0 = (start[1] - center[1]).atan2(start[0] - center[0]);
        let a1 = (end[1] - center[1]).atan2(end[0] - center[0]);
        // atan2 differences lie in (−2π, 2π); one wrap brings the sweep into [−π, π].
        let mut sweep = a1 - a0;
        if sweep > PI {
            sweep -= 2.0 * PI;
        } else if sweep < -PI {
            sweep += 2.0 * PI;
        }
        // Within ~1e-9 rad of a half circle the side is decided by round-off in the corners.
        if PI - sweep.abs() < 1e-9 {
            return Err(GeometryError::AmbiguousArc { edge, sweep });
        }
        Ok(Curve::Arc {
            center,
            radius: 0.5 * (r_start + r_end),
            start_angle: a0,
            end_angle: a0 + sweep,
        })
    }
}

/// Description of one block edge as given by a user: straight, or an arc about a centre.
#[derive(Clone, Debug, PartialEq)]
pub enum EdgeShape {
    /// Straight segment between the corners.
    Straight,
    /// Minor circular arc about the given centre [x, z], mm.
    ArcAbout(Point),
    /// Parabola through the given point [x, z] (mm) at the edge's parameter ½ (a
    /// second-order element's mid-edge node).
    Through(Point),
}

/// A curvilinear quadrilateral with corners c0..c3 counter-clockwise.
///
/// Edges in the natural counter-clockwise order: edge 0: c0→c1, edge 1: c1→c2, edge 2: c2→c3,
/// edge 3: c3→c0. Parameter square (u, v) ∈ \[0, 1\]²: c0 = (0,0), c1 = (1,0), c2 = (1,1),
/// c3 = (0,1); so edge 0 is v = 0, edge 1 is u = 1, edge 2 is v = 1, edge 3 is u = 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// Corners [x, z], mm, counter-clockwise.
    pub corners: [Point; 4],
    /// Edge curves in the counter-clockwise direction.
    pub edges: [Curve; 4],
}

impl Block {
    /// Builds and validates a block from corners (mm) and edge shapes. Checks: corners
    /// counter-clockwise (signed polygon area > 0), arcs consistent, and the map's Jacobian
    /// determinant > 0 on a 9 × 9 grid of (u, v), boundary included.
    pub fn new(corners: [Point; 4], shapes: [EdgeShape; 4]) -> Result<Block, GeometryError> {
        // For a quadrilateral the shoelace sum collapses to half the diagonals' cross product.
        let [c0, c1, c2, c3] = corners;
        let area = 0.5 * ((c2[0] - c0[0]) * (c3[1] - c1[1]) - (c2[1] - c0[1]) * (c3[0] - c1[0]));
        if area.is_nan() || area <= 0.0 {
            return Err(GeometryError::Clockwise { area });
        }
        let mut edges: [Curve; 4] = std::array::from_fn(|e| Curve::Line {
            start: corners[e],
            end: corners[(e + 1) % 4],
        });
        for (e, shape) in shapes.iter().enumerate() {
            match *shape {
                EdgeShape::Straight => {}
                EdgeShape::ArcAbout(c) => {
                    edges[e] = Curve::arc_through(corners[e], corners[(e + 1) % 4], c, e)?;
                }
                EdgeShape::Through(middle) => {
                    edges[e] = Curve::Quadratic {
                        start: corners[e],
                        middle,
                        end: corners[(e + 1) % 4],
                    };
                }
            }
        }
        let block = Block { corners, edges };
        // A sampled check cannot prove injectivity, but it catches the practical failures
        // (arcs bulging through the opposite edge, re-entrant corners) before meshing.
        for i in 0..9 {
            for j in 0..9 {
                let (u, v) = (i as f64 / 8.0, j as f64 / 8.0);
                let det = det2(&block.jacobian(u, v));
                if det.is_nan() || det <= 0.0 {
                    return Err(GeometryError::FoldedMap { det, u, v });
                }
            }
        }
        Ok(block)
    }

    /// The curve of edge e (0..4) in the counter-clockwise direction.
    pub fn edge(&self, e: usize) -> &Curve {
        &self.edges[e]
    }

    /// Gordon–Hall map, mm: x(u, v) = (1−v) B(u) + v T(u) + (1−u) L(v) + u R(v) − bilinear
    /// corner term, with B = edge 0 (t = u), R = edge 1 (t = v), T = edge 2 (t = 1−u),
    /// L = edge 3 (t = 1−v).
    pub fn map(&self, u: f64, v: f64) -> Point {
        let c = &self.corners;
        let bottom = self.edges[0].point(u);
        let right = self.edges[1].point(v);
        let top = self.edges[2].point(1.0 - u);
        let left = self.edges[3].point(1.0 - v);
        std::array::from_fn(|d| {
            (1.0 - v) * bottom[d] + v * top[d] + (1.0 - u) * left[d] + u * right[d]
                - ((1.0 - u) * (1.0 - v) * c[0][d]
                    + u * (1.0 - v) * c[1][d]
                    + u * v * c[2][d]
                    + (1.0 - u) * v * c[3][d])
        })
    }

    /// Jacobian [[∂x/∂u, ∂x/∂v], [∂z/∂u, ∂z/∂v]], mm.
    pub fn jacobian(&self, u: f64, v: f64) -> [[f64; 2]; 2] {
        let c = &self.corners;
        let e = &self.edges;
        let (bottom, db) = (e[0].point(u), e[0].derivative(u));
        let (right, dr) = (e[1].point(v), e[1].derivative(v));
        let (top, dt) = (e[2].point(1.0 - u), e[2].derivative(1.0 - u));
        let (left, dl) = (e[3].point(1.0 - v), e[3].derivative(1.0 - v));
        // T and L are evaluated at reversed parameters, hence the chain-rule minus signs.
        std::array::from_fn(|d| {
            [
                (1.0 - v) * db[d] - v * dt[d] - left[d] + right[d]
                    - (-(1.0 - v) * c[0][d] + (1.0 - v) * c[1][d] + v * c[2][d] - v * c[3][d]),
                -bottom[d] + top[d] - (1.0 - u) * dl[d] + u * dr[d]
                    - (-(1.0 - u) * c[0][d] - u * c[1][d] + u * c[2][d] + (1.0 - u) * c[3][d]),
            ]
        })
    }

    /// Inverse map of a point `x` (mm) by damped Newton iteration from the centre and a few
    /// other starts: `Some((u, v))` once the Newton step is below 1e-10 in u and v and the
    /// solution lies in [−1e-9, 1 + 1e-9]² (returned clamped to [0, 1]²), else `None`.
    pub fn inverse(&self, x: Point) -> Option<(f64, f64)> {
        const STARTS: [(f64, f64); 5] =
            [(0.5, 0.5), (0.2, 0.2), (0.8, 0.2), (0.8, 0.8), (0.2, 0.8)];
        let residual = |u: f64, v: f64| {
            let y = self.map(u, v);
            [x[0] - y[0], x[1] - y[1]]
        };
        let norm = |r: [f64; 2]| r[0].hypot(r[1]);
        for &(u0, v0) in &STARTS {
            let (mut u, mut v) = (u0, v0);
            let mut r = residual(u, v);
            for _ in 0..50 {
                let j = self.jacobian(u, v);
                let det = det2(&j);
                if det == 0.0 || !det.is_finite() {
                    break;
                }
                let mut du = (j[1][1] * r[0] - j[0][1] * r[1]) / det;
                let mut dv = (-j[1][0] * r[0] + j[0][0] * r[1]) / det;
                if du.abs().max(dv.abs()) < 1e-10 {
                    // Quadratic convergence makes this last step land to round-off.
                    let (uf, vf) = (u + du, v + dv);
                    let inside = |s: f64| (-1e-9..=1.0 + 1e-9).contains(&s);
                    if inside(uf) && inside(vf) {
                        return Some((uf.clamp(0.0, 1.0), vf.clamp(0.0, 1.0)));
                    }
                    break;
                }
                // Trust region: far from the square the extended arc map wraps around and
                // Newton would chase spurious preimages.
                let big = du.abs().max(dv.abs());
                if big > 0.5 {
                    du *= 0.5 / big;
                    dv *= 0.5 / big;
                }
                // Backtracking on the residual norm keeps curved-block iterations from cycling.
                let mut lambda = 1.0;
                let mut accepted = false;
                while lambda > 1e-3 {
                    let (ut, vt) = (u + lambda * du, v + lambda * dv);
                    let rt = residual(ut, vt);
                    if norm(rt) < norm(r) {
                        (u, v, r) = (ut, vt, rt);
                        accepted = true;
                        break;
                    }
                    lambda *= 0.5;
                }
                if !accepted {
                    break;
                }
            }
        }
        None
    }
}

/// The point in [lo, hi] where `f` changes sign (it must differ in sign at the two ends), by
/// `iterations` bisections: 60 reach the round-off of an edge parameter in [−1, 1]. Used to
/// find where an edge crosses a line or a coordinate, where bisection cannot leave the edge.
pub fn bisect(f: impl Fn(f64) -> f64, lo: f64, hi: f64, iterations: usize) -> f64 {
    let negative_at_lo = f(lo) < 0.0;
    let (mut a, mut b) = (lo, hi);
    for _ in 0..iterations {
        let mid = 0.5 * (a + b);
        if (f(mid) < 0.0) == negative_at_lo {
            a = mid;
        } else {
            b = mid;
        }
    }
    0.5 * (a + b)
}

fn det2(j: &[[f64; 2]; 2]) -> f64 {
    j[0][0] * j[1][1] - j[0][1] * j[1][0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use EdgeShape::{ArcAbout, Straight, Through};

    #[test]
    fn a_quadratic_edge_passes_through_its_three_points_and_has_its_length() {
        // The parabola z = x² on [0, 1] through (0, 0), (½, ¼), (1, 1): its length is
        // (2√5 + asinh 2)/4 (integral of √(1 + 4x²)).
        let curve = Curve::Quadratic {
            start: [0.0, 0.0],
            middle: [0.5, 0.25],
            end: [1.0, 1.0],
        };
        for t in [0.0, 0.3, 0.5, 1.0] {
            let p = curve.point(t);
            assert!((p[1] - p[0] * p[0]).abs() < 1e-15, "{p:?}");
        }
        let exact = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
        assert!((curve.length() - exact).abs() < 1e-12, "{}", curve.length());
        assert!((curve.reversed().point(0.3)[0] - curve.point(0.7)[0]).abs() < 1e-15);
        // A block with a bulging quadratic edge maps its mid-edge to the given node.
        let block = Block::new(
            [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            [Through([0.5, -0.1]), Straight, Straight, Straight],
        )
        .unwrap();
        assert_eq!(block.map(0.5, 0.0), [0.5, -0.1]);
    }

    fn quarter_ring() -> Block {
        let o = [0.0, 0.0];
        let c = [[100.0, 0.0], [200.0, 0.0], [0.0, 200.0], [0.0, 100.0]];
        Block::new(c, [Straight, ArcAbout(o), Straight, ArcAbout(o)]).unwrap()
    }

    const SKEW: [Point; 4] = [[0.0, 0.0], [5.0, 0.3], [5.7, 4.4], [-0.4, 5.0]];

    fn skew_block() -> Block {
        Block::new(SKEW, [Straight, Straight, Straight, Straight]).unwrap()
    }

    /// Deterministic pseudo-random points in [0, 1]² (64-bit LCG, top 53 bits).
    fn samples(n: usize) -> Vec<(f64, f64)> {
        let mut s: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = || {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n).map(|_| (next(), next())).collect()
    }

    fn dist(a: Point, b: Point) -> f64 {
        (a[0] - b[0]).hypot(a[1] - b[1])
    }

    #[test]
    fn straight_block_map_is_bilinear() {
        let b = skew_block();
        for (u, v) in samples(50) {
            let x = b.map(u, v);
            for (d, &xd) in x.iter().enumerate() {
                let bl = (1.0 - u) * (1.0 - v) * SKEW[0][d]
                    + u * (1.0 - v) * SKEW[1][d]
                    + u * v * SKEW[2][d]
                    + (1.0 - u) * v * SKEW[3][d];
                // Same polynomial summed differently: a few ulps of ~5 mm coordinates.
                assert!((xd - bl).abs() < 1e-13, "{xd} vs {bl}");
            }
        }
    }

    #[test]
    fn map_hits_corners_and_reproduces_edges() {
        for b in [skew_block(), quarter_ring()] {
            // Relative 1e-12 of the block size (200 mm) is ~100 ulps: the arc's cos/sin
            // reproduce the corners only to round-off, not bit for bit.
            let tol = 1e-12 * 200.0;
            let uv = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
            for (k, (u, v)) in uv.into_iter().enumerate() {
                assert!(dist(b.map(u, v), b.corners[k]) < tol);
            }
            for t in (0..=20).map(|i| i as f64 / 20.0) {
                let uv = [(t, 0.0), (1.0, t), (1.0 - t, 1.0), (0.0, 1.0 - t)];
                for (e, (u, v)) in uv.into_iter().enumerate() {
                    let m = b.map(u, v);
                    assert!(dist(m, b.edge(e).point(t)) < tol, "edge {e} at t = {t}");
                    if let Curve::Arc { center, radius, .. } = *b.edge(e) {
                        assert!((dist(m, center) - radius).abs() < 1e-12 * radius);
                    }
                }
            }
        }
    }

    #[test]
    fn quarter_ring_is_polar_and_jacobian_matches_differences() {
        let b = quarter_ring();
        for (u, v) in samples(50) {
            let x = b.map(u, v);
            let r = x[0].hypot(x[1]);
            assert!((100.0..=200.0).contains(&r));
            // For concentric arcs Gordon–Hall reduces to exact polar coordinates:
            // r = 100 + 100 u, θ = v π/2, here checked to ~10 ulps of 200 mm.
            assert!((r - (100.0 + 100.0 * u)).abs() < 1e-12 * 200.0);
            assert!((x[1].atan2(x[0]) - v * PI / 2.0).abs() < 1e-12);
        }
        let h = 1e-7;
        for (u, v) in samples(10) {
            let j = b.jacobian(u, v);
            for (d, row) in j.iter().enumerate() {
                let du = (b.map(u + h, v)[d] - b.map(u - h, v)[d]) / (2.0 * h);
                let dv = (b.map(u, v + h)[d] - b.map(u, v - h)[d]) / (2.0 * h);
                // Central differences: truncation |x'''| h²/6 ~ 300·1e-14 is negligible;
                // round-off ~ ε·200 mm / h ~ 4e-7 mm dominates, so allow 1e-5 mm
                // (entries are ~100–300 mm).
                assert!((du - row[0]).abs() < 1e-5, "{du} vs {}", row[0]);
                assert!((dv - row[1]).abs() < 1e-5, "{dv} vs {}", row[1]);
            }
        }
    }

    #[test]
    fn errors_are_reported() {
        use GeometryError::*;
        let s = [Straight, Straight, Straight, Straight];
        let cw = Block::new([[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]], s);
        assert!(matches!(cw, Err(Clockwise { .. })));
        let o = [0.0, 0.0];
        let c = [[100.0, 0.0], [200.0, 0.0], [0.0, 201.0], [0.0, 100.0]];
        let bad = Block::new(c, [Straight, ArcAbout(o), Straight, Straight]);
        assert!(matches!(bad, Err(ArcRadiusMismatch { edge: 1, .. })));
        let point = Curve::arc_through([0.0, 0.0], [0.0, 0.0], o, 2);
        assert!(matches!(point, Err(DegenerateArc { edge: 2, .. })));
        let half = Curve::arc_through([1.0, 0.0], [-1.0, 0.0], o, 0);
        assert!(matches!(half, Err(AmbiguousArc { .. })));
        // An arc bulging far through the opposite edge folds the map.
        let c = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.2], [0.0, 0.2]];
        let folded = Block::new(c, [ArcAbout([0.5, -0.1]), Straight, Straight, Straight]);
        assert!(matches!(folded, Err(FoldedMap { .. })));
    }

    #[test]
    fn inverse_undoes_the_map() {
        for b in [skew_block(), quarter_ring()] {
            let mut pts = samples(200);
            pts.extend([(0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.5)]);
            for (u, v) in pts {
                let (ui, vi) = b.inverse(b.map(u, v)).unwrap();
                // Newton stops at a 1e-10 step and then converges quadratically.
                assert!((ui - u).abs() < 1e-10 && (vi - v).abs() < 1e-10);
            }
        }
        let ring = quarter_ring();
        for x in [[300.0, 300.0], [10.0, 10.0], [150.0, -1.0], [-5.0, 150.0]] {
            assert!(ring.inverse(x).is_none(), "{x:?}");
        }
        assert!(skew_block().inverse([6.0, 2.0]).is_none());
    }

    #[test]
    fn curve_basics() {
        let arc = Curve::arc_through([100.0, 0.0], [-44.0, 72.0], [10.0, 0.0], 0).unwrap();
        // r·|sweep| with r = 90 mm; computed via hypot of the derivative, so a few ulps of
        // the ~199 mm result.
        assert!((arc.length() - 90.0 * 72f64.atan2(-54.0)).abs() < 1e-12);
        let back = arc.reversed();
        assert!((back.length() - arc.length()).abs() < 1e-12);
        assert!(dist(arc.point(0.3), back.point(0.7)) < 1e-12);
        assert!(dist(back.end(), [100.0, 0.0]) < 1e-12);
        let cw = Curve::arc_through([0.0, 100.0], [100.0, 0.0], [0.0, 0.0], 0).unwrap();
        assert!(matches!(cw, Curve::Arc { start_angle, end_angle, .. } if end_angle < start_angle));
    }
}
