//! The scene file: its layout (version 1, the program's public format, kept apart from
//! the in-memory types) and reading and writing a [`Document`] as TOML with it
//! ([`Document::from_toml`], [`Document::to_toml`]). The module's documentation shows a
//! file.

use glam::{DMat4, DVec3, DVec4};
use serde::{Deserialize, Serialize};

use super::{Document, DocumentError, printable_line, syntax, toml_error};
use crate::model::camera::CameraSpec;
use crate::model::materials;
use crate::model::rules::{RuleSet, Rules, SpecularModel};
use crate::model::scene::{
    ColorMaterial, ColorMaterialMode, Face, Light, LightModel, LightPlacement, Material, NormalMode, Scene, Vertex,
};
use crate::model::transform::{mat4_from_rows, mat4_rows};
use crate::model::view::View;
use crate::numerics::strict;

impl Document {
    /// Parses and checks a scene file.
    pub fn from_toml(text: &str) -> Result<Document, DocumentError> {
        Self::from_toml_in(text, None)
    }

    /// Parses and checks a scene file that lives in the folder `dir`: a relative mesh file
    /// path (`[view] obj`) is taken from that folder.
    ///
    /// A file with no key at all (empty, or only comments) is refused: it is more likely a
    /// file that lost its contents than a wish for OpenGL's defaults, which `name = "..."`
    /// alone asks for.
    pub fn from_toml_in(text: &str, dir: Option<&std::path::Path>) -> Result<Document, DocumentError> {
        let doc = Self::parse_unchecked(text, dir)?;
        doc.validate()?;
        Ok(doc)
    }

    /// [`Document::from_toml_in`], except that a mesh file that cannot be read (moved,
    /// deleted) does not refuse the scene: the view shows the sphere instead, keeps the
    /// path, and the note says so. For a session restored at start.
    pub fn from_toml_keeping_missing_mesh(
        text: &str,
        dir: Option<&std::path::Path>,
    ) -> Result<(Document, Option<String>), DocumentError> {
        let mut doc = Self::parse_unchecked(text, dir)?;
        let mut note = None;
        if doc.view.object == crate::model::view::ObjectKind::Obj
            && let Err(e) = doc.view.obj_mesh()
        {
            let path = doc.view.obj.clone().unwrap_or_default();
            note = Some(crate::t!("mesh-missing-kept", path = path, error = e.to_string()));
            doc.view.object = crate::model::view::ObjectKind::Sphere;
        }
        doc.validate()?;
        Ok((doc, note))
    }

    /// Parses a scene file without checking its values.
    fn parse_unchecked(text: &str, dir: Option<&std::path::Path>) -> Result<Document, DocumentError> {
        let table: toml::Table = toml::from_str(text).map_err(|e| toml_error(text, &e))?;
        if table.is_empty() {
            return Err(syntax(
                "the scene file is empty: it has no key (a scene file written by phonglab names at least its rules and material)".into(),
            ));
        }
        let file: FileV1 = toml::from_str(text).map_err(|e| toml_error(text, &e))?;
        let mut doc = file.into_document()?;
        if let (Some(dir), Some(obj)) = (dir, &doc.view.obj)
            && std::path::Path::new(obj).is_relative()
        {
            doc.view.obj = Some(dir.join(obj).display().to_string());
        }
        Ok(doc)
    }

    /// Writes the document as a scene file (every value explicit, so loading it gives back
    /// exactly this document).
    ///
    /// The name is written by [`crate::formats::escape::toml::string`], on one line whatever
    /// it holds; a mesh path with a control character is refused (it could not be read back).
    pub fn to_toml(&self) -> Result<String, DocumentError> {
        if let Some(obj) = &self.view.obj {
            printable_line("view.obj", obj).map_err(|e| DocumentError::Write(e.to_string()))?;
        }
        let mut file = FileV1::from_document(self);
        file.name = String::new();
        let text = toml::to_string(&file).map_err(|e| DocumentError::Write(e.to_string()))?;
        // The name is the file's first key: written here instead of by the toml crate.
        let rest = text.strip_prefix("name = \"\"\n").unwrap_or(&text);
        Ok(format!("name = {}\n{rest}", crate::formats::escape::toml::string(&self.name)))
    }
}

