//! Picture mistakes that no GL state value makes: a line of the exported shader edited (a
//! formula slip the general engine draws, [`FormulaSlip`]), `glShadeModel(GL_FLAT)` (the
//! renderer's [`ShadingMode::FlatProvoking`]), and the modelview built in the wrong order
//! (the rotation times the translation).

use glam::{DMat3, DMat4};

use crate::equation::lighting::FormulaSlip;
use crate::model::rules::SpecularVector;
use crate::model::scene::LightPlacement;
use crate::model::view::ShadingMode;

use super::drawing::Drawing;

/// The drawing lit with formula slip `slip`.
fn slipped(d: &mut Drawing, slip: FormulaSlip) -> bool {
    d.options.slip = slip;
    true
}

/// The diffuse term's `max(n . L, 0)` written `n . L`.
pub(super) fn diffuse_not_clamped(d: &mut Drawing) -> bool {
    slipped(d, FormulaSlip::DiffuseNotClamped)
}

/// A positional light's L from the light to the point (`P - P_l`); only where a light is
/// positional.
pub(super) fn light_reversed(d: &mut Drawing) -> bool {
    d.scene.lights.iter().any(|l| !l.is_directional()) && slipped(d, FormulaSlip::LightReversed)
}

/// The local viewer's V from the eye to the point (`normalize(P)`); only with a local viewer.
pub(super) fn viewer_reversed(d: &mut Drawing) -> bool {
    d.scene.light_model.local_viewer && slipped(d, FormulaSlip::ViewerReversed)
}

/// `n . (L + V)`, H not normalised; only where the specular takes H.
pub(super) fn halfway_not_normalised(d: &mut Drawing) -> bool {
    d.scene.rules.specular.vector() == SpecularVector::Halfway && slipped(d, FormulaSlip::HalfwayNotNormalised)
}

/// A positional light's L not normalised (`toL` for `toL / d`); only where a light is
/// positional.
pub(super) fn light_not_normalised(d: &mut Drawing) -> bool {
    d.scene.lights.iter().any(|l| !l.is_directional()) && slipped(d, FormulaSlip::LightNotNormalised)
}

/// `reflect(L, N)` for `reflect(-L, N)`: R reversed; only where the specular takes R . V.
pub(super) fn reflection_reversed(d: &mut Drawing) -> bool {
    d.scene.rules.specular.vector() == SpecularVector::Reflection && slipped(d, FormulaSlip::ReflectionReversed)
}

/// `glShadeModel(GL_FLAT)`: each face its provoking vertex's colour.
pub(super) fn flat_shade_model(d: &mut Drawing) -> bool {
    let was = d.mode;
    d.mode = ShadingMode::FlatProvoking;
    was != d.mode
}

/// `m` built as its rotation times its translation: `[M3 | M3 t]` for `[M3 | t]`; `None`
/// where that is `m` itself (no turn, or no translation) or `m` is not affine.
fn reordered(m: DMat4) -> Option<DMat4> {
    let affine = m.row(3) == glam::DVec4::W;
    let (m3, t) = (DMat3::from_mat4(m), m.w_axis.truncate());
    let moved = m3 * t;
    (affine && moved.distance(t) > 1e-9 * (1.0 + t.length())).then(|| {
        let mut r = m;
        r.w_axis = moved.extend(1.0);
        r
    })
}

/// The object drawn under `eye_from_object`, the projection kept: the model matrix made
/// to give it (the view, and the lights placed under it, kept).
fn drawn_under(d: &mut Drawing, eye_from_object: DMat4) -> bool {
    let before = d.scene.eye_from_object();
    let world_from_eye = d.scene.eye_from_world.inverse();
    if before.determinant().abs() < 1e-12 || !world_from_eye.is_finite() {
        return false;
    }
    d.clip_from_object = d.clip_from_object * before.inverse() * eye_from_object;
    d.scene.world_from_object = world_from_eye * eye_from_object;
    true
}

/// The object's modelview built as the rotation times the translation (`R @ T`, not
/// `T @ R`): the object moves off its place and is lit there; the lights stay where the
/// scene puts them.
pub(super) fn view_order_reversed(d: &mut Drawing) -> bool {
    match reordered(d.scene.eye_from_object()) {
        Some(m) => drawn_under(d, m),
        None => false,
    }
}

/// The camera's view built as the rotation times the translation, for the object and for
/// the lights placed under it (the same matrix given to both).
pub(super) fn view_order_reversed_with_lights(d: &mut Drawing) -> bool {
    let in_world = d.scene.lights.iter().any(|l| l.placement == LightPlacement::World);
    let (Some(view), Some(m)) = (reordered(d.scene.eye_from_world), reordered(d.scene.eye_from_object())) else {
        return false;
    };
    if !in_world || !drawn_under(d, m) {
        return false;
    }
    let world_from_object = view.inverse() * m;
    d.scene.eye_from_world = view;
    d.scene.world_from_object = world_from_object;
    true
}

/// The view built as the rotation times the translation for the lights alone (their own
/// modelview, `light_modelview`, so built; the object's drawn right): each light placed in
/// the world is placed under that matrix.
pub(super) fn view_order_reversed_for_lights(d: &mut Drawing) -> bool {
    let Some(view) = reordered(d.scene.eye_from_world) else { return false };
    let mut changed = false;
    for l in d.scene.lights.iter_mut().filter(|l| l.placement == LightPlacement::World) {
        l.placement = LightPlacement::Matrix(view);
        changed = true;
    }
    changed
}
