//! "What is wrong with this picture?": seven mistakes students make with the lighting
//! equation, each as a picture drawn right and drawn with the mistake, by the same renderer
//! with one switch changed, and the probe's numbers that show the cause.
//!
//! | mistake | the switch | drawn with |
//! |---|---|---|
//! | normals by `M`, not `(M^-1)^T` | each mesh normal `n` replaced by `M^T M n`, so that the inverse transpose makes it `M n` exactly | an ellipsoid: the sphere scaled (1.45, 0.65, 1) |
//! | a normal not normalised | `GL_NORMALIZE` off (`AsIs`) | a sphere of radius 2 scaled by 0.5: normals of length 2, Gouraud |
//! | `R . V` where `N . H` was meant | the specular model | Phong shading |
//! | Gouraud missing a highlight | Gouraud instead of Phong | a coarse sphere (8 x 8), shininess 60 |
//! | specular light on faces turned away | no `f_i` gate (the Phong demo's rule, Blinn-Phong kept; no scene ambient or emission, so nothing else differs) | a light from behind, shininess 4 |
//! | attenuation in the wrong space | the distance measured in object space: `k1 / s`, `k2 / s^2` for a uniform scale `s` (exact) | a sphere of radius 4 scaled by 0.25 |
//! | the light placed before the view transform | placement eye instead of world (Robins' lightposition tutor swaps the two calls) | the camera on the far side from the light: drawn right, half the sphere is dark |
//!
//! Each mistake's [`check`] is the claim its key makes, tested on its pictures.

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::equation::lighting::EvalOptions;
use crate::mesh::Mesh;
use crate::mesh::sphere::glu_sphere;
use crate::model::error::SceneError;
use crate::model::rules::{RuleSet, Rules, SpecularModel};
use crate::model::scene::{Light, LightPlacement, NormalMode, Scene};
use crate::model::view::ShadingMode;
use crate::raster::render::{Job, Renderer};

/// One of the mistakes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Misconception {
    /// Normals transformed by M instead of its inverse transpose.
    NormalsByModelview,
    /// A normal not normalised.
    NormalNotNormalised,
    /// The reflection vector used where the halfway vector belongs.
    ReflectionForHalfway,
    /// Gouraud shading missing a highlight.
    GouraudMissesHighlight,
    /// Specular light on faces turned away from the light.
    SpecularOnFacesTurnedAway,
    /// Attenuation computed from the distance in object space.
    AttenuationInObjectSpace,
    /// The light's position given before the view transform.
    LightBeforeView,
}

impl Misconception {
    /// All seven, in the sheets' order.
    pub const ALL: [Misconception; 7] = [
        Misconception::NormalsByModelview,
        Misconception::NormalNotNormalised,
        Misconception::ReflectionForHalfway,
        Misconception::GouraudMissesHighlight,
        Misconception::SpecularOnFacesTurnedAway,
        Misconception::AttenuationInObjectSpace,
        Misconception::LightBeforeView,
    ];

