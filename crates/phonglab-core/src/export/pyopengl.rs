//! A standalone PyOpenGL + GLUT program in the Phong demo's style that draws a scene's
//! shaded view as `phonglab render --scene FILE --size 512` does.
//!
//! How it is built:
//! - The lighting state is set the fixed-function way: `glLightfv`, `glMaterialfv` and
//!   `glLightModel*`, each light placed under the modelview that was current when its
//!   `GL_POSITION` was set (so GL keeps it in eye space, as OpenGL does).
//! - The shading is the general GLSL of [`super::general_shader`], Gouraud or Phong, as
//!   the demo draws with its own shaders: the whole of OpenGL 2.1's lighting, reading GL's
//!   state itself (`gl_LightSource[]`, `gl_FrontMaterial`, `gl_LightModel`, and what GLSL
//!   has no variable for through uniforms `set_uniforms()` reads with `glGet*` each frame).
//!   So every `glLight*`, `glMaterial*` or `glLightModel*` call a student edits changes the
//!   picture as it would under fixed-function GL; only the rule set's departures from
//!   OpenGL are fixed (`#define`s, and said in comments). `phonglab shader` keeps the
//!   scene's specialised shaders. The inputs are GL's own `gl_Vertex` and `gl_Normal` (a
//!   compatibility-profile context), so GLU's and GLUT's objects feed them directly.
//! - The object: `gluSphere`, `glutSolidTeapot` or `gluCylinder` where phonglab builds
//!   exactly what they draw; else (a mesh file, the demo's normals, another teapot
//!   tessellation, capped cylinders) phonglab's triangles as arrays.
//! - `--png FILE` draws one 512x512 frame, saves it and exits: for checking.

use glam::DMat4;

use super::python::num;
use super::template::{Fill, ProgramLanguage, Template};
use crate::equation::plan::{Key, Program, SpecularTerm, Stage};
use crate::formats::document::Document;
use crate::formats::escape::python::{comment, triple_quoted};
use crate::model::rules::RuleSet;
use crate::model::scene::{Light, LightPlacement, Scene};
use crate::model::view::{Framing, LightingSpace, ObjectKind, Shading, View};
use crate::model::vocabulary::Quantity as Q;
use crate::t;

/// The program's text for `doc`, or why it cannot be written (a Flat view: the generated
/// shaders are Gouraud and Phong).
/// `key` is the plan's key of the scene the program draws ([`Document::shaded_scene`]):
/// it says which terms the lighting has.
pub fn program(doc: &Document, key: &Key) -> Result<String, String> {
    let (per_fragment, shading_name) = match doc.view.shading {
        Shading::Gouraud => (false, "Gouraud"),
        Shading::Phong => (true, "Phong"),
        Shading::Flat => return Err(t!("export-flat-unsupported")),
    };
    let setup = doc.shaded_setup(crate::numerics::pow::PowFn::Exact);
    let (vertex, fragment) = super::general_shader::stages(setup.scene.rules, per_fragment);
    let scene = &setup.scene;
    let rules = match scene.rules.set {
        RuleSet::Worksheet => "worksheet",
        RuleSet::OpenGl => "opengl",
        RuleSet::PhongDemo => "phong-demo",
    };
    let background = doc.view.background.map(|c| num(f64::from(c))).join(", ");
    let text = |s: String| Fill::Text(s);
    let code = |s: String| Fill::Code(s);
    PROGRAM
        .fill(&[
            (
                "title",
                text(t!(
                    "py-title",
                    scene = crate::formats::library::localised_name(&doc.name),
                    shading = shading_name
                )),
            ),
            ("usage", text(t!("py-usage"))),
            ("rules", text(rules.into())),
            ("rules_comment", code(wrapped_comment(&t!("py-rules-comment"), ""))),
            ("background", code(background)),
            ("shaders_comment", code(wrapped_comment(&t!("py-shaders-comment"), ""))),
            ("vertex_shader", text(vertex)),
            ("fragment_shader", text(fragment)),
            ("matrices", code(matrices(&setup))),
            ("lighting_state", code(lighting_state(scene, key))),
            ("reader_doc", text(t!("py-reader-doc"))),
            ("normal_matrix_comment", text(t!("py-normal-matrix-comment"))),
            ("two_side_comment", code(wrapped_comment(&t!("py-two-side-program-comment"), "    "))),
            ("object", code(object(&doc.view)?)),
        ])
        .map_err(|e| e.to_string())
}

/// The program, whole, with its holes (see [`super::template`]).
const PROGRAM: Template = Template {
    name: "phong_scene.py",
    language: ProgramLanguage::Python,
    text: include_str!("templates/phong_scene.py"),
};

