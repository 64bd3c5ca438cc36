//! An openFrameworks 0.12 app (`ofApp.h`, `ofApp.cpp`, `main.cpp`) that sets up a scene's
//! lighting with oF's own calls, for the default renderer (`ofSetupOpenGL`: GL 2.1, where
//! `ofGLRenderer` lights with real fixed-function GL).
//!
//! What oF does, read from its sources, and what the writer relies on:
//! - `ofEnableLighting()` enables `GL_LIGHTING` and `GL_NORMALIZE`;
//! - light positions are world coordinates, loaded under the view matrix only (the
//!   camera's), so `ofTranslate`/`ofRotate` do not move lights;
//! - a directional light's `GL_POSITION` is its node's look direction with w = 0, and a
//!   spotlight's `GL_SPOT_DIRECTION` is its look direction;
//! - neither the local viewer nor two-sided lighting is set; `ofSetGlobalAmbientColor`
//!   sets `GL_LIGHT_MODEL_AMBIENT` (0.2 by default);
//! - `ofSetColor` under lighting with no material bound turns on `glColorMaterial`, so
//!   the app binds an `ofMaterial` and calls `ofSetColor` while lit only where the scene
//!   has `GL_COLOR_MATERIAL` on (then after `glColorMaterial` and
//!   `glEnable(GL_COLOR_MATERIAL)`, raw, once the material is bound).
//!
//! What oF cannot say (the local viewer, two-sided lighting and a back material, a
//! separate specular colour, a light fixed to the eye, a normal mode other than
//! `GL_NORMALIZE`) is the raw GL call, with a comment. What fixed-function GL cannot
//! compute at all is said in a comment too (Phong's R); where that is a term GL's
//! lighting would leave out (energy-conserving Blinn-Phong's normalisation), the app
//! draws with the general shaders of [`super::general_shader`] instead: the whole of
//! OpenGL's lighting read from GL's state (the lights and material oF set, GL's own
//! matrices, and what GLSL has no variable for read with `glGet*` in `draw()`), so the
//! app's calls keep deciding the picture.

use glam::{DMat4, DVec3, DVec4};

use super::template::{Fill, ProgramLanguage, Template, TemplateError};
use crate::equation::plan::{Key, Program, SpecularTerm, Stage};
use crate::formats::document::Document;
use crate::formats::escape::cpp::comment;
use crate::model::rules::RuleSet;
use crate::model::scene::{LightPlacement, Material, NormalMode, Scene};
use crate::model::view::{ObjectKind, Shading};
use crate::model::vocabulary::Quantity as Q;
use crate::t;

/// A C++ float literal: the value as a float holds it, in its shortest form.
fn f(x: f64) -> String {
    // -0 is written 0 (no light or camera depends on the sign of a zero).
    let s = format!("{:?}", if x == 0.0 { 0.0 } else { x as f32 });
    if s.contains(['.', 'e']) { format!("{s}f") } else { format!("{s}.0f") }
}

fn colour(c: DVec4) -> String {
    format!("ofFloatColor({}, {}, {}, {})", f(c.x), f(c.y), f(c.z), f(c.w))
}

/// A C array initialiser of four floats, `{r, g, b, a}`, for a raw `glLightfv`/`glMaterialfv`.
fn gl_array(c: DVec4) -> String {
    format!("{{{}, {}, {}, {}}}", f(c.x), f(c.y), f(c.z), f(c.w))
}

fn vec3(v: DVec3) -> String {
    format!("glm::vec3({}, {}, {})", f(v.x), f(v.y), f(v.z))
}

/// The three files, named as an oF project's `src/` holds them.
/// `key` is the plan's key of the scene the app draws ([`Document::shaded_scene`]): it
/// says which terms the lighting has.
pub fn app(doc: &Document, key: &Key) -> Result<Vec<super::File>, TemplateError> {
    let shader = unsaid(&Program::worked(key)).shader.then(|| general_shader(doc));
    Ok(vec![
        ("ofApp.h".into(), header(doc, shader.is_some())?),
        ("ofApp.cpp".into(), source(doc, key, shader.as_ref())?),
        ("main.cpp".into(), MAIN.fill(&[("renderer_comment", Fill::Text(t!("of-main-comment")))])?),
    ])
}

