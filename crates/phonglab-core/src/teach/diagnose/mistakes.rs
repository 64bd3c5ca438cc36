//! The table of picture mistakes: each a change of the state a student's program sets,
//! made to the drawing ([`Drawing`]) of the scene, for the whole scene or for each light
//! in turn ([`Scope`]). A change that cannot alter this scene (no spot, no colour material,
//! a light that is already directional) is not offered: its function says so.

use glam::{DMat3, DVec4};

use crate::model::rules::{RuleSet, SpecularModel};
use crate::model::scene::{ColorMaterialMode, Light, LightPlacement, NormalMode};
use crate::model::view::ShadingMode;

use super::calls::{
    colour_material_ambient_and_diffuse, colour_material_wrong_face, directional_reversed, emission_back_only,
    light_ambient_diffuse_swapped, light_diffuse_on_previous, light_specular_left_out, light_specular_on_previous,
    material_colours_255, material_diffuse_255, material_front_only, positions_as_normals, rescale_for_normalize,
    scene_ambient_default, shininess_refused, spot_cutoff_cosine,
};
use super::change::{At, back_only, each_material, the_light};
use super::colours;
use super::drawing::Drawing;
use super::sides;
use super::slips;
use super::values;

/// Where a mistake is made: once for the scene, or for each light in turn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// Once, for the whole scene.
    Scene,
    /// For each light alone, named with the light.
    EachLight,
}

/// A mistake a picture can show: its id (kebab-case, the same as `phonglab check`'s where
/// the mistake is the same), its message, where it is made, and the change it makes.
pub struct PictureMistake {
    /// The id in JSON and the docs.
    pub id: &'static str,
    /// The message id of its words (given `$light`, the light's number, and `$emission`).
    pub message: &'static str,
    /// Once for the scene, or for each light in turn.
    pub scope: Scope,
    /// Makes the mistake in the drawing; false when it cannot change this drawing (it is
    /// then not offered).
    pub apply: fn(&mut Drawing, At) -> bool,
}

impl PictureMistake {
    /// Its words in the reader's language, for light or emission `at`.
    pub fn words_at(&self, at: At) -> String {
        use crate::locale::Arg;
        let e = at.emission;
        let emission = colours::triple_said(e);
        let mut args = vec![
            ("light", Arg::Text(at.light.to_string())),
            ("previous", Arg::Text(at.light.saturating_sub(1).to_string())),
            ("emission", Arg::Text(emission)),
            ("terms", Arg::Text(at.colours.map(|c| colours::said(&c)).unwrap_or_default())),
            ("colours", Arg::Text(at.sides.map(|s| sides::said(&s)).unwrap_or_default())),
        ];
        let number = |v: f64| Arg::Text(crate::locale::decimal(&values::shown(v)));
        let g = at.given;
        let levels = g.diffuse.map(|v| format!("{}", (v * 255.0).round()));
        args.extend([
            ("shininess-given", number(g.shininess)),
            ("fraction", number(g.shininess / 128.0)),
            ("diffuse-given", Arg::Text(colours::triple_said(g.diffuse))),
            ("diffuse-levels", Arg::Text(format!("({})", levels.join(", ")))),
        ]);
        let own = at.values.lights.get(at.light).copied().unwrap_or_default();
        let negligible = at.values.negligible.get(at.light).copied().unwrap_or_default();
        for (k, fitted) in own.into_iter().enumerate() {
            if let Some((picture, scene)) = fitted {
                let least = Arg::Text(crate::locale::decimal(&values::shown(picture)));
                let shown = if negligible[k] {
                    Arg::Text(crate::locale::tr_args("diagnose-value-negligible", &[("least", least)]))
                } else {
                    number(picture)
                };
                args.push((values::ARGS[k].0, shown));
                args.push((values::ARGS[k].1, number(scene)));
            }
        }
        if let Some((picture, scene)) = at.values.shininess {
            args.push((values::ARGS[5].0, number(picture)));
            args.push((values::ARGS[5].1, number(scene)));
        }
        crate::locale::tr_args(self.message, &args)
    }

    /// Its words in the reader's language (a mistake of the whole scene).
    pub fn words(&self) -> String {
        self.words_at(At::default())
    }
}

/// Normals transformed by M: with each normal `n` replaced by `M^T M n`, the inverse
/// transpose gives `M n` (up to length), as the misconception's picture does.
fn normals_by_modelview(d: &mut Drawing, _: At) -> bool {
    let m = DMat3::from_mat4(d.scene.eye_from_object());
    for n in &mut d.mesh.normals {
        let bent = m.transpose() * m * n.as_dvec3();
        if bent.length() > 0.0 {
            *n = bent.normalize().as_vec3();
        }
    }
    true
}

