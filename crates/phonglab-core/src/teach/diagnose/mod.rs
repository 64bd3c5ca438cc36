//! `phonglab diagnose`: which mistake made a student's picture of a scene. The scene is
//! drawn right and with each mistake of [`MISTAKES`] (a table: each mistake a function from
//! the drawing to the changed drawing, made once or for each light in turn, drawn by the
//! same renderer), and each picture is compared with the student's image over the object's
//! pixels ([`super::picture_match`]). `emission-added`'s colour is fitted from the image
//! first (the median lift of the object's unclamped pixels).
//!
//! The verdict: "right" when the right picture explains at least [`RIGHT_AT`] of the
//! object's pixels; else "wrong" with the mistakes whose pictures explain at least
//! [`EXPLAINED_AT`] (best first), and [`MARGIN`] more than the right picture; else
//! "unexplained". A mistake whose change cannot alter this scene (a light that is already
//! directional, no colour material) is not offered; one whose picture the right picture
//! explains all the same (no scale for `GL_NORMALIZE`, no spot to leave out) is left out of
//! the comparison and listed as not visible, unless the image shows it where it differs
//! from the right picture ([`Footprint`]): then a "right" picture is wrong, that cause.
//! A picture the right one otherwise explains is not right either when a solid region or
//! thin marks of it differ ([`Region`], [`Marks`]).

mod bias;
mod calls;
mod change;
mod colours;
mod drawing;
mod falloff;
mod fit;
mod footprint;
mod grid;
mod levels;
mod mistakes;
mod offset;
mod outline;
pub mod said;
mod sides;
mod slips;
mod values;
mod within;

pub use bias::{Bias, SYSTEMATIC_AT, TILE as BIAS_SQUARE, systematic};
pub use change::{At, Given};
pub use colours::Colours;
pub use drawing::Drawing;
pub use footprint::{CLEARLY, FOOTPRINT_AT, Footprint, Group};
pub use grid::{JPEG_GRID_AT, jpeg_grid};
pub use levels::Levels;
pub use mistakes::{MISTAKES, PictureMistake, Scope, offered};
pub use offset::{BLOCK, OFFSET_AT, Offset};
pub use outline::{MARKS_AT, Marks, OUTLINE_AT, REGION_AT, Region};
pub use sides::Sides;
pub use within::{ROUNDING, Within};

use crate::model::error::SceneError;
use crate::raster::render::Renderer;
use crate::teach::picture_match::{LOSSY, Match, TOLERANCE, blended_share, compare, compare_within};

/// The share of the object's pixels the right picture must explain for "right". Measured
/// (docs/guide.md): the right picture shifted a pixel with 8-bit noise of ±2 scores 1;
/// Mesa's pictures of shipped scenes score 0.9986 to 1; a mistake's picture scores at most
/// 0.975 against the right one where the scene shows it at all.
pub const RIGHT_AT: f64 = 0.99;

/// The share a mistake's picture must explain to be named: each mistake's own picture,
/// shifted and noised, scores 1; the next best mistake at most 0.975 and an unrelated
/// picture at most 0.81.
pub const EXPLAINED_AT: f64 = 0.98;

/// How much more of the object a mistake's picture must explain than the right picture
/// does to be named: a mistake that changes only a few pixels cannot be told from noise.
pub const MARGIN: f64 = 0.01;

/// How far behind the first cause's share another cause may explain the picture and still
/// be named beside it ("also explains"): half of [`MARGIN`]. Measured (docs/guide.md): the
/// teacher's local viewer on the worksheet's scene is explained at 100 % by its cause and at
/// 98.8 % and 98.6 % by attenuations fitted to it; a shininess typed as its 0–1 value at 100 %
/// and at 99.3 % by a red-only specular colour fitted to it.
pub const ALSO_WITHIN: f64 = 0.005;

/// The verdict on an image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The right picture explains it.
    Right,
    /// One or more mistakes explain it.
    Wrong,
    /// Neither the right picture nor any mistake does.
    Unexplained,
}

