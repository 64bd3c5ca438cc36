//! The lighting state: light model, up to 8 lights, materials, transforms, normal handling.
//!
//! Values are stored in `f64` exactly as the user gave them; an engine of precision `S`
//! rounds them once when it is built (OpenGL stores them as `f32`). Defaults are OpenGL's
//! (OpenGL 2.1 spec, tables 6.9-6.11): only light 0 has white diffuse and specular.

use glam::{DMat4, DVec3, DVec4, Vec3};

use crate::model::rules::Rules;

/// OpenGL's limit on simultaneous lights (`GL_MAX_LIGHTS` is at least 8).
pub const MAX_LIGHTS: usize = 8;

/// An RGBA colour (unclamped: OpenGL accepts any value, negative or above 1).
pub type Rgba = DVec4;

/// Which sides a `glMaterial` or `glColorMaterial` call sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Face {
    /// `GL_FRONT`.
    Front,
    /// `GL_BACK`.
    Back,
    /// `GL_FRONT_AND_BACK` (OpenGL's initial `glColorMaterial` face).
    #[default]
    FrontAndBack,
}

impl Face {
    /// Does this face include side `side`?
    pub fn includes(self, side: Side) -> bool {
        matches!((self, side), (Face::FrontAndBack, _) | (Face::Front, Side::Front) | (Face::Back, Side::Back))
    }

    /// The OpenGL enum.
    pub fn gl(self) -> &'static str {
        match self {
            Face::Front => "GL_FRONT",
            Face::Back => "GL_BACK",
            Face::FrontAndBack => "GL_FRONT_AND_BACK",
        }
    }
}

/// A face's side: which normal and material the equation lights with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Side {
    /// Front-facing (`n` as given).
    #[default]
    Front,
    /// Back-facing (`-n`, the back material; only differs with two-sided lighting).
    Back,
}

impl Side {
    /// Both sides, front first.
    pub const ALL: [Side; 2] = [Side::Front, Side::Back];

    /// The side's place in per-side arrays: 0 front, 1 back.
    pub fn index(self) -> usize {
        match self {
            Side::Front => 0,
            Side::Back => 1,
        }
    }

    /// The back side where `back`, else the front.
    pub fn back_if(back: bool) -> Side {
        if back { Side::Back } else { Side::Front }
    }
}

/// A light, by its place among the scene's lights (`GL_LIGHTi`'s i): what a stage of the
/// plan and the writers name a light by. Written as its number in JSON (the probe's).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize)]
#[serde(transparent)]
pub struct LightId(pub usize);

impl LightId {
    /// The light's place in per-light arrays.
    pub fn index(self) -> usize {
        self.0
    }

    /// The first `count` lights, in order.
    pub fn all(count: usize) -> impl Iterator<Item = LightId> {
        (0..count).map(LightId)
    }
}

/// Written as the number alone, as generated code names a light (`L0`, `light0_position`).
impl std::fmt::Display for LightId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0)
    }
}

/// Which material properties track the current colour (`glColorMaterial`'s mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ColorMaterialMode {
    /// `GL_AMBIENT`: `a_cm`.
    Ambient,
    /// `GL_DIFFUSE`: `d_cm` (and so the lit colour's alpha).
    Diffuse,
    /// `GL_SPECULAR`: `s_cm`.
    Specular,
    /// `GL_EMISSION`: `e_cm`.
    Emission,
    /// `GL_AMBIENT_AND_DIFFUSE`: both (OpenGL's initial mode, and what
    /// openFrameworks' `ofEnableLighting` sets).
    #[default]
    AmbientAndDiffuse,
}

impl ColorMaterialMode {
    /// Every mode, in OpenGL's order.
    pub const ALL: [ColorMaterialMode; 5] = [
        ColorMaterialMode::Ambient,
        ColorMaterialMode::Diffuse,
        ColorMaterialMode::Specular,
        ColorMaterialMode::Emission,
        ColorMaterialMode::AmbientAndDiffuse,
    ];