/// The normals given the change `m` of the modelview's 3x3 `M` in place of its inverse
/// transpose: with each normal `n` replaced by `M^T m n`, the renderer's inverse transpose
/// gives `m n` (up to length). False where the modelview has no inverse.
fn normals_by(d: &mut Drawing, m: impl Fn(DMat3) -> DMat3) -> bool {
    let mview = DMat3::from_mat4(d.scene.eye_from_object());
    if mview.determinant().abs() < 1e-12 {
        return false;
    }
    let by = mview.transpose() * m(mview);
    for n in &mut d.mesh.normals {
        let bent = by * n.as_dvec3();
        if bent.length() > 0.0 {
            *n = bent.normalize().as_vec3();
        }
    }
    true
}

/// Normals by the inverse of the modelview's 3x3, not its transpose (`np.linalg.inv(m3)`).
fn normal_matrix_not_transposed(d: &mut Drawing, _: At) -> bool {
    normals_by(d, |m| m.inverse())
}

/// Normals left in object space (not transformed at all).
fn normal_not_transformed(d: &mut Drawing, _: At) -> bool {
    normals_by(d, |_| DMat3::IDENTITY)
}

/// `GL_NORMALIZE` (or `GL_RESCALE_NORMAL`) off.
fn normalize_off(d: &mut Drawing, _: At) -> bool {
    d.scene.normal_mode = NormalMode::AsIs;
    true
}

/// `R . V` where `n . H` belongs.
fn reflection_for_halfway(d: &mut Drawing, _: At) -> bool {
    d.scene.rules.specular = SpecularModel::Phong;
    true
}

/// Lit per vertex where the scene lights per fragment.
fn gouraud_for_phong(d: &mut Drawing, _: At) -> bool {
    if d.mode == ShadingMode::Phong {
        d.mode = ShadingMode::Gouraud;
    }
    true
}

/// No `f_i` gate: the Phong demo's rules (as the misconception draws it), Blinn-Phong kept.
fn specular_without_gate(d: &mut Drawing, _: At) -> bool {
    d.scene.rules.set = RuleSet::PhongDemo;
    true
}

/// The attenuation's distance in object space: `k1 / s`, `k2 / s^2` for the modelview's
/// scale `s` (the cube root of its determinant; exact for a uniform scale).
fn attenuation_object_distance(d: &mut Drawing, _: At) -> bool {
    let s = DMat3::from_mat4(d.scene.eye_from_object()).determinant().abs().cbrt();
    if s > 0.0 && s.is_finite() {
        for l in &mut d.scene.lights {
            l.attenuation = [l.attenuation[0], l.attenuation[1] / s, l.attenuation[2] / (s * s)];
        }
    }
    true
}

/// The light's position given before `gluLookAt`: under the identity, in eye coordinates.
fn light_before_view(d: &mut Drawing, _: At) -> bool {
    for l in &mut d.scene.lights {
        l.placement = LightPlacement::Eye;
    }
    true
}

/// One light's `GL_POSITION` given before `gluLookAt` (under the identity), where several
/// lights are placed in the world and the view moves them (the all-lights row draws the
/// others too), or where the light is a spotlight: its `GL_SPOT_DIRECTION`, given after the
/// camera as the exported program gives it, still turns with the view, so the position
/// alone is fixed to the eye (the all-lights row fixes the direction too).
fn light_before_view_alone(d: &mut Drawing, at: At) -> bool {
    let moves = d.scene.eye_from_world != glam::DMat4::IDENTITY;
    let in_world = d.scene.lights.iter().filter(|l| l.placement == LightPlacement::World).count();
    let Some(l) = d.scene.lights.get(at.light) else { return false };
    let turned = DMat3::from_mat4(d.scene.eye_from_light(l)) * l.spot_direction;
    the_light(
        d,
        at,
        |l| moves && (in_world >= 2 || l.is_spot()) && l.placement == LightPlacement::World,
        |l| {
            l.placement = LightPlacement::Eye;
            if l.is_spot() {
                l.spot_direction = turned;
            }
        },
    )
}

/// `GL_LIGHT_MODEL_LOCAL_VIEWER` the other way.
fn viewer_swapped(d: &mut Drawing, _: At) -> bool {
    d.scene.light_model.local_viewer = !d.scene.light_model.local_viewer;
    true
}

/// Every normal pointing inwards.
fn flipped_normals(d: &mut Drawing, _: At) -> bool {
    for n in &mut d.mesh.normals {
        *n = -*n;
    }
    true
}

/// `gluQuadricOrientation(q, GLU_INSIDE)`: the quadric's normals inwards, and its faces
/// wound inwards, its quads split along their other diagonal, as GLU then draws it.
fn quadric_inside(d: &mut Drawing, _: At) -> bool {
    match d.inside.take() {
        Some(inside) => {
            d.mesh = inside;
            true
        }
        None => false,
    }
}