    /// Its stem in message ids and file names.
    pub fn id(self) -> &'static str {
        match self {
            Misconception::NormalsByModelview => "normals-by-m",
            Misconception::NormalNotNormalised => "normal-not-normalised",
            Misconception::ReflectionForHalfway => "reflection-for-halfway",
            Misconception::GouraudMissesHighlight => "gouraud-misses-highlight",
            Misconception::SpecularOnFacesTurnedAway => "specular-facing-away",
            Misconception::AttenuationInObjectSpace => "attenuation-object-space",
            Misconception::LightBeforeView => "light-before-view",
        }
    }

    /// The cause, in the reader's language (what the student picks).
    pub fn cause(self) -> String {
        crate::locale::tr(match self {
            Misconception::NormalsByModelview => "wrong-cause-normals-by-m",
            Misconception::NormalNotNormalised => "wrong-cause-normal-not-normalised",
            Misconception::ReflectionForHalfway => "wrong-cause-reflection-for-halfway",
            Misconception::GouraudMissesHighlight => "wrong-cause-gouraud-misses-highlight",
            Misconception::SpecularOnFacesTurnedAway => "wrong-cause-specular-facing-away",
            Misconception::AttenuationInObjectSpace => "wrong-cause-attenuation-object-space",
            Misconception::LightBeforeView => "wrong-cause-light-before-view",
        })
    }

    /// The right formula and the mistaken one, the words in them in the reader's language.
    pub fn formulas(self) -> (String, String) {
        let both = |r: &str, w: &str| (r.to_string(), w.to_string());
        match self {
            Misconception::NormalsByModelview => both("n_eye = (M^-1)^T n", "n_eye = M n"),
            Misconception::NormalNotNormalised => both("n = n_eye / |n_eye|", "n = n_eye"),
            Misconception::ReflectionForHalfway => {
                both("(n . H)^s_rm, H = normalize(L + V)", "(R . V)^s_rm, R = 2 (n . L) n - L")
            }
            Misconception::GouraudMissesHighlight => {
                (crate::t!("wrong-formula-gouraud-right"), crate::t!("wrong-formula-gouraud-wrong"))
            }
            Misconception::SpecularOnFacesTurnedAway => {
                (crate::t!("wrong-formula-facing-away-right"), crate::t!("wrong-formula-facing-away-wrong"))
            }
            Misconception::AttenuationInObjectSpace => {
                (crate::t!("wrong-formula-attenuation-right"), crate::t!("wrong-formula-attenuation-wrong"))
            }
            // In words, not `a; b`: the feedback's sentence joins its two halves with a `;`.
            Misconception::LightBeforeView => {
                (crate::t!("wrong-formula-light-right"), crate::t!("wrong-formula-light-wrong"))
            }
        }
    }

    /// The choice to pick, as the sheet, the window's quiz and Moodle write it: the cause,
    /// then the mistaken formula (the dot product written `·`); Gouraud's and the
    /// attenuation's only the cause, whose "formula" is words that say the cause again
    /// ("Gouraud shading: lit only at the vertices…: lighting per vertex… (Gouraud)",
    /// "…the distance in object space: d measured in object space").
    pub fn choice(self) -> String {
        match self {
            Misconception::GouraudMissesHighlight | Misconception::AttenuationInObjectSpace => self.cause(),
            _ => format!("{}: {}", self.cause(), self.formulas().1.replace(" . ", " · ")),
        }
    }

    /// Why, in the reader's language (the key's explanation), its numbers in the reader's
    /// decimal mark (`--decimal point` in Portuguese: "0.5", not "0,5").
    pub fn why(self) -> String {
        // The scale the mistake's scene draws with (the table at the top of this file).
        let scale = match self {
            Misconception::NormalNotNormalised => Some("0.5"),
            Misconception::AttenuationInObjectSpace => Some("0.25"),
            _ => None,
        };
        let id = self.why_id();
        match scale {
            Some(s) => crate::locale::tr_args(id, &[("scale", crate::locale::decimal(s).into())]),
            None => crate::locale::tr(id),
        }
    }

    fn why_id(self) -> &'static str {
        match self {
            Misconception::NormalsByModelview => "wrong-why-normals-by-m",
            Misconception::NormalNotNormalised => "wrong-why-normal-not-normalised",
            Misconception::ReflectionForHalfway => "wrong-why-reflection-for-halfway",
            Misconception::GouraudMissesHighlight => "wrong-why-gouraud-misses-highlight",
            Misconception::SpecularOnFacesTurnedAway => "wrong-why-specular-facing-away",
            Misconception::AttenuationInObjectSpace => "wrong-why-attenuation-object-space",
            Misconception::LightBeforeView => "wrong-why-light-before-view",
        }
    }
}

/// A picture to draw: a scene, its mesh, the projection, the shading.
#[derive(Clone, Debug)]
pub struct Setup {
    /// The lighting state and the modelview.
    pub scene: Scene,
    /// The mesh, object space.
    pub mesh: Mesh,
    /// Object to clip space.
    pub clip_from_object: DMat4,
    /// The shading.
    pub mode: ShadingMode,
}

/// The background of the pictures.
pub const BACKGROUND: [f32; 3] = [0.08, 0.08, 0.1];

impl Setup {
    /// The renderer's job for it.
    pub fn job(&self) -> Job<'_> {
        Job {
            scene: &self.scene,
            mesh: &self.mesh,
            clip_from_object: self.clip_from_object,
            mode: self.mode,
            background: BACKGROUND,
            cull_back: false,
            depth_test: true,
            options: EvalOptions::default(),
        }
    }

    /// Drawn at `size` pixels square: the renderer, kept for probing, with its visibility.
    pub fn draw(&self, size: usize) -> Result<(Renderer, Vec<u8>), SceneError> {
        let mut r = Renderer::new();
        r.keep_visibility(true);
        let rgba = r.render(&self.job(), size, size)?.0.rgba.clone();
        Ok((r, rgba))
    }
}