impl Tried {
    /// Its id in JSON and the docs.
    pub fn id(&self) -> &'static str {
        MISTAKES[self.mistake].id
    }

    /// The light it was made for, for a mistake made for each light in turn.
    pub fn light(&self) -> Option<usize> {
        (MISTAKES[self.mistake].scope == Scope::EachLight).then_some(self.at.light)
    }

    /// Its id with the light it was made for ("light-left-out, GL_LIGHT1"), for text.
    pub fn label(&self) -> String {
        match self.light() {
            Some(n) => format!("{}, GL_LIGHT{n}", self.id()),
            None => self.id().to_owned(),
        }
    }

    /// Its id with the light it was made for in brackets ("light-left-out (GL_LIGHT1)"),
    /// for lists of ids, as the window names a cause.
    pub fn listed(&self) -> String {
        match self.light() {
            Some(n) => format!("{} (GL_LIGHT{n})", self.id()),
            None => self.id().to_owned(),
        }
    }

    /// Whether a value of it was fitted from the picture (a `-differs` value, the colours,
    /// the materials, the emission added), rather than one changed value of the scene.
    pub fn fitted(&self) -> bool {
        let id = self.id();
        id.ends_with("-differs") || ["colours-differ", "materials-differ", "emission-added"].contains(&id)
    }

    /// Its words in the reader's language, naming the light.
    pub fn words(&self) -> String {
        MISTAKES[self.mistake].words_at(self.at)
    }
}

impl Verdict {
    /// Its name in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Right => "right",
            Verdict::Wrong => "wrong",
            Verdict::Unexplained => "unexplained",
        }
    }
}

/// One mistake's picture against the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tried {
    /// Its place in [`MISTAKES`].
    pub mistake: usize,
    /// Where it was made: the light, for a mistake made for each light in turn; the
    /// emission fitted from the image.
    pub at: At,
    /// How its picture matches the image; `None` when this scene cannot show it (its
    /// picture is the right one).
    pub matched: Option<Match>,
}

/// What `diagnose` found.
pub struct Diagnosis {
    /// The verdict.
    pub verdict: Verdict,
    /// The right picture against the image.
    pub right: Match,
    /// The mistakes that explain the image, best first (empty unless wrong).
    pub causes: Vec<Tried>,
    /// Every mistake tried, best first; those the scene cannot show last.
    pub tried: Vec<Tried>,
    /// The causes whose pictures are the first cause's picture (it among them): the image
    /// cannot tell them apart. Empty when the first cause draws a picture of its own.
    pub same_picture: Vec<Tried>,
    /// The right picture (RGBA8).
    pub picture: Vec<u8>,
    /// The renderer that drew it, kept for probing.
    pub renderer: Renderer,
    /// What the picture's shape shows before its colours, when it is not the scene's
    /// picture or holds a defect (the verdict is then unexplained).
    pub shape: Option<Shape>,
    /// The right picture's match within [`LOSSY`] levels when the verdict "right" rests on
    /// it: the picture differs from the right one as a lossy saving (JPEG) does.
    pub lossy: Option<Match>,
    /// Where the first cause's picture differs from the right one, when the verdict
    /// "wrong" rests on it: the right picture explains the share [`RIGHT_AT`] asks, but
    /// over these pixels the picture is the mistake's ([`Footprint::shows_mistake`]).
    pub footprint: Option<Footprint>,
    /// How far the image is from the right picture inside the object, in place, when the
    /// verdict is "right": unless [`Within::exact`], it is right only within what a
    /// picture can tell.
    pub within: Option<Within>,
    /// How much more the image's difference from the right picture jumps across the edges
    /// of JPEG's 8 x 8 blocks than inside them ([`jpeg_grid`]): from [`JPEG_GRID_AT`] the
    /// picture looks saved as JPEG.
    pub grid: f64,
    /// Where the image is evenly off the right picture by more than losses make, when that
    /// alone kept an "unexplained" picture from "right as saved lossily" ([`systematic`]).
    pub bias: Option<Bias>,
    /// When "wrong" rests on the picture being nearer a fitted value's drawing than the
    /// right one's though both explain it within the tolerance (`colours_shown`): the mean
    /// levels (the three channels summed, over the object's inside) by which the image misses
    /// the cause's picture, then the right one's.
    pub nearer: Option<(f64, f64)>,
}

/// What a picture's shape shows that no mistake's colours explain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// Only the background: nothing of the object is drawn.
    NothingDrawn,
    /// The object's outline is not that of the scene's picture nor of any mistake's: the
    /// share of the outlines that differs (beyond a pixel's shift).
    OtherOutline(f64),
    /// A solid region differs from a picture the right one otherwise explains.
    Region(Region),
    /// Thin marks (lines drawn over the object) differ from a picture the right one
    /// otherwise explains.
    Marks(Marks),
    /// The whole picture's levels changed (a gamma, a brightness), which explains it at
    /// least as well as any mistake does.
    Levels(Levels),
    /// A square of [`BLOCK`] pixels is evenly lighter or darker than in a picture the
    /// right one otherwise explains ([`Offset`]).
    Offset(Offset),
}

impl Shape {
    /// Its id in JSON.
    pub fn id(&self) -> &'static str {
        match self {
            Shape::NothingDrawn => "nothing-drawn",
            Shape::OtherOutline(_) => "outline-differs",
            Shape::Region(_) => "region-differs",
            Shape::Marks(_) => "marks-differ",
            Shape::Levels(_) => "levels-changed",
            Shape::Offset(_) => "offset-differs",
        }
    }
}

