//! How the centre shares its space between the shaded view (one picture, or two side by
//! side) and what stands beside it (the vector plot or the lobe).
//!
//! Both want to be square and as large as they can be. Given the area, [`split`] tries both
//! arrangements, side by side and stacked, and keeps the one whose smaller square is the
//! larger (the plot weighted a little less than the picture), among those that give each
//! picture [`PICTURE_FLOOR`] where any does. The divider between the two
//! can be dragged; its place is a fraction of the area, kept per arrangement across
//! restarts. Nothing here depends on the frame: the first frame is laid out as every other.

use egui::{Rect, pos2, vec2};

use crate::app::panels::vector_plot::LEGEND_COLUMN;
use serde::{Deserialize, Serialize};

/// Where the shaded view's toolbar and caption, and the plot's buttons and legend, go:
/// the height each takes above its square (points).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chrome {
    /// Above the picture(s): the toolbar and the caption.
    pub picture: f32,
    /// Above the plot: its view buttons and legend.
    pub plot: f32,
    /// Above the plot when its legend stands beside it (a part wider than high by
    /// [`crate::app::panels::vector_plot::LEGEND_COLUMN`]): its view buttons.
    pub plot_wide: f32,
    /// The least width (side by side) or height (stacked) of each part, so that its widest
    /// button fits ("Vectors at the vertex", the shaded view's toolbar).
    pub min_part: f32,
}

/// The two arrangements.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Arrangement {
    /// The pictures on the left, the plot on the right.
    Beside,
    /// The pictures above, the plot below.
    Stacked,
}

/// The divider's place in each arrangement, as the fraction of the area the pictures take;
/// `None` until the user drags it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Dividers {
    /// Side by side: the fraction of the width.
    pub beside: Option<f32>,
    /// Stacked: the fraction of the height.
    pub stacked: Option<f32>,
}

/// The centre's parts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Split {
    /// Which arrangement.
    pub arrangement: Arrangement,
    /// The shaded view's part (toolbar, caption and picture or pictures).
    pub pictures: Rect,
    /// The divider's handle.
    pub divider: Rect,
    /// The plot's part (buttons, legend and diagram).
    pub beside: Rect,
    /// The fraction used.
    pub fraction: f32,
    /// The side of each picture, and of the plot's square, this gives.
    pub sides: (f32, f32),
}

/// The divider's thickness.
pub const DIVIDER: f32 = 8.0;

/// How the plot's square counts against a picture's: one picture is wanted at 55 % of the
/// window's height, each of two at 40 %, and the plot's unit circle at 40 % (its square 1.2
/// times that, and a little more for its letters: about 50 %), so a plot's side counts
/// 0.55 / 0.5 = 1.1 times one picture's, and 0.40 / 0.5 = 0.8 times each of two.
fn plot_weight(pictures: usize) -> f32 {
    if pictures > 1 { 0.8 } else { 1.1 }
}

/// The sides of the picture(s) and of the plot for `fraction` in `arrangement`.
fn sides(area: Rect, arrangement: Arrangement, fraction: f32, pictures: usize, chrome: Chrome) -> (f32, f32) {
    let n = pictures.max(1) as f32;
    let (w, h) = (area.width(), area.height());
    match arrangement {
        Arrangement::Beside => {
            let pw = (w - DIVIDER) * fraction;
            let picture = ((pw - 8.0 * (n - 1.0)) / n).min(h - chrome.picture);
            let plot = ((w - DIVIDER) * (1.0 - fraction)).min(h - chrome.plot);
            (picture.max(0.0), plot.max(0.0))
        }
        Arrangement::Stacked => {
            let ph = (h - DIVIDER) * fraction;
            let picture = ((w - 8.0 * (n - 1.0)) / n).min(ph - chrome.picture);
            let rest = (h - DIVIDER) * (1.0 - fraction);
            // The legend beside the diagram where the part is wide enough, else above.
            let legend_beside = rest - chrome.plot_wide;
            let plot = if w >= legend_beside + LEGEND_COLUMN { legend_beside } else { w.min(rest - chrome.plot) };
            (picture.max(0.0), plot.max(0.0))
        }
    }
}

fn score((picture, plot): (f32, f32), pictures: usize) -> f32 {
    picture.min(plot * plot_weight(pictures))
}

