//! `phonglab diagnose`: which mistake made a student's picture of a scene. The scene is
//! drawn right and with each mistake of [`MISTAKES`] (a table: each mistake a function from
//! the drawing to the changed drawing, drawn by the same renderer), and each picture is
//! compared with the student's image over the object's pixels ([`super::picture_match`]).
//!
//! The verdict: "right" when the right picture explains at least [`RIGHT_AT`] of the
//! object's pixels; else "wrong" with the mistakes whose pictures explain at least
//! [`EXPLAINED_AT`] (best first), and [`MARGIN`] more than the right picture; else
//! "unexplained". A mistake that this scene cannot show
//! (no scale for `GL_NORMALIZE`, no spot to leave out) draws the right picture again: it
//! is left out of the comparison and listed as not visible.

use glam::DMat3;

use crate::equation::lighting::EvalOptions;
use crate::mesh::Mesh;
use crate::model::error::SceneError;
use crate::model::rules::{RuleSet, SpecularModel};
use crate::model::scene::{LightPlacement, NormalMode, Scene};
use crate::model::view::ShadingMode;
use crate::raster::render::{Job, Renderer};
use crate::teach::picture_match::{Match, compare};

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

/// Everything a picture is drawn from, owned: the renderer's [`Job`] without the borrows.
#[derive(Clone, Debug)]
pub struct Drawing {
    /// The lighting state and the modelview the object is lit under.
    pub scene: Scene,
    /// The mesh, object space.
    pub mesh: Mesh,
    /// Object to clip space.
    pub clip_from_object: glam::DMat4,
    /// The shading.
    pub mode: ShadingMode,
    /// The background colour (linear, as written).
    pub background: [f32; 3],
    /// Numerical options.
    pub options: EvalOptions,
}

impl Drawing {
    /// The drawing of `job`.
    pub fn of(job: &Job<'_>) -> Drawing {
        Drawing {
            scene: job.scene.clone(),
            mesh: job.mesh.clone(),
            clip_from_object: job.clip_from_object,
            mode: job.mode,
            background: job.background,
            options: job.options,
        }
    }

    /// The renderer's job for it.
    pub fn job(&self) -> Job<'_> {
        Job {
            scene: &self.scene,
            mesh: &self.mesh,
            clip_from_object: self.clip_from_object,
            mode: self.mode,
            background: self.background,
            cull_back: false,
            options: self.options,
        }
    }

    /// Drawn `size` pixels square: the renderer (its visibility kept, for probing), the
    /// pixels (RGBA8) and which pixels the object covers.
    pub fn draw(&self, size: usize) -> Result<(Renderer, Vec<u8>, Vec<bool>), SceneError> {
        let mut r = Renderer::new();
        r.keep_visibility(true);
        let rgba = r.render(&self.job(), size, size)?.0.rgba.clone();
        let covered = (0..size * size).map(|i| r.surface_at(i).is_some()).collect();
        Ok((r, rgba, covered))
    }

    /// The background as 8-bit levels.
    pub fn background8(&self) -> [u8; 3] {
        self.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)
    }
}

/// A mistake a picture can show: its id (kebab-case, the same as `phonglab check`'s where
/// the mistake is the same), its message, and the change it makes to the drawing.
pub struct PictureMistake {
    /// The id in JSON and the docs.
    pub id: &'static str,
    /// The message id of its words.
    pub message: &'static str,
    /// The drawing with the mistake made.
    pub apply: fn(&mut Drawing),
}

impl PictureMistake {
    /// Its words in the reader's language.
    pub fn words(&self) -> String {
        crate::locale::tr(self.message)
    }
}

/// Normals transformed by M: with each normal `n` replaced by `M^T M n`, the inverse
/// transpose gives `M n` (up to length), as the misconception's picture does.
fn normals_by_modelview(d: &mut Drawing) {
    let m = DMat3::from_mat4(d.scene.eye_from_object());
    for n in &mut d.mesh.normals {
        let bent = m.transpose() * m * n.as_dvec3();
        if bent.length() > 0.0 {
            *n = bent.normalize().as_vec3();
        }
    }
}

/// `GL_NORMALIZE` (or `GL_RESCALE_NORMAL`) off.
fn normalize_off(d: &mut Drawing) {
    d.scene.normal_mode = NormalMode::AsIs;
}

/// `R . V` where `n . H` belongs.
fn reflection_for_halfway(d: &mut Drawing) {
    d.scene.rules.specular = SpecularModel::Phong;
}

/// Lit per vertex where the scene lights per fragment.
fn gouraud_for_phong(d: &mut Drawing) {
    if d.mode == ShadingMode::Phong {
        d.mode = ShadingMode::Gouraud;
    }
}

/// No `f_i` gate: the Phong demo's rules (as the misconception draws it), Blinn-Phong kept.
fn specular_without_gate(d: &mut Drawing) {
    d.scene.rules.set = RuleSet::PhongDemo;
}