/// The most pictures [`diagnose`] draws for `right`: the right one and each mistake it
/// offers (`emission-added` counted).
pub fn drawings_at_most(right: &Drawing) -> usize {
    let colours = Colours {
        lights: right.scene.lights.len(),
        fitted: [[1.0; 3]; colours::TERMS],
        scene: [[0.0; 3]; colours::TERMS],
        shown: Some(colours::Nearer { pixels: 0, to_fitted: 0.0, to_scene: 0.0 }),
    };
    let mut every = values::Values::default();
    for (i, l) in right.scene.lights.iter().enumerate().take(crate::model::scene::MAX_LIGHTS) {
        for k in 0..values::LIGHT_NAMES.len() {
            every.lights[i][k] = Some((values::light_value(l, k) + 1.0, values::light_value(l, k)));
        }
    }
    every.shininess = Some((right.scene.material.shininess + 1.0, right.scene.material.shininess));
    let sides = Sides { fitted: [[[1.0; 3]; 4]; 2], scene: [[[0.0; 3]; 4]; 2], shininess: [(0.0, 0.0); 2] };
    let at = At { emission: [1.0; 3], colours: Some(colours), values: every, sides: Some(sides), ..At::default() };
    offered(right, at).len()
        + 1
        + colours::drawings(right)
        + values::drawings(right)
        + falloff::drawings(right)
        + sides::drawings(right)
}