    /// The OpenGL enum.
    pub fn gl(self) -> &'static str {
        match self {
            ColorMaterialMode::Ambient => "GL_AMBIENT",
            ColorMaterialMode::Diffuse => "GL_DIFFUSE",
            ColorMaterialMode::Specular => "GL_SPECULAR",
            ColorMaterialMode::Emission => "GL_EMISSION",
            ColorMaterialMode::AmbientAndDiffuse => "GL_AMBIENT_AND_DIFFUSE",
        }
    }

    /// Does this mode track the material's ambient?
    pub fn ambient(self) -> bool {
        matches!(self, ColorMaterialMode::Ambient | ColorMaterialMode::AmbientAndDiffuse)
    }

    /// Does this mode track the material's diffuse?
    pub fn diffuse(self) -> bool {
        matches!(self, ColorMaterialMode::Diffuse | ColorMaterialMode::AmbientAndDiffuse)
    }
}

/// `glEnable(GL_COLOR_MATERIAL)` with `glColorMaterial(face, mode)`: the material
/// properties `mode` names, on the sides `face` names, are the current colour `color`
/// (`glColor`, what openFrameworks' `ofSetColor` sets) instead of what `glMaterial` set
/// (OpenGL 2.1, section 2.14.3). openFrameworks' `ofEnableLighting` turns it on with
/// `GL_FRONT_AND_BACK` and `GL_AMBIENT_AND_DIFFUSE`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColorMaterial {
    /// The sides that track.
    pub face: Face,
    /// The properties that track.
    pub mode: ColorMaterialMode,
    /// The current colour, rgba (OpenGL's initial one is (1, 1, 1, 1)).
    pub color: Rgba,
}

impl Default for ColorMaterial {
    /// OpenGL's initial `glColorMaterial` state and current colour, enabled.
    fn default() -> Self {
        Self { face: Face::FrontAndBack, mode: ColorMaterialMode::AmbientAndDiffuse, color: DVec4::ONE }
    }
}

impl ColorMaterial {
    /// `m`, the material of side `side`, with the properties this tracks there replaced by
    /// the current colour.
    pub fn apply(&self, m: &Material, side: Side) -> Material {
        let mut m = m.clone();
        if !self.face.includes(side) {
            return m;
        }
        if self.mode.ambient() {
            m.ambient = self.color;
        }
        if self.mode.diffuse() {
            m.diffuse = self.color;
        }
        match self.mode {
            ColorMaterialMode::Specular => m.specular = self.color,
            ColorMaterialMode::Emission => m.emission = self.color,
            _ => {}
        }
        m
    }

    /// Does this track `q` (one of the material's colours) on side `side`?
    pub fn tracks(&self, property: ColorMaterialMode, side: Side) -> bool {
        self.face.includes(side)
            && match property {
                ColorMaterialMode::Ambient => self.mode.ambient(),
                ColorMaterialMode::Diffuse => self.mode.diffuse(),
                other => self.mode == other,
            }
    }
}

/// Material parameters of one face side (`glMaterial`).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// `a_cm`, reflects ambient light. Default (0.2, 0.2, 0.2, 1).
    pub ambient: Rgba,
    /// `d_cm`, reflects diffuse light; its alpha is the lit colour's alpha. Default (0.8, 0.8, 0.8, 1).
    pub diffuse: Rgba,
    /// `s_cm`, reflects specular light. Default (0, 0, 0, 1).
    pub specular: Rgba,
    /// `e_cm`, light the surface emits. Default (0, 0, 0, 1).
    pub emission: Rgba,
    /// `s_rm`, the specular exponent, in [0, 128]. Default 0.
    pub shininess: f64,
}

impl Default for Material {
    fn default() -> Self {
        Self {
            ambient: DVec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: DVec4::new(0.8, 0.8, 0.8, 1.0),
            specular: DVec4::new(0.0, 0.0, 0.0, 1.0),
            emission: DVec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 0.0,
        }
    }
}

