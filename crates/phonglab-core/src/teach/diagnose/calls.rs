//! Picture mistakes in one call of the lighting state: a value left at OpenGL's default
//! (the scene's ambient, a light's specular), given to the wrong light, face or side, on
//! the wrong scale (0..255), refused by OpenGL (a shininess over 128), reversed (a
//! directional light's direction), or the wrong data given (positions as normals). Rows of
//! [`super::MISTAKES`], each a change of the drawing.

use glam::{DMat3, DVec4};

use crate::model::scene::{ColorMaterialMode, Face, Light, Material, NormalMode};

use super::change::{At, back_only, each_material, the_light};
use super::drawing::Drawing;

/// A light's specular colour never set: OpenGL's default, white for light 0, black for
/// the others.
pub(super) fn light_specular_left_out(d: &mut Drawing, at: At) -> bool {
    let default = Light::gl_default(at.light).specular;
    the_light(d, at, |l| l.specular != default, |l| l.specular = default)
}

/// A light's ambient and diffuse colours exchanged.
pub(super) fn light_ambient_diffuse_swapped(d: &mut Drawing, at: At) -> bool {
    the_light(d, at, |l| l.ambient != l.diffuse, |l| std::mem::swap(&mut l.ambient, &mut l.diffuse))
}

/// Light `at.light`'s colour `colour` given to the light before it (a block copied from
/// `GL_LIGHT0`'s, one call's light left unchanged): that light takes it, this one keeps
/// OpenGL's default.
fn colour_on_previous_light(d: &mut Drawing, at: At, colour: fn(&mut Light) -> &mut DVec4) -> bool {
    let i = at.light;
    if i == 0 || i >= d.scene.lights.len() {
        return false;
    }
    let given = *colour(&mut d.scene.lights[i]);
    let default = *colour(&mut Light::gl_default(i));
    let before = (*colour(&mut d.scene.lights[i - 1]), given);
    *colour(&mut d.scene.lights[i - 1]) = given;
    *colour(&mut d.scene.lights[i]) = default;
    before != (given, default)
}

/// A light's diffuse colour given to the light before it.
pub(super) fn light_diffuse_on_previous(d: &mut Drawing, at: At) -> bool {
    colour_on_previous_light(d, at, |l| &mut l.diffuse)
}

/// A light's specular colour given to the light before it.
pub(super) fn light_specular_on_previous(d: &mut Drawing, at: At) -> bool {
    colour_on_previous_light(d, at, |l| &mut l.specular)
}

/// A directional light's direction reversed: `GL_POSITION` (x, y, z, 0) given as the
/// direction the light travels, not the direction towards the light.
pub(super) fn directional_reversed(d: &mut Drawing, at: At) -> bool {
    let applies = |l: &Light| l.is_directional() && l.position.truncate() != glam::DVec3::ZERO;
    the_light(d, at, applies, |l| l.position = (-l.position.truncate()).extend(0.0))
}

/// A spotlight's cutoff given as its cosine (`math.cos(math.radians(7))`: 0.99), which
/// OpenGL takes as degrees: a cone of about one degree.
pub(super) fn spot_cutoff_cosine(d: &mut Drawing, at: At) -> bool {
    let applies = |l: &Light| l.is_spot() && l.spot_cutoff > 1.0 && l.spot_cutoff <= 90.0;
    the_light(d, at, applies, |l| l.spot_cutoff = l.spot_cutoff.to_radians().cos())
}

/// The scene's ambient light (`GL_LIGHT_MODEL_AMBIENT`) never set: OpenGL's default
/// (0.2, 0.2, 0.2, 1).
pub(super) fn scene_ambient_default(d: &mut Drawing, _: At) -> bool {
    let default = DVec4::new(0.2, 0.2, 0.2, 1.0);
    std::mem::replace(&mut d.scene.light_model.ambient, default) != default
}

/// A colour written on a 0-255 scale (`[102, 102, 102, 1]` for 0.4): its RGB times 255,
/// its alpha kept.
fn times_255(c: &mut DVec4) {
    *c = (c.truncate() * 255.0).extend(c.w);
}

/// The material's diffuse colour given in 0..255.
pub(super) fn material_diffuse_255(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| times_255(&mut m.diffuse))
}

/// Every material colour (ambient, diffuse, specular) given in 0..255.
pub(super) fn material_colours_255(d: &mut Drawing, _: At) -> bool {
    each_material(d, |m| {
        times_255(&mut m.ambient);
        times_255(&mut m.diffuse);
        times_255(&mut m.specular);
    })
}

/// The vertex positions given as normals (`glNormal3fv(POSITIONS[i])`): the direction from
/// the object's origin, with the point's distance as its length (the radius, on a sphere).
pub(super) fn positions_as_normals(d: &mut Drawing, _: At) -> bool {
    let given = d.mesh.positions.clone();
    let changed = given.iter().zip(&d.mesh.normals).any(|(p, n)| (*p - *n).length() > 1e-6);
    d.mesh.normals = given;
    changed
}

/// `glColorMaterial` tracking `GL_AMBIENT_AND_DIFFUSE` where the scene tracks `GL_DIFFUSE`:
/// the current colour is the ambient too.
pub(super) fn colour_material_ambient_and_diffuse(d: &mut Drawing, _: At) -> bool {
    match &mut d.scene.color_material {
        Some(c) if c.mode == ColorMaterialMode::Diffuse => {
            c.mode = ColorMaterialMode::AmbientAndDiffuse;
            true
        }
        _ => false,
    }
}