/// Compares `image` (RGBA8, `size` pixels square) with `right` drawn right and with each
/// mistake it offers, one picture at a time (the renderer spreads each over the thread
/// pool; drawing several at once would hold several renderers' memory).
pub fn diagnose(right: &Drawing, image: &[u8], size: usize) -> Result<Diagnosis, SceneError> {
    let (renderer, picture, covered) = right.draw(size)?;
    let bg = right.background8();
    let exact = compare(&picture, &covered, image, bg, size);
    let outline = outline::mask(image, None, bg, size);
    let mut outlines = Outlines {
        apart: outline::apart(&outline::mask(&picture, Some(&covered), bg, size), &outline, size),
        drawn: true,
    };
    let mut found = Found::default();
    let given = Given::of(right);
    // The mistakes of one changed value first: their outlines alone decide whether the
    // picture's shape is the scene's, and where it is not, no value fitted from the picture
    // can change the verdict, so the fits (most of the drawing) are not made.
    let unfitted = At { light: 0, emission: [0.0; 3], colours: None, values: Default::default(), sides: None, given };
    for (mistake, at) in offered(right, unfitted) {
        if !(Tried { mistake, at, matched: None }).fitted() {
            let wrong = found.try_one(right, (mistake, at), (&picture, &covered), image, size)?;
            outlines.add(&outline::mask(&wrong.0, Some(&wrong.1), bg, size), &outline, size);
        }
    }
    if outlines.shape(&outline).is_none() {
        let emission = fit::emission(&picture, &covered, image, size);
        let colours = colours::fit(right, &covered, image, size)?;
        let values = values::fit(right, image, size)?;
        let values = falloff::shown(right, (&picture, &covered), colours.as_ref(), values, image, size)?;
        let sides = sides::fit(right, &covered, image, size)?;
        for (mistake, at) in offered(right, At { light: 0, emission, colours, values, sides, given }) {
            // A colour fitted from the picture may draw the object in the background's
            // colour: its outline is not compared.
            if (Tried { mistake, at, matched: None }).fitted() {
                found.try_one(right, (mistake, at), (&picture, &covered), image, size)?;
            }
        }
    }
    // In the table's order, as the mistakes are offered.
    found.tried.sort_by_key(|t| (t.mistake, t.at.light));
    let Found { tried, mut subtle, mut seen, pictures } = found;
    let mut d = verdict_of(exact, tried, picture, renderer);
    d.shape = outlines.shape(&outline);
    if d.shape.is_none() && d.verdict != Verdict::Right {
        d.shape = levels_changed(&d, &pictures, &covered, image, bg, size).map(Shape::Levels);
    }
    if d.shape.is_none() && d.verdict == Verdict::Unexplained {
        // A mean over many pixels that noise cannot make is a change of the picture, not
        // losses: the cause that explains the picture within the losses, or none.
        let lossy = lossy_right(&d, &covered, image, bg, size);
        match lossy.map(|_| systematic(&d.picture, &covered, image, size)) {
            Some(None) => {
                (d.verdict, d.lossy) = (Verdict::Right, lossy);
                subtle.append(&mut seen);
            }
            Some(Some(bias)) => match lossy_cause(right, &d, image, bg, size)? {
                Some(t) => (d.verdict, d.causes) = (Verdict::Wrong, vec![t]),
                None => d.bias = Some(bias),
            },
            None => {}
        }
    }
    if d.shape.is_none() && d.verdict == Verdict::Right {
        shown_subtly(&mut d, subtle);
    }
    if d.shape.is_none()
        && d.verdict == Verdict::Right
        && let Some(t) = colours_shown(right, &d, &covered, image, size)?
    {
        (d.verdict, d.causes, d.lossy) = (Verdict::Wrong, vec![t.0], None);
        let flat = levels::inner_pixels(&covered, size);
        d.nearer = Some((t.1, levels::distance(&d.picture, image, &flat)));
    }
    // A picture right as saved lossily may have had its colour subsampled (a JPEG): a region
    // or marks must differ beyond what that makes of the right picture.
    let subsampled = d.lossy.is_some();
    if d.shape.is_none() && d.verdict == Verdict::Right {
        let region = outline::largest_region(&d.picture, &covered, image, bg, size, subsampled);
        d.shape = region.filter(|r| r.pixels >= REGION_AT).map(Shape::Region);
    }
    if d.shape.is_none() && d.verdict == Verdict::Right {
        let marks = outline::largest_marks(&d.picture, &covered, image, bg, size, subsampled);
        d.shape = marks.filter(|m| m.pixels >= MARKS_AT).map(Shape::Marks);
    }
    if d.shape.is_none() && d.verdict == Verdict::Right {
        // A picture right as saved lossily: what a JPEG's subsampled colour makes of a square
        // near a coloured edge is a loss, as a sub-pixel shift is.
        let largest = if subsampled { offset::largest_offset_subsampled } else { offset::largest_offset };
        let off = largest(&d.picture, &covered, image, size).filter(|o| o.beyond_shift() >= OFFSET_AT);
        if let Some(o) = off {
            match offset_explained(right, &d, (&covered, o), image, size)? {
                Some(t) => (d.verdict, d.causes, d.lossy) = (Verdict::Wrong, vec![t], None),
                None => d.shape = Some(Shape::Offset(o)),
            }
        }
    }
    if d.shape.is_some() {
        (d.verdict, d.causes, d.lossy) = (Verdict::Unexplained, Vec::new(), None);
    }
    if d.verdict == Verdict::Right {
        d.within = Some(within::within(&d.picture, &covered, image, size));
    }
    d.grid = jpeg_grid(&d.picture, &covered, image, size);
    d.same_picture = pictures.same_as_first(&d.causes, bg, size);
    // The image cannot rank causes that draw the same picture: they go first in the
    // table's order, the other causes after them as scored.
    let rest: Vec<Tried> = d.causes.iter().filter(|t| !d.same_picture.contains(t)).copied().collect();
    d.causes = d.same_picture.iter().chain(&rest).copied().collect();
    // "Also explains" lists only the causes that explain the picture about as well as the
    // first: a fit a share behind it is not a cause the picture points to.
    let best = d.causes.iter().filter_map(|t| t.matched).map(|m| m.score).fold(0.0, f64::max);
    d.causes.retain(|t| t.matched.is_some_and(|m| m.score >= best - ALSO_WITHIN));
    Ok(d)
}

/// What drawing each mistake found: every mistake tried, those the image shows over their
/// footprints, and the pictures of those that may be named.
#[derive(Default)]
struct Found {
    tried: Vec<Tried>,
    /// The footprints of mistakes the right picture explains that the image shows.
    subtle: Vec<(Tried, Footprint)>,
    /// The footprints of the mistakes the scene shows that the image shows too: a lossy
    /// saving's noise may hide them from the share, never from their footprint.
    seen: Vec<(Tried, Footprint)>,
    pictures: Pictures,
}