/// One mistake's two pictures.
#[derive(Clone, Debug)]
pub struct Case {
    /// The mistake.
    pub kind: Misconception,
    /// Drawn right.
    pub correct: Setup,
    /// Drawn with the mistake.
    pub bugged: Setup,
    /// The uniform scale of the model transform (attenuation's case), else 1.
    pub scale: f64,
}

/// The base scene: OpenGL's rules, a red plastic, one white light placed in the world above
/// and to the right, no scene ambient and no emission, the camera on +z.
fn base_scene(world_from_object: DMat4) -> Scene {
    let mut s =
        Scene { rules: Rules::OPENGL, world_from_object, normal_mode: NormalMode::Normalize, ..Scene::default() };
    s.light_model.ambient = DVec4::new(0.0, 0.0, 0.0, 1.0);
    s.material.ambient = DVec4::new(0.6, 0.15, 0.1, 1.0);
    s.material.diffuse = DVec4::new(0.75, 0.2, 0.15, 1.0);
    s.material.specular = DVec4::new(0.7, 0.7, 0.7, 1.0);
    s.material.emission = DVec4::new(0.0, 0.0, 0.0, 1.0);
    s.material.shininess = 30.0;
    let mut l = Light::gl_default(0);
    l.ambient = DVec4::new(0.08, 0.08, 0.08, 1.0);
    l.position = DVec4::new(2.5, 3.0, 3.0, 1.0);
    l.placement = LightPlacement::World;
    s.lights = vec![l];
    s.eye_from_world =
        crate::model::transform::try_look_at(DVec3::new(0.0, 0.0, 4.5), DVec3::ZERO, DVec3::Y).expect("a valid camera");
    s
}

/// The projection of every picture.
fn projection() -> DMat4 {
    crate::model::transform::perspective(40.0, 1.0, 0.5, 20.0)
}

fn setup(scene: Scene, mesh: Mesh, mode: ShadingMode) -> Setup {
    let clip_from_object = projection() * scene.eye_from_object();
    Setup { scene, mesh, clip_from_object, mode }
}