// ---------------------------------------------------------------- the file layout (v1)

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileV1 {
    #[serde(default)]
    name: String,
    #[serde(default)]
    rules: RuleName,
    #[serde(default)]
    specular: SpecularName,
    #[serde(default)]
    normals: NormalsName,
    #[serde(default)]
    light_model: LightModelFile,
    #[serde(default)]
    camera: CameraFile,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::rows_opt")]
    object_matrix: Option<[[f64; 4]; 4]>,
    #[serde(default)]
    material: MaterialFile,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    back_material: Option<MaterialFile>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    color_material: Option<ColorMaterialFile>,
    #[serde(default)]
    lights: Vec<LightFile>,
    #[serde(default)]
    vertex: VertexFile,
    #[serde(default)]
    view: View,
}

#[derive(Serialize, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum RuleName {
    #[default]
    Opengl,
    Worksheet,
    PhongDemo,
}

#[derive(Serialize, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum SpecularName {
    #[default]
    BlinnPhong,
    Phong,
    BlinnPhongNormalised,
}

#[derive(Serialize, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum NormalsName {
    #[default]
    AsIs,
    Normalize,
    Rescale,
}

/// Three numbers (the fourth taken as 1) or four; otherwise `rule`, with the count.
fn three_or_four(v: &[f64], rule: &str) -> Result<DVec4, String> {
    match v {
        [x, y, z] => Ok(DVec4::new(*x, *y, *z, 1.0)),
        [x, y, z, w] => Ok(DVec4::new(*x, *y, *z, *w)),
        _ => Err(format!("{rule}, not {}", v.len())),
    }
}

/// A file's vector of three or four numbers (the fourth 1 when left out), read through
/// [`three_or_four`] and refused with `rule`.
macro_rules! three_or_four_numbers {
    ($(#[$doc:meta])* $name:ident, $rule:literal) => {
        $(#[$doc])*
        #[derive(Serialize, Deserialize, Clone, Copy)]
        #[serde(try_from = "Vec<f64>", into = "Vec<f64>")]
        struct $name(DVec4);

        impl TryFrom<Vec<f64>> for $name {
            type Error = String;
            fn try_from(v: Vec<f64>) -> Result<Self, String> {
                three_or_four(&v, $rule).map($name)
            }
        }

        impl From<$name> for Vec<f64> {
            fn from(c: $name) -> Vec<f64> {
                c.0.to_array().to_vec()
            }
        }
    };
}

three_or_four_numbers!(
    /// A colour: rgb (alpha 1) or rgba.
    Color,
    "a colour has 3 or 4 numbers (rgb or rgba)"
);
three_or_four_numbers!(
    /// A homogeneous point: xyz (w = 1) or xyzw.
    Point,
    "a position has 3 or 4 numbers (xyz or xyzw)"
);

/// `[color_material]`: `GL_COLOR_MATERIAL` enabled, with `glColorMaterial(face, mode)` and
/// the current colour (`glColor`).
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ColorMaterialFile {
    #[serde(default)]
    face: FaceName,
    #[serde(default)]
    mode: ColorMaterialModeName,
    #[serde(default = "white")]
    color: Color,
}

fn white() -> Color {
    Color(DVec4::ONE)
}

#[derive(Serialize, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum FaceName {
    Front,
    Back,
    #[default]
    FrontAndBack,
}

#[derive(Serialize, Deserialize, Default, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum ColorMaterialModeName {
    Ambient,
    Diffuse,
    Specular,
    Emission,
    #[default]
    AmbientAndDiffuse,
}

impl ColorMaterialFile {
    fn into_color_material(self) -> ColorMaterial {
        ColorMaterial {
            face: match self.face {
                FaceName::Front => Face::Front,
                FaceName::Back => Face::Back,
                FaceName::FrontAndBack => Face::FrontAndBack,
            },
            mode: match self.mode {
                ColorMaterialModeName::Ambient => ColorMaterialMode::Ambient,
                ColorMaterialModeName::Diffuse => ColorMaterialMode::Diffuse,
                ColorMaterialModeName::Specular => ColorMaterialMode::Specular,
                ColorMaterialModeName::Emission => ColorMaterialMode::Emission,
                ColorMaterialModeName::AmbientAndDiffuse => ColorMaterialMode::AmbientAndDiffuse,
            },
            color: self.color.0,
        }
    }

