//! Where a diagram's labels go: each beside its anchor (an arrow's tip, an arc's middle),
//! clear of every label already placed and of every line drawn, inside the diagram.
//!
//! The rule: try places around the anchor, first straight on along the label's own
//! direction (beyond an arrow's tip), then turning away from it by steps of 30 degrees to
//! either side, at growing distances; the first place whose box (with a margin) touches no
//! placed box and no line, and lies inside the bounds, is the label's. If none does within
//! reach, the free place nearest the anchor on a grid over the bounds is taken. Labels are
//! placed in the order given, so the most important first.

use egui::{Pos2, Rect, Vec2, pos2, vec2};

/// A drawn line segment labels must keep clear of: its ends and half its width.
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    /// One end.
    pub a: Pos2,
    /// The other end.
    pub b: Pos2,
    /// Half the stroke's width (points).
    pub half_width: f32,
}

/// One label to place: where it belongs, which way it leans, how big its box is.
#[derive(Clone, Copy, Debug)]
pub struct Wanted {
    /// The point it labels.
    pub anchor: Pos2,
    /// The direction to put it in first (an arrow's direction; any when zero).
    pub direction: Vec2,
    /// The box's size.
    pub size: Vec2,
    /// The least distance from the anchor to the box's nearest side.
    pub gap: f32,
}

/// Space kept around each box.
const MARGIN: f32 = 2.0;