/// The case of `kind`: its two pictures' setups.
pub fn case(kind: Misconception) -> Case {
    let sphere = || glu_sphere(1.0, 48, 48);
    let phong = ShadingMode::Phong;
    let (correct, bugged, scale) = match kind {
        Misconception::NormalsByModelview => {
            let scene = base_scene(DMat4::from_scale(DVec3::new(1.45, 0.65, 1.0)));
            let m = DMat3::from_mat4(scene.eye_from_object());
            let mut bent = sphere();
            // With these normals the inverse transpose gives M n: the mistake, exactly.
            for n in &mut bent.normals {
                *n = (m.transpose() * m * n.as_dvec3()).normalize().as_vec3();
            }
            (setup(scene.clone(), sphere(), phong), setup(scene, bent, phong), 1.0)
        }
        Misconception::NormalNotNormalised => {
            let mut scene = base_scene(DMat4::from_scale(DVec3::splat(0.5)));
            scene.material.shininess = 10.0;
            let big = glu_sphere(2.0, 24, 24);
            let right = setup(scene.clone(), big.clone(), ShadingMode::Gouraud);
            scene.normal_mode = NormalMode::AsIs;
            (right, setup(scene, big, ShadingMode::Gouraud), 0.5)
        }
        Misconception::ReflectionForHalfway => {
            let scene = base_scene(DMat4::IDENTITY);
            let mut wrong = scene.clone();
            wrong.rules.specular = SpecularModel::Phong;
            (setup(scene, sphere(), phong), setup(wrong, sphere(), phong), 1.0)
        }
        Misconception::GouraudMissesHighlight => {
            let mut scene = base_scene(DMat4::IDENTITY);
            scene.material.shininess = 60.0;
            let coarse = glu_sphere(1.0, 8, 8);
            (setup(scene.clone(), coarse.clone(), phong), setup(scene, coarse, ShadingMode::Gouraud), 1.0)
        }
        Misconception::SpecularOnFacesTurnedAway => {
            let mut scene = base_scene(DMat4::IDENTITY);
            scene.material.shininess = 4.0;
            // From behind and to the side: much of the sphere faces away from the light
            // while its specular cosine is still positive.
            scene.lights[0].position = DVec4::new(3.0, 1.0, -2.5, 1.0);
            let mut wrong = scene.clone();
            wrong.rules = Rules { set: RuleSet::PhongDemo, specular: SpecularModel::BlinnPhong };
            (setup(scene, sphere(), phong), setup(wrong, sphere(), phong), 1.0)
        }
        Misconception::AttenuationInObjectSpace => {
            let s = 0.25;
            let mut scene = base_scene(DMat4::from_scale(DVec3::splat(s)));
            scene.lights[0].attenuation = [0.3, 0.25, 0.05];
            let big = glu_sphere((1.0 / s) as f32, 48, 48);
            let mut wrong = scene.clone();
            let k = scene.lights[0].attenuation;
            // Distances in object space are the eye's over s.
            wrong.lights[0].attenuation = [k[0], k[1] / s, k[2] / (s * s)];
            (setup(scene, big.clone(), phong), setup(wrong, big, phong), s)
        }
        Misconception::LightBeforeView => {
            let mut scene = base_scene(DMat4::IDENTITY);
            // The camera on the other side from the light: drawn right, the light comes
            // from the right and leaves half the sphere dark; taken in eye coordinates it
            // sits above and behind the camera and lights the whole face (from the light's
            // side, at (3.5, 1, 2.5), the two pictures were nearly the same).
            scene.eye_from_world =
                crate::model::transform::try_look_at(DVec3::new(-3.5, 1.0, 2.5), DVec3::ZERO, DVec3::Y)
                    .expect("a valid camera");
            let mut wrong = scene.clone();
            wrong.lights[0].placement = LightPlacement::Eye;
            (setup(scene, sphere(), phong), setup(wrong, sphere(), phong), 1.0)
        }
    };
    Case { kind, correct, bugged, scale }
}

/// The two pictures of a case, drawn, and the pixel where they differ most, probed in
/// each.
pub struct Drawn {
    /// Side in pixels.
    pub size: usize,
    /// The right picture (RGBA8).
    pub correct: Vec<u8>,
    /// The mistaken one.
    pub bugged: Vec<u8>,
    /// The pixel where they differ most (both covered).
    pub pixel: (usize, usize),
    /// The probe of the right picture there.
    pub correct_probe: crate::raster::probe::Probe,
    /// And of the mistaken one.
    pub bugged_probe: crate::raster::probe::Probe,
    /// Pixels whose bytes differ.
    pub pixels_differing: usize,
}

impl Case {
    /// Both pictures at `size` pixels square, and their most different pixel probed (an
    /// error when none is covered in both).
    pub fn draw(&self, size: usize) -> Result<Drawn, String> {
        let (rc, correct) = self.correct.draw(size).map_err(|e| e.to_string())?;
        let (rb, bugged) = self.bugged.draw(size).map_err(|e| e.to_string())?;
        let (mut best, mut pixel, mut differing) = (0u32, (0, 0), 0);
        for i in 0..size * size {
            let (a, b) = (&correct[i * 4..i * 4 + 3], &bugged[i * 4..i * 4 + 3]);
            let d: u32 = a.iter().zip(b).map(|(x, y)| x.abs_diff(*y) as u32).sum();
            differing += (d > 0) as usize;
            let both = rc.surface_at(i).is_some() && rb.surface_at(i).is_some();
            if both && d > best {
                (best, pixel) = (d, (i % size, i / size));
            }
        }
        let probe = |r: &Renderer, s: &Setup| match crate::raster::probe::probe(r, &s.job(), pixel.0, pixel.1) {
            Ok(Some(p)) => Ok(p),
            Ok(None) => Err(format!("{:?}: no pixel covered in both pictures", self.kind)),
            Err(e) => Err(e.to_string()),
        };
        Ok(Drawn {
            size,
            correct_probe: probe(&rc, &self.correct)?,
            bugged_probe: probe(&rb, &self.bugged)?,
            correct,
            bugged,
            pixel,
            pixels_differing: differing,
        })
    }
}