/// The app's files, whole, with their holes (see [`super::template`]).
const HEADER: Template =
    Template { name: "ofApp.h", language: ProgramLanguage::Cpp, text: include_str!("templates/ofApp.h") };
const SOURCE: Template =
    Template { name: "ofApp.cpp", language: ProgramLanguage::Cpp, text: include_str!("templates/ofApp.cpp") };
const MAIN: Template =
    Template { name: "main.cpp", language: ProgramLanguage::Cpp, text: include_str!("templates/main.cpp") };

fn header(doc: &Document, shader: bool) -> Result<String, TemplateError> {
    let lights = oflights(&doc.shaded_scene());
    let mut members: String = (0..lights.len()).map(|i| format!("    ofLight light{i};\n")).collect();
    if shader {
        members.push_str("    ofShader shader;\n");
    }
    HEADER.fill(&[
        ("title", Fill::Text(t!("of-header-comment", scene = crate::formats::library::localised_name(&doc.name)))),
        ("members", Fill::Code(members)),
    ])
}

/// The shaders the app draws with where fixed-function GL cannot compute the scene's
/// terms: the general GLSL of [`super::general_shader`] (the whole of OpenGL's lighting,
/// read from GL's state, so the app's oF and GL calls keep deciding the picture), for the
/// view's shading (Gouraud for Flat): vertex and fragment stages.
type Stages = (String, String);

fn general_shader(doc: &Document) -> Stages {
    super::general_shader::stages(doc.shaded_scene().rules, doc.view.shading == Shading::Phong)
}

/// A general stage as oF compiles it: GL's own modelview, normal matrix (the modelview
/// itself under the worksheet's rules) and rescale factor, which hold oF's camera, the
/// spin and the cylinder's turn.
fn compatibility_stage(text: &str, scene: &Scene) -> String {
    let normal = match scene.rules.normal_transform() {
        crate::model::rules::NormalTransform::Modelview => "mat3(gl_ModelViewMatrix)",
        crate::model::rules::NormalTransform::InverseTranspose => "gl_NormalMatrix",
    };
    text.replace("uniform mat4 u_eye_from_object;", "#define u_eye_from_object gl_ModelViewMatrix")
        .replace("uniform mat3 u_normal_matrix;", &format!("#define u_normal_matrix {normal}"))
        .replace("uniform float u_rescale;", "#define u_rescale gl_NormalScale")
}

/// setup()'s lines that compile and link the shaders.
fn shader_setup(shader: &Stages, scene: &Scene) -> String {
    let mut s = format!("    // {}\n", comment(&t!("of-shader-comment")));
    for (kind, text) in [("GL_VERTEX_SHADER", &shader.0), ("GL_FRAGMENT_SHADER", &shader.1)] {
        s.push_str(&format!(
            "    shader.setupShaderFromSource({kind}, R\"GLSL(\n{})GLSL\");\n",
            compatibility_stage(text, scene)
        ));
    }
    s.push_str("    shader.linkProgram();\n");
    s
}

/// draw()'s lines that bind the shaders and give them, from GL's state, what GLSL has no
/// variable for (the rest, lights and materials, they read themselves).
fn shader_begin() -> String {
    format!("    shader.begin();\n    // {}\n{}", comment(&t!("of-shader-state-comment")), SHADER_STATE)
}