impl Found {
    /// Draws mistake `made` (its row and where) of `right` and measures its picture against
    /// `image` and the right picture `right_picture` (RGBA8 and covered); returns the
    /// mistake's picture and covered pixels.
    fn try_one(
        &mut self,
        right: &Drawing,
        made: (usize, At),
        right_picture: (&[u8], &[bool]),
        image: &[u8],
        size: usize,
    ) -> Result<(Vec<u8>, Vec<bool>), SceneError> {
        let (mistake, at) = made;
        let (picture, covered) = right_picture;
        let bg = right.background8();
        let mut d = right.clone();
        (MISTAKES[mistake].apply)(&mut d, at);
        let (_, wrong, wrong_covered) = d.draw(size)?;
        // A mistake whose picture the right one explains cannot be seen in this scene,
        // unless the image is the mistake's where the two differ.
        let visible = compare(&wrong, &wrong_covered, picture, bg, size).score < RIGHT_AT;
        let shown = footprint::footprint((picture, covered), (&wrong, &wrong_covered), image, size)
            .filter(Footprint::shows_mistake);
        let matched = (visible || shown.is_some()).then(|| compare(&wrong, &wrong_covered, image, bg, size));
        let t = Tried { mistake, at, matched };
        if visible {
            self.seen.extend(shown.map(|f| (t, f)));
        } else {
            self.subtle.extend(shown.map(|f| (t, f)));
        }
        if matched.is_some_and(|m| m.score >= EXPLAINED_AT) {
            self.pictures.0.push((t, wrong.clone(), wrong_covered.clone()));
        }
        self.tried.push(t);
        Ok((wrong, wrong_covered))
    }
}

/// When the picture shows the colours fitted from it ([`Colours::shown`]) though the right
/// picture explains it (a colour a few levels off, the Phong demo's diffuse 0.388 for 0.4,
/// moves each pixel within the share's tolerance, and the picture is still nearer the
/// fitted colours' drawing than the scene's by far): of the mistakes with values fitted
/// from the picture (`colours-differ`, a shininess, an attenuation), the one whose drawing
/// is nearest it in place (a shininess 10 % off is shown by a specular colour fitted to it
/// too), its match measured.
/// With the mean levels by which the image misses the chosen mistake's drawing (over the
/// object's inside).
fn colours_shown(
    right: &Drawing,
    d: &Diagnosis,
    covered: &[bool],
    image: &[u8],
    size: usize,
) -> Result<Option<(Tried, f64)>, SceneError> {
    let shown = |t: &Tried| t.id() == "colours-differ" && t.at.colours.is_some_and(|c| c.shown.is_some());
    if !d.tried.iter().any(shown) {
        return Ok(None);
    }
    let flat = levels::inner_pixels(covered, size);
    let best = best_fitted_scored(right, d, image, size, |rgba, _| Some(levels::distance(rgba, image, &flat)))?;
    Ok(best.map(|(far, t)| (t, far)))
}

/// Of the mistakes with a value fitted from `image`, drawn one by one, the one `score`
/// (its picture and coverage; `None`: not this one) gives the least, its match measured
/// against `image`: the one loop [`colours_shown`], [`offset_explained`] and [`lossy_cause`]
/// choose with.
fn best_fitted(
    right: &Drawing,
    d: &Diagnosis,
    image: &[u8],
    size: usize,
    score: impl Fn(&[u8], &[bool]) -> Option<f64>,
) -> Result<Option<Tried>, SceneError> {
    Ok(best_fitted_scored(right, d, image, size, score)?.map(|(_, t)| t))
}

/// [`best_fitted`] with the least score it found.
fn best_fitted_scored(
    right: &Drawing,
    d: &Diagnosis,
    image: &[u8],
    size: usize,
    score: impl Fn(&[u8], &[bool]) -> Option<f64>,
) -> Result<Option<(f64, Tried)>, SceneError> {
    let mut best: Option<(f64, Tried)> = None;
    for t in d.tried.iter().filter(|t| t.fitted()) {
        let mut wrong = right.clone();
        if !(MISTAKES[t.mistake].apply)(&mut wrong, t.at) {
            continue;
        }
        let (_, rgba, wrong_covered) = wrong.draw(size)?;
        let Some(score) = score(&rgba, &wrong_covered) else { continue };
        if best.is_none_or(|(b, _)| score < b) {
            let matched = compare(&rgba, &wrong_covered, image, right.background8(), size);
            best = Some((score, Tried { matched: Some(matched), ..*t }));
        }
    }
    Ok(best)
}

/// The mistake with a value fitted from `image` (a shininess, an attenuation, the colours)
/// whose picture moves the square of `off` as the image does ([`OFFSET_AT`]) and leaves no
/// square of the image evenly off its own picture: a shininess 10 % off on the three-lights
/// scene brightens the highlights' surround by a few levels, each pixel within the share's
/// tolerance, and is that mistake, not a square painted over. The one whose picture leaves
/// the least offset, its match measured; `None` when none explains it.
fn offset_explained(
    right: &Drawing,
    d: &Diagnosis,
    (covered, off): (&[bool], Offset),
    image: &[u8],
    size: usize,
) -> Result<Option<Tried>, SceneError> {
    best_fitted(right, d, image, size, |rgba, wrong_covered| {
        let own = offset::offset_over(&d.picture, covered, rgba, off, size);
        let left = offset::largest_offset(rgba, wrong_covered, image, size).map_or(0.0, |o| o.beyond_shift().max(0.0));
        let moves = own.abs() >= OFFSET_AT && own.signum() == off.levels.signum();
        (moves && left < OFFSET_AT).then_some(left)
    })
}