/// A matrix as a NumPy array of its rows.
fn np_matrix(m: &DMat4) -> String {
    let rows = crate::model::transform::mat4_rows(m);
    format!(
        "np.array([\n{}])",
        rows.iter()
            .map(|r| format!("    [{}, {}, {}, {}],\n", num(r[0]), num(r[1]), num(r[2]), num(r[3])))
            .collect::<String>()
    )
}

/// The projection, the view and the object's placement, as phonglab's view draws.
fn matrices(setup: &crate::raster::shaded::ShadedSetup) -> String {
    let view = &setup.view;
    let mut s = String::new();
    let projection = match view.framing {
        Framing::Orbit => {
            format!(
                "{}PROJECTION = None  # gluPerspective(40, 1, 0.1, 100)\n",
                wrapped_comment(&t!("py-projection-orbit"), "")
            )
        }
        Framing::ClipSpace => {
            format!("{}PROJECTION = np.identity(4)\n", wrapped_comment(&t!("py-projection-clip"), ""))
        }
    };
    s.push_str(&projection);
    // The drawing modelview: the camera and the object's spin (and gluCylinder moved to be
    // centred, as phonglab centres its cylinder).
    let shift = object_shift(view);
    let drawing = match view.framing {
        Framing::Orbit => view.camera.eye_from_world() * view.spin(),
        Framing::ClipSpace => view.spin(),
    } * shift;
    s.push_str(&format!("{}MODELVIEW = {}\n", wrapped_comment(&t!("py-modelview-comment"), ""), np_matrix(&drawing)));
    let lighting = setup.scene.eye_from_object() * shift;
    if view.lighting_space == LightingSpace::Object || !lighting.abs_diff_eq(drawing, 1e-12) {
        s.push_str(&format!(
            "{}LIGHTING_MODELVIEW = {}\n",
            wrapped_comment(&t!("py-lighting-modelview-comment"), ""),
            np_matrix(&lighting)
        ));
    } else {
        s.push_str("LIGHTING_MODELVIEW = MODELVIEW\n");
    }
    s.push('\n');
    s
}

/// The modelview a light was placed under, for `glLoadMatrixf` before its `GL_POSITION`,
/// and a comment saying what that placement does.
fn light_modelview(scene: &Scene, l: &Light) -> (String, String) {
    let matrix = || np_matrix(&scene.eye_from_light(l)).replace('\n', "\n    ");
    match l.placement {
        LightPlacement::Eye => ("np.identity(4)".into(), comment(&t!("py-light-eye"))),
        LightPlacement::Object => (matrix(), comment(&t!("py-light-object"))),
        LightPlacement::World | LightPlacement::Matrix(_) => (matrix(), comment(&t!("py-light-world"))),
    }
}

fn rgba(c: glam::DVec4) -> String {
    format!("[{}, {}, {}, {}]", num(c.x), num(c.y), num(c.z), num(c.w))
}

/// The longest line a wrapped comment takes, its indent and `# ` included.
const COMMENT_WIDTH: usize = 90;