/// The C++ that reads the state GLSL has no variable for and sets the shaders' uniforms.
const SHADER_STATE: &str = r#"    {
        GLint on[8];
        for (int i = 0; i < 8; i++) on[i] = glIsEnabled(GL_LIGHT0 + i);
        shader.setUniform1iv("u_light_on", on, 8);
        GLint v = 0;
        glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER, &v);
        shader.setUniform1i("u_local_viewer", v);
        glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, &v);
        shader.setUniform1i("u_two_side", v);
        glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &v);
        shader.setUniform1i("u_separate_specular", v == GL_SEPARATE_SPECULAR_COLOR);
        shader.setUniform1i("u_normal_mode", glIsEnabled(GL_NORMALIZE) ? 1 : glIsEnabled(GL_RESCALE_NORMAL) ? 2 : 0);
        GLint mode = 0, face = 0;
        glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &mode);
        glGetIntegerv(GL_COLOR_MATERIAL_FACE, &face);
        int tracked = mode == GL_AMBIENT ? 1 : mode == GL_DIFFUSE ? 2 : mode == GL_SPECULAR ? 3
            : mode == GL_EMISSION ? 4 : mode == GL_AMBIENT_AND_DIFFUSE ? 5 : 0;
        shader.setUniform1i("u_color_material", glIsEnabled(GL_COLOR_MATERIAL) ? tracked : 0);
        shader.setUniform1i("u_color_material_face", face == GL_FRONT ? 1 : face == GL_BACK ? 2 : 3);
        glGetIntegerv(GL_SHADE_MODEL, &v);
        shader.setUniform1i("u_flat", v == GL_FLAT);
        glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
    }
"#;

/// The scene's lights that oF places (every light but those fixed to the eye), with
/// their indices in the scene.
fn oflights(scene: &Scene) -> Vec<usize> {
    (0..scene.lights.len()).filter(|&i| scene.lights[i].placement != LightPlacement::Eye).collect()
}

/// A light's position and spot direction in world coordinates (what oF's lights take).
fn in_world(scene: &Scene, i: usize) -> (DVec4, DVec3) {
    let l = &scene.lights[i];
    let world_from_light = scene.eye_from_world.inverse() * scene.eye_from_light(l);
    (world_from_light * l.position, world_from_light.transform_vector3(l.spot_direction))
}

/// An up vector not parallel to `dir`, for `lookAt`.
fn up_for(dir: DVec3) -> DVec3 {
    if dir.normalize_or_zero().cross(DVec3::Y).length() < 1e-3 { DVec3::X } else { DVec3::Y }
}

fn source(doc: &Document, key: &Key, shader: Option<&Stages>) -> Result<String, TemplateError> {
    let scene = doc.shaded_scene();
    SOURCE.fill(&[
        ("source_comment", Fill::Text(t!("of-source-comment"))),
        ("camera", Fill::Code(camera_calls(&scene))),
        ("lights", Fill::Code(light_calls(&scene, key))),
        ("material_comment", Fill::Text(t!("of-material-comment"))),
        ("material", Fill::Code(material_calls("material", &scene.material, key.rules.emission()))),
        ("shader", Fill::Code(shader.map(|sh| shader_setup(sh, &scene)).unwrap_or_default())),
        ("draw", Fill::Code(draw_body(doc, &scene, key, shader))),
    ])
}

/// The camera: phonglab's view (gluPerspective(40, 1, 0.1, 100) and the orbit camera's
/// position and orientation).
fn camera_calls(scene: &Scene) -> String {
    let mut s = String::new();
    let world_from_eye = scene.eye_from_world.inverse();
    let (_, rotation, position) = world_from_eye.to_scale_rotation_translation();
    s.push_str(&format!("    // {}\n", comment(&t!("of-camera-comment"))));
    s.push_str(
        "    cam.setFov(40);\n    cam.setNearClip(0.1f);\n    cam.setFarClip(100);\n    cam.setAspectRatio(1);\n",
    );
    s.push_str(&format!("    cam.setGlobalPosition({});\n", vec3(position)));
    s.push_str(&format!(
        "    cam.setGlobalOrientation(glm::quat({}, {}, {}, {}));\n\n",
        f(rotation.w),
        f(rotation.x),
        f(rotation.y),
        f(rotation.z)
    ));
    s
}

