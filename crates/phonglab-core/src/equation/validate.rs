//! Checking a scene: what OpenGL refuses, and what the app refuses on top.

use glam::{DMat4, DVec3, DVec4};

use crate::model::error::SceneError;
use crate::model::scene::{Light, LightPlacement, MAX_LIGHTS, Material, Scene};

/// Allowed range of shininess and spot exponent (`GL_MAX_SHININESS`, `GL_MAX_SPOT_EXPONENT`).
pub const MAX_EXPONENT: f64 = 128.0;

fn check_range(
    field: impl FnOnce() -> String,
    v: f64,
    lo: f64,
    hi: f64,
    allowed: &'static str,
) -> Result<(), SceneError> {
    if v.is_nan() {
        return Err(SceneError::NotFinite { field: field(), value: v });
    }
    if v < lo || v > hi {
        return Err(SceneError::OutOfRange { field: field(), value: v, allowed });
    }
    Ok(())
}

fn check_material(m: &Material, name: &str) -> Result<(), SceneError> {
    check_range(|| format!("{name}.shininess"), m.shininess, 0.0, MAX_EXPONENT, "[0, 128]")
}

fn check_light(l: &Light, i: usize) -> Result<(), SceneError> {
    let c = l.spot_cutoff;
    if c.is_nan() {
        return Err(SceneError::NotFinite { field: format!("lights[{i}].spot_cutoff"), value: c });
    }
    if c != 180.0 && !(0.0..=90.0).contains(&c) {
        return Err(SceneError::OutOfRange {
            field: format!("lights[{i}].spot_cutoff"),
            value: c,
            allowed: "[0, 90], or 180 for no spotlight",
        });
    }
    check_range(|| format!("lights[{i}].spot_exponent"), l.spot_exponent, 0.0, MAX_EXPONENT, "[0, 128]")?;
    for (k, name) in l.attenuation.iter().zip(["constant", "linear", "quadratic"]) {
        check_range(|| format!("lights[{i}].attenuation.{name}"), *k, 0.0, f64::INFINITY, "[0, infinity)")?;
    }
    Ok(())
}

impl Scene {
    /// The checks OpenGL makes (`GL_INVALID_VALUE`): shininess and spot exponent in
    /// [0, 128], spot cutoff in [0, 90] or 180, attenuation factors not negative, at most
    /// 8 lights. NaN in any of these is refused too. Other values (colours, positions,
    /// matrices) are accepted as OpenGL accepts them, even when not finite.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.lights.len() > MAX_LIGHTS {
            return Err(SceneError::TooManyLights { count: self.lights.len(), max: MAX_LIGHTS });
        }
        check_material(&self.material, "material")?;
        if let Some(b) = &self.back_material {
            check_material(b, "back_material")?;
        }
        for (i, l) in self.lights.iter().enumerate() {
            check_light(l, i)?;
        }
        Ok(())
    }

    /// [`Scene::validate`] plus what the app refuses on top: any NaN or infinity in any
    /// field, any number a float cannot hold ([`is_float`]: OpenGL's state is float, so
    /// 1e300 would be infinity and 1e-300 zero), and a light whose three attenuation
    /// factors are all zero. With these, the f64 engine's colours are always finite.
    pub fn validate_for_editing(&self) -> Result<(), SceneError> {
        self.validate()?;
        let mut fin = Finite::default();
        fin.v4("light_model.ambient", self.light_model.ambient);
        fin.material("material", &self.material);
        if let Some(b) = &self.back_material {
            fin.material("back_material", b);
        }
        if let Some(cm) = &self.color_material {
            fin.v4("color_material.color", cm.color);
        }
        fin.m4("eye_from_world", &self.eye_from_world);
        fin.m4("world_from_object", &self.world_from_object);
        fin.v4("vertex.position", self.vertex.position);
        fin.v3("vertex.normal", self.vertex.normal);
        for (i, l) in self.lights.iter().enumerate() {
            let p = format!("lights[{i}]");
            fin.v4(&format!("{p}.ambient"), l.ambient);
            fin.v4(&format!("{p}.diffuse"), l.diffuse);
            fin.v4(&format!("{p}.specular"), l.specular);
            fin.v4(&format!("{p}.position"), l.position);
            fin.v3(&format!("{p}.spot_direction"), l.spot_direction);
            fin.slice(&format!("{p}.attenuation"), &l.attenuation);
            if let LightPlacement::Matrix(m) = &l.placement {
                fin.m4(&format!("{p}.placement"), m);
            }
        }
        if let Some(e) = fin.error {
            return Err(e);
        }
        for (i, l) in self.lights.iter().enumerate() {
            if l.attenuation == [0.0; 3] && !self.light_is_directional(l) {
                return Err(SceneError::ZeroAttenuation { field: format!("lights[{i}].attenuation") });
            }
        }
        Ok(())
    }
}