    fn of(cm: &ColorMaterial) -> Self {
        ColorMaterialFile {
            face: match cm.face {
                Face::Front => FaceName::Front,
                Face::Back => FaceName::Back,
                Face::FrontAndBack => FaceName::FrontAndBack,
            },
            mode: match cm.mode {
                ColorMaterialMode::Ambient => ColorMaterialModeName::Ambient,
                ColorMaterialMode::Diffuse => ColorMaterialModeName::Diffuse,
                ColorMaterialMode::Specular => ColorMaterialModeName::Specular,
                ColorMaterialMode::Emission => ColorMaterialModeName::Emission,
                ColorMaterialMode::AmbientAndDiffuse => ColorMaterialModeName::AmbientAndDiffuse,
            },
            color: Color(cm.color),
        }
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LightModelFile {
    #[serde(default = "default_scene_ambient")]
    ambient: Color,
    #[serde(default)]
    local_viewer: bool,
    #[serde(default)]
    two_sided: bool,
    #[serde(default)]
    separate_specular: bool,
}

fn default_scene_ambient() -> Color {
    Color(LightModel::default().ambient)
}

impl Default for LightModelFile {
    fn default() -> Self {
        Self { ambient: default_scene_ambient(), local_viewer: false, two_sided: false, separate_specular: false }
    }
}

/// The camera's kinds (the `kind` key of `[camera]`).
#[derive(Serialize, Deserialize, Default, Clone, Copy, PartialEq)]
#[serde(rename_all = "kebab-case")]
enum CameraKind {
    Worksheet,
    LookAt,
    Openframeworks,
    #[default]
    Matrix,
}

/// `[camera]`: a kind and that kind's keys. A plain table rather than a tagged enum, so an
/// error in a key names that key's line (serde reads a tagged enum's keys out of their place).
#[derive(Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct CameraFile {
    #[serde(default)]
    kind: CameraKind,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    modelview: Option<u8>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::exact_opt")]
    eye: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::exact_opt")]
    centre: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::exact_opt")]
    up: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    width: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    height: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::rows_opt")]
    rows: Option<[[f64; 4]; 4]>,
}

impl CameraFile {
    /// The camera, when the keys given are exactly those of its kind.
    fn spec(&self) -> Result<CameraSpec, DocumentError> {
        let given: Vec<&str> = [
            ("modelview", self.modelview.is_some()),
            ("eye", self.eye.is_some()),
            ("centre", self.centre.is_some()),
            ("up", self.up.is_some()),
            ("width", self.width.is_some()),
            ("height", self.height.is_some()),
            ("rows", self.rows.is_some()),
        ]
        .into_iter()
        .filter_map(|(k, g)| g.then_some(k))
        .collect();
        let (name, keys): (&str, &[&str]) = match self.kind {
            CameraKind::Worksheet => ("worksheet", &["modelview"]),
            CameraKind::LookAt => ("look-at", &["eye", "centre", "up"]),
            CameraKind::Openframeworks => ("openframeworks", &["width", "height"]),
            CameraKind::Matrix => ("matrix", &["rows"]),
        };
        if let Some(extra) = given.iter().find(|k| !keys.contains(k)) {
            let field = format!("camera.{extra}");
            return Err(syntax(crate::t!("toml-camera-takes", field = field, kind = name, keys = keys.join(", "))));
        }
        let missing: Vec<&str> = keys.iter().copied().filter(|k| !given.contains(k)).collect();
        if !missing.is_empty() && self.kind != CameraKind::Matrix {
            return Err(syntax(crate::t!("toml-camera-needs", kind = name, keys = missing.join(", "))));
        }
        let v3 = |v: Option<[f64; 3]>| DVec3::from(v.unwrap_or_default());
        Ok(match self.kind {
            CameraKind::Worksheet => CameraSpec::Worksheet(self.modelview.unwrap_or(5)),
            CameraKind::LookAt => CameraSpec::LookAt { eye: v3(self.eye), centre: v3(self.centre), up: v3(self.up) },
            CameraKind::Openframeworks => CameraSpec::OpenFrameworks {
                width: self.width.unwrap_or_default(),
                height: self.height.unwrap_or_default(),
            },
            CameraKind::Matrix => CameraSpec::Matrix(self.rows.map_or(DMat4::IDENTITY, mat4_from_rows)),
        })
    }

