//! Sliding contact pairs (`contact.pairs = "sliding"`): body 2 moves along a straight track
//! under body 1, and wears where the stroke brings it.
//!
//! # Positions
//!
//! Body 2 is moved rigidly along x by the offset e(τ) = −d u₀ cos ωτ in the first half period
//! (d = +1 when the first sliding direction is "+": body 2 then drags body 1 towards +x) and
//! back in the second. A half period is cut into m equal intervals of the offset,
//! [e_j, e_{j+1}], each represented by its middle s_j. At each s_j the bodies meet as they
//! are: body 2's mesh translated by s_j and met by body 1's contact points through mortar
//! traces, condensed by the same code as fixed pairs ([`CondensedContact::from_bodies`]).
//! A translation does not change a body's stiffness, so both factorisations serve every
//! position, and each position's condensed problem is built once for the whole run.
//!
//! # The track
//!
//! Body 2's wear is a profile w₂(X) over its own coordinate X (the x of its points at rest):
//! the point of body 2 under body 1's x at offset s is X = x − s. It is held in cells of
//! width h along X ([`Track`]). Body 1's pressure at its contact point i stands for the part
//! of the edge its weight w_i covers: the edge's x range cut at the cumulative weights
//! (`dual_cells`, one cell [c_i, c_{i+1}] per point, its width proportional to w_i). Over an
//! interval, cell i sweeps X ∈ [c_i − s, c_{i+1} − s] for s from e_j to e_{j+1}; every track
//! cell collects the wear rate times the exact integral over s of its overlap with the swept
//! cell ([`swept_overlap`]). So the track's volume grows by Σ_i w_i ẇ_i |Δs| per interval,
//! exactly what body 1's points wear at the same pressures (Archard per body, for a = b = 1:
//! β̃ F s / t), and a long stroke paints a flat-bottomed trough whose ramps are as wide as the
//! contact.
//!
//! The gap at body 1's point i reads the track at the middle of its share, (c_i + c_{i+1})/2
//! − s_j (linear between cell centres), not at x_i − s_j: the end points of the edge lie on
//! the ends of their shares, where a vanishing stroke leaves a step in the track (worn under
//! the slider, unworn beside it), and a reading there took half the step (punch-b40's corner
//! wore body 2 at 57 % of the fixed pairs' rate). In the middle of the share, a vanishing
//! stroke gives back what the point deposited, and the model is the fixed pairs' one; where
//! the track is smooth, the reading moves by less than half a point spacing.

use super::CondensedContact;
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::problem::{Problem, ProblemError};

mod surface;
pub use surface::track_surface;

/// Body 2's worn profile along its track, in cells of equal width.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// X of the first cell's start (body 2's coordinate at rest), mm.
    pub start: f64,
    /// Cell width h, mm.
    pub cell: f64,
    /// Body 2's wear depth in each cell, mm.
    pub wear: Vec<f64>,
    /// A closed track's length (a ring's circumference, mm): X is then taken modulo it.
    pub period: Option<f64>,
}

impl Track {
    /// A track over [start, end] (mm) in cells of at most `cell` mm, unworn.
    pub fn new(start: f64, end: f64, cell: f64) -> Track {
        let count = ((end - start) / cell).ceil().max(1.0) as usize;
        Track {
            start,
            cell: (end - start) / count as f64,
            wear: vec![0.0; count],
            period: None,
        }
    }

    /// A closed track of length `period` (mm) from X = 0, in cells of at most `cell` mm.
    pub fn closed(period: f64, cell: f64) -> Track {
        Track {
            period: Some(period),
            ..Track::new(0.0, period, cell)
        }
    }

    /// Cell `k` of the unwrapped numbering (a closed track's cells repeat), if it exists.
    fn slot(&self, k: i64) -> Option<usize> {
        let n = self.wear.len() as i64;
        match self.period {
            Some(_) => Some(k.rem_euclid(n) as usize),
            None => (0..n).contains(&k).then_some(k as usize),
        }
    }

    /// The cells' centres X, mm.
    pub fn centres(&self) -> Vec<f64> {
        (0..self.wear.len())
            .map(|k| self.start + (k as f64 + 0.5) * self.cell)
            .collect()
    }

