//! A student who edits the exported PyOpenGL program (`phonglab export --to pyopengl`)
//! gets what OpenGL draws: each `glLight*`, `glMaterial*` and `glLightModel*` call of the
//! program for a few shipped scenes (a spotlight in Phong and Gouraud shading, three
//! lights, an open cylinder lit on both sides with a back material, the worksheet's
//! rules, `GL_COLOR_MATERIAL`, energy-conserving Blinn-Phong, and the Phong demo's
//! rules lit in object space) is changed to another valid value, the program is run by a real
//! OpenGL (Mesa 22.3.6, llvmpipe, freeglut, GLU), and its picture is compared with
//! phonglab's renderer drawing the scene edited the same way, within the tolerance of
//! `tests/pyopengl_mesa.rs` (the same coverage to 0.5 %, a mean difference within 3/255),
//! and no pixel both cover more than 8/255 apart in a channel.
//!
//! The outcome is data, `tests/data/pyopengl_edits.txt`: one line per edit with its
//! differences, under the CRC-32 of the general shaders and the program's state reader
//! that Mesa ran. So this test needs neither Python nor Mesa: it checks that the edits
//! are still every call of the programs, that each was within the tolerance, and that the
//! shader and reader code is still what was verified. Made again by:
//!
//! ```text
//! PHONGLAB_EDITS_DIR=/tmp/edits cargo test --test all pyopengl_edits::write_edited_programs -- --ignored
//! PYTHON=/usr/bin/python3 scripts/pyopengl_mesa.sh /tmp/edits /tmp/edits/mesa
//! PHONGLAB_EDITS_DIR=/tmp/edits cargo test --test all pyopengl_edits::record_mesa -- --ignored
//! ```
//!
//! The same run draws each program with `glShadeModel(GL_SMOOTH)` edited to `GL_FLAT`,
//! and that state drawn by fixed-function GL (`glUseProgram(0)`) where the rules are
//! OpenGL's: `tests/data/pyopengl_flat.txt` keeps the outcome. The shaders draw exactly
//! what GL's own GL_FLAT draws (each face the colour lit at its provoking vertex);
//! phonglab's Flat, which lights a face at its centre with the plane's normal, is recorded
//! beside it.

use std::path::{Path, PathBuf};

use glam::DVec4;
use phonglab::io::image::{Difference, read_png};
use phonglab_core::export::pyopengl::program;
use phonglab_core::render::Renderer;
use phonglab_core::{Document, ObjectKind, PowFn, Shading};

const SIZE: usize = 128;

fn recorded_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pyopengl_edits.txt")
}

fn scene_file(path: &str) -> Document {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes").join(path);
    Document::from_toml_in(&std::fs::read_to_string(&p).unwrap(), p.parent()).unwrap()
}

/// The scenes whose programs are edited.
fn scenes() -> Vec<(&'static str, Document)> {
    let mut spot_gouraud = scene_file("spotlight.toml");
    spot_gouraud.view.shading = Shading::Gouraud;
    let mut two_sided = scene_file("three-lights.toml");
    two_sided.view.object = ObjectKind::Cylinder;
    two_sided.view.shading = Shading::Phong;
    two_sided.scene.light_model.two_sided = true;
    let mut back = two_sided.scene.material.clone();
    back.diffuse = DVec4::new(0.2, 0.5, 0.9, 1.0);
    back.ambient = DVec4::new(0.1, 0.2, 0.3, 1.0);
    two_sided.scene.back_material = Some(back);
    let mut worksheet = scene_file("worksheet-mview5.toml");
    worksheet.view.shading = Shading::Gouraud;
    let mut normalised = scene_file("three-lights.toml");
    normalised.scene.rules.specular = phonglab_core::SpecularModel::BlinnPhongNormalised;
    let mut colour = scene_file("of-set-color.toml");
    colour.view.shading = Shading::Phong;
    vec![
        ("spotlight-phong", scene_file("spotlight.toml")),
        ("spotlight-gouraud", spot_gouraud),
        ("three-lights", scene_file("three-lights.toml")),
        ("two-sided-cylinder", two_sided),
        ("worksheet-rules", worksheet),
        ("color-material", colour),
        ("normalised-specular", normalised),
        ("phong-demo", scene_file("phong-demo.toml")),
    ]
}