/// `GL_LIGHT_MODEL_TWO_SIDE` off.
fn two_sided_off(d: &mut Drawing, _: At) -> bool {
    d.scene.light_model.two_sided = false;
    true
}

/// `GL_LIGHT_MODEL_TWO_SIDE` on where the scene has it off (`two_sided = true` typed into
/// a scene without it): the back faces lit with their own normals and the back material.
/// Not offered where the scene has it on already.
fn two_sided_on(d: &mut Drawing, _: At) -> bool {
    if d.scene.light_model.two_sided {
        return false;
    }
    d.scene.light_model.two_sided = true;
    true
}

/// Attenuation left out: (1, 0, 0), on every light.
fn attenuation_left_out(d: &mut Drawing, _: At) -> bool {
    for l in &mut d.scene.lights {
        l.attenuation = [1.0, 0.0, 0.0];
    }
    true
}

/// The spot left out: cutoff 180.
fn spot_left_out(d: &mut Drawing, _: At) -> bool {
    for l in &mut d.scene.lights {
        l.spot_cutoff = 180.0;
    }
    true
}

/// Shininess given as the 0-1 value of a material table (0.4) instead of `0.4 * 128`.
fn shininess_fraction(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| m.shininess /= 128.0)
}

/// One light not enabled.
fn light_left_out(d: &mut Drawing, at: At) -> bool {
    if at.light >= d.scene.lights.len() {
        return false;
    }
    d.scene.lights.remove(at.light);
    true
}

/// A point light given w = 0: a directional light from the direction of its position.
fn point_as_directional(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| !l.is_directional(), |l| l.position.w = 0.0)
}

/// A light's ambient colour left at OpenGL's default (0, 0, 0, 1).
fn light_ambient_left_out(d: &mut Drawing, at: At) -> bool {
    let black = DVec4::new(0.0, 0.0, 0.0, 1.0);
    the_light(d, at, |l| l.ambient.truncate() != black.truncate(), |l| l.ambient = black)
}

/// The material's specular colour left at its default (0, 0, 0, 1): no highlight.
fn specular_left_out(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| m.specular = DVec4::new(0.0, 0.0, 0.0, 1.0))
}

/// The material's diffuse and specular colours exchanged.
fn diffuse_specular_swapped(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| std::mem::swap(&mut m.diffuse, &mut m.specular))
}

/// An emission the scene does not have: the colour fitted from the student's picture.
fn emission_added(d: &mut Drawing, at: At) -> bool {
    if at.emission.iter().all(|&c| c <= 0.0) {
        return false;
    }
    let [r, g, b] = at.emission;
    each_material(d, |m| m.emission += DVec4::new(r, g, b, 0.0))
}

/// How many lights are attenuated.
fn attenuated(d: &Drawing) -> usize {
    d.scene.lights.iter().filter(|l| l.is_attenuated()).count()
}

/// One light's attenuation left out, where several lights are attenuated (with one, the
/// all-lights row draws the same picture).
fn attenuation_left_out_alone(d: &mut Drawing, at: At) -> bool {
    let several = attenuated(d) >= 2;
    the_light(d, at, |l| several && l.is_attenuated(), |l| l.attenuation = [1.0, 0.0, 0.0])
}

/// A spotlight's direction given under the identity (before the camera transform) while
/// its position is given where the scene gives it: the direction is taken as already in
/// eye coordinates.
fn spot_direction_untransformed(d: &mut Drawing, at: At) -> bool {
    let Some(l) = d.scene.lights.get(at.light) else { return false };
    let m = DMat3::from_mat4(d.scene.eye_from_light(l));
    if !l.is_spot() || l.placement == LightPlacement::Eye || m.determinant().abs() < 1e-12 {
        return false;
    }
    // The renderer takes the direction through the light's modelview; through its inverse
    // first, the direction arrives in eye coordinates unchanged. It changes the picture
    // only where the modelview turns the direction.
    let (given, direction) = (l.spot_direction, m.inverse() * l.spot_direction);
    let turned = (m * given).normalize_or_zero().distance(given.normalize_or_zero()) > 1e-9;
    turned && the_light(d, at, |_| true, |l| l.spot_direction = direction)
}

/// The world-placed lights given under view * model (after the model transform) instead
/// of the view, where the scene has a model transform.
fn light_after_model(d: &mut Drawing, _: At) -> bool {
    if d.scene.world_from_object == glam::DMat4::IDENTITY {
        return false;
    }
    let mut changed = false;
    for l in d.scene.lights.iter_mut().filter(|l| l.placement == LightPlacement::World) {
        l.placement = LightPlacement::Object;
        changed = true;
    }
    changed
}

