//! What a row of the table changes a drawing with, and its common changes: where a mistake
//! is made ([`At`]: the light, and what was fitted from the student's picture), one light
//! changed, each side's material changed, a material property given for `GL_BACK` only.

use crate::model::scene::{Light, Material};

use super::colours::Colours;
use super::drawing::Drawing;
use super::sides::Sides;
use super::values::Values;

/// What a mistake is made with: the light (for [`super::Scope::EachLight`]) and the emission fitted
/// from the student's picture (for `emission-added`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct At {
    /// The light's index (`GL_LIGHTn`); 0 for a mistake of the whole scene.
    pub light: usize,
    /// The emission the picture shows beyond the right one (linear RGB, 0 to 1).
    pub emission: [f64; 3],
    /// The products of colours the picture shows, term by term (for `colours-differ`).
    pub colours: Option<Colours>,
    /// The single numbers the picture shows (for `spot-cutoff-differs` and its kin).
    pub values: Values,
    /// Each side's material colours the picture shows (for `materials-differ`).
    pub sides: Option<Sides>,
    /// The scene's own values its rows' words quote.
    pub given: Given,
}

/// The scene's own values a row's words quote ("0.4 for 51.2" is the scene's shininess).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Given {
    /// The front material's diffuse colour (RGB, 0 to 1).
    pub diffuse: [f64; 3],
    /// The front material's shininess.
    pub shininess: f64,
}

impl Given {
    /// The values of `d`'s scene.
    pub fn of(d: &Drawing) -> Given {
        let m = &d.scene.material;
        Given { diffuse: m.diffuse.truncate().to_array(), shininess: m.shininess }
    }
}

/// Each side's `glMaterial` values changed by `change`; false when it changed none.
pub(super) fn each_material(d: &mut Drawing, change: impl Fn(&mut Material)) -> bool {
    let mut changed = false;
    for m in std::iter::once(&mut d.scene.material).chain(d.scene.back_material.as_mut()) {
        let before = m.clone();
        change(m);
        changed |= *m != before;
    }
    changed
}

/// Light `at.light` changed by `change` where `applies` holds for it.
pub(super) fn the_light(
    d: &mut Drawing,
    at: At,
    applies: impl Fn(&Light) -> bool,
    change: impl Fn(&mut Light),
) -> bool {
    match d.scene.lights.get_mut(at.light) {
        Some(l) if applies(l) => {
            change(l);
            true
        }
        _ => false,
    }
}

/// The material's properties `part` given for `GL_BACK` only: the back keeps the scene's
/// material, the front OpenGL's defaults for them.
pub(super) fn back_only(d: &mut Drawing, part: fn(&mut Material, &Material)) -> bool {
    let given = d.scene.material.clone();
    let mut front = given.clone();
    part(&mut front, &Material::default());
    if front == given {
        return false;
    }
    d.scene.back_material.get_or_insert(given);
    d.scene.material = front;
    true
}