/// The lights oF places: point, spot or directional, in world coordinates.
fn light_calls(scene: &Scene, key: &Key) -> String {
    let mut s = String::new();
    for (k, &i) in oflights(scene).iter().enumerate() {
        let l = &scene.lights[i];
        let (pos, spot_dir) = in_world(scene, i);
        let name = format!("light{k}");
        s.push_str(&format!("    // {}\n", comment(&t!("of-light-comment", index = i))));
        if pos.w == 0.0 {
            let dir = pos.truncate();
            s.push_str(&format!("    {name}.setDirectional();\n"));
            s.push_str(&format!("    {name}.setPosition(0, 0, 0);\n"));
            s.push_str(&format!(
                "    {name}.lookAt({}, {});  // {}\n",
                vec3(dir),
                vec3(up_for(dir)),
                comment(&t!("of-directional-comment"))
            ));
        } else {
            let p = pos.truncate() / pos.w;
            let spot = key.lights[i].spot;
            if spot {
                s.push_str(&format!("    {name}.setSpotlight({}, {});\n", f(l.spot_cutoff), f(l.spot_exponent)));
            } else {
                s.push_str(&format!("    {name}.setPointLight();\n"));
            }
            s.push_str(&format!("    {name}.setPosition({}, {}, {});\n", f(p.x), f(p.y), f(p.z)));
            if spot {
                s.push_str(&format!(
                    "    {name}.lookAt({}, {});  // {}\n",
                    vec3(p + spot_dir),
                    vec3(up_for(spot_dir)),
                    comment(&t!("of-spot-comment"))
                ));
            }
        }
        s.push_str(&format!("    {name}.setAmbientColor({});\n", colour(l.ambient)));
        s.push_str(&format!("    {name}.setDiffuseColor({});\n", colour(l.diffuse)));
        s.push_str(&format!("    {name}.setSpecularColor({});\n", colour(l.specular)));
        s.push_str(&format!(
            "    {name}.setAttenuation({}, {}, {});\n\n",
            f(l.attenuation[0]),
            f(l.attenuation[1]),
            f(l.attenuation[2])
        ));
    }
    s
}

/// `draw()`: the background, the camera, the lighting model (raw GL for what oF cannot
/// say), the lights, the material and the object.
fn draw_body(doc: &Document, scene: &Scene, key: &Key, shader: Option<&Stages>) -> String {
    let view = &doc.view;
    let mut s = String::new();
    let bg = view.background.map(|c| f64::from(c) * 255.0);
    s.push_str(&format!("    ofBackground({}, {}, {});\n    ofEnableDepthTest();\n", f(bg[0]), f(bg[1]), f(bg[2])));
    s.push_str("    cam.begin();\n    ofEnableLighting();\n");
    s.push_str(&lighting_model(scene, key));
    for (k, _) in oflights(scene).iter().enumerate() {
        s.push_str(&format!("    light{k}.enable();\n"));
    }
    s.push_str(&eye_lights(scene));
    s.push_str("    material.begin();\n");
    if let Some(cm) = &scene.color_material {
        // After the material is bound: enabling it sets the tracked colours to the current one.
        s.push_str(&format!("    // {}\n", comment(&t!("of-color-material-comment"))));
        s.push_str(&format!(
            "    glColorMaterial({}, {});\n    glEnable(GL_COLOR_MATERIAL);\n",
            cm.face.gl(),
            cm.mode.gl()
        ));
        s.push_str(&format!("    ofSetColor({});\n", colour(cm.color)));
    }
    if let Some(back) = &scene.back_material {
        s.push_str(&format!("    // {}\n", comment(&t!("of-back-material-comment"))));
        s.push_str(&raw_material("GL_BACK", back, key.rules.emission()));
    }
    if shader.is_some() {
        s.push_str(&shader_begin());
    }
    s.push_str(&object(doc));
    if shader.is_some() {
        s.push_str("    shader.end();\n");
    }
    s.push_str("    material.end();\n");
    for (k, _) in oflights(scene).iter().enumerate() {
        s.push_str(&format!("    light{k}.disable();\n"));
    }
    s.push_str("    ofDisableLighting();\n    cam.end();\n");
    s
}

/// The material's emission as the rules let it into the sum (black where they leave it out).
fn emission_as_drawn(m: &Material, emission: bool) -> DVec4 {
    if emission { m.emission } else { DVec4::new(0.0, 0.0, 0.0, 1.0) }
}