/// A colour term at a pixel: which quantity (emission, scene ambient, or one light's
/// ambient, diffuse or specular share, after `spot` and `1/at`), and whose light.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TermAt {
    /// The quantity: `EmissionTerm`, `SceneAmbientTerm`, `Ambient`, `Diffuse`, `Specular`.
    pub quantity: crate::model::vocabulary::Quantity,
    /// The light (its place among the enabled ones) for a light's term.
    pub light: Option<usize>,
}

/// The colour terms of a probe with their rgb (they add up to the colour before any clamp).
pub fn colour_terms(t: &crate::raster::probe::Terms) -> Vec<(TermAt, [f64; 3])> {
    use crate::model::vocabulary::Quantity as Q;
    let mut out = vec![
        (TermAt { quantity: Q::EmissionTerm, light: None }, t.emission),
        (TermAt { quantity: Q::SceneAmbientTerm, light: None }, t.scene_ambient),
    ];
    for (i, l) in t.lights.iter().enumerate() {
        for (q, v) in [(Q::Ambient, l.ambient), (Q::Diffuse, l.diffuse), (Q::Specular, l.specular)] {
            out.push((TermAt { quantity: q, light: Some(i) }, v));
        }
    }
    out
}

/// The term whose change makes the difference at the pixel a key quotes: the one whose
/// luminance (Rec. 709, before any clamp) changes most between the two pictures' probes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deciding {
    /// Which term.
    pub term: TermAt,
    /// Its luminance drawn right.
    pub right: f64,
    /// And with the mistake.
    pub wrong: f64,
}

/// The term that changes most at the probed pixel (`None` with no term at all).
pub fn deciding_term(d: &Drawn) -> Option<Deciding> {
    let luminance = crate::raster::channels::luminance;
    let (a, b) = (colour_terms(&d.correct_probe.terms), colour_terms(&d.bugged_probe.terms));
    a.iter()
        .zip(&b)
        .map(|((term, x), (_, y))| Deciding { term: *term, right: luminance(*x), wrong: luminance(*y) })
        .max_by(|p, q| (p.wrong - p.right).abs().total_cmp(&(q.wrong - q.right).abs()))
}

/// One light's terms at the probed pixel, short: `N.L`, the specular cosine (`n . H`, or
/// `R . V` under Phong's rule), `1/at`, diffuse and specular (their rgb).
fn light_line(p: &crate::raster::probe::Probe, scene: &Scene) -> String {
    use crate::locale::num;
    use crate::raster::probe_report::numbers;
    let Some(l) = p.terms.lights.first() else { return String::new() };
    let cosine = match scene.rules.specular {
        SpecularModel::Phong => "R · V",
        _ => "n · H",
    };
    crate::t!(
        "wrong-probe-line",
        rgba = format!("({}, {}, {})", p.rgba8[0], p.rgba8[1], p.rgba8[2]),
        ndotl = num(l.n_dot_l, 4),
        cosine = cosine,
        ndoth = num(l.n_dot_h, 4),
        att = num(l.attenuation, 4),
        diffuse = numbers(&l.diffuse),
        specular = numbers(&l.specular)
    )
}

/// The key of a drawn case: the cause, the two formulas, why, the probe's numbers at the
/// pixel that differs most, and the term whose change makes the difference there, in the
/// reader's language.
pub fn key_lines(case: &Case, d: &Drawn) -> Vec<String> {
    let (right, wrong) = case.kind.formulas();
    let mut out = vec![
        crate::t!("wrong-key-cause", cause = case.kind.cause()),
        crate::t!("wrong-key-formulas", right = right, wrong = wrong),
        case.kind.why(),
        crate::t!("wrong-key-pixel", x = d.pixel.0 as i64, y = d.pixel.1 as i64, count = d.pixels_differing as i64),
        crate::t!("wrong-key-right", line = light_line(&d.correct_probe, &case.correct.scene)),
        crate::t!("wrong-key-wrong", line = light_line(&d.bugged_probe, &case.bugged.scene)),
    ];
    if let Some(c) = deciding_term(d) {
        out.push(crate::t!(
            "wrong-key-term",
            term = c.term.quantity.label(),
            name = c.term.quantity.name(),
            right = crate::locale::num(c.right, 4),
            wrong = crate::locale::num(c.wrong, 4)
        ));
    }
    if let (crate::raster::probe::ProbeShading::Phong(a), crate::raster::probe::ProbeShading::Phong(b)) =
        (&d.correct_probe.shading, &d.bugged_probe.shading)
    {
        let angle = DVec3::from_array(a.normal).angle_between(DVec3::from_array(b.normal)).to_degrees();
        if angle > 0.05 {
            out.push(crate::t!("wrong-key-normals", degrees = crate::locale::num(angle, 3)));
        }
    }
    out
}