/// The attenuation's distance in object space: `k1 / s`, `k2 / s^2` for the modelview's
/// scale `s` (the cube root of its determinant; exact for a uniform scale).
fn attenuation_object_distance(d: &mut Drawing) {
    let s = DMat3::from_mat4(d.scene.eye_from_object()).determinant().abs().cbrt();
    if s > 0.0 && s.is_finite() {
        for l in &mut d.scene.lights {
            l.attenuation = [l.attenuation[0], l.attenuation[1] / s, l.attenuation[2] / (s * s)];
        }
    }
}

/// The light's position given before `gluLookAt`: under the identity, in eye coordinates.
fn light_before_view(d: &mut Drawing) {
    for l in &mut d.scene.lights {
        l.placement = LightPlacement::Eye;
    }
}

/// `GL_LIGHT_MODEL_LOCAL_VIEWER` the other way.
fn viewer_swapped(d: &mut Drawing) {
    d.scene.light_model.local_viewer = !d.scene.light_model.local_viewer;
}

/// Every normal pointing inwards.
fn flipped_normals(d: &mut Drawing) {
    for n in &mut d.mesh.normals {
        *n = -*n;
    }
}

/// `GL_LIGHT_MODEL_TWO_SIDE` off.
fn two_sided_off(d: &mut Drawing) {
    d.scene.light_model.two_sided = false;
}

/// Attenuation left out: (1, 0, 0).
fn attenuation_left_out(d: &mut Drawing) {
    for l in &mut d.scene.lights {
        l.attenuation = [1.0, 0.0, 0.0];
    }
}

/// The spot left out: cutoff 180.
fn spot_left_out(d: &mut Drawing) {
    for l in &mut d.scene.lights {
        l.spot_cutoff = 180.0;
    }
}

/// The picture mistakes, in the order the docs list them.
pub const MISTAKES: [PictureMistake; 12] = [
    PictureMistake { id: "normal-by-modelview", message: "wrong-cause-normals-by-m", apply: normals_by_modelview },
    PictureMistake { id: "normal-not-normalised", message: "diagnose-normalize-off", apply: normalize_off },
    PictureMistake {
        id: "reflection-for-halfway",
        message: "wrong-cause-reflection-for-halfway",
        apply: reflection_for_halfway,
    },
    PictureMistake {
        id: "gouraud-for-phong",
        message: "wrong-cause-gouraud-misses-highlight",
        apply: gouraud_for_phong,
    },
    PictureMistake {
        id: "specular-without-gate",
        message: "wrong-cause-specular-facing-away",
        apply: specular_without_gate,
    },
    PictureMistake {
        id: "attenuation-object-distance",
        message: "wrong-cause-attenuation-object-space",
        apply: attenuation_object_distance,
    },
    PictureMistake { id: "light-before-view", message: "wrong-cause-light-before-view", apply: light_before_view },
    PictureMistake { id: "viewer-swapped", message: "diagnose-viewer-swapped", apply: viewer_swapped },
    PictureMistake { id: "flipped-normals", message: "diagnose-flipped-normals", apply: flipped_normals },
    PictureMistake { id: "two-sided-off", message: "diagnose-two-sided-off", apply: two_sided_off },
    PictureMistake {
        id: "attenuation-left-out",
        message: "diagnose-attenuation-left-out",
        apply: attenuation_left_out,
    },
    PictureMistake { id: "spot-left-out", message: "diagnose-spot-left-out", apply: spot_left_out },
];

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
    /// The right picture (RGBA8).
    pub picture: Vec<u8>,
    /// The renderer that drew it, kept for probing.
    pub renderer: Renderer,
}

/// Compares `image` (RGBA8, `size` pixels square) with `right` drawn right and with each
/// mistake.
pub fn diagnose(right: &Drawing, image: &[u8], size: usize) -> Result<Diagnosis, SceneError> {
    let (renderer, picture, covered) = right.draw(size)?;
    let bg = right.background8();
    let exact = compare(&picture, &covered, image, bg, size);
    let mut tried = Vec::new();
    for (i, m) in MISTAKES.iter().enumerate() {
        let mut d = right.clone();
        (m.apply)(&mut d);
        let (_, wrong, wrong_covered) = d.draw(size)?;
        // A mistake whose picture the right one explains cannot be seen in this scene.
        let visible = compare(&wrong, &wrong_covered, &picture, bg, size).score < RIGHT_AT;
        let matched = visible.then(|| compare(&wrong, &wrong_covered, image, bg, size));
        tried.push(Tried { mistake: i, matched });
    }
    let key = |t: &Tried| t.matched.map_or(-1.0, |m| m.score);
    tried.sort_by(|a, b| key(b).total_cmp(&key(a)));
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
    Ok(Diagnosis { verdict, right: exact, causes, tried, picture, renderer })
}