    /// The wear at X (mm), linear between cell centres and constant beyond the outer ones
    /// (a closed track goes round).
    pub fn at(&self, x: f64) -> f64 {
        let n = self.wear.len();
        let u = (x - self.start) / self.cell - 0.5;
        if self.period.is_some() {
            let k = u.floor();
            let f = u - k;
            let k = k as i64;
            let (a, b) = (self.slot(k).unwrap_or(0), self.slot(k + 1).unwrap_or(0));
            return (1.0 - f) * self.wear[a] + f * self.wear[b];
        }
        if u <= 0.0 {
            return self.wear[0];
        }
        let k = u.floor() as usize;
        if k + 1 >= n {
            return self.wear[n - 1];
        }
        let f = u - k as f64;
        (1.0 - f) * self.wear[k] + f * self.wear[k + 1]
    }

    /// Deposit the wear of a part [from, to] of body 1's edge (x, mm) swept over body 2 by the
    /// offsets s from `shift[0]` to `shift[1]` (mm): each track point under it for a length ℓ
    /// of offset gains `rate` × ℓ (`rate`, mm of depth per mm of sliding).
    pub fn sweep(&mut self, from: f64, to: f64, shift: [f64; 2], rate: f64) {
        let (s0, s1) = (shift[0].min(shift[1]), shift[0].max(shift[1]));
        let first = ((from - s1 - self.start) / self.cell).floor() as i64;
        let last = ((to - s0 - self.start) / self.cell).ceil() as i64;
        for k in first..last {
            let Some(slot) = self.slot(k) else {
                continue;
            };
            let x0 = self.start + k as f64 * self.cell;
            let collected = swept_overlap([from, to], [x0, x0 + self.cell], [s0, s1]);
            self.wear[slot] += rate * collected / self.cell;
        }
    }

    /// The worn area ∫ w₂ dX (mm²; times the thickness, the worn volume).
    pub fn area(&self) -> f64 {
        self.cell * self.wear.iter().sum::<f64>()
    }
}

/// ∫ |[a₀ − s, a₁ − s] ∩ [b₀, b₁]| ds over s ∈ [s₀, s₁] (mm²): how long, summed over the
/// offsets, a part [a₀, a₁] of body 1 shifted by −s covers the cell [b₀, b₁]. The overlap is
/// piecewise linear in s with kinks where an end of one interval passes an end of the other,
/// so the trapezoidal rule between those kinks is exact.
pub fn swept_overlap(a: [f64; 2], b: [f64; 2], s: [f64; 2]) -> f64 {
    let overlap = |t: f64| ((a[1] - t).min(b[1]) - (a[0] - t).max(b[0])).max(0.0);
    // At most six knots, on the stack: this runs for every point, position and track cell.
    let mut knots = [s[0], s[1], 0.0, 0.0, 0.0, 0.0];
    let mut count = 2;
    for k in [a[1] - b[1], a[0] - b[0], a[1] - b[0], a[0] - b[1]] {
        if k > s[0] && k < s[1] {
            knots[count] = k;
            count += 1;
        }
    }
    let knots = &mut knots[..count];
    knots.sort_unstable_by(f64::total_cmp);
    knots
        .windows(2)
        .map(|w| 0.5 * (w[1] - w[0]) * (overlap(w[0]) + overlap(w[1])))
        .sum()
}

/// The x range of each contact point's share of body 1's edge: the edge's x range from the
/// first to the last point cut at the cumulative weights (N + 1 ends, mm), so that cell i's
/// width is w_i times the edge's x extent over its length.
pub fn dual_cells(x: &[f64], weight: &[f64]) -> Vec<f64> {
    let (first, last) = (x[0], x[x.len() - 1]);
    let total: f64 = weight.iter().sum();
    let mut ends = Vec::with_capacity(x.len() + 1);
    let mut sum = 0.0;
    ends.push(first);
    for w in &weight[..weight.len() - 1] {
        sum += w;
        ends.push(first + (last - first) * sum / total);
    }
    ends.push(last);
    ends
}

/// Positions per half period when `contact.positions` is not given: offset steps of at most
/// 1/16 of body 1's contact edge (x extent `edge_length`, mm), at least 4, at most
/// [`super::MAX_POSITIONS`].
pub fn default_positions(stroke: f64, edge_length: f64) -> usize {
    let steps = (16.0 * stroke / edge_length).ceil() as usize;
    steps.clamp(4, super::spec::MAX_POSITIONS)
}

/// The stroke cut into positions: the offsets of body 2 that end the intervals of the first
/// half period and the middle of each.
#[derive(Clone, Debug, PartialEq)]
pub struct Stroke {
    /// Interval ends e_0 … e_m of the first half period, mm (from −d u₀ to d u₀).
    pub ends: Vec<f64>,
    /// Interval middles s_j, mm: the positions.
    pub positions: Vec<f64>,
}

