//! Scene files: everything the app shows, as TOML (parsing and writing text; no file I/O).
//!
//! A [`Document`] is a [`Scene`] plus how its camera was chosen ([`CameraSpec`]) and a name.
//! The file layout is the program's public format, kept apart from the in-memory types:
//! matrices are written as rows, colours as rgb or rgba, rule sets by name, and unknown
//! keys are refused so a typo is reported with its line and column.
//! This file holds the document, its errors and its checks; `document/file.rs` holds the
//! file's layout and the reading and writing ([`Document::from_toml`], [`Document::to_toml`]).
//!
//! ```toml
//! name = "the worksheet, mview5"
//! rules = "worksheet"            # opengl | worksheet | phong-demo
//! specular = "blinn-phong"       # blinn-phong | phong | blinn-phong-normalised
//! normals = "as-is"              # as-is | normalize | rescale
//!
//! [camera]
//! kind = "worksheet"             # worksheet | look-at | openframeworks | matrix
//! modelview = 5
//!
//! [material]
//! preset = "bronze"              # optional: a classic material; the keys below override it
//! shininess = 25.6
//!
//! [color_material]              # optional: GL_COLOR_MATERIAL enabled (what oF's ofSetColor sets)
//! face = "front-and-back"        # front | back | front-and-back
//! mode = "ambient-and-diffuse"   # ambient | diffuse | specular | emission | ambient-and-diffuse
//! color = [1, 0.5, 0]            # the current colour, glColor
//!
//! [[lights]]
//! position = [0, 0, 90, 1]
//! ambient = [1, 1, 1]
//! attenuation = [1, 0.0001, 0.00001]
//! placement = "world"            # eye | world | object | matrix (with placement_matrix)
//!
//! [vertex]
//! position = [-512, -384, 0, 1]
//! normal = [0, 0, 1]
//! ```

use thiserror::Error;

mod file;

use crate::model::camera::CameraSpec;
use crate::model::error::SceneError;
use crate::model::scene::Scene;
use crate::model::view::View;
use crate::numerics::strict;

/// A scene as the app holds it and files store it.
#[derive(Clone, Debug, PartialEq)]
pub struct Document {
    /// A title, e.g. "the worksheet, mview5".
    pub name: String,
    /// How `scene.eye_from_world` was chosen.
    pub camera: CameraSpec,
    /// The lighting state; `eye_from_world` equals `camera.matrix()`.
    pub scene: Scene,
    /// The shaded view's object and shading.
    pub view: View,
}

/// The start view's teapot tessellation (quads a patch side): see [`Document::default`].
pub const START_TEAPOT_GRID: u32 = 3;
/// The start view's camera distance: the whole teapot, spout included, in the picture.
pub const START_CAMERA_DISTANCE: f64 = 2.8;

impl Default for Document {
    /// The worksheet with modelview 5, its shaded view on the Utah teapot tessellated
    /// coarsely (3 quads a patch side, where glutSolidTeapot has 7): coarse enough that
    /// Gouraud's highlight, interpolated between vertices, visibly misses Phong's (at 512
    /// pixels, 5.4 % of the teapot's pixels differ by more than 24/255, where
    /// glutSolidTeapot's 7 give 1.1 %), with the camera back far enough (2.8) that the
    /// spout is in the picture. The worked vertex stays the worksheet's.
    fn default() -> Self {
        let mut d = Document::from_scene(
            &crate::t!("doc-worksheet", k = "5"),
            CameraSpec::Worksheet(5),
            crate::model::presets::worksheet(5),
        );
        d.view.object = crate::model::view::ObjectKind::Teapot;
        d.view.teapot_grid = START_TEAPOT_GRID;
        d.view.camera.distance = START_CAMERA_DISTANCE;
        d
    }
}

/// Why a scene file could not be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DocumentError {
    /// Not TOML, or not this format (the message names the line and column).
    #[error("{0}")]
    Syntax(String),
    /// A value is out of range or not finite (the message names the field).
    #[error("{0}")]
    Invalid(#[from] SceneError),
    /// The scene cannot be written (a non-finite number has no TOML form here).
    #[error("cannot write the scene: {0}")]
    Write(String),
}

impl Document {
    /// A document for `scene`, with its view matrix replaced by `camera`'s when it has one.
    pub fn from_scene(name: &str, camera: CameraSpec, mut scene: Scene) -> Self {
        if let Ok(m) = camera.matrix() {
            scene.eye_from_world = m;
        }
        Document { name: name.to_string(), camera, scene, view: View::default() }
    }

    /// Checks the document as the app does ([`Scene::validate_for_editing`] and the camera).
    pub fn validate(&self) -> Result<(), SceneError> {
        let m = self.camera.matrix()?;
        if m != self.scene.eye_from_world {
            return Err(SceneError::CameraMismatch { camera: self.camera.kind_label() });
        }
        self.view.validate()?;
        self.scene.validate_for_editing()
    }
}

