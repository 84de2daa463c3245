//! Exact 2D geometry in the x–z plane: blocks bounded by straight segments and circular arcs,
//! mapped from the unit square by the Gordon–Hall transfinite (blending-function) map, so
//! that curved boundaries are represented exactly. Lengths in mm, angles in radians.

/// A point [x, z], mm.
pub type Point = [f64; 2];

/// Errors in a block's geometry.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum GeometryError {
    /// The corners run clockwise.
    #[error("block corners are not counter-clockwise (signed area {area} mm²)")]
    Clockwise { area: f64 },
    /// The two ends of an arc are not equally far from its centre.
    #[error(
        "arc on edge {edge}: corners are at distances {r_start} and {r_end} mm from the centre"
    )]
    ArcRadiusMismatch {
        edge: usize,
        r_start: f64,
        r_end: f64,
    },
    /// An arc of zero radius.
    #[error("arc on edge {edge} is degenerate (radius {radius} mm)")]
    DegenerateArc { edge: usize, radius: f64 },
    /// The block map folds over.
    #[error("block map is not invertible: Jacobian determinant {det} at (u, v) = ({u}, {v})")]
    FoldedMap { det: f64, u: f64, v: f64 },
}

/// A boundary curve parametrised by t ∈ [0, 1] from `start()` to `end()`.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    /// Straight segment.
    Line { start: Point, end: Point },
    /// Arc about `center`, radius `radius`, angle going linearly from `start_angle` to
    /// `end_angle` (radians; end < start means clockwise).
    Arc {
        center: Point,
        radius: f64,
        start_angle: f64,
        end_angle: f64,
    },
}

impl Curve {
    /// Point at parameter t.
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
        }
    }

    /// First point.
    pub fn start(&self) -> Point {
        self.point(0.0)
    }

    /// Last point.
    pub fn end(&self) -> Point {
        self.point(1.0)
    }

    /// The same curve traversed backwards.
    pub fn reversed(&self) -> Curve {
        match *self {
            Curve::Line { start, end } => Curve::Line {
                start: end,
                end: start,
            },
            Curve::Arc {
                center,
                radius,
                start_angle,
                end_angle,
            } => Curve::Arc {
                center,
                radius,
                start_angle: end_angle,
                end_angle: start_angle,
            },
        }
    }

    /// Length, mm.
    pub fn length(&self) -> f64 {
        match *self {
            Curve::Line { start, end } => (end[0] - start[0]).hypot(end[1] - start[1]),
            Curve::Arc {
                radius,
                start_angle,
                end_angle,
                ..
            } => radius * (end_angle - start_angle).abs(),
        }
    }

    /// Minor arc (|sweep| < π) from `start` to `end` about `center`.
    pub fn arc_through(
        start: Point,
        end: Point,
        center: Point,
        edge: usize,
    ) -> Result<Curve, GeometryError> {
        let r_start = (start[0] - center[0]).hypot(start[1] - center[1]);
        let r_end = (end[0] - center[0]).hypot(end[1] - center[1]);
        if r_start <= 0.0 || r_end <= 0.0 || !r_start.is_finite() {
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
        let mut sweep = a1 - a0;
        while sweep > std::f64::consts::PI {
            sweep -= 2.0 * std::f64::consts::PI;
        }
        while sweep < -std::f64::consts::PI {
            sweep += 2.0 * std::f64::consts::PI;
        }
        Ok(Curve::Arc {
            center,
            radius: 0.5 * (r_start + r_end),
            start_angle: a0,
            end_angle: a0 + sweep,
        })
    }
}

/// How a user describes one block edge.
#[derive(Clone, Debug, PartialEq)]
pub enum EdgeShape {
    /// Straight segment between the corners.
    Straight,
    /// Minor circular arc about the given centre.
    ArcAbout(Point),
}

/// A curvilinear quadrilateral with corners c0..c3 counter-clockwise.
///
/// Edges in counter-clockwise order: edge 0: c0→c1, 1: c1→c2, 2: c2→c3, 3: c3→c0. Parameter
/// square (u, v) ∈ \[0, 1\]²: c0 = (0,0), c1 = (1,0), c2 = (1,1), c3 = (0,1); edge 0 is v = 0,
/// edge 1 is u = 1, edge 2 is v = 1, edge 3 is u = 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// Corners [x, z], mm.
    pub corners: [Point; 4],
    /// Edge curves in counter-clockwise direction.
    pub edges: [Curve; 4],
}