/// `text` as Python comment lines of at most [`COMMENT_WIDTH`] characters (a word longer
/// than that on a line of its own), each `indent` then `# `, escaped, ending in a newline.
fn wrapped_comment(text: &str, indent: &str) -> String {
    let room = COMMENT_WIDTH.saturating_sub(indent.chars().count() + 2).max(1);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in comment(text).split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > room {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines.iter().map(|l| format!("{indent}# {l}\n")).collect()
}

/// The fixed-function calls that set the scene's lighting state.
fn lighting_state(scene: &Scene, key: &Key) -> String {
    let mut s = format!(
        "def set_lighting_state():\n    \"\"\"{}\"\"\"\n{}    glMatrixMode(GL_MODELVIEW)\n",
        triple_quoted(&t!("py-state-doc"), false),
        wrapped_comment(&t!("py-editable-comment"), "    ")
    );
    for (i, l) in scene.lights.iter().enumerate() {
        let light = format!("GL_LIGHT{i}");
        let (matrix, placement) = light_modelview(scene, l);
        s.push_str(&format!(
            "{}    light_modelview = {matrix}\n    glLoadMatrixf(light_modelview.T)\n",
            wrapped_comment(&format!("GL_LIGHT{i}: {placement}"), "    ")
        ));
        s.push_str(&format!("    glLightfv({light}, {}, {})\n", gl(Q::LightPos), rgba(l.position)));
        s.push_str(&format!(
            "    glLightfv({light}, {}, [{}, {}, {}])\n",
            gl(Q::SpotDirection),
            num(l.spot_direction.x),
            num(l.spot_direction.y),
            num(l.spot_direction.z)
        ));
        for (q, c) in [(Q::LightAmbient, l.ambient), (Q::LightDiffuse, l.diffuse), (Q::LightSpecular, l.specular)] {
            s.push_str(&format!("    glLightfv({light}, {}, {})\n", gl(q), rgba(c)));
        }
        for (q, v) in [(Q::SpotCutoff, l.spot_cutoff), (Q::SpotExponent, l.spot_exponent)] {
            s.push_str(&format!("    glLightf({light}, {}, {})\n", gl(q), num(v)));
        }
        for (k, q) in [Q::AttConstant, Q::AttLinear, Q::AttQuadratic].into_iter().enumerate() {
            s.push_str(&format!("    glLightf({light}, {}, {})\n", gl(q), num(l.attenuation[k])));
        }
        s.push_str(&format!("    glEnable({light})\n"));
    }
    let faces = if scene.back_material.is_some() {
        ["GL_FRONT", "GL_BACK"].as_slice()
    } else {
        ["GL_FRONT_AND_BACK"].as_slice()
    };
    for face in faces {
        let m = if *face == "GL_BACK" { scene.back() } else { &scene.material };
        let colours = [
            (Q::MatAmbient, m.ambient),
            (Q::MatDiffuse, m.diffuse),
            (Q::MatSpecular, m.specular),
            (Q::MatEmission, m.emission),
        ];
        for (q, c) in colours {
            s.push_str(&format!("    glMaterialfv({face}, {}, {})\n", gl(q), rgba(c)));
        }
        s.push_str(&format!("    glMaterialf({face}, {}, {})\n", gl(Q::Shininess), num(m.shininess)));
    }
    for said in unsaid(&Program::worked(key)) {
        s.push_str(&wrapped_comment(&said, "    "));
    }
    if let Some(cm) = &scene.color_material {
        // After the glMaterial calls: enabling it sets the tracked colours to the current one.
        s.push_str(&wrapped_comment(&t!("py-color-material-comment"), "    "));
        s.push_str(&format!("    glColorMaterial({}, {})\n", cm.face.gl(), cm.mode.gl()));
        s.push_str("    glEnable(GL_COLOR_MATERIAL)\n");
        s.push_str(&format!("    glColor4f({})\n", cm.color.to_array().map(num).join(", ")));
    }
    let lm = &scene.light_model;
    // The shaders' SCENE_AMBIENT (general_shader): without it they add neither the scene's
    // ambient nor the material's emission, whatever GL's state says.
    if !(scene.rules.scene_ambient() && scene.rules.emission()) {
        s.push_str(&wrapped_comment(&t!("py-scene-ambient-off"), "    "));
    }
    s.push_str(&format!("    glLightModelfv({}, {})\n", gl(Q::SceneAmbient), rgba(lm.ambient)));
    s.push_str(&format!(
        "    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, {})\n",
        if key.local_viewer { "GL_TRUE" } else { "GL_FALSE" }
    ));
    s.push_str(&format!(
        "    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, {})\n",
        if key.two_sided { "GL_TRUE" } else { "GL_FALSE" }
    ));
    s.push_str(&format!(
        "    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, {})\n",
        if key.separate_specular { "GL_SEPARATE_SPECULAR_COLOR" } else { "GL_SINGLE_COLOR" }
    ));
    let normals = match key.normals {
        crate::model::scene::NormalMode::Normalize => "    glEnable(GL_NORMALIZE)\n",
        crate::model::scene::NormalMode::Rescale => "    glEnable(GL_RESCALE_NORMAL)\n",
        crate::model::scene::NormalMode::AsIs => "",
    };
    s.push_str(normals);
    s.push_str(&wrapped_comment(&t!("py-lighting-comment"), "    "));
    s.push_str("    glEnable(GL_LIGHTING)\n");
    s.push_str(&wrapped_comment(&t!("py-shade-model-comment"), "    "));
    s.push_str("    glShadeModel(GL_SMOOTH)\n\n\n");
    s
}

/// What GL's fixed-function state cannot say of `program`'s terms, each said once, in the
/// program's order: the generated shader computes every stage, but GL's own lighting, from
/// the state above, would not.
fn unsaid(program: &Program) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for &stage in &program.stages {
        let said: Option<String> = match stage {
            // GL's state says these (the shader reads them back from it).
            Stage::TransformNormal
            | Stage::RescaleNormal
            | Stage::NormalizeNormal
            | Stage::NormalizeNormalFast
            | Stage::TransformPosition
            | Stage::TransformPositionProjective
            | Stage::TranslatePosition
            | Stage::ZeroNormals
            | Stage::ViewVector(_)
            | Stage::LightVector(_)
            | Stage::LightConstant(_)
            | Stage::Attenuate(_)
            | Stage::SpotCone(_)
            | Stage::SpotPower(_)
            | Stage::Halfway(_)
            | Stage::HalfwayConstant(_)
            | Stage::DiffuseCosine(..)
            | Stage::SpecularCosine(..)
            | Stage::Power(..)
            | Stage::SceneColor => None,
            Stage::Sum(_, _, term) => match term {
                SpecularTerm::Zero | SpecularTerm::Plain => None,
                SpecularTerm::Normalised => Some(t!("py-normalised-comment")),
            },
            // The rules' R: the program's RULES names them, and the shader draws with them.
            Stage::Reflect(_) => None,
        };
        if let Some(said) = said.filter(|s| !out.contains(s)) {
            out.push(said);
        }
    }
    out
}