/// Which coordinate frame a light's position and spot direction were given in: the
/// modelview current when `glLight(GL_POSITION)` was called.
#[derive(Clone, Debug, PartialEq, Default)]
pub enum LightPlacement {
    /// Set under an identity modelview: the light moves with the eye (a head lamp).
    Eye,
    /// Set under the view matrix: the light stays put in the world as the object turns.
    World,
    /// Set under the full modelview: the light turns with the object.
    #[default]
    Object,
    /// Set under an explicit matrix (`light_modelview` in the glref case schema).
    Matrix(DMat4),
}

/// One light source (`glLight`).
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// `a_cli`. Default (0, 0, 0, 1).
    pub ambient: Rgba,
    /// `d_cli`. Default white for light 0, black for the others.
    pub diffuse: Rgba,
    /// `s_cli`. Default white for light 0, black for the others.
    pub specular: Rgba,
    /// `P_pli`, homogeneous: w = 0 is a directional light, otherwise positional at xyz/w.
    /// Default (0, 0, 1, 0): a directional light shining down -z.
    pub position: DVec4,
    /// `s_dli`, the spot axis. Default (0, 0, -1).
    pub spot_direction: DVec3,
    /// `c_rli`, the spot cone's half angle in degrees: [0, 90], or 180 for no spotlight.
    pub spot_cutoff: f64,
    /// `s_rli`, the spot exponent, in [0, 128]. Default 0.
    pub spot_exponent: f64,
    /// `k_0i`, `k_1i`, `k_2i`: constant, linear and quadratic attenuation. Default (1, 0, 0).
    pub attenuation: [f64; 3],
    /// The frame `position` and `spot_direction` are given in.
    pub placement: LightPlacement,
}

impl Light {
    /// OpenGL's defaults for `GL_LIGHTi`: light 0 is white, lights 1..7 are black.
    pub fn gl_default(index: usize) -> Self {
        let white = DVec4::ONE;
        let black = DVec4::new(0.0, 0.0, 0.0, 1.0);
        let c = if index == 0 { white } else { black };
        Self {
            ambient: black,
            diffuse: c,
            specular: c,
            position: DVec4::new(0.0, 0.0, 1.0, 0.0),
            spot_direction: DVec3::new(0.0, 0.0, -1.0),
            spot_cutoff: 180.0,
            spot_exponent: 0.0,
            attenuation: [1.0, 0.0, 0.0],
            placement: LightPlacement::default(),
        }
    }

    /// True when the light is directional (w = 0).
    pub fn is_directional(&self) -> bool {
        self.position.w == 0.0
    }

    /// True when the light is a spotlight (cutoff other than 180).
    pub fn is_spot(&self) -> bool {
        self.spot_cutoff != 180.0
    }

    /// True when the attenuation differs from OpenGL's default (1, 0, 0).
    pub fn is_attenuated(&self) -> bool {
        self.attenuation != [1.0, 0.0, 0.0]
    }
}

/// `glLightModel` state.
#[derive(Clone, Debug, PartialEq)]
pub struct LightModel {
    /// `a_cs`, the scene's ambient light. Default (0.2, 0.2, 0.2, 1).
    pub ambient: Rgba,
    /// `v_bs`: the viewer is at the eye (true) or infinitely far along +z (false, default).
    pub local_viewer: bool,
    /// `t_bs`: back faces lit with the back material and -n.
    pub two_sided: bool,
    /// `c_es = SEPARATE_SPECULAR_COLOR`: specular goes to the secondary colour.
    pub separate_specular: bool,
}

impl Default for LightModel {
    fn default() -> Self {
        Self {
            ambient: DVec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: false,
            two_sided: false,
            separate_specular: false,
        }
    }
}

/// How normals are treated after the inverse-transpose transform.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Hash)]
pub enum NormalMode {
    /// Used as transformed (OpenGL's default): a non-unit normal scales diffuse and specular.
    #[default]
    AsIs,
    /// `GL_NORMALIZE`: divided by its length.
    Normalize,
    /// `GL_RESCALE_NORMAL`: scaled by the modelview's inverse scale (exact for uniform scales).
    Rescale,
}

/// A vertex in object coordinates: the point whose colour is computed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vertex {
    /// Homogeneous position (w = 1 for an ordinary point).
    pub position: DVec4,
    /// Object-space normal.
    pub normal: DVec3,
}