/// An eye-fixed light (given under the identity) given under the view instead: placed in
/// the world.
fn headlight_under_view(d: &mut Drawing, at: At) -> bool {
    let moves = d.scene.eye_from_world != glam::DMat4::IDENTITY;
    the_light(d, at, |l| moves && l.placement == LightPlacement::Eye, |l| l.placement = LightPlacement::World)
}

/// `GL_COLOR_MATERIAL` not enabled: the `glMaterial` colours light the object.
fn colour_material_off(d: &mut Drawing, _: At) -> bool {
    d.scene.color_material.take().is_some()
}

/// `glColorMaterial` tracking `GL_DIFFUSE` only instead of `GL_AMBIENT_AND_DIFFUSE`.
fn colour_material_diffuse_only(d: &mut Drawing, _: At) -> bool {
    match &mut d.scene.color_material {
        Some(c) if c.mode == ColorMaterialMode::AmbientAndDiffuse => {
            c.mode = ColorMaterialMode::Diffuse;
            true
        }
        _ => false,
    }
}

/// A spotlight's cutoff halved (the cone's full angle taken for the cutoff).
fn spot_cutoff_halved(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, Light::is_spot, |l| l.spot_cutoff /= 2.0)
}

/// A spotlight's cutoff given in radians (`math.radians(12)`: 0.21), which OpenGL takes
/// as degrees.
fn spot_cutoff_radians(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| l.is_spot() && l.spot_cutoff > 0.0, |l| l.spot_cutoff = l.spot_cutoff.to_radians())
}

/// A spotlight's exponent left out: 0, a hard-edged pool.
fn spot_exponent_ignored(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| l.is_spot() && l.spot_exponent != 0.0, |l| l.spot_exponent = 0.0)
}

/// A spotlight's cutoff and exponent exchanged, where OpenGL takes both (a cutoff in
/// [0, 90], an exponent in [0, 128]; otherwise the call is refused and nothing changes).
fn spot_cutoff_exponent_swapped(d: &mut Drawing, at: At) -> bool {
    let takes = |l: &Light| l.is_spot() && l.spot_exponent <= 90.0 && l.spot_cutoff != l.spot_exponent;
    the_light(d, at, takes, |l| std::mem::swap(&mut l.spot_cutoff, &mut l.spot_exponent))
}

/// A spotlight's direction reversed: pointing from the target to the light.
fn spot_direction_reversed(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| l.is_spot() && l.spot_direction != glam::DVec3::ZERO, |l| l.spot_direction = -l.spot_direction)
}

/// A positional light's linear and quadratic attenuation exchanged.
fn attenuation_terms_swapped(d: &mut Drawing, at: At) -> bool {
    let differ = |l: &Light| !l.is_directional() && l.attenuation[1] != l.attenuation[2];
    the_light(d, at, differ, |l| l.attenuation.swap(1, 2))
}

/// A positional light's constant attenuation 0 (thinking 0 means none), where a linear or
/// quadratic term keeps the division finite.
fn attenuation_constant_left_out(d: &mut Drawing, at: At) -> bool {
    let applies = |l: &Light| {
        let [constant, linear, quadratic] = l.attenuation;
        !l.is_directional() && constant != 0.0 && linear + quadratic > 0.0
    };
    the_light(d, at, applies, |l| l.attenuation[0] = 0.0)
}

/// A directional light given w = 1: a point light at its direction.
fn directional_as_point(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, Light::is_directional, |l| l.position.w = 1.0)
}

/// The material's diffuse colour given for `GL_BACK` only.
fn diffuse_back_only(d: &mut Drawing, _: At) -> bool {
    back_only(d, |m, gl| m.diffuse = gl.diffuse)
}

/// The material's ambient colour given for `GL_BACK` only.
fn ambient_back_only(d: &mut Drawing, _: At) -> bool {
    back_only(d, |m, gl| m.ambient = gl.ambient)
}

/// The material's specular colour and shininess given for `GL_BACK` only.
fn specular_back_only(d: &mut Drawing, _: At) -> bool {
    back_only(d, |m, gl| (m.specular, m.shininess) = (gl.specular, gl.shininess))
}

/// Every `glMaterial` call given for `GL_BACK` only.
fn material_back_only(d: &mut Drawing, _: At) -> bool {
    back_only(d, |m, gl| *m = gl.clone())
}

/// A light's diffuse colour given in 0..255 (as `ofSetColor` takes it) instead of 0..1.
fn light_colour_255(d: &mut Drawing, at: At) -> bool {
    let scale = |c: &mut DVec4| *c = (c.truncate() * 255.0).extend(c.w);
    the_light(d, at, |l| l.diffuse.truncate().max_element() > 0.0, |l| scale(&mut l.diffuse))
}