impl Stroke {
    /// `count` equal intervals from −`direction` u₀ to `direction` u₀ (u₀ = `amplitude`, mm).
    pub fn new(amplitude: f64, direction: f64, count: usize) -> Stroke {
        let ends: Vec<f64> = (0..=count)
            .map(|j| direction * amplitude * (2.0 * j as f64 / count as f64 - 1.0))
            .collect();
        let positions = ends.windows(2).map(|e| 0.5 * (e[0] + e[1])).collect();
        Stroke { ends, positions }
    }

    /// Once round a closed track of length `period` (mm) in `count` equal intervals, in
    /// `direction` (±1).
    pub fn around(period: f64, direction: f64, count: usize) -> Stroke {
        let ends: Vec<f64> = (0..=count)
            .map(|j| direction * period * j as f64 / count as f64)
            .collect();
        let positions = ends.windows(2).map(|e| 0.5 * (e[0] + e[1])).collect();
        Stroke { ends, positions }
    }
}

/// The shape of body 2's track.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TrackShape {
    /// Straight along x: body 2 is translated by the offset.
    Straight,
    /// A whole circle (a ring, a disc, a drum under body 1): body 2 is turned about its centre,
    /// clockwise for a positive offset (its top then moves towards +x), and the track
    /// coordinate is the arc length, clockwise from the top.
    Ring {
        /// The circle's centre [x, z], mm.
        center: Point,
        /// Its radius, mm.
        radius: f64,
    },
}

impl TrackShape {
    /// The track coordinate (mm) of the point of body 2 under body 1's x, body 2 at rest.
    pub fn coordinate(&self, x: f64) -> f64 {
        match *self {
            TrackShape::Straight => x,
            TrackShape::Ring { center, radius } => {
                radius * ((x - center[0]) / radius).clamp(-1.0, 1.0).asin()
            }
        }
    }

    /// A closed track's length (mm).
    pub fn period(&self) -> Option<f64> {
        match *self {
            TrackShape::Straight => None,
            TrackShape::Ring { radius, .. } => Some(std::f64::consts::TAU * radius),
        }
    }

    /// Body 2's mesh at offset `s` (mm), and the angle it was turned by (radians).
    fn moved(&self, at_rest: &crate::mesh::Mesh, s: f64) -> (crate::mesh::Mesh, f64) {
        match *self {
            TrackShape::Straight => (at_rest.translated([s, 0.0]), 0.0),
            TrackShape::Ring { center, radius } => {
                let turn = -s / radius;
                (at_rest.rotated(center, turn), turn)
            }
        }
    }
}

/// Loads and prescribed displacements on a turning ring are not built: they would have to turn
/// with it or stay in space, and the condensation reads them in the frame the ring was
/// assembled in (review of 2026-11-29: a rim traction made the positions differ and the ring
/// wear 0.5 % unevenly, in silence).
fn refuse_ring_loads(problem: &Problem, body2: &ElasticBody) -> Result<(), ProblemError> {
    let (b2, _) = super::target_edge(problem, body2)?;
    let plate: Vec<&str> = problem.spec.plate.iter().map(|p| p.edge.as_str()).collect();
    let loaded = problem
        .load_vector(b2, body2, &plate)?
        .iter()
        .any(|f| *f != 0.0);
    if loaded || body2.has_prescribed() {
        let key = if loaded {
            format!("bodies[{b2}].tractions")
        } else {
            format!("bodies[{b2}].supports")
        };
        return Err(problem.error(
            key,
            "a ring turning under body 1 (sliding pairs on a closed track) may not carry loads or prescribed displacements of its own yet; hold it by fixed supports (its shaft or hub)",
        ));
    }
    Ok(())
}