/// One state-setting call of a program: the function, its first two arguments, its value.
#[derive(Clone, Debug, PartialEq)]
struct Call {
    function: String,
    target: String,
    pname: String,
    value: Vec<f64>,
    /// A GL enum value (`GL_TRUE`, `GL_SINGLE_COLOR`), for glLightModeli.
    word: Option<String>,
}

impl Call {
    fn line(&self) -> String {
        let value = match &self.word {
            Some(w) => w.clone(),
            None if self.function.ends_with("fv") => {
                format!("[{}]", self.value.iter().map(|v| format!("{v:?}")).collect::<Vec<_>>().join(", "))
            }
            None => format!("{:?}", self.value[0]),
        };
        match self.target.as_str() {
            "" => format!("    {}({}, {value})", self.function, self.pname),
            target => format!("    {}({target}, {}, {value})", self.function, self.pname),
        }
    }
}

/// The glLight*, glMaterial* and glLightModel* calls of `text`, with their line numbers.
fn calls(text: &str) -> Vec<(usize, Call)> {
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let l = line.trim();
        let Some((function, rest)) = l.split_once('(') else { continue };
        if !["glLightfv", "glLightf", "glMaterialfv", "glMaterialf", "glLightModelfv", "glLightModeli"]
            .contains(&function)
        {
            continue;
        }
        let args = rest.strip_suffix(')').unwrap();
        let (target, pname, value) = if function.starts_with("glLightModel") {
            let (p, v) = args.split_once(", ").unwrap();
            (String::new(), p.to_string(), v.to_string())
        } else {
            let mut parts = args.splitn(3, ", ");
            let t = parts.next().unwrap().to_string();
            let p = parts.next().unwrap().to_string();
            (t, p, parts.next().unwrap().to_string())
        };
        let numbers: Option<Vec<f64>> =
            value.trim_matches(['[', ']']).split(", ").map(|x| x.parse::<f64>().ok()).collect();
        let (value, word) = match numbers {
            Some(n) => (n, None),
            None => (Vec::new(), Some(value)),
        };
        out.push((i, Call { function: function.into(), target, pname, value, word }));
    }
    out
}

/// Another valid value for `c`'s state.
fn changed(c: &Call) -> Call {
    let mut n = c.clone();
    let colour = |v: &[f64]| vec![0.3 + 0.5 * v[1], 0.2 + 0.5 * v[2], 0.1 + 0.5 * v[0], v[3]];
    match (c.pname.as_str(), &c.word) {
        (_, Some(w)) => {
            n.word = Some(
                match w.as_str() {
                    "GL_TRUE" => "GL_FALSE",
                    "GL_FALSE" => "GL_TRUE",
                    "GL_SINGLE_COLOR" => "GL_SEPARATE_SPECULAR_COLOR",
                    _ => "GL_SINGLE_COLOR",
                }
                .into(),
            );
        }
        ("GL_POSITION", _) => n.value[3] = if c.value[3] == 0.0 { 1.0 } else { 0.0 },
        ("GL_SPOT_DIRECTION", _) => n.value[0] += 0.3,
        ("GL_SPOT_CUTOFF", _) => n.value[0] = if c.value[0] == 180.0 { 30.0 } else { (c.value[0] * 2.0).min(90.0) },
        ("GL_SPOT_EXPONENT", _) => n.value[0] += 10.0,
        ("GL_CONSTANT_ATTENUATION", _) => n.value[0] += 0.5,
        ("GL_LINEAR_ATTENUATION", _) => n.value[0] += 0.2,
        ("GL_QUADRATIC_ATTENUATION", _) => n.value[0] += 0.1,
        ("GL_SHININESS", _) => n.value[0] = if c.value[0] > 64.0 { c.value[0] / 2.0 } else { c.value[0] * 2.0 + 5.0 },
        _ => n.value = colour(&c.value),
    }
    n
}