/// The fractions `arrangement` may use in `area`: each part at least `min_part`, and
/// between 20 % and 85 %; empty when the area is too small for both.
fn allowed(area: Rect, arrangement: Arrangement, min_part: f32) -> (f32, f32) {
    let span = match arrangement {
        Arrangement::Beside => area.width(),
        Arrangement::Stacked => area.height(),
    } - DIVIDER;
    let lo = (min_part / span.max(1.0)).max(0.2);
    let hi = (1.0 - min_part / span.max(1.0)).min(0.85);
    (lo, hi)
}

/// The least side of a picture wherever the area allows it, before the plot's share is
/// weighed: a picture read from the back of a room (the Phong demo's two, its own and the
/// corrected one, were 125 points each at 1280x720 with both side panels open).
pub const PICTURE_FLOOR: f32 = 240.0;

/// The fractions `arrangement` may use (see [`allowed`]), only those that give each
/// picture [`PICTURE_FLOOR`] when `floor` holds.
fn fractions(area: Rect, arrangement: Arrangement, pictures: usize, chrome: Chrome, floor: bool) -> Vec<f32> {
    let (lo, hi) = allowed(area, arrangement, chrome.min_part);
    (20..=85)
        .map(|k| k as f32 / 100.0)
        .filter(|f| *f >= lo && *f <= hi)
        .filter(|f| !floor || sides(area, arrangement, *f, pictures, chrome).0 >= PICTURE_FLOOR)
        .collect()
}

/// The best fraction for `arrangement`: the one whose smaller square is largest (among
/// those that keep the pictures at the floor, when `floor`); among those, the one whose
/// picture is largest: where the plot is bound by the height (its buttons and legend above
/// it), the width it cannot use goes to the picture rather than to empty space.
fn best_fraction(area: Rect, arrangement: Arrangement, pictures: usize, chrome: Chrome, floor: bool) -> f32 {
    let (lo, hi) = allowed(area, arrangement, chrome.min_part);
    fractions(area, arrangement, pictures, chrome, floor)
        .into_iter()
        .max_by(|a, b| {
            let (ta, tb) =
                (sides(area, arrangement, *a, pictures, chrome), sides(area, arrangement, *b, pictures, chrome));
            let (sa, sb) = (score(ta, pictures), score(tb, pictures));
            // (Half a point is no difference.)
            let same = (sa - sb).abs() < 0.5;
            (if same { std::cmp::Ordering::Equal } else { sa.total_cmp(&sb) })
                .then(ta.0.total_cmp(&tb.0))
                .then(b.total_cmp(a))
        })
        .unwrap_or((lo + hi) * 0.5)
}

/// Shares `area` between `pictures` pictures and the plot (see the module's rule, and
/// [`PICTURE_FLOOR`]), with
/// the divider where the user left it in the arrangement chosen.
pub fn split(area: Rect, pictures: usize, chrome: Chrome, dividers: Dividers) -> Split {
    // Where some arrangement keeps the pictures at the floor, only such ones compete.
    let floor = [Arrangement::Beside, Arrangement::Stacked]
        .into_iter()
        .any(|a| !fractions(area, a, pictures, chrome, true).is_empty());
    let candidates = [Arrangement::Beside, Arrangement::Stacked].map(|a| {
        let f = best_fraction(area, a, pictures, chrome, floor);
        let (lo, hi) = allowed(area, a, chrome.min_part);
        // An arrangement whose parts cannot both have their least size (or, with the
        // floor, its pictures theirs) counts for nothing.
        let fits = lo <= hi && !(floor && fractions(area, a, pictures, chrome, true).is_empty());
        (a, f, if fits { score(sides(area, a, f, pictures, chrome), pictures) } else { -1.0 })
    });
    let (arrangement, best, _) = if candidates[1].2 > candidates[0].2 * 1.02 { candidates[1] } else { candidates[0] };
    let chosen = match arrangement {
        Arrangement::Beside => dividers.beside,
        Arrangement::Stacked => dividers.stacked,
    };
    let (lo, hi) = allowed(area, arrangement, chrome.min_part);
    let fraction = chosen.unwrap_or(best).clamp(lo.min(hi), hi.max(lo));
    let s = sides(area, arrangement, fraction, pictures, chrome);
    let (pictures_rect, divider, beside) = match arrangement {
        Arrangement::Beside => {
            let x = area.min.x + (area.width() - DIVIDER) * fraction;
            (
                Rect::from_min_max(area.min, pos2(x, area.max.y)),
                Rect::from_min_max(pos2(x, area.min.y), pos2(x + DIVIDER, area.max.y)),
                Rect::from_min_max(pos2(x + DIVIDER, area.min.y), area.max),
            )
        }
        Arrangement::Stacked => {
            let y = area.min.y + (area.height() - DIVIDER) * fraction;
            (
                Rect::from_min_max(area.min, pos2(area.max.x, y)),
                Rect::from_min_max(pos2(area.min.x, y), pos2(area.max.x, y + DIVIDER)),
                Rect::from_min_max(pos2(area.min.x, y + DIVIDER), area.max),
            )
        }
    };
    Split { arrangement, pictures: pictures_rect, divider, beside, fraction, sides: s }
}