/// The shape of body 2's contact edge as a track: a whole circle (every element edge's ends and
/// middle at one distance from one centre, to 1e-9 of it) or, when the edge has two ends,
/// straight.
pub fn track_shape(problem: &Problem, body2: &ElasticBody) -> Result<TrackShape, ProblemError> {
    let c = problem.spec.contact.as_ref().expect("checked");
    let (_, edge) = super::target_edge(problem, body2)?;
    if !super::closed_loop(body2, edge) {
        return Ok(TrackShape::Straight);
    }
    let at = |k: usize, t: f64| body2.mesh.point_on_edge(edge[k].0, edge[k].1, t);
    let center = circumcentre(at(0, -1.0), at(0, 0.0), at(0, 1.0));
    let radius = center.map_or(0.0, |c| dist(c, at(0, 0.0)));
    let not_a_circle = || {
        problem.error(
            "contact.target_edge",
            format!("\"{}\" is closed, so body 2 would turn under body 1, but it is not a whole circle (its element edges do not all lie at one distance from one centre); a closed track must be a circle", c.target_edge),
        )
    };
    let center = center.ok_or_else(not_a_circle)?;
    for k in 0..edge.len() {
        for t in [-1.0, 0.0, 1.0] {
            if (dist(center, at(k, t)) - radius).abs() > 1e-9 * radius {
                return Err(not_a_circle());
            }
        }
    }
    Ok(TrackShape::Ring { center, radius })
}