/// Light `i`'s modelview, where loading it transposed would change it.
fn transposable(d: &Drawing, i: usize) -> Option<glam::DMat4> {
    let m = d.scene.eye_from_light(d.scene.lights.get(i)?);
    (m != m.transpose()).then_some(m)
}

/// Light `i` placed under its modelview's transpose; false where that changes nothing.
fn transposed(d: &mut Drawing, i: usize) -> bool {
    match transposable(d, i) {
        Some(m) => {
            d.scene.lights[i].placement = LightPlacement::Matrix(m.transpose());
            true
        }
        None => false,
    }
}

/// The lights' modelview loaded transposed (NumPy's rows given to `glLoadMatrixf` as
/// columns): each light placed under its matrix's transpose.
fn row_vectors(d: &mut Drawing, _: At) -> bool {
    let mut changed = false;
    for i in 0..d.scene.lights.len() {
        changed |= transposed(d, i);
    }
    changed
}

/// One light's modelview loaded transposed, where several lights would change (with one,
/// the all-lights row draws the same picture).
fn row_vectors_alone(d: &mut Drawing, at: At) -> bool {
    let several = (0..d.scene.lights.len()).filter(|&i| transposable(d, i).is_some()).count() >= 2;
    several && transposed(d, at.light)
}

/// A light's ambient colour copied from its diffuse colour.
fn light_ambient_from_diffuse(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| l.ambient.truncate() != l.diffuse.truncate(), |l| l.ambient = l.diffuse)
}

/// The material's ambient given its diffuse colour (`GL_AMBIENT_AND_DIFFUSE`).
fn ambient_from_diffuse(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| m.ambient = m.diffuse)
}

/// The object's colour: the current colour where colour material tracks the diffuse,
/// else the material's diffuse.
fn object_colour(d: &Drawing) -> DVec4 {
    match &d.scene.color_material {
        Some(c) if matches!(c.mode, ColorMaterialMode::Diffuse | ColorMaterialMode::AmbientAndDiffuse) => c.color,
        _ => d.scene.material.diffuse,
    }
}

/// The material's specular colour given the object's colour.
fn specular_from_colour(d: &mut Drawing, _: At) -> bool {
    let colour = object_colour(d);
    each_material(d, |m| m.specular = colour)
}

/// The material's emission given the object's colour.
fn emission_from_colour(d: &mut Drawing, _: At) -> bool {
    let colour = object_colour(d);
    each_material(d, |m| m.emission = colour)
}

/// The material's ambient and diffuse colours exchanged.
fn ambient_diffuse_swapped(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| std::mem::swap(&mut m.ambient, &mut m.diffuse))
}

/// A light's diffuse colour never set: OpenGL's default, white for light 0, black for
/// the others.
fn light_diffuse_left_out(d: &mut Drawing, at: At) -> bool {
    let default = Light::gl_default(at.light).diffuse;
    the_light(d, at, |l| l.diffuse != default, |l| l.diffuse = default)
}

/// Light number `k` set to the value fitted from the picture.
fn light_value_fitted(d: &mut Drawing, at: At, k: usize) -> bool {
    match (at.values.lights.get(at.light).and_then(|l| l[k]), d.scene.lights.get_mut(at.light)) {
        (Some((picture, _)), Some(l)) => {
            values::set_light_value(l, k, picture);
            true
        }
        _ => false,
    }
}

fn spot_cutoff_differs(d: &mut Drawing, at: At) -> bool {
    light_value_fitted(d, at, 0)
}

fn spot_exponent_differs(d: &mut Drawing, at: At) -> bool {
    light_value_fitted(d, at, 1)
}

fn attenuation_constant_differs(d: &mut Drawing, at: At) -> bool {
    light_value_fitted(d, at, 2)
}

fn attenuation_linear_differs(d: &mut Drawing, at: At) -> bool {
    light_value_fitted(d, at, 3)
}

fn attenuation_quadratic_differs(d: &mut Drawing, at: At) -> bool {
    light_value_fitted(d, at, 4)
}

/// The shininess set to the value fitted from the picture.
fn shininess_differs(d: &mut Drawing, at: At) -> bool {
    match at.values.shininess {
        Some((picture, _)) => each_material(d, |m| m.shininess = picture),
        None => false,
    }
}

/// The spot cutoff doubled (the cone's full angle given for its half), within 90 degrees.
fn spot_cutoff_doubled(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| l.is_spot() && l.spot_cutoff > 0.0 && l.spot_cutoff <= 45.0, |l| l.spot_cutoff *= 2.0)
}

/// A side's material colours (two-sided lighting with two materials): the picture drawn
/// with each side's colours it shows.
fn materials_differ(d: &mut Drawing, at: At) -> bool {
    match at.sides {
        Some(s) if !s.differing().is_empty() => {
            *d = sides::with_sides(d, &s.fitted, s.shininess.map(|(shown, _)| shown));
            true
        }
        _ => false,
    }
}