/// `doc` with `c`'s state set as the edited call sets it.
fn edited(doc: &Document, c: &Call) -> Document {
    let mut d = doc.clone();
    let s = &mut d.scene;
    let v = &c.value;
    let v4 = || DVec4::new(v[0], v[1], v[2], v[3]);
    let on = c.word.as_deref() == Some("GL_TRUE");
    match c.function.as_str() {
        "glLightModelfv" => s.light_model.ambient = v4(),
        "glLightModeli" => match c.pname.as_str() {
            "GL_LIGHT_MODEL_LOCAL_VIEWER" => s.light_model.local_viewer = on,
            "GL_LIGHT_MODEL_TWO_SIDE" => s.light_model.two_sided = on,
            _ => s.light_model.separate_specular = c.word.as_deref() == Some("GL_SEPARATE_SPECULAR_COLOR"),
        },
        "glLightfv" | "glLightf" => {
            let l = &mut s.lights[c.target.trim_start_matches("GL_LIGHT").parse::<usize>().unwrap()];
            match c.pname.as_str() {
                "GL_POSITION" => l.position = v4(),
                "GL_SPOT_DIRECTION" => l.spot_direction = glam::DVec3::new(v[0], v[1], v[2]),
                "GL_AMBIENT" => l.ambient = v4(),
                "GL_DIFFUSE" => l.diffuse = v4(),
                "GL_SPECULAR" => l.specular = v4(),
                "GL_SPOT_CUTOFF" => l.spot_cutoff = v[0],
                "GL_SPOT_EXPONENT" => l.spot_exponent = v[0],
                "GL_CONSTANT_ATTENUATION" => l.attenuation[0] = v[0],
                "GL_LINEAR_ATTENUATION" => l.attenuation[1] = v[0],
                "GL_QUADRATIC_ATTENUATION" => l.attenuation[2] = v[0],
                p => panic!("no field for {p}"),
            }
        }
        _ => {
            let m = match c.target.as_str() {
                "GL_BACK" => s.back_material.as_mut().unwrap(),
                _ => &mut s.material,
            };
            match c.pname.as_str() {
                "GL_AMBIENT" => m.ambient = v4(),
                "GL_DIFFUSE" => m.diffuse = v4(),
                "GL_SPECULAR" => m.specular = v4(),
                "GL_EMISSION" => m.emission = v4(),
                "GL_SHININESS" => m.shininess = v[0],
                p => panic!("no field for {p}"),
            }
        }
    }
    d
}