    fn of(spec: &CameraSpec) -> CameraFile {
        match spec {
            CameraSpec::Worksheet(i) => {
                CameraFile { kind: CameraKind::Worksheet, modelview: Some(*i), ..Default::default() }
            }
            CameraSpec::LookAt { eye, centre, up } => CameraFile {
                kind: CameraKind::LookAt,
                eye: Some(eye.to_array()),
                centre: Some(centre.to_array()),
                up: Some(up.to_array()),
                ..Default::default()
            },
            CameraSpec::OpenFrameworks { width, height } => CameraFile {
                kind: CameraKind::Openframeworks,
                width: Some(*width),
                height: Some(*height),
                ..Default::default()
            },
            CameraSpec::Matrix(m) => {
                CameraFile { kind: CameraKind::Matrix, rows: Some(mat4_rows(m)), ..Default::default() }
            }
        }
    }
}

#[derive(Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct MaterialFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    preset: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ambient: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    diffuse: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    specular: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    emission: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    shininess: Option<f64>,
}

#[derive(Serialize, Deserialize, Clone, Copy, Default, PartialEq)]
#[serde(rename_all = "kebab-case")]
enum PlacementName {
    Eye,
    World,
    #[default]
    Object,
    Matrix,
}

#[derive(Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct LightFile {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    position: Option<Point>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ambient: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    diffuse: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    specular: Option<Color>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::exact_opt")]
    spot_direction: Option<[f64; 3]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    spot_cutoff: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    spot_exponent: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::exact_opt")]
    attenuation: Option<[f64; 3]>,
    #[serde(default)]
    placement: PlacementName,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "strict::rows_opt")]
    placement_matrix: Option<[[f64; 4]; 4]>,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct VertexFile {
    position: Point,
    #[serde(deserialize_with = "strict::exact")]
    normal: [f64; 3],
}

impl Default for VertexFile {
    fn default() -> Self {
        let v = Vertex::default();
        Self { position: Point(v.position), normal: v.normal.to_array() }
    }
}

impl MaterialFile {
    fn into_material(self, field: &str) -> Result<Material, DocumentError> {
        let base = match &self.preset {
            Some(name) => materials::by_name(name).cloned().ok_or_else(|| {
                let names: Vec<&str> = materials::classic().iter().map(|m| m.name.as_str()).collect();
                syntax(crate::t!(
                    "toml-unknown-material",
                    field = format!("{field}.preset"),
                    name = format!("{name:?}"),
                    names = names.join(", ")
                ))
            })?,
            None => Material::default(),
        };
        Ok(Material {
            ambient: self.ambient.map_or(base.ambient, |c| c.0),
            diffuse: self.diffuse.map_or(base.diffuse, |c| c.0),
            specular: self.specular.map_or(base.specular, |c| c.0),
            emission: self.emission.map_or(base.emission, |c| c.0),
            shininess: self.shininess.unwrap_or(base.shininess),
        })
    }

    fn from_material(m: &Material) -> Self {
        Self {
            preset: materials::name_of(m).map(str::to_string),
            ambient: Some(Color(m.ambient)),
            diffuse: Some(Color(m.diffuse)),
            specular: Some(Color(m.specular)),
            emission: Some(Color(m.emission)),
            shininess: Some(m.shininess),
        }
    }
}