/// The fraction the divider is dragged to, with the pointer at `pointer`.
pub fn dragged_fraction(area: Rect, arrangement: Arrangement, pointer: egui::Pos2) -> f32 {
    let f = match arrangement {
        Arrangement::Beside => (pointer.x - area.min.x) / (area.width() - DIVIDER).max(1.0),
        Arrangement::Stacked => (pointer.y - area.min.y) / (area.height() - DIVIDER).max(1.0),
    };
    f.clamp(0.2, 0.85)
}

/// An area of `w` x `h` points at the origin (for tests).
pub fn area(w: f32, h: f32) -> Rect {
    Rect::from_min_size(pos2(0.0, 0.0), vec2(w, h))
}

#[cfg(test)]
mod tests {
    use super::*;

    const CHROME: Chrome = Chrome { picture: 60.0, plot: 70.0, plot_wide: 36.0, min_part: 160.0 };

    #[test]
    fn a_wide_area_goes_side_by_side_and_a_tall_one_stacks() {
        let wide = split(area(900.0, 560.0), 1, CHROME, Dividers::default());
        assert_eq!(wide.arrangement, Arrangement::Beside);
        let tall = split(area(520.0, 900.0), 1, CHROME, Dividers::default());
        assert_eq!(tall.arrangement, Arrangement::Stacked);
        for s in [wide, tall] {
            assert!(s.pictures.max.x <= s.divider.min.x + 0.01 || s.pictures.max.y <= s.divider.min.y + 0.01);
            assert!(!s.pictures.intersects(s.beside.shrink(0.5)), "{s:?}");
            let (p, q) = s.sides;
            assert!(p > 300.0 && q > 250.0, "both large: {s:?}");
        }
    }

    #[test]
    fn the_squares_fill_the_area_they_are_given() {
        // 1280x720 presenting: the centre is about 880 x 600.
        let s = split(area(880.0, 600.0), 1, CHROME, Dividers::default());
        let (p, q) = s.sides;
        let used = p * p + q * q;
        assert!(used > 0.55 * 880.0 * 600.0, "{s:?}: {used}");
        // Two pictures share theirs.
        let s = split(area(880.0, 600.0), 2, CHROME, Dividers::default());
        assert!(s.sides.0 > 250.0 && s.sides.1 > 200.0, "{s:?}");
    }

    #[test]
    fn two_pictures_keep_the_floor_where_the_area_allows_it() {
        // 1280x720, both side panels open, the demo corrected: the centre is about 600 x 540.
        let s = split(area(600.0, 540.0), 2, CHROME, Dividers::default());
        assert!(s.sides.0 >= PICTURE_FLOOR, "{s:?}");
        assert_eq!(s.arrangement, Arrangement::Stacked);
        // Without the floor's constraint this area put them beside the plot, smaller.
        let beside = best_fraction(area(600.0, 540.0), Arrangement::Beside, 2, CHROME, false);
        assert!(sides(area(600.0, 540.0), Arrangement::Beside, beside, 2, CHROME).0 < PICTURE_FLOOR);
        // Where no arrangement can, the best one is used as before.
        let small = split(area(300.0, 300.0), 2, CHROME, Dividers::default());
        assert!(small.sides.0 > 0.0 && small.sides.0 < PICTURE_FLOOR, "{small:?}");
    }

    #[test]
    fn a_dragged_divider_is_kept_per_arrangement() {
        let a = area(900.0, 560.0);
        let d = Dividers { beside: Some(0.7), stacked: None };
        let s = split(a, 1, CHROME, d);
        assert_eq!(s.fraction, 0.7);
        let f = dragged_fraction(a, Arrangement::Beside, pos2(300.0, 10.0));
        assert!((f - 300.0 / 892.0).abs() < 1e-6);
        assert_eq!(dragged_fraction(a, Arrangement::Beside, pos2(-50.0, 0.0)), 0.2);
    }
}