/// Every edit: its name, the program with one call changed, and the scene changed alike.
fn edits() -> Vec<(String, String, Document)> {
    let mut out = Vec::new();
    for (scene, doc) in scenes() {
        let text = program(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
        for (k, (line, call)) in calls(&text).into_iter().enumerate() {
            let new = changed(&call);
            let lines: Vec<String> =
                text.lines().enumerate().map(|(i, l)| if i == line { new.line() } else { l.to_string() }).collect();
            let name = format!("{scene}-{k:02}-{}-{}", call.target.to_lowercase(), call.pname.to_lowercase())
                .replace("--", "-");
            out.push((name, lines.join("\n") + "\n", edited(&doc, &new)));
        }
    }
    out
}

/// The CRC-32 of what Mesa verified: the general shaders (each rule set, both shadings)
/// and the program's reader of GL's state, `set_uniforms`.
fn verified_code() -> String {
    let mut all = String::new();
    for rules in [phonglab_core::Rules::OPENGL, phonglab_core::Rules::WORKSHEET, phonglab_core::Rules::PHONG_DEMO] {
        for per_fragment in [false, true] {
            let (v, f) = phonglab_core::export::general_shader::stages(rules, per_fragment);
            all.push_str(&v);
            all.push_str(&f);
        }
    }
    let (_, doc) = scenes().remove(0);
    let text = program(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
    let start = text.find("def set_uniforms").unwrap();
    let end = start + text[start..].find("\n\n\n").unwrap();
    // The docstring is in the reader's language: the code is what was verified.
    all.extend(text[start..end].lines().filter(|l| !l.trim_start().starts_with("\"\"\"")).map(|l| format!("{l}\n")));
    format!("{:08x}", crc32fast::hash(all.as_bytes()))
}

#[test]
fn every_edit_changes_the_program_as_the_edited_scene_exports() {
    // The edit and the scene's change agree: the edited scene's own export sets the same
    // state, so phonglab's picture of it is the picture the edited program should draw.
    let all = edits();
    assert!(all.len() >= 80, "{} edits", all.len());
    for (name, text, doc) in &all {
        doc.scene.validate().unwrap_or_else(|e| panic!("{name}: the edit is not valid: {e}"));
        let exported = program(doc, &phonglab_core::export::shaded_key(doc)).unwrap();
        let ours: Vec<Call> = calls(text).into_iter().map(|(_, c)| c).collect();
        let theirs: Vec<Call> = calls(&exported).into_iter().map(|(_, c)| c).collect();
        assert_eq!(ours.len(), theirs.len(), "{name}");
        for (a, b) in ours.iter().zip(&theirs) {
            assert_eq!(
                (&a.function, &a.target, &a.pname, &a.word),
                (&b.function, &b.target, &b.pname, &b.word),
                "{name}"
            );
            for (x, y) in a.value.iter().zip(&b.value) {
                assert!((x - y).abs() <= 1e-9 * x.abs().max(1.0), "{name}: {a:?} against {b:?}");
            }
        }
    }
}

#[test]
#[ignore = "writes the edited programs (set PHONGLAB_EDITS_DIR) for scripts/pyopengl_mesa.sh"]
fn write_edited_programs() {
    let dir = PathBuf::from(std::env::var("PHONGLAB_EDITS_DIR").expect("PHONGLAB_EDITS_DIR"));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text, _) in edits() {
        std::fs::write(dir.join(format!("{name}.py")), text).unwrap();
    }
    for (name, text, _) in flat_edits() {
        std::fs::write(dir.join(format!("{name}.py")), text).unwrap();
    }
}

/// Phonglab's picture of `doc` against Mesa's `mesa`: the difference, the mean of its
/// channels and the largest difference of one channel of a pixel both cover.
fn compare(doc: &Document, mesa: &[u8]) -> (Difference, f64, u8) {
    let ours = render(doc);
    let bg = doc.view.background.map(|c| (c * 255.0).round() as u8);
    let d = Difference::of(&ours, mesa, bg);
    let max = ours
        .chunks_exact(4)
        .zip(mesa.chunks_exact(4))
        .filter(|(a, b)| a[..3] != bg && b[..3] != bg)
        .flat_map(|(a, b)| (0..3).map(move |k| a[k].abs_diff(b[k])))
        .max()
        .unwrap_or(0);
    let mean = d.mad.iter().sum::<f64>() / 3.0;
    (d, mean, max)
}

/// Two pictures (RGBA8) of a scene with background `bg`: the difference, the mean of its
/// channels and the largest difference of one channel of a pixel both cover.
fn compare_pictures(a: &[u8], b: &[u8], bg: [u8; 3]) -> (Difference, f64, u8) {
    let d = Difference::of(a, b, bg);
    let max = a
        .chunks_exact(4)
        .zip(b.chunks_exact(4))
        .filter(|(a, b)| a[..3] != bg && b[..3] != bg)
        .flat_map(|(a, b)| (0..3).map(move |k| a[k].abs_diff(b[k])))
        .max()
        .unwrap_or(0);
    (d, (d.mad.iter().sum::<f64>() / 3.0), max)
}

/// phonglab's picture of `doc` (RGBA8).
fn render(doc: &Document) -> Vec<u8> {
    let setup = doc.shaded_setup(PowFn::Exact);
    let mesh = doc.view.mesh();
    let mut renderer = Renderer::new();
    renderer.render(&setup.job(&mesh), SIZE, SIZE).unwrap().0.rgba.clone()
}

/// How many pixels of phonglab's picture the edit changes: whether it is seen at all.
fn changed_pixels(before: &Document, after: &Document) -> usize {
    let (a, b) = (render(before), render(after));
    a.chunks_exact(4).zip(b.chunks_exact(4)).filter(|(x, y)| x != y).count()
}

#[test]
#[ignore = "compares Mesa's pictures of the edited programs with phonglab's and records the outcome"]
fn record_mesa_outcome() {
    let dir = PathBuf::from(std::env::var("PHONGLAB_EDITS_DIR").expect("PHONGLAB_EDITS_DIR")).join("mesa");
    let mut out = format!(
        "# tests/pyopengl_edits.rs: each edit of an exported program, run by Mesa, against phonglab render\n\
         verified {}\n# name both-covered only-one mean/255 max/255 pixels-the-edit-changes\n",
        verified_code()
    );
    let unedited: std::collections::BTreeMap<&str, Document> = scenes().into_iter().collect();
    for (name, _, doc) in edits() {
        let before = unedited.iter().find(|(s, _)| name.starts_with(&format!("{s}-"))).unwrap().1;
        let (w, h, mesa) = read_png(&dir.join(format!("{name}.png"))).unwrap();
        assert_eq!((w, h), (SIZE, SIZE));
        let (d, mean, max) = compare(&doc, &mesa);
        let seen = changed_pixels(before, &doc);
        out.push_str(&format!("{name} {} {} {mean:.3} {max} {seen}\n", d.both, d.only_one()));
    }
    std::fs::write(recorded_path(), out).unwrap();
}

#[test]
fn the_edited_programs_drew_under_mesa_what_phonglab_draws_of_the_edited_scenes() {
    let recorded = std::fs::read_to_string(recorded_path()).unwrap();
    let verified = recorded.lines().find_map(|l| l.strip_prefix("verified ")).unwrap();
    assert_eq!(
        verified,
        verified_code(),
        "the general shaders or the state reader changed since Mesa ran the edits: run them again (this file's header)"
    );
    let rows: std::collections::BTreeMap<&str, Vec<f64>> = recorded
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("verified "))
        .filter_map(|l| l.split_once(' '))
        .map(|(n, rest)| (n, rest.split(' ').map(|x| x.parse().unwrap()).collect()))
        .collect();
    let all = edits();
    assert_eq!(rows.len(), all.len(), "the recorded edits are not the programs' calls");
    let seen = all.iter().filter(|(name, _, _)| rows.get(name.as_str()).is_some_and(|r| r[4] > 0.0)).count();
    // Some edits change nothing by GL's own rules (a spot direction or exponent of a light
    // that is no spotlight, attenuation of a directional light, a light ambient times a
    // material ambient of 0): most must show.
    assert!(seen * 3 >= all.len() * 2, "only {seen} of {} edits change the picture: the edits test little", all.len());
    for (name, _, _) in &all {
        let row = rows.get(name.as_str()).unwrap_or_else(|| panic!("{name} was not run under Mesa"));
        let (both, only_one, mean) = (row[0], row[1], row[2]);
        // An edit may darken the object to the background (a spot cone that misses it),
        // in both pictures alike.
        assert!(both > 500.0 || only_one == 0.0, "{name}: only {both} pixels covered");
        assert!(only_one <= 0.005 * (SIZE * SIZE) as f64, "{name}: coverage differs by {only_one} pixels");
        assert!(mean <= 3.0, "{name}: mean difference {mean}/255");
        // The mean alone lets a moved highlight pass (the old export, which ignored
        // GL_LIGHT_MODEL_LOCAL_VIEWER, drew that edit at a mean of 0.53/255 but 57/255 at
        // the highlight): no pixel both cover may differ by more than the rounding.
        assert!(row[3] <= 8.0, "{name}: a pixel differs by {}/255", row[3]);
    }
}