impl FileV1 {
    fn into_document(self) -> Result<Document, DocumentError> {
        printable_line("name", &self.name)?;
        if let Some(obj) = &self.view.obj {
            printable_line("view.obj", obj)?;
        }
        let camera = self.camera.spec()?;
        let eye_from_world = camera.matrix()?;
        let mut lights = Vec::with_capacity(self.lights.len());
        for (i, l) in self.lights.into_iter().enumerate() {
            let d = Light::gl_default(i);
            let placement = match (l.placement, l.placement_matrix) {
                (PlacementName::Eye, None) => LightPlacement::Eye,
                (PlacementName::World, None) => LightPlacement::World,
                (PlacementName::Object, None) => LightPlacement::Object,
                (PlacementName::Matrix, Some(rows)) => LightPlacement::Matrix(mat4_from_rows(rows)),
                (PlacementName::Matrix, None) => {
                    return Err(syntax(crate::t!("toml-placement-needs-matrix", field = format!("lights[{i}]"))));
                }
                (_, Some(_)) => {
                    return Err(syntax(crate::t!("toml-matrix-needs-placement", field = format!("lights[{i}]"))));
                }
            };
            lights.push(Light {
                ambient: l.ambient.map_or(d.ambient, |c| c.0),
                diffuse: l.diffuse.map_or(d.diffuse, |c| c.0),
                specular: l.specular.map_or(d.specular, |c| c.0),
                position: l.position.map_or(d.position, |p| p.0),
                spot_direction: l.spot_direction.map_or(d.spot_direction, DVec3::from),
                spot_cutoff: l.spot_cutoff.unwrap_or(d.spot_cutoff),
                spot_exponent: l.spot_exponent.unwrap_or(d.spot_exponent),
                attenuation: l.attenuation.unwrap_or(d.attenuation),
                placement,
            });
        }
        let scene = Scene {
            light_model: LightModel {
                ambient: self.light_model.ambient.0,
                local_viewer: self.light_model.local_viewer,
                two_sided: self.light_model.two_sided,
                separate_specular: self.light_model.separate_specular,
            },
            lights,
            material: self.material.into_material("material")?,
            back_material: self.back_material.map(|m| m.into_material("back_material")).transpose()?,
            color_material: self.color_material.map(ColorMaterialFile::into_color_material),
            eye_from_world,
            world_from_object: self.object_matrix.map_or(DMat4::IDENTITY, mat4_from_rows),
            normal_mode: match self.normals {
                NormalsName::AsIs => NormalMode::AsIs,
                NormalsName::Normalize => NormalMode::Normalize,
                NormalsName::Rescale => NormalMode::Rescale,
            },
            rules: Rules {
                set: match self.rules {
                    RuleName::Opengl => RuleSet::OpenGl,
                    RuleName::Worksheet => RuleSet::Worksheet,
                    RuleName::PhongDemo => RuleSet::PhongDemo,
                },
                specular: match self.specular {
                    SpecularName::BlinnPhong => SpecularModel::BlinnPhong,
                    SpecularName::Phong => SpecularModel::Phong,
                    SpecularName::BlinnPhongNormalised => SpecularModel::BlinnPhongNormalised,
                },
            },
            vertex: Vertex { position: self.vertex.position.0, normal: DVec3::from(self.vertex.normal) },
        };
        Ok(Document { name: self.name, camera, scene, view: self.view })
    }

    fn from_document(doc: &Document) -> Self {
        let s = &doc.scene;
        FileV1 {
            name: doc.name.clone(),
            rules: match s.rules.set {
                RuleSet::OpenGl => RuleName::Opengl,
                RuleSet::Worksheet => RuleName::Worksheet,
                RuleSet::PhongDemo => RuleName::PhongDemo,
            },
            specular: match s.rules.specular {
                SpecularModel::BlinnPhong => SpecularName::BlinnPhong,
                SpecularModel::Phong => SpecularName::Phong,
                SpecularModel::BlinnPhongNormalised => SpecularName::BlinnPhongNormalised,
            },
            normals: match s.normal_mode {
                NormalMode::AsIs => NormalsName::AsIs,
                NormalMode::Normalize => NormalsName::Normalize,
                NormalMode::Rescale => NormalsName::Rescale,
            },
            light_model: LightModelFile {
                ambient: Color(s.light_model.ambient),
                local_viewer: s.light_model.local_viewer,
                two_sided: s.light_model.two_sided,
                separate_specular: s.light_model.separate_specular,
            },
            camera: CameraFile::of(&doc.camera),
            object_matrix: (s.world_from_object != DMat4::IDENTITY).then(|| mat4_rows(&s.world_from_object)),
            material: MaterialFile::from_material(&s.material),
            back_material: s.back_material.as_ref().map(MaterialFile::from_material),
            color_material: s.color_material.as_ref().map(ColorMaterialFile::of),
            lights: s
                .lights
                .iter()
                .map(|l| {
                    let (placement, placement_matrix) = match &l.placement {
                        LightPlacement::Eye => (PlacementName::Eye, None),
                        LightPlacement::World => (PlacementName::World, None),
                        LightPlacement::Object => (PlacementName::Object, None),
                        LightPlacement::Matrix(m) => (PlacementName::Matrix, Some(mat4_rows(m))),
                    };
                    LightFile {
                        position: Some(Point(l.position)),
                        ambient: Some(Color(l.ambient)),
                        diffuse: Some(Color(l.diffuse)),
                        specular: Some(Color(l.specular)),
                        spot_direction: Some(l.spot_direction.to_array()),
                        spot_cutoff: Some(l.spot_cutoff),
                        spot_exponent: Some(l.spot_exponent),
                        attenuation: Some(l.attenuation),
                        placement,
                        placement_matrix,
                    }
                })
                .collect(),
            vertex: VertexFile { position: Point(s.vertex.position), normal: s.vertex.normal.to_array() },
            view: doc.view.clone(),
        }
    }
}