/// Does the segment `s` come within its half width of `r`?
pub fn touches(r: Rect, s: &Segment) -> bool {
    let r = r.expand(s.half_width);
    if r.contains(s.a) || r.contains(s.b) {
        return true;
    }
    // Clip the segment against the box (Liang-Barsky).
    let d = s.b - s.a;
    let (mut t0, mut t1) = (0.0_f32, 1.0_f32);
    for (p, q) in [(-d.x, s.a.x - r.min.x), (d.x, r.max.x - s.a.x), (-d.y, s.a.y - r.min.y), (d.y, r.max.y - s.a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

fn free(r: Rect, placed: &[Rect], lines: &[Segment], bounds: Rect) -> bool {
    bounds.contains_rect(r)
        && !placed.iter().any(|p| p.expand(MARGIN).intersects(r))
        && !lines.iter().any(|s| touches(r.expand(MARGIN), s))
}

/// The box of size `size` whose side nearest the anchor is `gap` away from it in the
/// direction `dir` (a unit vector).
fn box_towards(anchor: Pos2, dir: Vec2, size: Vec2, gap: f32) -> Rect {
    // The distance from a box's centre to its edge along `dir`.
    let reach = (size.x * 0.5 / dir.x.abs().max(1e-6)).min(size.y * 0.5 / dir.y.abs().max(1e-6));
    Rect::from_center_size(anchor + dir * (gap + reach), size)
}

/// Places `wanted` in order (see the module's rule); returns one box each.
pub fn place(wanted: &[Wanted], lines: &[Segment], bounds: Rect) -> Vec<Rect> {
    let mut placed: Vec<Rect> = Vec::with_capacity(wanted.len());
    for w in wanted {
        let base = if w.direction.length() > 1e-3 {
            w.direction.normalized()
        } else {
            vec2(std::f32::consts::FRAC_1_SQRT_2, -std::f32::consts::FRAC_1_SQRT_2)
        };
        let step = w.size.y.max(6.0) * 0.5;
        let mut found = None;
        'search: for ring in 0..8 {
            let gap = w.gap + ring as f32 * step;
            for turn in [0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6] {
                let a = (turn as f32 * 30.0).to_radians();
                let dir = vec2(base.x * a.cos() - base.y * a.sin(), base.x * a.sin() + base.y * a.cos());
                let r = box_towards(w.anchor, dir, w.size, gap);
                if free(r, &placed, lines, bounds) {
                    found = Some(r);
                    break 'search;
                }
            }
        }
        let r = found.or_else(|| nearest_free(w, &placed, lines, bounds)).unwrap_or_else(|| {
            // Nothing free anywhere: beside the anchor, as good as it gets.
            box_towards(w.anchor, base, w.size, w.gap)
        });
        placed.push(r);
    }
    placed
}

/// Whether `boxes` (as [`place`] returned them) all lie inside `bounds`, clear of each
/// other and of `lines`: false where some label found no free place and was put beside its
/// anchor regardless.
pub fn all_clear(boxes: &[Rect], lines: &[Segment], bounds: Rect) -> bool {
    boxes.iter().enumerate().all(|(i, r)| {
        bounds.contains_rect(*r)
            && !boxes[i + 1..].iter().any(|q| q.intersects(*r))
            && !lines.iter().any(|s| touches(*r, s))
    })
}

/// The free box nearest the anchor, on a grid over `bounds`.
fn nearest_free(w: &Wanted, placed: &[Rect], lines: &[Segment], bounds: Rect) -> Option<Rect> {
    let (sx, sy) = ((w.size.x * 0.25).max(2.0), (w.size.y * 0.5).max(2.0));
    let mut best: Option<(f32, Rect)> = None;
    let mut y = bounds.min.y + w.size.y * 0.5;
    while y <= bounds.max.y - w.size.y * 0.5 {
        let mut x = bounds.min.x + w.size.x * 0.5;
        while x <= bounds.max.x - w.size.x * 0.5 {
            let r = Rect::from_center_size(pos2(x, y), w.size);
            let d = r.distance_sq_to_pos(w.anchor);
            if best.is_none_or(|(b, _)| d < b) && free(r, placed, lines, bounds) {
                best = Some((d, r));
            }
            x += sx;
        }
        y += sy;
    }
    best.map(|(_, r)| r)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_through_a_box_touches_it_and_one_beside_does_not() {
        let r = Rect::from_min_max(pos2(0.0, 0.0), pos2(10.0, 10.0));
        let s = |a: [f32; 2], b: [f32; 2], w: f32| Segment { a: a.into(), b: b.into(), half_width: w };
        assert!(touches(r, &s([-5.0, 5.0], [15.0, 5.0], 0.0)), "through");
        assert!(touches(r, &s([5.0, 5.0], [50.0, 50.0], 0.0)), "from inside");
        assert!(!touches(r, &s([-5.0, -5.0], [-5.0, 20.0], 1.0)), "beside");
        assert!(touches(r, &s([-5.0, -5.0], [-5.0, 20.0], 6.0)), "beside, but wide");
        assert!(!touches(r, &s([12.0, -1.0], [20.0, 3.0], 1.0)));
        assert!(touches(r, &s([-10.0, 20.0], [20.0, -10.0], 0.0)), "across a corner");
    }

    /// A tiny generator (xorshift), so the test needs no crate.
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    #[test]
    fn random_fans_of_arrows_get_labels_that_touch_nothing() {
        let bounds = Rect::from_min_max(pos2(0.0, 0.0), pos2(400.0, 400.0));
        let centre = pos2(200.0, 200.0);
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for case in 0..2000 {
            let arrows = 2 + (rng.next() * 7.0) as usize;
            let mut lines = Vec::new();
            let mut wanted = Vec::new();
            for _ in 0..arrows {
                let a = rng.next() * std::f32::consts::TAU;
                let len = 20.0 + rng.next() * 130.0;
                let tip = centre + vec2(a.cos(), a.sin()) * len;
                lines.push(Segment { a: centre, b: tip, half_width: 2.0 });
                wanted.push(Wanted { anchor: tip, direction: tip - centre, size: vec2(28.0, 24.0), gap: 4.0 });
            }
            // Two angle labels near the centre, as the plot has.
            for k in 0..2 {
                let a = rng.next() * std::f32::consts::TAU;
                let at = centre + vec2(a.cos(), a.sin()) * (40.0 + 25.0 * k as f32);
                wanted.push(Wanted { anchor: at, direction: at - centre, size: vec2(90.0, 22.0), gap: 3.0 });
            }
            let boxes = place(&wanted, &lines, bounds);
            for (i, a) in boxes.iter().enumerate() {
                assert!(bounds.contains_rect(*a), "case {case}: label {i} outside");
                for b in &boxes[i + 1..] {
                    assert!(!a.intersects(*b), "case {case}: labels overlap: {a:?} {b:?}");
                }
                for s in &lines {
                    assert!(!touches(*a, s), "case {case}: label {i} on an arrow");
                }
            }
        }
    }
}