/// Where `glShadeModel(GL_SMOOTH)` is edited to `GL_FLAT`: each scene's program unedited
/// (`NAME-smooth`) and so edited (`NAME-flat`), and, where the scene's rules are OpenGL's own, the same program drawn by
/// fixed-function GL (`NAME-flat-fixed`: `glUseProgram(0)`, the lighting state untouched),
/// which is what the shaders must draw; with the scene drawn Flat by phonglab.
fn flat_edits() -> Vec<(String, String, Document)> {
    let mut out = Vec::new();
    for (scene, doc) in scenes() {
        let text = program(&doc, &phonglab_core::export::shaded_key(&doc)).unwrap();
        assert_eq!(text.matches("    glShadeModel(GL_SMOOTH)\n").count(), 1, "{scene}: no glShadeModel call to edit");
        let flat = text.replace("    glShadeModel(GL_SMOOTH)\n", "    glShadeModel(GL_FLAT)\n");
        out.push((format!("{scene}-smooth"), text.clone(), doc.clone()));
        let mut drawn = doc.clone();
        drawn.view.shading = Shading::Flat;
        if doc.scene.rules == phonglab_core::Rules::OPENGL {
            let draw = "    glUseProgram(program)\n    set_uniforms(program)\n";
            assert_eq!(flat.matches(draw).count(), 1);
            let fixed = flat.replace(draw, "    glUseProgram(0)\n");
            out.push((format!("{scene}-flat-fixed"), fixed, drawn.clone()));
        }
        out.push((format!("{scene}-flat"), flat, drawn));
    }
    out
}

fn flat_recorded_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/pyopengl_flat.txt")
}