/// Any colour the program sets: the picture drawn with the products it shows.
fn colours_differ(d: &mut Drawing, at: At) -> bool {
    match at.colours {
        Some(c) if !c.differing().is_empty() => {
            *d = colours::with_products(d, &c.fitted);
            true
        }
        _ => false,
    }
}

fn emission_left_out(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| m.emission = DVec4::new(0.0, 0.0, 0.0, 1.0))
}

/// `glEnable(GL_DEPTH_TEST)` left out: each triangle covers the ones drawn before it, the
/// far side of the object over the near one wherever it comes later.
fn depth_test_off(d: &mut Drawing, _: At) -> bool {
    std::mem::replace(&mut d.depth_test, false)
}

/// One light given under the modelview the object is drawn with (view × model) instead of
/// its own (the identity for a light fixed to the eye, the view for one in the world): it
/// moves with the object. Only under a model transform (without one, an eye-fixed light's
/// is `headlight-under-view`); the world's lights alone where the scene has several (the
/// all-lights row draws one alone).
fn light_after_model_alone(d: &mut Drawing, at: At) -> bool {
    let s = &d.scene;
    let in_world = s.lights.iter().filter(|l| l.placement == LightPlacement::World).count();
    let model_moves = s.world_from_object != glam::DMat4::IDENTITY;
    the_light(
        d,
        at,
        |l| match l.placement {
            LightPlacement::Eye => model_moves,
            LightPlacement::World => model_moves && in_world >= 2,
            _ => false,
        },
        |l| l.placement = LightPlacement::Object,
    )
}

/// A row of the table.
const fn row(id: &'static str, message: &'static str, apply: fn(&mut Drawing, At) -> bool) -> PictureMistake {
    PictureMistake { id, message, scope: Scope::Scene, apply }
}

/// A row of the table made for each light in turn.
const fn per_light(id: &'static str, message: &'static str, apply: fn(&mut Drawing, At) -> bool) -> PictureMistake {
    PictureMistake { id, message, scope: Scope::EachLight, apply }
}