/// The change of the whole picture's levels ([`levels`]) that explains `image` where the
/// right picture does not: at least [`EXPLAINED_AT`] of the object's pixels, and no cause
/// named clearly closer ([`levels::clearly_closer`]). A gamma or a brightness change of a
/// right picture is not a lighting mistake.
fn levels_changed(
    d: &Diagnosis,
    pictures: &Pictures,
    covered: &[bool],
    image: &[u8],
    bg: [u8; 3],
    size: usize,
) -> Option<Levels> {
    let flat = levels::inner_pixels(covered, size);
    let changed = levels::fit(&d.picture, covered, image, bg, &flat, size)?;
    let first = d.causes.first().and_then(|t| pictures.0.iter().find(|(p, ..)| p == t));
    let closer = first.is_some_and(|(t, rgba, _)| {
        t.matched.is_some_and(|m| levels::clearly_closer(m, levels::distance(rgba, image, &flat), &changed, MARGIN))
    });
    (changed.matched.score >= EXPLAINED_AT && !closer).then_some(changed)
}

/// The right picture's match within [`LOSSY`] levels when it explains `image` as a picture
/// saved lossily (JPEG) explains its original: at least [`RIGHT_AT`] of the object's pixels
/// within [`LOSSY`] levels of a blend of their neighbours ([`blended_share`]), and the right
/// picture missing by less, on the mean, than every
/// mistake's picture that the scene shows (noise adds to each alike; a mistake adds its own
/// difference to the right picture's), with no level lifted or lowered on the median by
/// more than 1 (lossy saving adds noise, not a bias: a tone curve is not taken for it).
fn lossy_right(d: &Diagnosis, covered: &[bool], image: &[u8], bg: [u8; 3], size: usize) -> Option<Match> {
    let loose = compare_within(&d.picture, covered, image, bg, size, LOSSY);
    // A pixel may also be a blend of its neighbours (resized, blurred, antialiased, moved
    // half a pixel): along the outline such a pixel is half the object's, half the
    // background's, far from either.
    // A JPEG may also have had its colour subsampled (4:2:0, JPEG's usual way, its 8 x 8
    // blocks too faint to see at high quality): its brightness is then the right picture's
    // blend, its colour a wider one's.
    let share = blended_share(&d.picture, covered, image, bg, size, LOSSY)
        .max(crate::teach::picture_match::blended_share_subsampled(&d.picture, covered, image, bg, size, LOSSY));
    let blended = Match { score: share, ..loose };
    let closest = d.tried.iter().filter_map(|t| t.matched).map(|m| m.miss).fold(f64::INFINITY, f64::min);
    let unbiased = fit::lifts(&d.picture, covered, image, size).iter().all(|(all, _)| all.abs() <= 1);
    // A blend of the right picture's neighbours within the tolerance nearly everywhere is
    // the right picture resampled or blurred, however near a value fitted to it comes.
    let resampled = blended_share(&d.picture, covered, image, bg, size, TOLERANCE) >= RIGHT_AT;
    (blended.score >= RIGHT_AT && (d.right.miss < closest || resampled) && unbiased).then_some(blended)
}

/// The mistake with a value fitted from `image` whose picture explains it as a lossy saving
/// explains its original ([`blended_share`] within [`LOSSY`] levels for at least
/// [`RIGHT_AT`] of the object, and no square evenly off it: [`systematic`]), the nearest in
/// place of those; `None` when none does.
fn lossy_cause(
    right: &Drawing,
    d: &Diagnosis,
    image: &[u8],
    bg: [u8; 3],
    size: usize,
) -> Result<Option<Tried>, SceneError> {
    best_fitted(right, d, image, size, |rgba, wrong_covered| {
        let within = blended_share(rgba, wrong_covered, image, bg, size, LOSSY) >= RIGHT_AT;
        let flat = levels::inner_pixels(wrong_covered, size);
        (within && systematic(rgba, wrong_covered, image, size).is_none()).then(|| levels::distance(rgba, image, &flat))
    })
}

/// A "right" verdict made "wrong" by the mistakes the image shows over their footprints
/// (`subtle`), those it is nearest first (the mean levels it misses the mistake's picture
/// by, as a share of those it misses the right one's by).
fn shown_subtly(d: &mut Diagnosis, mut subtle: Vec<(Tried, Footprint)>) {
    let nearer = |f: &Footprint| f.mistake / f.right.max(f64::MIN_POSITIVE);
    subtle.sort_by(|a, b| nearer(&a.1).total_cmp(&nearer(&b.1)).then(a.0.mistake.cmp(&b.0.mistake)));
    let Some((_, first)) = subtle.first().cloned() else { return };
    d.verdict = Verdict::Wrong;
    d.causes = subtle.iter().map(|(t, _)| *t).collect();
    (d.lossy, d.footprint) = (None, Some(first));
}