impl Block {
    /// Build and validate a block: corners counter-clockwise, arcs consistent, and a positive
    /// Jacobian on a 9 × 9 grid of the parameter square.
    pub fn new(corners: [Point; 4], shapes: [EdgeShape; 4]) -> Result<Block, GeometryError> {
        let area = 0.5
            * (0..4)
                .map(|i| {
                    let (a, b) = (corners[i], corners[(i + 1) % 4]);
                    a[0] * b[1] - b[0] * a[1]
                })
                .sum::<f64>();
        if area.is_nan() || area <= 0.0 {
            return Err(GeometryError::Clockwise { area });
        }
        let mut edges = Vec::with_capacity(4);
        for (e, shape) in shapes.iter().enumerate() {
            let (a, b) = (corners[e], corners[(e + 1) % 4]);
            edges.push(match shape {
                EdgeShape::Straight => Curve::Line { start: a, end: b },
                EdgeShape::ArcAbout(c) => Curve::arc_through(a, b, *c, e)?,
            });
        }
        let block = Block {
            corners,
            edges: [
                edges[0].clone(),
                edges[1].clone(),
                edges[2].clone(),
                edges[3].clone(),
            ],
        };
        for i in 0..9 {
            for j in 0..9 {
                let (u, v) = (i as f64 / 8.0, j as f64 / 8.0);
                let jac = block.jacobian(u, v);
                let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
                if det.is_nan() || det <= 0.0 {
                    return Err(GeometryError::FoldedMap { det, u, v });
                }
            }
        }
        Ok(block)
    }

    /// The curve of edge e in the counter-clockwise direction.
    pub fn edge(&self, e: usize) -> &Curve {
        &self.edges[e]
    }

    /// Gordon–Hall map x(u, v) = (1−v) B(u) + v T(u) + (1−u) L(v) + u R(v) − bilinear corner
    /// term, with B = edge 0 (t = u), R = edge 1 (t = v), T = edge 2 (t = 1−u), L = edge 3 (t = 1−v).
    pub fn map(&self, u: f64, v: f64) -> Point {
        let c = &self.corners;
        let bottom = self.edges[0].point(u);
        let right = self.edges[1].point(v);
        let top = self.edges[2].point(1.0 - u);
        let left = self.edges[3].point(1.0 - v);
        let mut x = [0.0; 2];
        for d in 0..2 {
            x[d] = (1.0 - v) * bottom[d] + v * top[d] + (1.0 - u) * left[d] + u * right[d]
                - ((1.0 - u) * (1.0 - v) * c[0][d]
                    + u * (1.0 - v) * c[1][d]
                    + u * v * c[2][d]
                    + (1.0 - u) * v * c[3][d]);
        }
        x
    }

    /// Jacobian [[∂x/∂u, ∂x/∂v], [∂z/∂u, ∂z/∂v]], mm.
    pub fn jacobian(&self, u: f64, v: f64) -> [[f64; 2]; 2] {
        let c = &self.corners;
        let (bottom, db) = (self.edges[0].point(u), self.edges[0].derivative(u));
        let (right, dr) = (self.edges[1].point(v), self.edges[1].derivative(v));
        let (top, dt) = (
            self.edges[2].point(1.0 - u),
            self.edges[2].derivative(1.0 - u),
        );
        let (left, dl) = (
            self.edges[3].point(1.0 - v),
            self.edges[3].derivative(1.0 - v),
        );
        let mut j = [[0.0; 2]; 2];
        for d in 0..2 {
            j[d][0] = (1.0 - v) * db[d] - v * dt[d] - left[d] + right[d]
                - (-(1.0 - v) * c[0][d] + (1.0 - v) * c[1][d] + v * c[2][d] - v * c[3][d]);
            j[d][1] = -bottom[d] + top[d] - (1.0 - u) * dl[d] + u * dr[d]
                - (-(1.0 - u) * c[0][d] - u * c[1][d] + u * c[2][d] + (1.0 - u) * c[3][d]);
        }
        j
    }