/// Whether the object is drawn by GLU's or GLUT's own call (else as phonglab's arrays).
fn drawn_by_call(view: &View) -> bool {
    !view.demo_normals
        && match view.object {
            ObjectKind::Sphere => true,
            ObjectKind::Teapot => view.teapot_grid == 7,
            ObjectKind::Cylinder => !view.cylinder_caps,
            ObjectKind::Obj => false,
        }
}

/// The object's own placement under the modelview: gluCylinder runs from z = 0 to 0.5,
/// and phonglab centres its cylinder (its arrays are centred already).
fn object_shift(view: &View) -> DMat4 {
    if view.object == ObjectKind::Cylinder && view.cylinder_centered && drawn_by_call(view) {
        DMat4::from_translation(glam::DVec3::new(0.0, 0.0, -0.25))
    } else {
        DMat4::IDENTITY
    }
}

/// Draws `view`'s object: GLU's or GLUT's own call where phonglab's mesh is what it draws,
/// else phonglab's triangles.
fn object(view: &View) -> Result<String, String> {
    let call = match view.object {
        _ if !drawn_by_call(view) => None,
        ObjectKind::Sphere => {
            Some(format!("    gluSphere(quadric, 0.5, {}, {})\n", view.sphere_slices, view.sphere_stacks))
        }
        ObjectKind::Teapot if view.teapot_grid == 7 => Some(format!(
            "    # {}\n    glFrontFace(GL_CW)\n    glutSolidTeapot(0.5)\n    glFrontFace(GL_CCW)\n",
            comment(&t!("py-teapot-winding"))
        )),
        ObjectKind::Cylinder if !view.cylinder_caps => Some(format!(
            "    gluCylinder(quadric, 0.3, 0.3, 0.5, {}, {})\n",
            view.cylinder_slices, view.cylinder_stacks
        )),
        _ => None,
    };
    let mut s = format!("def draw_object(quadric):\n    \"\"\"{}\"\"\"\n", triple_quoted(&t!("py-object-doc"), false));
    match call {
        Some(c) => s.push_str(&c),
        None => {
            let mesh = if view.object == ObjectKind::Obj {
                view.obj_mesh().map_err(|e| e.to_string())?.mesh.clone()
            } else {
                view.mesh()
            };
            s.push_str("    glBegin(GL_TRIANGLES)\n    for i in TRIANGLES:\n        glNormal3fv(NORMALS[i])\n        glVertex3fv(POSITIONS[i])\n    glEnd()\n\n\n");
            let v3 = |v: &glam::Vec3| format!("({}, {}, {})", num(v.x as f64), num(v.y as f64), num(v.z as f64));
            s.push_str(&format!(
                "{}POSITIONS = [{}]\n",
                wrapped_comment(&t!("py-arrays-comment"), ""),
                mesh.positions.iter().map(v3).collect::<Vec<_>>().join(", ")
            ));
            s.push_str(&format!("NORMALS = [{}]\n", mesh.normals.iter().map(v3).collect::<Vec<_>>().join(", ")));
            s.push_str(&format!(
                "TRIANGLES = [{}]\n",
                mesh.triangles
                    .iter()
                    .flat_map(|t| t.iter())
                    .map(std::string::ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
            return Ok(s + "\n\n");
        }
    }
    Ok(s + "\n\n")
}

/// OpenGL's name for `q` (its `GL_` enum), from the vocabulary.
fn gl(q: Q) -> &'static str {
    q.term().gl
}