/// How the image's outline agrees with the pictures drawn: the least share apart, and
/// whether every picture draws something.
struct Outlines {
    apart: f64,
    drawn: bool,
}

impl Outlines {
    /// Takes in a mistake's picture's outline `mask` against the image's `image`.
    fn add(&mut self, mask: &[bool], image: &[bool], size: usize) {
        self.apart = self.apart.min(outline::apart(mask, image, size));
        self.drawn &= mask.contains(&true);
    }

    /// What the image's outline `image` shows when no picture's outline is within
    /// [`OUTLINE_AT`] of it: nothing drawn where the image has no outline (and every
    /// picture has one), else another outline.
    fn shape(&self, image: &[bool]) -> Option<Shape> {
        if self.apart <= OUTLINE_AT {
            None
        } else if self.drawn && !image.contains(&true) {
            Some(Shape::NothingDrawn)
        } else {
            Some(Shape::OtherOutline(self.apart))
        }
    }
}

/// The pictures of the mistakes that may be named, kept to tell which draw the same.
#[derive(Default)]
struct Pictures(Vec<(Tried, Vec<u8>, Vec<bool>)>);

impl Pictures {
    /// The causes named with the first cause's score (to the 0.1 % the report shows) whose
    /// pictures and the first cause's explain each other as the right picture explains its
    /// own copy ([`RIGHT_AT`]), the first among them, in the table's order; empty when none
    /// but the first.
    fn same_as_first(&self, causes: &[Tried], bg: [u8; 3], size: usize) -> Vec<Tried> {
        let picture_of = |t: &Tried| self.0.iter().find(|(p, ..)| p == t).map(|(_, rgba, covered)| (rgba, covered));
        let score = |t: &Tried| t.matched.map_or(0.0, |m| m.score);
        let Some(top) = causes.first() else { return Vec::new() };
        let Some((first, first_covered)) = picture_of(top) else { return Vec::new() };
        let same: Vec<Tried> = causes
            .iter()
            .filter(|t| (score(t) - score(top)).abs() < 0.0005)
            .filter(|t| {
                picture_of(t).is_some_and(|(rgba, covered)| {
                    compare(rgba, covered, first, bg, size).score >= RIGHT_AT
                        && compare(first, first_covered, rgba, bg, size).score >= RIGHT_AT
                })
            })
            .copied()
            .collect();
        let mut same = same;
        same.sort_by_key(|t| (t.mistake, t.at.light));
        if same.len() >= 2 { same } else { Vec::new() }
    }
}

impl Diagnosis {
    /// The verdict "right" in words when it rests on a lossy saving ([`Diagnosis::lossy`]).
    pub fn lossy_words(&self) -> Option<String> {
        self.lossy.and_then(|_| self.lines().into_iter().next())
    }

    /// In words, when the verdict "wrong" rests on where the first cause's picture differs
    /// from the right one ([`Diagnosis::footprint`]): how few pixels, where, and how near
    /// the picture is to each there.
    pub fn footprint_words(&self) -> Option<String> {
        self.footprint.as_ref().map(footprint_said)
    }

    /// In words, when the first causes draw the same picture: that the image cannot tell
    /// them apart, and the order they are listed in.
    pub fn same_picture_words(&self) -> Option<String> {
        same_picture_said(&self.same_picture)
    }
}

/// [`Diagnosis::footprint_words`] of the footprint `f`.
fn footprint_said(f: &Footprint) -> String {
    use crate::locale::{Arg, decimal, tr_args};
    use crate::teach::picture_match::TOLERANCE;
    let levels = |v: f64| Arg::Text(decimal(&format!("{v:.1}")));
    tr_args(
        "diagnose-footprint",
        &[
            ("most", Arg::Text(f.most.to_string())),
            ("tolerance", Arg::Text(TOLERANCE.to_string())),
            ("pixels", Arg::Text(f.pixels.to_string())),
            ("groups", Arg::Text(groups_said(&f.groups))),
            ("mistake", levels(f.mistake)),
            ("right", levels(f.right)),
        ],
    )
}

/// The mistakes students make most often, in that order: among causes that draw the same
/// picture these are listed first; the others follow in the table's order, those with a
/// value fitted from the picture last.
const MOST_COMMON: [&str; 8] = [
    "light-left-out",
    "spot-cutoff-radians",
    "spot-direction-reversed",
    "light-before-view",
    "row-vectors",
    "vlv-reversed",
    "spot-cutoff-cosine",
    "flipped-normals",
];