fn dist(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The centre of the circle through three points (None if they are in a line).
fn circumcentre(a: Point, b: Point, c: Point) -> Option<Point> {
    let d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    if d.abs() < 1e-300 {
        return None;
    }
    let sq = |p: Point| p[0] * p[0] + p[1] * p[1];
    let x = (sq(a) * (b[1] - c[1]) + sq(b) * (c[1] - a[1]) + sq(c) * (a[1] - b[1])) / d;
    let z = (sq(a) * (c[0] - b[0]) + sq(b) * (a[0] - c[0]) + sq(c) * (b[0] - a[0])) / d;
    Some([x, z])
}

/// Every position's condensed contact problem: body 2's mesh translated by each offset of
/// `stroke` and met by body 1 as at rest.
pub fn position_contacts(
    problem: &Problem,
    body1: &ElasticBody,
    body2: &mut ElasticBody,
    stroke: &Stroke,
    shape: TrackShape,
) -> Result<Vec<CondensedContact>, ProblemError> {
    let at_rest = body2.mesh.clone();
    let mut contacts = Vec::with_capacity(stroke.positions.len());
    let mut failure = None;
    let known = match known_flexibility(problem, body1, body2, stroke, shape) {
        Ok(k) => k,
        Err(e) => {
            body2.mesh = at_rest;
            return Err(e);
        }
    };
    for &s in &stroke.positions {
        let (mesh, turn) = shape.moved(&at_rest, s);
        body2.mesh = mesh;
        match CondensedContact::condense(problem, body1, body2, known.as_ref(), turn) {
            Ok(c) => contacts.push(c),
            Err(e) => {
                failure = Some((s, e));
                break;
            }
        }
    }
    body2.mesh = at_rest;
    match failure {
        None => Ok(contacts),
        Some((s, e)) if e.to_string().contains("has no partner") => Err(problem.error(
            "wear.amplitude",
            format!("at the offset {s:+.4} mm of the stroke body 2's track is too short: {e}. Lengthen body 2's contact edge to cover the stroke plus body 1's contact edge"),
        )),
        Some((_, e)) => Err(e),
    }
}

/// The contact problem of sliding pairs: the stroke's positions, each one's condensed
/// contact, and body 1's points' shares of the edge.
#[derive(Clone, Debug)]
pub struct SlidingContact {
    /// The positions of the first half period.
    pub stroke: Stroke,
    /// The condensed contact at each position (`stroke.positions` order).
    pub contacts: Vec<CondensedContact>,
    /// Each contact point's share of body 1's edge in x ([`dual_cells`]), mm.
    pub cells: Vec<f64>,
    /// Where each contact point reads the track at offset 0: the middle of its share, mm.
    pub readings: Vec<f64>,
    /// The track's shape.
    pub shape: TrackShape,
}

impl SlidingContact {
    /// Build every position's condensed contact: `stroke` (reciprocating: the amplitude u₀,
    /// mm; monotonic, on a closed track only: None, once round) in the first sliding
    /// direction (±1), `count` positions per half period (per turn).
    pub fn build(
        problem: &Problem,
        body1: &ElasticBody,
        body2: &mut ElasticBody,
        stroke: Option<f64>,
        direction: f64,
        count: usize,
    ) -> Result<SlidingContact, ProblemError> {
        let shape = track_shape(problem, body2)?;
        let (points, _) = CondensedContact::body1_points(problem, body1)?;
        if points.x.len() < 2 || points.normal.iter().any(|n| n[0].abs() > 1e-9) {
            // Body 2 moves along x under body 1's points; an inclined or curved contact edge
            // of body 1 would meet it at other points than that motion brings.
            return Err(problem.error(
                "contact.pairs",
                "\"sliding\" needs body 1's contact edge straight and horizontal; model a rounded slider by contact.initial_shape",
            ));
        }
        let stroke = match (stroke, shape.period()) {
            (Some(amplitude), _) => Stroke::new(amplitude, direction, count),
            (None, Some(period)) => Stroke::around(period, direction, count),
            (None, None) => {
                return Err(problem.error(
                    "wear.sliding",
                    "monotonic sliding pairs need a closed track: body 2's contact edge a whole circle (a ring, a disc) that turns under body 1; a straight track would run out",
                ))
            }
        };
        if let TrackShape::Ring { center, radius } = shape {
            refuse_ring_loads(problem, body2)?;
            if let Some(p) = points.x.iter().find(|p| (p[0] - center[0]).abs() >= radius) {
                return Err(problem.error(
                    "contact.edge",
                    format!("body 1's contact point ({:.4}, {:.4}) lies beyond the ring's width (centre x = {:.4}, radius {radius:.4} mm): it has nothing of the ring under it", p[0], p[1], center[0]),
                ));
            }
        }
        let contacts = position_contacts(problem, body1, body2, &stroke, shape)?;
        let x: Vec<f64> = points.x.iter().map(|p| p[0]).collect();
        let share_ends = dual_cells(&x, &points.weight);
        let readings = share_ends
            .windows(2)
            .map(|c| shape.coordinate(0.5 * (c[0] + c[1])))
            .collect();
        let cells = share_ends.iter().map(|&c| shape.coordinate(c)).collect();
        Ok(SlidingContact {
            stroke,
            contacts,
            cells,
            readings,
            shape,
        })
    }

    /// Positions per half period m.
    pub fn len(&self) -> usize {
        self.contacts.len()
    }

    /// Whether there are no positions.
    pub fn is_empty(&self) -> bool {
        self.contacts.is_empty()
    }

    /// A track over all that the stroke brings under body 1 (with one cell's margin), in
    /// cells of a quarter of the narrowest contact point's share, so that a cell of the
    /// track straddles the ends of body 1's shares over a small part of them, or of 1/64 of
    /// an interval of the stroke where that is longer.
    pub fn empty_track(&self) -> Track {
        let narrowest = self
            .cells
            .windows(2)
            .map(|c| c[1] - c[0])
            .fold(f64::INFINITY, f64::min);
        let interval = self
            .stroke
            .ends
            .windows(2)
            .map(|e| (e[1] - e[0]).abs())
            .fold(f64::INFINITY, f64::min);
        // A share's middle lies 2 cells from its ends, so that its reading (linear between
        // the two nearest centres) sees only its own deposit when the stroke vanishes. Where
        // an interval is long against the shares, every share's deposit is a plateau that
        // long with ramps as wide as the share, and the track is smooth on the interval's
        // scale: cells of 1/64 of it cost a 64th of the sweeps of the finest (the block on
        // a ring, 6.9 mm intervals over shares down to 0.008 mm: 12.8 s of run → 0.9 s).
        let cell = (0.25 * narrowest).max(interval / 64.0);
        if let Some(period) = self.shape.period() {
            return Track::closed(period, cell.max(period / MAX_TRACK_CELLS as f64));
        }
        let ends = &self.stroke.ends;
        let (low, high) = (
            ends[0].min(ends[ends.len() - 1]),
            ends[0].max(ends[ends.len() - 1]),
        );
        let first = self.cells[0] - high - cell;
        let last = self.cells[self.cells.len() - 1] - low + cell;
        Track::new(first, last, cell)
    }
}

/// Most cells of a closed track (a ring's wear is held in at most this many).
pub const MAX_TRACK_CELLS: usize = 200_000;

/// Most dofs of body 2's track whose flexibility is kept as one dense matrix (8000² numbers:
/// 512 MB); beyond, each position is condensed on its own (slower, no larger).
pub const MAX_TRACK_DOFS: usize = 8000;

/// Body 1's flexibility and body 2's on its track, shared by every position; None when the
/// track has more than [`MAX_TRACK_DOFS`] dofs.
fn known_flexibility(
    problem: &Problem,
    body1: &ElasticBody,
    body2: &ElasticBody,
    stroke: &Stroke,
    shape: TrackShape,
) -> Result<Option<super::KnownFlexibility>, ProblemError> {
    if shape.period().is_some() {
        // A ring turns all of its edge under body 1.
        let reach = [f64::NEG_INFINITY, f64::INFINITY];
        if body2_track_dofs(problem, body2, reach)? > MAX_TRACK_DOFS {
            return Ok(None);
        }
        return CondensedContact::sliding_flexibility(problem, body1, body2, reach).map(Some);
    }
    let (points, _) = CondensedContact::body1_points(problem, body1)?;
    let x = &points.x;
    let (first, last) = (
        x[0][0].min(x[x.len() - 1][0]),
        x[0][0].max(x[x.len() - 1][0]),
    );
    let (low, high) = stroke
        .ends
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &e| {
            (a.min(e), b.max(e))
        });
    // A partner element may reach a little beyond the points' own range.
    let margin = 0.05 * (last - first);
    let reach = [first - high - margin, last - low + margin];
    let touched = body2_track_dofs(problem, body2, reach)?;
    if touched > MAX_TRACK_DOFS {
        return Ok(None);
    }
    CondensedContact::sliding_flexibility(problem, body1, body2, reach).map(Some)
}