impl Vertex {
    /// A point (w = 1) and its normal as meshes and the batch API store them, in f32,
    /// widened exactly to f64.
    pub fn from_f32(position: Vec3, normal: Vec3) -> Self {
        Self { position: position.as_dvec3().extend(1.0), normal: normal.as_dvec3() }
    }
}

impl Default for Vertex {
    fn default() -> Self {
        Self { position: DVec4::new(0.0, 0.0, 0.0, 1.0), normal: DVec3::Z }
    }
}

/// Everything that decides a vertex's lit colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// `glLightModel` state.
    pub light_model: LightModel,
    /// Enabled lights, at most [`MAX_LIGHTS`]; light `i` is `GL_LIGHTi`.
    pub lights: Vec<Light>,
    /// Front material (and back, unless `back_material` is set).
    pub material: Material,
    /// Back material for two-sided lighting; `None` means the same as the front.
    pub back_material: Option<Material>,
    /// `GL_COLOR_MATERIAL`: material properties that track the current colour
    /// (`glColorMaterial` and `glColor`); `None`: disabled, OpenGL's initial state.
    pub color_material: Option<ColorMaterial>,
    /// The camera: world to eye coordinates.
    pub eye_from_world: DMat4,
    /// The object's placement: object to world coordinates.
    pub world_from_object: DMat4,
    /// Normal handling.
    pub normal_mode: NormalMode,
    /// Which rule set (OpenGL, the worksheet's, the Phong demo's) and specular model.
    pub rules: Rules,
    /// The vertex under study.
    pub vertex: Vertex,
}

impl Default for Scene {
    /// OpenGL's initial state with light 0 enabled, identity transforms, a vertex at the
    /// origin with normal +z.
    fn default() -> Self {
        Self {
            light_model: LightModel::default(),
            lights: vec![Light::gl_default(0)],
            material: Material::default(),
            back_material: None,
            color_material: None,
            eye_from_world: DMat4::IDENTITY,
            world_from_object: DMat4::IDENTITY,
            normal_mode: NormalMode::default(),
            rules: Rules::default(),
            vertex: Vertex::default(),
        }
    }
}

impl Scene {
    /// The modelview: object to eye coordinates.
    pub fn eye_from_object(&self) -> DMat4 {
        self.eye_from_world * self.world_from_object
    }

    /// The modelview that was current when light `light` was placed.
    pub fn eye_from_light(&self, light: &Light) -> DMat4 {
        match &light.placement {
            LightPlacement::Eye => DMat4::IDENTITY,
            LightPlacement::World => self.eye_from_world,
            LightPlacement::Object => self.eye_from_object(),
            LightPlacement::Matrix(m) => *m,
        }
    }

    /// Light `l`'s position in eye space (homogeneous, not divided): its position by the
    /// modelview that was current when it was placed.
    pub fn light_pos_in_eye(&self, l: &Light) -> DVec4 {
        crate::numerics::robust::transform_point(&self.eye_from_light(l), l.position)
    }

    /// Is light `l` directional where it counts, in eye space (w = 0 there)? Usually the
    /// same as [`Light::is_directional`], but a placement matrix whose last row is not
    /// (0, 0, 0, 1) can send a positional light to infinity, or bring a directional one
    /// back.
    pub fn light_is_directional(&self, l: &Light) -> bool {
        self.light_pos_in_eye(l).w == 0.0
    }

    /// The material lighting the back side, as set by `glMaterial` (before
    /// `GL_COLOR_MATERIAL`: see [`Scene::lit_material`]).
    pub fn back(&self) -> &Material {
        self.back_material.as_ref().unwrap_or(&self.material)
    }

    /// The material side `side` is lit with: its `glMaterial` values, with
    /// the properties `GL_COLOR_MATERIAL` tracks on that side replaced by the current
    /// colour. What every engine, shader and exporter lights with.
    pub fn lit_material(&self, side: Side) -> Material {
        let set = match side {
            Side::Front => &self.material,
            Side::Back => self.back(),
        };
        match &self.color_material {
            Some(cm) => cm.apply(set, side),
            None => set.clone(),
        }
    }
}
