//! A standalone PyOpenGL + GLUT program in the Phong demo's style that draws a scene's
//! shaded view as `phonglab render --scene FILE --size 512` does.
//!
//! How it is built:
//! - The lighting state is set the fixed-function way: `glLightfv`, `glMaterialfv` and
//!   `glLightModel*`, each light placed under the modelview that was current when its
//!   `GL_POSITION` was set (so GL keeps it in eye space, as OpenGL does).
//! - The shading is the scene's generated GLSL (`phonglab shader`), Gouraud or Phong, as
//!   the demo draws with its own shaders. It reads the state back from GL (`glGetLightfv`,
//!   `glGetMaterialfv`, the matrices): one state, set once, that the program's shader and a
//!   fixed-function reader see alike. Its inputs are GL's own `gl_Vertex` and `gl_Normal`
//!   (a compatibility-profile context), so GLU's and GLUT's objects feed it directly.
//! - The object: `gluSphere`, `glutSolidTeapot` or `gluCylinder` where phonglab builds
//!   exactly what they draw; else (a mesh file, the demo's normals, another teapot
//!   tessellation, capped cylinders) phonglab's triangles as arrays.
//! - `--png FILE` draws one 512x512 frame, saves it and exits: for checking.

use glam::DMat4;

use super::python::{num, string};
use crate::formats::document::Document;
use crate::model::rules::RuleSet;
use crate::model::scene::{Light, LightPlacement, Scene};
use crate::model::view::{Framing, LightingSpace, ObjectKind, Shading, View};
use crate::t;
use crate::teach::shader::{Lang, ShaderShading};

/// The program's text for `doc`, or why it cannot be written (a Flat view: the generated
/// shaders are Gouraud and Phong).
pub fn program(doc: &Document) -> Result<String, String> {
    let shading = match doc.view.shading {
        Shading::Gouraud => ShaderShading::Gouraud,
        Shading::Phong => ShaderShading::Phong,
        Shading::Flat => return Err(t!("export-flat-unsupported")),
    };
    let setup = doc.shaded_setup(crate::numerics::pow::PowFn::Exact);
    let shader = crate::teach::shader::for_view(doc, Lang::Glsl, shading).map_err(|e| e.to_string())?;
    let scene = &setup.scene;
    let mut s = String::new();
    s.push_str(&header(doc, shading));
    s.push_str(&format!(
        "RULES = {}  # {}\n",
        string(match scene.rules.set {
            RuleSet::Worksheet => "worksheet",
            RuleSet::OpenGl => "opengl",
            RuleSet::PhongDemo => "phong-demo",
        }),
        t!("py-rules-comment")
    ));
    s.push_str(&format!(
        "SIZE = 512\nBACKGROUND = ({}, {}, {})\n\n",
        num(doc.view.background[0] as f64),
        num(doc.view.background[1] as f64),
        num(doc.view.background[2] as f64)
    ));
    s.push_str(&shaders(&shader));
    s.push_str(&matrices(&setup));
    s.push_str(&lighting_state(scene));
    s.push_str(&uniforms_from_state());
    s.push_str(&object(&doc.view)?);
    s.push_str(MAIN);
    Ok(s)
}

/// The docstring and the imports.
fn header(doc: &Document, shading: ShaderShading) -> String {
    let shading = match shading {
        ShaderShading::Gouraud => "Gouraud",
        ShaderShading::Phong => "Phong",
    };
    format!(
        "#!/usr/bin/env python3\n\"\"\"{}\n\n{}\n\"\"\"\nimport sys\nimport math\nimport struct\nimport zlib\n\nfrom OpenGL.GLUT import *\nfrom OpenGL.GL import *\nfrom OpenGL.GLU import *\nimport OpenGL.GL.shaders\nimport numpy as np  # matrix manipulation\n\n",
        t!("py-title", scene = doc.name.clone(), shading = shading),
        t!("py-usage")
    )
}