#[test]
#[ignore = "compares Mesa's pictures of the programs edited to GL_FLAT and records the outcome"]
fn record_mesa_flat_outcome() {
    let dir = PathBuf::from(std::env::var("PHONGLAB_EDITS_DIR").expect("PHONGLAB_EDITS_DIR")).join("mesa");
    let mut out = format!(
        "# tests/pyopengl_edits.rs: each program edited to glShadeModel(GL_FLAT), run by Mesa\n\
         verified {}\n# name against: both-covered only-one mean/255 max/255 pixels-the-edit-changes\n\
         # (fixed: fixed-function GL drawing the same program's state; render: phonglab render, Flat;\n\
         # pixels-the-edit-changes: of the unedited program's Mesa picture)\n",
        verified_code()
    );
    let read = |name: &str| {
        let (w, h, p) = read_png(&dir.join(format!("{name}.png"))).unwrap();
        assert_eq!((w, h), (SIZE, SIZE));
        p
    };
    for (name, _, doc) in flat_edits() {
        if !name.ends_with("-flat") {
            continue;
        }
        let bg = doc.view.background.map(|c| (c * 255.0).round() as u8);
        let flat = read(&name);
        let smooth = read(&name.replace("-flat", "-smooth"));
        let seen = smooth.chunks_exact(4).zip(flat.chunks_exact(4)).filter(|(a, b)| a != b).count();
        let mut against = vec![("render", render(&doc))];
        if doc.scene.rules == phonglab_core::Rules::OPENGL {
            against.insert(0, ("fixed", read(&format!("{name}-fixed"))));
        }
        for (what, other) in against {
            let (d, mean, max) = compare_pictures(&other, &flat, bg);
            out.push_str(&format!("{name} {what} {} {} {mean:.3} {max} {seen}\n", d.both, d.only_one()));
        }
    }
    std::fs::write(flat_recorded_path(), out).unwrap();
}

#[test]
fn the_programs_follow_glshademodel_flat_as_fixed_function_gl_draws_it() {
    // Mesa drew each program with `glShadeModel(GL_SMOOTH)` edited to `GL_FLAT`, and the
    // same state drawn by fixed-function GL: the shaders must give what GL's own GL_FLAT
    // gives (each face the colour lit at its provoking vertex). The old shaders ignored
    // the call: the picture did not change.
    let recorded = std::fs::read_to_string(flat_recorded_path()).unwrap();
    let verified = recorded.lines().find_map(|l| l.strip_prefix("verified ")).unwrap();
    assert_eq!(verified, verified_code(), "the shaders or the state reader changed since Mesa ran: run it again");
    let rows: std::collections::BTreeMap<(&str, &str), Vec<f64>> = recorded
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("verified "))
        .map(|l| {
            let mut w = l.split(' ');
            let (name, against) = (w.next().unwrap(), w.next().unwrap());
            ((name, against), w.map(|x| x.parse().unwrap()).collect())
        })
        .collect();
    let all = flat_edits();
    let flat: Vec<&(String, String, Document)> = all.iter().filter(|(n, _, _)| n.ends_with("-flat")).collect();
    assert_eq!(flat.len(), scenes().len());
    let mut fixed = 0;
    for (name, _, doc) in flat {
        let render = rows.get(&(name.as_str(), "render")).unwrap_or_else(|| panic!("{name} was not run under Mesa"));
        // GL_FLAT changes most of the object's pixels.
        assert!(render[4] > 0.5 * render[0], "{name}: GL_FLAT changed only {} pixels", render[4]);
        // phonglab's own Flat lights each face at its centre with the plane's normal, not
        // at GL's provoking vertex: the same coverage, colours apart by the lighting's change
        // across a face.
        assert_eq!(render[1], 0.0, "{name}: coverage differs");
        assert!(render[2] <= 8.0, "{name}: mean {}/255 from phonglab's Flat", render[2]);
        if doc.scene.rules == phonglab_core::Rules::OPENGL {
            let gl = rows.get(&(name.as_str(), "fixed")).unwrap_or_else(|| panic!("{name}: no fixed-function picture"));
            assert_eq!(gl[1], 0.0, "{name}: coverage differs from fixed-function GL");
            assert!(gl[3] <= 1.0, "{name}: a pixel {}/255 from fixed-function GL_FLAT", gl[3]);
            fixed += 1;
        }
    }
    assert!(fixed >= 5, "only {fixed} scenes checked against fixed-function GL");
}