/// What [`is_float`] allows, in words.
pub use crate::model::error::FLOAT_RANGE;

/// Is `x` a value OpenGL's float state holds as it is: 0, or a normal f32 magnitude?
/// (1e300 would be infinity to it, 1e-300 zero; either can turn a finite scene into an
/// infinite colour, in f32 and even in f64.)
pub fn is_float(x: f64) -> bool {
    x == 0.0 || (f32::MIN_POSITIVE as f64..=f32::MAX as f64).contains(&x.abs())
}

/// Collects the first non-finite or non-float value met.
#[derive(Default)]
struct Finite {
    error: Option<SceneError>,
}

impl Finite {
    fn slice(&mut self, field: &str, v: &[f64]) {
        if self.error.is_some() {
            return;
        }
        if let Some((i, x)) = v.iter().enumerate().find(|(_, x)| !x.is_finite()) {
            self.error = Some(SceneError::NotFinite { field: format!("{field}[{i}]"), value: *x });
        } else if let Some((i, x)) = v.iter().enumerate().find(|(_, x)| !is_float(**x)) {
            self.error =
                Some(SceneError::OutOfRange { field: format!("{field}[{i}]"), value: *x, allowed: FLOAT_RANGE });
        }
    }
    fn v3(&mut self, field: &str, v: DVec3) {
        self.slice(field, &v.to_array());
    }
    fn v4(&mut self, field: &str, v: DVec4) {
        self.slice(field, &v.to_array());
    }
    fn m4(&mut self, field: &str, m: &DMat4) {
        // Row-major indices, as the matrix is shown and written.
        self.slice(field, &m.transpose().to_cols_array());
    }
    fn material(&mut self, name: &str, m: &Material) {
        self.v4(&format!("{name}.ambient"), m.ambient);
        self.v4(&format!("{name}.diffuse"), m.diffuse);
        self.v4(&format!("{name}.specular"), m.specular);
        self.v4(&format!("{name}.emission"), m.emission);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_gl_invalid_values_and_names_the_field() {
        let mut s = Scene::default();
        s.material.shininess = 200.0;
        let e = s.validate().unwrap_err();
        assert_eq!(e.field(), "material.shininess");
        assert!(e.to_string().contains("[0, 128]"), "{e}");

        let mut s = Scene::default();
        s.lights[0].spot_cutoff = 91.0;
        let e = s.validate().unwrap_err();
        assert_eq!(e.field(), "lights[0].spot_cutoff");
        assert!(e.to_string().contains("180"), "{e}");

        let mut s = Scene::default();
        s.lights[0].attenuation[1] = -0.5;
        assert_eq!(s.validate().unwrap_err().field(), "lights[0].attenuation.linear");

        let mut s = Scene::default();
        s.lights[0].spot_exponent = f64::NAN;
        assert!(matches!(s.validate().unwrap_err(), SceneError::NotFinite { .. }));

        let s = Scene { lights: vec![Light::gl_default(1); 9], ..Scene::default() };
        assert!(matches!(s.validate().unwrap_err(), SceneError::TooManyLights { count: 9, .. }));
    }

    #[test]
    fn accepts_gl_edge_values() {
        let mut s = Scene::default();
        s.material.shininess = 128.0;
        s.lights[0].spot_cutoff = 90.0;
        s.lights[0].spot_exponent = 0.0;
        s.lights[0].attenuation = [0.0, 0.0, 0.0];
        s.validate().unwrap();
        s.lights[0].spot_cutoff = 0.0;
        s.validate().unwrap();
    }

    #[test]
    fn editing_refuses_nan_and_zero_attenuation() {
        let mut s = Scene::default();
        s.lights[0].position = DVec4::new(0.0, 0.0, 1.0, 1.0);
        s.lights[0].attenuation = [0.0; 3];
        assert!(matches!(s.validate_for_editing().unwrap_err(), SceneError::ZeroAttenuation { .. }));
        let mut s = Scene::default();
        s.material.diffuse.y = f64::NAN;
        let e = s.validate_for_editing().unwrap_err();
        assert_eq!(e.field(), "material.diffuse[1]");
        let mut s = Scene::default();
        s.eye_from_world.w_axis.z = f64::INFINITY;
        let e = s.validate_for_editing().unwrap_err();
        assert_eq!(e.field(), "eye_from_world[11]", "row 2, column 3 in row-major order");
    }
}