/// The generated shaders, adapted to a compatibility-profile context: the attributes are
/// GL's own vertex and normal (what GLU's and GLUT's objects send).
fn shaders(shader: &crate::teach::shader::Shader) -> String {
    let adapt = |text: &str| {
        text.replace("#version 330 core", "#version 330 compatibility")
            .replace("layout(location = 0) in vec3 a_position;", "#define a_position (gl_Vertex.xyz / gl_Vertex.w)")
            .replace("layout(location = 1) in vec3 a_normal;", "#define a_normal gl_Normal")
    };
    format!(
        "# {}\nvertex_shader = \"\"\"\n{}\"\"\"\n\nfragment_shader = \"\"\"\n{}\"\"\"\n\n# {}\nUNIFORMS = [{}]\n\n",
        t!("py-shaders-comment"),
        adapt(&shader.vertex),
        adapt(&shader.fragment),
        t!("py-uniforms-comment"),
        shader.uniforms.iter().map(|(n, ty)| format!("({}, {})", string(n), string(ty))).collect::<Vec<_>>().join(", ")
    )
}

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
            format!("# {}\nPROJECTION = None  # gluPerspective(40, 1, 0.1, 100)\n", t!("py-projection-orbit"))
        }
        Framing::ClipSpace => format!("# {}\nPROJECTION = np.identity(4)\n", t!("py-projection-clip")),
    };
    s.push_str(&projection);
    // The drawing modelview: the camera and the object's spin (and gluCylinder moved to be
    // centred, as phonglab centres its cylinder).
    let shift = object_shift(view);
    let drawing = match view.framing {
        Framing::Orbit => view.camera.eye_from_world() * view.spin(),
        Framing::ClipSpace => view.spin(),
    } * shift;
    s.push_str(&format!("# {}\nMODELVIEW = {}\n", t!("py-modelview-comment"), np_matrix(&drawing)));
    let lighting = setup.scene.eye_from_object() * shift;
    if view.lighting_space == LightingSpace::Object || !lighting.abs_diff_eq(drawing, 1e-12) {
        s.push_str(&format!(
            "# {}\nLIGHTING_MODELVIEW = {}\n",
            t!("py-lighting-modelview-comment"),
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
        LightPlacement::Eye => ("np.identity(4)".into(), t!("py-light-eye")),
        LightPlacement::Object => (matrix(), t!("py-light-object")),
        LightPlacement::World | LightPlacement::Matrix(_) => (matrix(), t!("py-light-world")),
    }
}

fn rgba(c: glam::DVec4) -> String {
    format!("[{}, {}, {}, {}]", num(c.x), num(c.y), num(c.z), num(c.w))
}

/// The fixed-function calls that set the scene's lighting state.
fn lighting_state(scene: &Scene) -> String {
    let mut s =
        format!("def set_lighting_state():\n    \"\"\"{}\"\"\"\n    glMatrixMode(GL_MODELVIEW)\n", t!("py-state-doc"));
    for (i, l) in scene.lights.iter().enumerate() {
        let light = format!("GL_LIGHT{i}");
        let (matrix, placement) = light_modelview(scene, l);
        s.push_str(&format!(
            "    # GL_LIGHT{i}: {placement}\n    light_modelview = {matrix}\n    glLoadMatrixf(light_modelview.T)\n"
        ));
        s.push_str(&format!("    glLightfv({light}, GL_POSITION, {})\n", rgba(l.position)));
        s.push_str(&format!(
            "    glLightfv({light}, GL_SPOT_DIRECTION, [{}, {}, {}])\n",
            num(l.spot_direction.x),
            num(l.spot_direction.y),
            num(l.spot_direction.z)
        ));
        s.push_str(&format!("    glLightfv({light}, GL_AMBIENT, {})\n", rgba(l.ambient)));
        s.push_str(&format!("    glLightfv({light}, GL_DIFFUSE, {})\n", rgba(l.diffuse)));
        s.push_str(&format!("    glLightfv({light}, GL_SPECULAR, {})\n", rgba(l.specular)));
        s.push_str(&format!("    glLightf({light}, GL_SPOT_CUTOFF, {})\n", num(l.spot_cutoff)));
        s.push_str(&format!("    glLightf({light}, GL_SPOT_EXPONENT, {})\n", num(l.spot_exponent)));
        for (k, name) in
            ["GL_CONSTANT_ATTENUATION", "GL_LINEAR_ATTENUATION", "GL_QUADRATIC_ATTENUATION"].iter().enumerate()
        {
            s.push_str(&format!("    glLightf({light}, {name}, {})\n", num(l.attenuation[k])));
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
        s.push_str(&format!("    glMaterialfv({face}, GL_AMBIENT, {})\n", rgba(m.ambient)));
        s.push_str(&format!("    glMaterialfv({face}, GL_DIFFUSE, {})\n", rgba(m.diffuse)));
        s.push_str(&format!("    glMaterialfv({face}, GL_SPECULAR, {})\n", rgba(m.specular)));
        s.push_str(&format!("    glMaterialfv({face}, GL_EMISSION, {})\n", rgba(m.emission)));
        s.push_str(&format!("    glMaterialf({face}, GL_SHININESS, {})\n", num(m.shininess)));
    }
    let lm = &scene.light_model;
    s.push_str(&format!("    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, {})\n", rgba(lm.ambient)));
    s.push_str(&format!(
        "    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, {})\n",
        if lm.local_viewer { "GL_TRUE" } else { "GL_FALSE" }
    ));
    s.push_str(&format!(
        "    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, {})\n",
        if lm.two_sided { "GL_TRUE" } else { "GL_FALSE" }
    ));
    s.push_str(&format!(
        "    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, {})\n",
        if lm.separate_specular { "GL_SEPARATE_SPECULAR_COLOR" } else { "GL_SINGLE_COLOR" }
    ));
    let normals = match scene.normal_mode {
        crate::model::scene::NormalMode::Normalize => "    glEnable(GL_NORMALIZE)\n",
        crate::model::scene::NormalMode::Rescale => "    glEnable(GL_RESCALE_NORMAL)\n",
        crate::model::scene::NormalMode::AsIs => "",
    };
    s.push_str(normals);
    s.push_str("    glEnable(GL_LIGHTING)\n\n\n");
    s
}

/// The function that gives the generated program's uniforms their values, read from GL.
fn uniforms_from_state() -> String {
    format!(
        "{}\n\n",
        STATE_READER
            .replace("__DOC__", &t!("py-reader-doc"))
            .replace("__NORMAL_MATRIX__", &t!("py-normal-matrix-comment"))
    )
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
            t!("py-teapot-winding")
        )),
        ObjectKind::Cylinder if !view.cylinder_caps => Some(format!(
            "    gluCylinder(quadric, 0.3, 0.3, 0.5, {}, {})\n",
            view.cylinder_slices, view.cylinder_stacks
        )),
        _ => None,
    };
    let mut s = format!("def draw_object(quadric):\n    \"\"\"{}\"\"\"\n", t!("py-object-doc"));
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
                "# {}\nPOSITIONS = [{}]\n",
                t!("py-arrays-comment"),
                mesh.positions.iter().map(v3).collect::<Vec<_>>().join(", ")
            ));
            s.push_str(&format!("NORMALS = [{}]\n", mesh.normals.iter().map(v3).collect::<Vec<_>>().join(", ")));
            s.push_str(&format!(
                "TRIANGLES = [{}]\n",
                mesh.triangles.iter().flat_map(|t| t.iter()).map(|i| i.to_string()).collect::<Vec<_>>().join(", ")
            ));
            return Ok(s + "\n\n");
        }
    }
    Ok(s + "\n\n")
}