/// `ofMaterial` calls for `m` (emission 0 where the rules leave it out).
fn material_calls(name: &str, m: &Material, emission: bool) -> String {
    let e = emission_as_drawn(m, emission);
    format!(
        "    {name}.setAmbientColor({});\n    {name}.setDiffuseColor({});\n    {name}.setSpecularColor({});\n    {name}.setEmissiveColor({});\n    {name}.setShininess({});\n",
        colour(m.ambient),
        colour(m.diffuse),
        colour(m.specular),
        colour(e),
        f(m.shininess)
    )
}

/// Raw `glMaterial` calls for one face.
fn raw_material(face: &str, m: &Material, emission: bool) -> String {
    let e = emission_as_drawn(m, emission);
    let mut s = String::from("    {\n");
    for (q, c) in
        [(Q::MatAmbient, m.ambient), (Q::MatDiffuse, m.diffuse), (Q::MatSpecular, m.specular), (Q::MatEmission, e)]
    {
        let param = q.term().gl;
        let var = param.trim_start_matches("GL_").to_lowercase();
        s.push_str(&format!(
            "        const GLfloat {var}[4] = {};\n        glMaterialfv({face}, {param}, {var});\n",
            gl_array(c)
        ));
    }
    s.push_str(&format!("        glMaterialf({face}, {}, {});\n    }}\n", Q::Shininess.term().gl, f(m.shininess)));
    s
}

/// The light model: oF's global ambient, and the raw GL for what oF cannot say.
fn lighting_model(scene: &Scene, key: &Key) -> String {
    let lm = &scene.light_model;
    let mut s = String::new();
    if key.rules.scene_ambient() {
        s.push_str(&format!("    ofSetGlobalAmbientColor({});\n", colour(lm.ambient)));
    } else {
        s.push_str(&format!("    // {}\n", comment(&t!("of-no-scene-ambient"))));
        s.push_str("    ofSetGlobalAmbientColor(ofFloatColor(0, 0, 0, 1));\n");
    }
    match key.rules.set {
        RuleSet::OpenGl => {}
        RuleSet::Worksheet | RuleSet::PhongDemo => {
            s.push_str(&format!("    // {}\n", comment(&t!("of-rules-comment", rules = key.rules.to_string()))));
        }
    }
    for said in unsaid(&Program::worked(key)).comments {
        s.push_str(&format!("    // {}\n", comment(&said)));
    }
    if key.local_viewer {
        s.push_str(&format!(
            "    // {}\n    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);\n",
            comment(&t!("of-local-viewer-comment"))
        ));
    }
    if key.two_sided {
        s.push_str(&format!(
            "    // {}\n    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);\n",
            comment(&t!("of-two-sided-comment"))
        ));
    }
    if key.separate_specular {
        s.push_str(&format!(
            "    // {}\n    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);\n",
            comment(&t!("of-separate-specular-comment"))
        ));
    }
    match key.normals {
        NormalMode::Normalize => {}
        NormalMode::AsIs => {
            s.push_str(&format!("    // {}\n    glDisable(GL_NORMALIZE);\n", comment(&t!("of-normal-as-is-comment"))));
        }
        NormalMode::Rescale => s.push_str(&format!(
            "    // {}\n    glDisable(GL_NORMALIZE);\n    glEnable(GL_RESCALE_NORMAL);\n",
            comment(&t!("of-normal-rescale-comment"))
        )),
    }
    s
}

/// What oF's fixed-function lighting cannot compute of a program's terms: comments, each
/// said once in the program's order, and whether the app must draw with the generated
/// shader instead.
struct Unsaid {
    comments: Vec<String>,
    shader: bool,
}

/// What oF's fixed-function lighting cannot compute of `program`'s terms.
fn unsaid(program: &Program) -> Unsaid {
    let mut out = Unsaid { comments: Vec::new(), shader: false };
    for &stage in &program.stages {
        let said = match stage {
            // GL computes these from the state the app sets.
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
                // GL has no such factor: the generated shader draws.
                SpecularTerm::Normalised => {
                    out.shader = true;
                    Some(t!("of-normalised-comment"))
                }
            },
            // GL's specular is Blinn-Phong's: Phong's R has no switch.
            Stage::Reflect(_) => Some(t!("of-phong-specular-comment")),
        };
        if let Some(said) = said.filter(|s| !out.comments.contains(s)) {
            out.comments.push(said);
        }
    }
    out
}