/// `glColorMaterial` given the wrong face: `GL_BACK` for `GL_FRONT` (or for
/// `GL_FRONT_AND_BACK`), `GL_FRONT` for `GL_BACK`; the faces it leaves keep the
/// `glMaterial` colours.
pub(super) fn colour_material_wrong_face(d: &mut Drawing, _: At) -> bool {
    match &mut d.scene.color_material {
        Some(c) => {
            c.face = match c.face {
                Face::Back => Face::Front,
                Face::Front | Face::FrontAndBack => Face::Back,
            };
            true
        }
        None => false,
    }
}

/// `GL_SHININESS` given over 128 (a 0-1 value times 128 twice, a 0-1000 scale): OpenGL
/// refuses the call (`GL_INVALID_VALUE`) and the shininess stays its default, 0.
pub(super) fn shininess_refused(d: &mut Drawing, _: At) -> bool {
    d.scene.material.specular.truncate().max_element() > 0.0 && each_material(d, |m| m.shininess = 0.0)
}

/// Two-sided lighting with the materials given for `GL_FRONT` only: the back keeps
/// OpenGL's default material.
pub(super) fn material_front_only(d: &mut Drawing, _: At) -> bool {
    if !d.scene.light_model.two_sided {
        return false;
    }
    // Colour material still tracks on the back where its face says so.
    let back = crate::model::scene::Side::Back;
    let lit = d.scene.lit_material(back);
    d.scene.back_material = Some(Material::default());
    d.scene.lit_material(back) != lit
}

/// The material's emission given for `GL_BACK` only: the front keeps OpenGL's black.
pub(super) fn emission_back_only(d: &mut Drawing, _: At) -> bool {
    back_only(d, |m, gl| m.emission = gl.emission)
}

/// `GL_RESCALE_NORMAL` where the scene enables `GL_NORMALIZE`, under a scale that is not
/// uniform: the normals rescaled, not made unit.
pub(super) fn rescale_for_normalize(d: &mut Drawing, _: At) -> bool {
    let m = DMat3::from_mat4(d.scene.eye_from_object());
    let lengths = [m.x_axis.length(), m.y_axis.length(), m.z_axis.length()];
    let uneven = lengths.iter().any(|&s| (s - lengths[0]).abs() > 1e-6 * lengths[0]);
    if d.scene.normal_mode != NormalMode::Normalize || !uneven {
        return false;
    }
    d.scene.normal_mode = NormalMode::Rescale;
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_lights() -> Drawing {
        let mut scene = crate::model::scene::Scene::default();
        let mut fill = Light::gl_default(1);
        (fill.diffuse, fill.specular) = (DVec4::new(0.3, 0.2, 0.5, 1.0), DVec4::new(0.1, 0.1, 0.1, 1.0));
        scene.lights = vec![Light::gl_default(0), fill];
        Drawing {
            scene,
            mesh: crate::mesh::sphere::glu_sphere(0.5, 4, 4),
            clip_from_object: glam::DMat4::IDENTITY,
            mode: crate::model::view::ShadingMode::Phong,
            background: [0.0; 3],
            options: Default::default(),
            depth_test: true,
            inside: None,
        }
    }

    #[test]
    fn a_lights_colour_given_to_the_light_before_it_leaves_this_one_the_default() {
        let mut d = two_lights();
        assert!(!light_diffuse_on_previous(&mut d.clone(), At::default()), "GL_LIGHT0 has no light before it");
        assert!(light_diffuse_on_previous(&mut d, At { light: 1, ..At::default() }));
        assert_eq!(d.scene.lights[0].diffuse, DVec4::new(0.3, 0.2, 0.5, 1.0));
        assert_eq!(d.scene.lights[1].diffuse, Light::gl_default(1).diffuse);
        // The specular goes the same way; the diffuse is left alone.
        let mut d = two_lights();
        assert!(light_specular_on_previous(&mut d, At { light: 1, ..At::default() }));
        assert_eq!(d.scene.lights[0].specular, DVec4::new(0.1, 0.1, 0.1, 1.0));
        assert_eq!(d.scene.lights[1].specular.truncate(), glam::DVec3::ZERO);
        assert_eq!(d.scene.lights[0].diffuse, DVec4::ONE);
    }

    #[test]
    fn a_cutoff_as_its_cosine_and_a_reversed_direction_and_the_default_ambient() {
        let mut d = two_lights();
        d.scene.lights[1].spot_cutoff = 7.0;
        assert!(spot_cutoff_cosine(&mut d, At { light: 1, ..At::default() }));
        assert!((d.scene.lights[1].spot_cutoff - 0.992_546).abs() < 1e-6);
        // GL_LIGHT0's default position (0, 0, 1, 0) is a direction: reversed, (0, 0, -1, 0).
        assert!(directional_reversed(&mut d, At::default()));
        assert_eq!(d.scene.lights[0].position, DVec4::new(0.0, 0.0, -1.0, 0.0));
        // The scene's ambient: offered only where it is not OpenGL's already.
        d.scene.light_model.ambient = DVec4::new(0.2, 0.2, 0.2, 1.0);
        assert!(!scene_ambient_default(&mut d, At::default()));
        d.scene.light_model.ambient = DVec4::new(0.1, 0.1, 0.1, 1.0);
        assert!(scene_ambient_default(&mut d, At::default()));
        assert_eq!(d.scene.light_model.ambient, DVec4::new(0.2, 0.2, 0.2, 1.0));
    }

    #[test]
    fn positions_as_normals_have_the_radius_for_their_length() {
        let mut d = two_lights();
        assert!(positions_as_normals(&mut d, At::default()));
        assert!(d.mesh.normals.iter().all(|n| (n.length() - 0.5).abs() < 1e-6));
        // A unit sphere's positions are its normals: nothing changes, not offered.
        d.mesh = crate::mesh::sphere::glu_sphere(1.0, 4, 4);
        assert!(!positions_as_normals(&mut d, At::default()));
    }
}