/// Reads each uniform's value from GL's state (see the module's documentation).
const STATE_READER: &str = r#"def scalar(v):
    return float(np.asarray(v).reshape(-1)[0])


def normalize(v):
    n = np.linalg.norm(v)
    return v / n if n > 0 else v


def state_value(name):
    """__DOC__"""
    modelview = LIGHTING_MODELVIEW
    m3 = modelview[:3, :3]
    if name.startswith("light"):
        index, what = name[len("light"):].split("_", 1)
        light = GL_LIGHT0 + int(index)
        position = np.array(glGetLightfv(light, GL_POSITION), dtype=np.float64)
        if what == "position":
            return position
        if what == "direction":
            return normalize(position[:3])
        if what == "halfway":
            return normalize(normalize(position[:3]) + np.array([0.0, 0.0, 1.0]))
        if what in ("ambient", "diffuse", "specular"):
            return np.array(glGetLightfv(light, {"ambient": GL_AMBIENT, "diffuse": GL_DIFFUSE, "specular": GL_SPECULAR}[what]))[:3]
        if what == "attenuation":
            return np.array([scalar(glGetLightfv(light, k)) for k in (GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION)])
        if what == "spot_direction":
            return np.array(glGetLightfv(light, GL_SPOT_DIRECTION))
        if what == "spot_cos_cutoff":
            return np.array([math.cos(math.radians(scalar(glGetLightfv(light, GL_SPOT_CUTOFF))))])
        if what == "spot_exponent":
            return np.array([scalar(glGetLightfv(light, GL_SPOT_EXPONENT))])
    if name.startswith("mat_") or name.startswith("back_"):
        face = GL_FRONT if name.startswith("mat_") else GL_BACK
        what = name.split("_", 1)[1]
        key = {"ambient": GL_AMBIENT, "diffuse": GL_DIFFUSE, "specular": GL_SPECULAR, "shininess": GL_SHININESS}[what]
        value = np.array(glGetMaterialfv(face, key), dtype=np.float64).reshape(-1)
        return value if what == "diffuse" else value[:1] if what == "shininess" else value[:3]
    if name == "clip_from_object":
        projection = np.array(glGetFloatv(GL_PROJECTION_MATRIX)).T
        drawing = np.array(glGetFloatv(GL_MODELVIEW_MATRIX)).T
        return projection @ drawing
    if name == "eye_from_object":
        return modelview
    if name == "normal_matrix":
        # __NORMAL_MATRIX__
        return m3 if RULES == "worksheet" else np.linalg.inv(m3).T
    if name == "rescale":
        return np.array([1.0 / np.linalg.norm(np.linalg.inv(m3)[2])])
    if name == "scene_color":
        if RULES != "opengl":
            return np.zeros(3)
        emission = np.array(glGetMaterialfv(GL_FRONT, GL_EMISSION))[:3]
        ambient = np.array(glGetMaterialfv(GL_FRONT, GL_AMBIENT))[:3]
        return emission + ambient * np.array(glGetFloatv(GL_LIGHT_MODEL_AMBIENT))[:3]
    raise KeyError(name)


