//! How body 2's material moves through the contact under monotonic sliding, in the frame of
//! body 1 where the heat problem is solved: a strip sliding past (a translation along its
//! straight contact edge) or a ring or disc turning (a rotation about the centre of its
//! circular contact edge). Under reciprocating sliding the stroke u₀ is small against the
//! bodies (the paper's §2) and neither body's material moves through the contact.
//!
//! The motion is read from the contact itself: the partners of the contact points on body 2
//! lie on a straight line or on a circle, and at each of them the material moves with the
//! sliding speed along the contact tangent τ (the '+' direction: the strip moves towards +τ
//! and drags body 1; reference-model.md, Example 1). Any other shape of contact edge has no
//! rigid motion that keeps the body in place, and is refused.

use super::ThermalError;
use crate::conduction::Flow;
use crate::contact::ContactPoints;
use crate::geometry::Point;

/// Relative tolerance of "on a line" and "on a circle", against the contact's length: the
/// partners are exact points of the geometry, so only round-off separates them from it.
const SHAPE_TOLERANCE: f64 = 1e-7;

/// The motion of body 2's material (mm/s) for monotonic sliding at `speed` mm/s.
pub fn counterface_flow(points: &ContactPoints, speed: f64) -> Result<Flow, ThermalError> {
    let partners = &points.partner;
    let refuse = |why: &str| ThermalError::Counterface(why.to_string());
    let (Some(&first), Some(&last)) = (partners.first(), partners.last()) else {
        return Err(refuse("the contact has no points"));
    };
    let chord = [last[0] - first[0], last[1] - first[1]];
    let length = chord[0].hypot(chord[1]);
    if length == 0.0 {
        return Err(refuse("the contact points' partners on body 2 coincide"));
    }
    let direction = [chord[0] / length, chord[1] / length];
    let off_line = |x: Point| {
        let d = [x[0] - first[0], x[1] - first[1]];
        (d[0] * direction[1] - d[1] * direction[0]).abs()
    };
    let tangent = points.tangent[0];
    if partners
        .iter()
        .all(|&x| off_line(x) <= SHAPE_TOLERANCE * length)
    {
        // Along the line, oriented with the contact tangent τ.
        let sign = (direction[0] * tangent[0] + direction[1] * tangent[1]).signum();
        return Ok(Flow::Translation([
            sign * speed * direction[0],
            sign * speed * direction[1],
        ]));
    }
    let middle = partners[partners.len() / 2];
    let center = circle_through(first, middle, last)
        .ok_or_else(|| refuse("its contact edge is neither straight nor a circular arc"))?;
    let radius = (first[0] - center[0]).hypot(first[1] - center[1]);
    let on_circle = partners.iter().all(|&x| {
        ((x[0] - center[0]).hypot(x[1] - center[1]) - radius).abs() <= SHAPE_TOLERANCE * length
    });
    if !on_circle {
        return Err(refuse(
            "its contact edge is neither straight nor a circular arc",
        ));
    }
    // w = ω e_y × (x − c) must be +v τ at the contact.
    let radial = [first[0] - center[0], first[1] - center[1]];
    let turning = [-radial[1], radial[0]];
    let sign = (turning[0] * tangent[0] + turning[1] * tangent[1]).signum();
    Ok(Flow::Rotation {
        center,
        rate: sign * speed / radius,
    })
}

/// The centre of the circle through three points; None if they are (nearly) on a line.
fn circle_through(a: Point, b: Point, c: Point) -> Option<Point> {
    let (bx, by) = (b[0] - a[0], b[1] - a[1]);
    let (cx, cy) = (c[0] - a[0], c[1] - a[1]);
    let d = 2.0 * (bx * cy - by * cx);
    let scale = (bx * bx + by * by).max(cx * cx + cy * cy);
    if d.abs() <= 1e-12 * scale {
        return None;
    }
    let b2 = bx * bx + by * by;
    let c2 = cx * cx + cy * cy;
    Some([
        a[0] + (cy * b2 - by * c2) / d,
        a[1] + (bx * c2 - cx * b2) / d,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(partner: Vec<Point>, tangent: Point) -> ContactPoints {
        let n = partner.len();
        ContactPoints {
            x: partner.clone(),
            weight: vec![1.0; n],
            normal: vec![[0.0, -1.0]; n],
            tangent: vec![tangent; n],
            initial_gap: vec![0.0; n],
            partner,
        }
    }

    #[test]
    fn a_strip_translates_with_the_tangent() {
        let line: Vec<Point> = (0..5).map(|i| [i as f64, 100.0]).collect();
        let flow = counterface_flow(&points(line.clone(), [1.0, 0.0]), 40.0).unwrap();
        assert_eq!(flow, Flow::Translation([40.0, 0.0]));
        let flow = counterface_flow(&points(line, [-1.0, 0.0]), 40.0).unwrap();
        assert_eq!(flow, Flow::Translation([-40.0, 0.0]));
    }

    #[test]
    fn a_ring_turns_about_its_centre_at_the_sliding_speed() {
        // Partners on the top of a ring of radius 50 about (0, 0); τ = +x there: the rim
        // moves towards +x at the top, so the ring turns clockwise (ω < 0), |ω| = v/R.
        let arc: Vec<Point> = (0..7)
            .map(|i| {
                let angle = std::f64::consts::FRAC_PI_2 + 0.1 * (i as f64 - 3.0);
                [50.0 * angle.cos(), 50.0 * angle.sin()]
            })
            .collect();
        let Flow::Rotation { center, rate } =
            counterface_flow(&points(arc.clone(), [1.0, 0.0]), 100.0).unwrap()
        else {
            panic!("a rotation");
        };
        assert!(
            center[0].abs() < 1e-9 && center[1].abs() < 1e-9,
            "{center:?}"
        );
        assert!((rate + 2.0).abs() < 1e-12, "{rate}");
        let flow = Flow::Rotation { center, rate };
        let w = flow.at([0.0, 50.0]);
        assert!((w[0] - 100.0).abs() < 1e-9 && w[1].abs() < 1e-9);
        // A wavy edge is refused.
        let mut wavy = arc;
        wavy[2][1] += 0.01;
        assert!(counterface_flow(&points(wavy, [1.0, 0.0]), 100.0).is_err());
    }
}