/// Lights fixed to the eye: raw GL, placed under the identity modelview, on the GL light
/// indices after oF's.
fn eye_lights(scene: &Scene) -> String {
    let placed = oflights(scene).len();
    let mut s = String::new();
    for (k, l) in scene.lights.iter().filter(|l| l.placement == LightPlacement::Eye).enumerate() {
        let gl = format!("GL_LIGHT{}", placed + k);
        s.push_str(&format!("    // {}\n    {{\n", comment(&t!("of-eye-light-comment"))));
        s.push_str("        glMatrixMode(GL_MODELVIEW);\n        glPushMatrix();\n        glLoadIdentity();\n");
        s.push_str(&format!(
            "        const GLfloat position[4] = {};\n        glLightfv({gl}, GL_POSITION, position);\n",
            gl_array(l.position)
        ));
        let d = l.spot_direction;
        s.push_str(&format!(
            "        const GLfloat spot_direction[3] = {{{}, {}, {}}};\n        glLightfv({gl}, GL_SPOT_DIRECTION, spot_direction);\n",
            f(d.x),
            f(d.y),
            f(d.z)
        ));
        s.push_str("        glPopMatrix();\n");
        for (q, c) in [(Q::LightAmbient, l.ambient), (Q::LightDiffuse, l.diffuse), (Q::LightSpecular, l.specular)] {
            let param = q.term().gl;
            let var = param.trim_start_matches("GL_").to_lowercase();
            s.push_str(&format!(
                "        const GLfloat {var}[4] = {};\n        glLightfv({gl}, {param}, {var});\n",
                gl_array(c)
            ));
        }
        s.push_str(&format!(
            "        glLightf({gl}, GL_SPOT_CUTOFF, {});\n        glLightf({gl}, GL_SPOT_EXPONENT, {});\n",
            f(l.spot_cutoff),
            f(l.spot_exponent)
        ));
        for (k2, q) in [Q::AttConstant, Q::AttLinear, Q::AttQuadratic].into_iter().enumerate() {
            let param = q.term().gl;
            s.push_str(&format!("        glLightf({gl}, {param}, {});\n", f(l.attenuation[k2])));
        }
        s.push_str(&format!("        glEnable({gl});\n    }}\n"));
    }
    s
}

/// The object, placed and turned as the view draws it.
fn object(doc: &Document) -> String {
    let view = &doc.view;
    let mut s = String::new();
    let spin = view.spin();
    let placed = spin != DMat4::IDENTITY;
    if placed {
        let c = spin.to_cols_array();
        s.push_str(&format!(
            "    ofPushMatrix();\n    ofMultMatrix(glm::mat4({}));  // {}\n",
            c.iter().map(|x| f(*x)).collect::<Vec<_>>().join(", "),
            comment(&t!("of-spin-comment"))
        ));
    }
    match view.object {
        ObjectKind::Sphere => s.push_str(&format!(
            "    ofSetSphereResolution({});\n    ofDrawSphere(0.5f);\n",
            view.sphere_slices.max(view.sphere_stacks)
        )),
        ObjectKind::Cylinder => s.push_str(&format!(
            "    // {}\n    ofSetCylinderResolution({}, {}, {});\n    ofPushMatrix();\n    ofRotateXDeg(90);\n    ofDrawCylinder(0.3f, 0.5f);\n    ofPopMatrix();\n",
            comment(&t!("of-cylinder-comment")),
            view.cylinder_slices,
            view.cylinder_stacks,
            if view.cylinder_caps { 2 } else { 0 }
        )),
        ObjectKind::Teapot | ObjectKind::Obj => s.push_str(&format!(
            "    // {}\n    ofSetSphereResolution({});\n    ofDrawSphere(0.5f);\n",
            comment(&t!("of-no-teapot-comment")),
            view.sphere_slices.max(view.sphere_stacks)
        )),
    }
    if placed {
        s.push_str("    ofPopMatrix();\n");
    }
    s
}