/// Refuses a name or a path (`field`) that holds a control character (a line break, ESC,
/// a bidirectional control: [`crate::formats::escape::is_control`]), naming the character.
pub(crate) fn printable_line(field: &str, text: &str) -> Result<(), DocumentError> {
    match text.chars().enumerate().find(|(_, c)| crate::formats::escape::is_control(*c)) {
        None => Ok(()),
        Some((k, c)) => Err(syntax(crate::t!(
            "toml-control-character",
            field = field,
            char = format!("U+{:04X}", c as u32),
            position = k + 1
        ))),
    }
}

pub(crate) fn syntax(msg: String) -> DocumentError {
    DocumentError::Syntax(msg)
}

/// A TOML error as "line L, column C: what (did you mean ...?)" and a short excerpt of the
/// line, however long the line is.
pub(crate) fn toml_error(text: &str, e: &toml::de::Error) -> DocumentError {
    syntax(toml_error_text(text, e))
}

/// The TOML error `e` of `text` as every reader of TOML says it: "line L, column C: what
/// (did you mean ...?)" and a short excerpt of that line of `text` alone (never the
/// whole line, however long), or only what, where `e` has no place.
pub fn toml_error_text(text: &str, e: &toml::de::Error) -> String {
    let what = strict::shortened(&strict::with_suggestion(e.message().trim_end()), strict::MESSAGE_CHARS);
    match e.span() {
        Some(span) => {
            let (place, excerpt) = strict::place(text, span.start);
            format!("{place}: {what}\n{excerpt}")
        }
        None => what,
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec4;

    use super::*;
    use crate::model::materials;
    use crate::model::rules::Rules;
    use crate::model::scene::LightPlacement;

    #[test]
    fn the_default_document_round_trips() {
        let doc = Document::default();
        let text = doc.to_toml().unwrap();
        assert!(text.contains("preset = \"bronze\""), "{text}");
        assert_eq!(Document::from_toml(&text).unwrap(), doc);
    }

    #[test]
    fn a_short_file_takes_defaults_and_presets() {
        let doc = Document::from_toml(
            r#"
            rules = "worksheet"
            [camera]
            kind = "openframeworks"
            width = 1024
            height = 768
            [material]
            preset = "gold"
            shininess = 10
            [[lights]]
            position = [0, 0, 90]
            [[lights]]
            placement = "eye"
            "#,
        )
        .unwrap();
        assert_eq!(doc.scene.rules, Rules::WORKSHEET);
        assert_eq!(doc.scene.material.ambient, materials::by_name("gold").unwrap().ambient);
        assert_eq!(doc.scene.material.shininess, 10.0);
        assert_eq!(doc.scene.lights[0].position, DVec4::new(0.0, 0.0, 90.0, 1.0));
        assert_eq!(doc.scene.lights[0].diffuse, DVec4::ONE, "light 0 is white");
        assert_eq!(doc.scene.lights[1].diffuse, DVec4::new(0.0, 0.0, 0.0, 1.0), "light 1 is black");
        assert_eq!(doc.scene.lights[1].placement, LightPlacement::Eye);
        assert!((doc.scene.eye_from_world.w_axis.z + 665.1075).abs() < 1e-4);
    }

    #[test]
    fn errors_name_the_line_or_the_field() {
        let e = Document::from_toml("rules = \"worksheet\"\nnormals = 3\n").unwrap_err();
        assert!(e.to_string().contains("line 2"), "{e}");
        let e = Document::from_toml("[material]\nshinyness = 3\n").unwrap_err();
        assert!(e.to_string().contains("shinyness") && e.to_string().contains("line 2"), "{e}");
        let e = Document::from_toml("[material]\nshininess = 300\n").unwrap_err();
        assert_eq!(
            e,
            DocumentError::Invalid(SceneError::OutOfRange {
                field: "material.shininess".into(),
                value: 300.0,
                allowed: "[0, 128]"
            })
        );
        let e = Document::from_toml("[material]\npreset = \"unobtainium\"\n").unwrap_err();
        assert!(e.to_string().contains("bronze"), "{e}");
        let e = Document::from_toml("[[lights]]\nattenuation = [0, 0, 0]\nposition = [1, 2, 3]\n").unwrap_err();
        assert!(e.to_string().contains("lights[0].attenuation"), "{e}");
        let e = Document::from_toml("[camera]\nkind = \"look-at\"\neye = [0,0,1]\ncentre = [0,0,1]\nup = [0,1,0]\n")
            .unwrap_err();
        assert!(e.to_string().contains("camera.look_at"), "{e}");
        let e = Document::from_toml("[vertex]\nposition = [1, 2]\nnormal = [0, 0, 1]\n").unwrap_err();
        assert!(e.to_string().contains("3 or 4 numbers"), "{e}");
        let e = Document::from_toml("[[lights]]\nplacement = \"matrix\"\n").unwrap_err();
        assert!(e.to_string().contains("placement_matrix"), "{e}");
    }
}