/// What each case's key claims, checked on its drawn pictures: `Err` says which claim
/// failed.
pub fn check(case: &Case, d: &Drawn) -> Result<(), String> {
    use crate::raster::probe::ProbeShading;
    if d.pixels_differing < 50 {
        return Err(format!("only {} pixels differ", d.pixels_differing));
    }
    let (a, b) = (&d.correct_probe, &d.bugged_probe);
    let (la, lb) = (&a.terms.lights[0], &b.terms.lights[0]);
    let luminance = crate::raster::channels::luminance;
    let claim = |ok: bool, what: &str| if ok { Ok(()) } else { Err(what.to_string()) };
    match case.kind {
        Misconception::NormalsByModelview => {
            // The fragment's normal turns; at the pixel it turns by degrees.
            let (ProbeShading::Phong(x), ProbeShading::Phong(y)) = (&a.shading, &b.shading) else {
                return Err("Phong expected".into());
            };
            let angle = DVec3::from_array(x.normal).angle_between(DVec3::from_array(y.normal)).to_degrees();
            claim(angle > 5.0, &format!("the normals part by {angle} degrees only"))
        }
        Misconception::NormalNotNormalised => {
            // Normals of length 2 (1 / 0.5): the diffuse term doubles where no clamp bites,
            // and n . H passes 1, where the power blows the specular term up.
            let ratio = luminance(lb.diffuse) / luminance(la.diffuse);
            claim((ratio - 2.0).abs() < 0.02, &format!("diffuse ratio {ratio}, not 2"))?;
            claim(la.n_dot_h <= 1.0 && lb.n_dot_h > 1.0, &format!("n . H {} is not past 1", lb.n_dot_h))
        }
        Misconception::ReflectionForHalfway => {
            // R . V falls off faster than n . H: a smaller highlight at the same exponent.
            claim(lb.n_dot_h < la.n_dot_h && luminance(lb.specular) < luminance(la.specular), "R.V not below n.H")
        }
        Misconception::GouraudMissesHighlight => {
            claim(luminance(lb.specular) < 0.5 * luminance(la.specular), "Gouraud keeps the highlight")
        }
        Misconception::SpecularOnFacesTurnedAway => claim(
            la.n_dot_l <= 0.0 && luminance(la.specular) == 0.0 && luminance(lb.specular) > 0.0,
            "the pixel is not a face turned away lit by specular",
        ),
        Misconception::AttenuationInObjectSpace => {
            // The same point, its distance read as d / s.
            let k = case.correct.scene.lights[0].attenuation;
            let d_eye = 1.0 / la.attenuation;
            let d_eye = {
                // k0 + k1 d + k2 d^2 = 1 / att: solve for d.
                let c = k[0] - d_eye;
                (-k[1] + (k[1] * k[1] - 4.0 * k[2] * c).sqrt()) / (2.0 * k[2])
            };
            let d_obj = d_eye / case.scale;
            let want = 1.0 / (k[0] + k[1] * d_obj + k[2] * d_obj * d_obj);
            claim((lb.attenuation - want).abs() < 1e-9 * want.max(1.0), &format!("{} against {want}", lb.attenuation))
        }
        Misconception::LightBeforeView => {
            let pa = case.correct.scene.light_pos_in_eye(&case.correct.scene.lights[0]);
            let pb = case.bugged.scene.light_pos_in_eye(&case.bugged.scene.lights[0]);
            // Seen from the sphere's centre, the light comes from another side (58 degrees
            // apart; 30 from the camera at (3.5, 1, 2.5), where the pictures looked alike).
            let centre = case.correct.scene.eye_from_object().w_axis.truncate();
            let turn = (pa.truncate() - centre).angle_between(pb.truncate() - centre).to_degrees();
            claim(turn >= 45.0, &format!("the light moves by {turn:.1} degrees only"))?;
            claim((la.n_dot_l - lb.n_dot_l).abs() > 0.05, "n . L did not change at the pixel")
        }
    }
}