    /// Inverse map by damped Newton iteration: `Some((u, v))` if `x` lies in the block.
    pub fn inverse(&self, x: Point) -> Option<(f64, f64)> {
        let size = self
            .edges
            .iter()
            .map(|e| e.length())
            .fold(0.0, f64::max)
            .max(1e-300);
        for &(u0, v0) in &[
            (0.5, 0.5),
            (0.25, 0.25),
            (0.75, 0.25),
            (0.75, 0.75),
            (0.25, 0.75),
        ] {
            let (mut u, mut v) = (u0, v0);
            for _ in 0..60 {
                let y = self.map(u, v);
                let r = [x[0] - y[0], x[1] - y[1]];
                let j = self.jacobian(u, v);
                let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
                if det == 0.0 || !det.is_finite() {
                    break;
                }
                let du = (j[1][1] * r[0] - j[0][1] * r[1]) / det;
                let dv = (-j[1][0] * r[0] + j[0][0] * r[1]) / det;
                // Keep the iterate near the square: the map is only defined (and invertible) there.
                u = (u + du).clamp(-0.5, 1.5);
                v = (v + dv).clamp(-0.5, 1.5);
                if r[0].hypot(r[1]) < 1e-13 * size && du.abs() < 1e-12 && dv.abs() < 1e-12 {
                    break;
                }
            }
            let y = self.map(u, v);
            let close = (x[0] - y[0]).hypot(x[1] - y[1]) < 1e-9 * size;
            let tol = 1e-9;
            if close && u >= -tol && u <= 1.0 + tol && v >= -tol && v <= 1.0 + tol {
                return Some((u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)));
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quarter_ring() -> Block {
        let o = [0.0, 0.0];
        Block::new(
            [[100.0, 0.0], [200.0, 0.0], [0.0, 200.0], [0.0, 100.0]],
            [
                EdgeShape::Straight,
                EdgeShape::ArcAbout(o),
                EdgeShape::Straight,
                EdgeShape::ArcAbout(o),
            ],
        )
        .unwrap()
    }

    #[test]
    fn straight_block_map_is_bilinear() {
        let c = [[0.0, 0.0], [5.0, 0.0], [5.7, 4.4], [0.0, 5.0]];
        let b = Block::new(
            c,
            [
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
            ],
        )
        .unwrap();
        for &(u, v) in &[(0.3, 0.7), (0.9, 0.1), (0.5, 0.5)] {
            let x = b.map(u, v);
            for d in 0..2 {
                let bl = (1.0 - u) * (1.0 - v) * c[0][d]
                    + u * (1.0 - v) * c[1][d]
                    + u * v * c[2][d]
                    + (1.0 - u) * v * c[3][d];
                // Same formula, different rounding: a few ulps of the 5 mm coordinates.
                assert!((x[d] - bl).abs() < 1e-13);
            }
        }
    }

    #[test]
    fn arc_edges_are_exact_and_jacobian_matches_differences() {
        let b = quarter_ring();
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            let outer = b.map(1.0, t);
            let inner = b.map(0.0, t);
            // Points of an arc edge lie on the circle to round-off.
            assert!((outer[0].hypot(outer[1]) - 200.0).abs() < 1e-12 * 200.0);
            assert!((inner[0].hypot(inner[1]) - 100.0).abs() < 1e-12 * 100.0);
        }
        let (u, v, h) = (0.37, 0.61, 1e-6);
        let j = b.jacobian(u, v);
        for (d, row) in j.iter().enumerate() {
            let du = (b.map(u + h, v)[d] - b.map(u - h, v)[d]) / (2.0 * h);
            let dv = (b.map(u, v + h)[d] - b.map(u, v - h)[d]) / (2.0 * h);
            // Central differences: O(h²) truncation and O(ε/h) round-off on 200 mm coordinates.
            assert!((du - row[0]).abs() < 1e-6 && (dv - row[1]).abs() < 1e-6);
        }
    }

    #[test]
    fn errors_are_reported() {
        let s = [
            EdgeShape::Straight,
            EdgeShape::Straight,
            EdgeShape::Straight,
            EdgeShape::Straight,
        ];
        let cw = Block::new([[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]], s.clone());
        assert!(matches!(cw, Err(GeometryError::Clockwise { .. })));
        let bad = Block::new(
            [[100.0, 0.0], [200.0, 0.0], [0.0, 201.0], [0.0, 100.0]],
            [
                EdgeShape::Straight,
                EdgeShape::ArcAbout([0.0, 0.0]),
                EdgeShape::Straight,
                EdgeShape::Straight,
            ],
        );
        assert!(matches!(bad, Err(GeometryError::ArcRadiusMismatch { .. })));
    }

    #[test]
    fn inverse_undoes_the_map() {
        let b = quarter_ring();
        for &(u, v) in &[(0.1, 0.2), (0.5, 0.5), (0.93, 0.71), (0.0, 1.0)] {
            let (uu, vv) = b.inverse(b.map(u, v)).unwrap();
            assert!((uu - u).abs() < 1e-9 && (vv - v).abs() < 1e-9);
        }
        assert!(b.inverse([300.0, 300.0]).is_none());
        assert!(b.inverse([10.0, 10.0]).is_none());
        let arc = Curve::arc_through([1.0, 0.0], [0.0, 1.0], [0.0, 0.0], 0).unwrap();
        assert!((arc.length() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    }
}