/// The causes `same` (which draw the same picture) the most common first.
pub fn most_common_first(same: &[Tried]) -> Vec<Tried> {
    let rank = |t: &Tried| (t.fitted(), MOST_COMMON.iter().position(|&id| id == t.id()).unwrap_or(MOST_COMMON.len()));
    let mut out = same.to_vec();
    out.sort_by_key(|t| rank(t));
    out
}

/// The ids of `tried` as a list for people: each once, its light in brackets.
pub fn listed(tried: &[Tried]) -> String {
    let mut seen: Vec<String> = Vec::new();
    for t in tried {
        let l = t.listed();
        if !seen.contains(&l) {
            seen.push(l);
        }
    }
    seen.join(", ")
}

/// What the picture shows, in one sentence, when the causes `same` that draw it include a
/// light left out: nothing of that light reaches the object.
pub fn picture_shows(same: &[Tried]) -> Option<String> {
    let off = same.iter().find(|t| t.id() == "light-left-out")?;
    let light = crate::locale::Arg::Text(off.at.light.to_string());
    Some(crate::locale::tr_args("diagnose-light-unseen", &[("light", light)]))
}

/// [`Diagnosis::same_picture_words`] of the causes `same` (none when it is empty): one
/// line, the ids the most common first, each once; the order's rule said only when some
/// are fitted from the picture and some are not.
pub fn same_picture_said(same: &[Tried]) -> Option<String> {
    (!same.is_empty()).then(|| {
        let ordered = most_common_first(same);
        let ids = crate::locale::Arg::Text(listed(&ordered));
        let mixed = ordered.iter().any(Tried::fitted) && !ordered.iter().all(Tried::fitted);
        let id = if mixed { "diagnose-same-picture-fitted" } else { "diagnose-same-picture" };
        crate::locale::tr_args(id, &[("ids", ids)])
    })
}

/// The verdict from the right picture's match and each mistake's.
fn verdict_of(exact: Match, mut tried: Vec<Tried>, picture: Vec<u8>, renderer: Renderer) -> Diagnosis {
    let key = |t: &Tried| t.matched.map_or(-1.0, |m| m.score);
    // Among mistakes that explain the same share, the one whose pixels miss by least first.
    let miss = |t: &Tried| t.matched.map_or(f64::INFINITY, |m| m.miss);
    tried.sort_by(|a, b| key(b).total_cmp(&key(a)).then(miss(a).total_cmp(&miss(b))));
    let causes: Vec<Tried> =
        tried.iter().filter(|t| key(t) >= EXPLAINED_AT && key(t) >= exact.score + MARGIN).copied().collect();
    let verdict = if exact.score >= RIGHT_AT {
        Verdict::Right
    } else if causes.is_empty() {
        Verdict::Unexplained
    } else {
        Verdict::Wrong
    };
    let causes = if verdict == Verdict::Wrong { causes } else { Vec::new() };
    Diagnosis {
        verdict,
        right: exact,
        causes,
        tried,
        same_picture: Vec::new(),
        picture,
        renderer,
        shape: None,
        lossy: None,
        footprint: None,
        within: None,
        grid: 1.0,
        bias: None,
        nearer: None,
    }
}

/// A footprint's groups in words: the largest [`GROUPS_SAID`], each with its pixels and
/// box, then how many pixels the rest hold.
fn groups_said(groups: &[Group]) -> String {
    use crate::locale::{Arg, tr, tr_args};
    let mut said: Vec<String> = groups
        .iter()
        .take(GROUPS_SAID)
        .map(|g| {
            let at = |name: &'static str, v: usize| (name, Arg::Text(v.to_string()));
            tr_args(
                "diagnose-footprint-group",
                &[
                    ("count", Arg::Text(g.pixels.to_string())),
                    at("x0", g.from.0),
                    at("y0", g.from.1),
                    at("x1", g.to.0),
                    at("y1", g.to.1),
                ],
            )
        })
        .collect();
    let rest: usize = groups.iter().skip(GROUPS_SAID).map(|g| g.pixels).sum();
    if rest > 0 {
        said.push(tr_args("diagnose-footprint-rest", &[("count", Arg::Text(rest.to_string()))]));
    }
    match said.split_last() {
        Some((last, first)) if !first.is_empty() => {
            format!("{} {} {last}", first.join(", "), tr("diagnose-footprint-and"))
        }
        _ => said.concat(),
    }
}

/// How many of a footprint's groups are told one by one.
const GROUPS_SAID: usize = 3;