/// The picture mistakes, in the order the docs list them.
pub const MISTAKES: [PictureMistake; 89] = [
    row("normal-by-modelview", "wrong-cause-normals-by-m", normals_by_modelview),
    row("normal-not-normalised", "diagnose-normalize-off", normalize_off),
    row("reflection-for-halfway", "wrong-cause-reflection-for-halfway", reflection_for_halfway),
    row("gouraud-for-phong", "wrong-cause-gouraud-misses-highlight", gouraud_for_phong),
    row("specular-without-gate", "wrong-cause-specular-facing-away", specular_without_gate),
    row("attenuation-object-distance", "wrong-cause-attenuation-object-space", attenuation_object_distance),
    row("light-before-view", "wrong-cause-light-before-view", light_before_view),
    row("viewer-swapped", "diagnose-viewer-swapped", viewer_swapped),
    row("flipped-normals", "diagnose-flipped-normals", flipped_normals),
    row("two-sided-off", "diagnose-two-sided-off", two_sided_off),
    row("attenuation-left-out", "diagnose-attenuation-left-out", attenuation_left_out),
    row("spot-left-out", "diagnose-spot-left-out", spot_left_out),
    row("shininess-fraction", "diagnose-shininess-fraction", shininess_fraction),
    row("shininess-refused", "diagnose-shininess-refused", shininess_refused),
    per_light("light-left-out", "diagnose-light-left-out", light_left_out),
    per_light("point-as-directional", "diagnose-point-as-directional", point_as_directional),
    per_light("directional-reversed", "diagnose-directional-reversed", directional_reversed),
    per_light("light-ambient-left-out", "diagnose-light-ambient-left-out", light_ambient_left_out),
    row("scene-ambient-default", "diagnose-scene-ambient-default", scene_ambient_default),
    per_light("light-specular-left-out", "diagnose-light-specular-left-out", light_specular_left_out),
    per_light("light-ambient-diffuse-swapped", "diagnose-light-ambient-diffuse-swapped", light_ambient_diffuse_swapped),
    per_light("light-diffuse-on-previous", "diagnose-light-diffuse-on-previous", light_diffuse_on_previous),
    per_light("light-specular-on-previous", "diagnose-light-specular-on-previous", light_specular_on_previous),
    row("positions-as-normals", "diagnose-positions-as-normals", positions_as_normals),
    row("specular-left-out", "diagnose-specular-left-out", specular_left_out),
    row("diffuse-specular-swapped", "diagnose-diffuse-specular-swapped", diffuse_specular_swapped),
    per_light("attenuation-left-out", "diagnose-attenuation-left-out-light", attenuation_left_out_alone),
    per_light("spot-direction-untransformed", "diagnose-spot-direction-untransformed", spot_direction_untransformed),
    row("light-after-model", "diagnose-light-after-model", light_after_model),
    per_light("headlight-under-view", "diagnose-headlight-under-view", headlight_under_view),
    per_light("light-before-view", "diagnose-light-before-view-light", light_before_view_alone),
    row("colour-material-off", "diagnose-colour-material-off", colour_material_off),
    row("colour-material-diffuse-only", "diagnose-colour-material-diffuse-only", colour_material_diffuse_only),
    row(
        "colour-material-ambient-and-diffuse",
        "diagnose-colour-material-ambient-and-diffuse",
        colour_material_ambient_and_diffuse,
    ),
    row("colour-material-wrong-face", "diagnose-colour-material-wrong-face", colour_material_wrong_face),
    per_light("spot-cutoff-halved", "diagnose-spot-cutoff-halved", spot_cutoff_halved),
    per_light("spot-cutoff-radians", "diagnose-spot-cutoff-radians", spot_cutoff_radians),
    per_light("spot-cutoff-cosine", "diagnose-spot-cutoff-cosine", spot_cutoff_cosine),
    per_light("spot-exponent-ignored", "diagnose-spot-exponent-ignored", spot_exponent_ignored),
    per_light("spot-cutoff-exponent-swapped", "diagnose-spot-cutoff-exponent-swapped", spot_cutoff_exponent_swapped),
    per_light("spot-direction-reversed", "diagnose-spot-direction-reversed", spot_direction_reversed),
    per_light("attenuation-terms-swapped", "diagnose-attenuation-terms-swapped", attenuation_terms_swapped),
    per_light("attenuation-constant-left-out", "diagnose-attenuation-constant-left-out", attenuation_constant_left_out),
    per_light("directional-as-point", "diagnose-directional-as-point", directional_as_point),
    row("diffuse-back-only", "diagnose-diffuse-back-only", diffuse_back_only),
    row("ambient-back-only", "diagnose-ambient-back-only", ambient_back_only),
    row("specular-back-only", "diagnose-specular-back-only", specular_back_only),
    row("material-back-only", "diagnose-material-back-only", material_back_only),
    row("material-front-only", "diagnose-material-front-only", material_front_only),
    // The material's colours on 0..255 before a light's: the more common, and with one
    // light the two draw the same picture.
    row("material-colour-0-255", "diagnose-material-diffuse-0-255", material_diffuse_255),
    row("material-colour-0-255", "diagnose-material-colours-0-255", material_colours_255),
    per_light("light-colour-0-255", "diagnose-light-colour-0-255", light_colour_255),
    row("row-vectors", "diagnose-row-vectors", row_vectors),
    per_light("row-vectors", "diagnose-row-vectors-light", row_vectors_alone),
    per_light("light-ambient-from-diffuse", "diagnose-light-ambient-from-diffuse", light_ambient_from_diffuse),
    row("ambient-from-diffuse", "diagnose-ambient-from-diffuse", ambient_from_diffuse),
    row("specular-from-colour", "diagnose-specular-from-colour", specular_from_colour),
    row("emission-left-out", "diagnose-emission-left-out", emission_left_out),
    row("emission-back-only", "diagnose-emission-back-only", emission_back_only),
    row("emission-from-colour", "diagnose-emission-from-colour", emission_from_colour),
    row("ambient-diffuse-swapped", "diagnose-ambient-diffuse-swapped", ambient_diffuse_swapped),
    per_light("light-diffuse-left-out", "diagnose-light-diffuse-left-out", light_diffuse_left_out),
    // Edits of the exported shader's formula, the ids `phonglab check`'s for the same slip.
    row("diffuse-not-clamped", "diagnose-diffuse-not-clamped", |d, _| slips::diffuse_not_clamped(d)),
    row("vlv-reversed", "diagnose-vlv-reversed", |d, _| slips::light_reversed(d)),
    row("viewer-reversed", "diagnose-viewer-reversed", |d, _| slips::viewer_reversed(d)),
    row("halfway-not-normalised", "diagnose-halfway-not-normalised", |d, _| slips::halfway_not_normalised(d)),
    row("vlv-not-normalised", "diagnose-light-not-normalised", |d, _| slips::light_not_normalised(d)),
    row("reflection-reversed", "diagnose-reflection-reversed", |d, _| slips::reflection_reversed(d)),
    row("flat-shade-model", "diagnose-flat-shade-model", |d, _| slips::flat_shade_model(d)),
    row("view-order-reversed", "diagnose-view-order-reversed", |d, _| slips::view_order_reversed(d)),
    row("view-order-reversed", "diagnose-view-order-reversed-lights", |d, _| slips::view_order_reversed_with_lights(d)),
    row("view-order-reversed", "diagnose-view-order-reversed-lights-only", |d, _| {
        slips::view_order_reversed_for_lights(d)
    }),
    // Last: its colour is fitted, so a mistake of the scene's own values that draws the
    // same picture (the material's ambient given its diffuse) is named before it.
    row("emission-added", "diagnose-emission-added", emission_added),
    per_light("spot-cutoff-doubled", "diagnose-spot-cutoff-doubled", spot_cutoff_doubled),
    row("normal-matrix-not-transposed", "diagnose-normal-matrix-not-transposed", normal_matrix_not_transposed),
    row("normal-not-transformed", "diagnose-normal-not-transformed", normal_not_transformed),
    row("depth-test-off", "diagnose-depth-test-off", depth_test_off),
    row("two-sided-on", "diagnose-two-sided-on", two_sided_on),
    row("quadric-inside", "diagnose-quadric-inside", quadric_inside),
    row("rescale-for-normalize", "diagnose-rescale-for-normalize", rescale_for_normalize),
    per_light("light-after-model", "diagnose-light-after-model-light", light_after_model_alone),
    // After every row of the scene's own values: each number is fitted from the picture, so
    // a row that names why it differs (halved, in radians, swapped) is named before.
    per_light("spot-cutoff-differs", "diagnose-spot-cutoff-differs", spot_cutoff_differs),
    per_light("spot-exponent-differs", "diagnose-spot-exponent-differs", spot_exponent_differs),
    per_light("attenuation-constant-differs", "diagnose-attenuation-constant-differs", attenuation_constant_differs),
    per_light("attenuation-linear-differs", "diagnose-attenuation-linear-differs", attenuation_linear_differs),
    per_light("attenuation-quadratic-differs", "diagnose-attenuation-quadratic-differs", attenuation_quadratic_differs),
    row("shininess-differs", "diagnose-shininess-differs", shininess_differs),
    // After every row of the scene's own values: it explains any of their colour mistakes
    // (in words less plain than theirs) and other colours besides.
    row("colours-differ", "diagnose-colours-differ", colours_differ),
    // Its kin where two-sided lighting has two materials: each side's colours.
    row("materials-differ", "diagnose-materials-differ", materials_differ),
];