/// How many dofs body 2's contact edge has within x ∈ `reach`.
fn body2_track_dofs(
    problem: &Problem,
    body2: &ElasticBody,
    reach: [f64; 2],
) -> Result<usize, ProblemError> {
    let (_, edge) = super::target_edge(problem, body2)?;
    let inside = edge
        .iter()
        .filter(|&&(element, local)| {
            let ends = [-1.0, 1.0].map(|t| body2.mesh.point_on_edge(element, local, t)[0]);
            ends[0].max(ends[1]) >= reach[0] && ends[0].min(ends[1]) <= reach[1]
        })
        .count();
    Ok(2 * (inside * body2.dofs.p + 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn swept_overlap_is_the_area_under_the_trapezoid() {
        // A part 2 mm wide sweeping a cell 1 mm wide from far left to far right covers it
        // fully for 1 mm of offset and partly for 1 mm on each side: ∫ = 1·1 + 2·½ = 2.
        assert!((swept_overlap([0.0, 2.0], [5.0, 6.0], [-10.0, 0.0]) - 2.0).abs() < 1e-14);
        // Stopped early, at s = −3.5 (the part then at [3.5, 5.5]): the first ramp (½) and the
        // full cover (1) as before, then the overlap −3 − s falling from 1 to ½ over half a
        // millimetre (0.375).
        assert!((swept_overlap([0.0, 2.0], [5.0, 6.0], [-10.0, -3.5]) - 1.875).abs() < 1e-14);
        // No offset at all covers nothing.
        assert_eq!(swept_overlap([0.0, 2.0], [0.0, 1.0], [1.0, 1.0]), 0.0);
    }

    #[test]
    fn a_sweep_keeps_its_volume_and_paints_a_trough() {
        let mut track = Track::new(-20.0, 20.0, 0.1);
        // A cell [−1, 1] at rate 0.5 over offsets −10 … 10: area 2 × 0.5 × 20 = 20.
        track.sweep(-1.0, 1.0, [-10.0, 10.0], 0.5);
        assert!((track.area() - 20.0).abs() < 1e-12);
        // Track points in [−9, 9] see the whole cell pass: depth 0.5 × 2 = 1; the ramps run
        // over ±[9, 11], where X is under the part for offsets [−10, 1 − X]: 0.5 (11 − X),
        // linear, so a cell's mean is its centre's value.
        assert!((track.at(0.0) - 1.0).abs() < 1e-12);
        assert!((track.at(8.95) - 1.0).abs() < 1e-12);
        assert!(track.at(11.5).abs() < 1e-12);
        assert!((track.at(10.05) - 0.475).abs() < 1e-12);
    }

    #[test]
    fn dual_cells_have_the_widths_of_the_weights() {
        let x = [0.0, 1.0, 3.0];
        let w = [0.5, 1.5, 1.0];
        let c = dual_cells(&x, &w);
        assert_eq!(c.len(), 4);
        assert!((c[1] - 0.5).abs() < 1e-15 && (c[2] - 2.0).abs() < 1e-15 && c[3] == 3.0);
    }

    #[test]
    fn the_stroke_runs_from_one_end_to_the_other() {
        let s = Stroke::new(1.5, -1.0, 3);
        let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-15);
        assert!(close(&s.ends, &[1.5, 0.5, -0.5, -1.5]));
        assert!(close(&s.positions, &[1.0, 0.0, -1.0]));
    }
}