def set_uniforms(program):
    for name, kind in UNIFORMS:
        location = glGetUniformLocation(program, "u_" + name)
        if location < 0:
            continue
        value = np.asarray(state_value(name), dtype=np.float32)
        if kind == "mat4":
            glUniformMatrix4fv(location, 1, GL_TRUE, value)
        elif kind == "mat3":
            glUniformMatrix3fv(location, 1, GL_TRUE, value)
        elif kind == "vec4":
            glUniform4fv(location, 1, value)
        elif kind == "vec3":
            glUniform3fv(location, 1, value)
        else:
            glUniform1f(location, float(value[0]))"#;

/// The window, the frame and `--png`.
const MAIN: &str = r#"def draw():
    glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1.0)
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)
    glMatrixMode(GL_PROJECTION)
    glLoadIdentity()
    if PROJECTION is None:
        gluPerspective(40, 1, 0.1, 100)
    else:
        glLoadMatrixf(PROJECTION.T)
    glMatrixMode(GL_MODELVIEW)
    glLoadMatrixf(MODELVIEW.T)
    glUseProgram(program)
    set_uniforms(program)
    draw_object(quadric)
    glUseProgram(0)


def save_png(path):
    glPixelStorei(GL_PACK_ALIGNMENT, 1)
    pixels = glReadPixels(0, 0, SIZE, SIZE, GL_RGB, GL_UNSIGNED_BYTE)
    rows = [pixels[(SIZE - 1 - y) * SIZE * 3:(SIZE - y) * SIZE * 3] for y in range(SIZE)]
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def display():
    draw()
    glutSwapBuffers()


def main():
    global program, quadric, SIZE
    png = sys.argv[sys.argv.index("--png") + 1] if "--png" in sys.argv else None
    if "--size" in sys.argv:
        SIZE = int(sys.argv[sys.argv.index("--size") + 1])
    glutInit(sys.argv)
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH)
    glutInitWindowSize(SIZE, SIZE)
    glutCreateWindow(b"phonglab")
    glEnable(GL_DEPTH_TEST)
    set_lighting_state()
    program = OpenGL.GL.shaders.compileProgram(
        OpenGL.GL.shaders.compileShader(vertex_shader, GL_VERTEX_SHADER),
        OpenGL.GL.shaders.compileShader(fragment_shader, GL_FRAGMENT_SHADER),
    )
    quadric = gluNewQuadric()
    if png:
        draw()
        glFinish()
        save_png(png)
        return
    glutDisplayFunc(display)
    glutMainLoop()


if __name__ == "__main__":
    main()
"#;