/// Each mistake this drawing offers, with where it is made: the table's rows, the
/// per-light ones once for each light, those that cannot change the drawing left out.
/// `fitted` holds what was fitted from the student's picture (the emission, the colours).
pub fn offered(right: &Drawing, fitted: At) -> Vec<(usize, At)> {
    let mut out = Vec::new();
    for (i, m) in MISTAKES.iter().enumerate() {
        let lights = match m.scope {
            Scope::Scene => 1,
            Scope::EachLight => right.scene.lights.len(),
        };
        for light in 0..lights {
            let at = At { light, ..fitted };
            if (m.apply)(&mut right.clone(), at) {
                out.push((i, at));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DMat4, DVec3};

    /// A world-placed spotlight pointing down -z under the view `view`.
    fn spot_under(view: DMat4) -> Drawing {
        let mut scene = crate::model::scene::Scene { eye_from_world: view, ..Default::default() };
        let mut l = Light::gl_default(0);
        (l.spot_cutoff, l.spot_direction, l.placement) = (30.0, DVec3::NEG_Z, LightPlacement::World);
        scene.lights = vec![l];
        Drawing {
            scene,
            mesh: crate::mesh::sphere::glu_sphere(1.0, 4, 4),
            clip_from_object: DMat4::IDENTITY,
            mode: ShadingMode::Phong,
            background: [0.0; 3],
            options: Default::default(),
            depth_test: true,
            inside: None,
        }
    }

    #[test]
    fn the_untransformed_spot_direction_is_offered_where_the_view_turns_it() {
        // Turned half a turn about x, the view sends -z to +z: given under the identity
        // it stays -z in the eye. (A half turn is its own inverse: comparing the turned
        // direction with the inverse-turned one would find no change.)
        let mut d = spot_under(DMat4::from_rotation_x(std::f64::consts::PI));
        assert!(spot_direction_untransformed(&mut d, At::default()));
        let l = &d.scene.lights[0];
        let in_eye = DMat3::from_mat4(d.scene.eye_from_light(l)) * l.spot_direction;
        assert!(in_eye.distance(DVec3::NEG_Z) < 1e-12, "{in_eye}");
        // A view that moves but does not turn changes nothing: not offered.
        let mut d = spot_under(DMat4::from_translation(DVec3::new(0.0, 0.0, -3.0)));
        assert!(!spot_direction_untransformed(&mut d, At::default()));
        // Nor is it for a light that is not a spot.
        let mut d = spot_under(DMat4::from_rotation_x(1.0));
        d.scene.lights[0].spot_cutoff = 180.0;
        assert!(!spot_direction_untransformed(&mut d, At::default()));
    }
}
