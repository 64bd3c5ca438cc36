//! The worksheet's Jupyter notebook, written for a scene.
//!
//! The cells are the worksheet's (`vertex_color_calculator.ipynb`): its variable names
//! (`vertexPos`, `vertexNormal`, `lightPos`, `Lamb`, `Ldif`, `Lspec`, `atC`, `atLin`,
//! `atQuad`, `matAmb`, `matDif`, `matSpec`, `ns`, `mview`), its order (normal and vectors,
//! ambient, diffuse, specular, attenuation, I) and its prints, with this scene's values.
//! What the worksheet leaves out is added in the same style, and only where the scene
//! has it: several lights (lists, one loop per cell), spotlights, OpenGL's scene ambient
//! and emission, the local viewer, OpenGL's inverse transpose for normals, the Phong
//! reflection vector, a separate specular colour, the back side of two-sided lighting.
//! Run cell by cell, it prints the values `phonglab explain` prints, under the same names.

use super::python::{array4, colour, matrix, num, shininess, string};
use crate::equation::explain::fmt_value;
use crate::equation::plan::{Key, Program, SpecularTerm, Stage};
use crate::formats::document::Document;
use crate::formats::escape;
use crate::model::rules::{NormalTransform, RuleSet, Rules, SpecularGate, SpecularVector};
use crate::model::scene::{Face, Light, Material, NormalMode, Scene, Side};
use crate::model::vocabulary::Quantity::{self, self as Q};
use crate::t;

/// One cell of a notebook.
#[derive(Clone, Debug, PartialEq)]
pub enum Cell {
    /// Markdown text.
    Markdown(String),
    /// Python code.
    Code(String),
}

/// Why the notebook is not written for `doc`, when it is not: it prints what `explain`
/// prints, but NumPy has no policy of its own where a value is undefined (a zero normal
/// normalised, a vertex at infinity, a light with no direction, a singular modelview):
/// where the engine takes a limit and `explain` says so, NumPy would print nan or raise
/// `LinAlgError`. Such a scene is refused, with `explain`'s note as the reason.
pub fn refusal(doc: &Document) -> Option<String> {
    let lit = crate::equation::lighting::Engine::<f64>::light_scene_vertex(&doc.scene).ok()?;
    let (_, limit) = lit.all_limits().into_iter().next()?;
    Some(t!("notebook-refused", reason = limit.message()))
}

/// The notebook as a Jupyter `.ipynb` file (nbformat 4).
pub fn notebook(doc: &Document, key: &Key) -> String {
    ipynb(&cells(doc, key))
}

/// Cells as an `.ipynb` document.
pub fn ipynb(cells: &[Cell]) -> String {
    let lines = |text: &str| -> Vec<String> {
        let mut out: Vec<String> = text.split_inclusive('\n').map(str::to_string).collect();
        if out.is_empty() {
            out.push(String::new());
        }
        out
    };
    // nbformat 4.5 gives every cell an `id`; the cell's place makes it unique and the same
    // on every export (Jupyter warns of, and later versions refuse, a 4.5 cell without one).
    let cells: Vec<serde_json::Value> = cells
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let id = format!("cell-{}", i + 1);
            match c {
                Cell::Markdown(t) => {
                    serde_json::json!({"cell_type": "markdown", "id": id, "metadata": {}, "source": lines(t)})
                }
                Cell::Code(t) => serde_json::json!({
                    "cell_type": "code", "execution_count": null, "id": id, "metadata": {}, "outputs": [],
                    "source": lines(t)
                }),
            }
        })
        .collect();
    let doc = serde_json::json!({
        "cells": cells,
        "metadata": {
            "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
            "language_info": {"name": "python"}
        },
        "nbformat": 4,
        "nbformat_minor": 5
    });
    let mut text = crate::formats::escape::json::text(&serde_json::to_string_pretty(&doc).unwrap_or_default());
    text.push('\n');
    text
}

/// What the scene needs the cells to say beyond the worksheet's own.
struct Needs {
    /// How many lights (the worksheet has one: plain names; more: lists and loops).
    lights: usize,
    /// The rule set and the specular model.
    rules: Rules,
    /// The vector the specular cosine is taken with: H or R.
    vector: SpecularVector,
    /// The specular term's form (every light's: one loop writes them all).
    term: SpecularTerm,
    /// Normal handling.
    normals: NormalMode,
    /// Two-sided lighting: the back side's cells follow.
    two_sided: bool,
    /// Specular goes to the secondary colour.
    separate_specular: bool,
    /// Some light is placed under a modelview other than `mview`.
    light_mview: bool,
    /// Some light is a spotlight.
    spot: bool,
    /// OpenGL's rules: scene ambient and emission.
    opengl_terms: bool,
    /// The vertex or a light needs its division by w.
    divide_w: bool,
}

impl Needs {
    /// What the cells of `scene` need: the terms are the stages of the key's worked program
    /// (every term the worksheet computes, from the plan the renderer and the shader run);
    /// the scene says where the lights were placed and whether w needs dividing.
    fn of(scene: &Scene, key: &Key) -> Self {
        let mview = scene.eye_from_object();
        let mut needs = Needs {
            lights: key.lights.len(),
            rules: key.rules,
            vector: SpecularVector::Halfway,
            term: SpecularTerm::Plain,
            normals: key.normals,
            two_sided: key.two_sided,
            separate_specular: key.separate_specular,
            light_mview: scene.lights.iter().any(|l| scene.eye_from_light(l) != mview),
            spot: false,
            opengl_terms: false,
            divide_w: key.projective
                || scene.vertex.position.w != 1.0
                || scene.lights.iter().any(|l| {
                    let w = scene.light_pos_in_eye(l).w;
                    w != 0.0 && w != 1.0
                }),
        };
        for &stage in &Program::worked(key).stages {
            needs.take(stage);
        }
        needs
    }

    /// What one stage of the worked program asks of the cells.
    fn take(&mut self, stage: Stage) {
        match stage {
            // The worksheet's own cells: the normal and the positions, L, d and at, the
            // cosines and the power, each light's share (one loop over the lights).
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
            | Stage::DiffuseCosine(..)
            | Stage::SpecularCosine(..)
            | Stage::Power(..) => {}
            Stage::Sum(_, _, term) => self.term = term,
            // The spotlight's cell.
            Stage::SpotCone(_) | Stage::SpotPower(_) => self.spot = true,
            Stage::Halfway(_) | Stage::HalfwayConstant(_) => self.vector = SpecularVector::Halfway,
            Stage::Reflect(_) => self.vector = SpecularVector::Reflection,
            // OpenGL's scene ambient and emission.
            Stage::SceneColor => self.opengl_terms = true,
        }
    }

    /// The worksheet's own scene shape: one light, no spot, the worksheet's terms.
    fn worksheet_shape(&self) -> bool {
        self.lights == 1 && !self.spot && !self.opengl_terms && !self.separate_specular
    }
}

/// Writes a per-light cell body: for one light as it is (`⟨i⟩` and `⟨p⟩` dropped); for
/// several, the lists it assigns made first and the body in `for i in range(n):`, with
/// `⟨i⟩` indexing (`vlv[i]`) and `⟨p⟩` in the printed names (`vlv[0] = `).
fn per_light(n: usize, assigned: &[&str], body: &str) -> String {
    if n == 1 {
        return body.replace("[⟨i⟩]", "").replace("[⟨p⟩]", "").replace("print(f\"", "print(\"");
    }
    let mut out = String::new();
    for name in assigned {
        out.push_str(&format!("{name} = [None] * {n}\n"));
    }
    out.push_str(&format!("for i in range({n}):\n"));
    for line in body.lines() {
        let line = line.replace("[⟨i⟩]", "[i]").replace("[⟨p⟩]", "[{i}]");
        if line.is_empty() {
            out.push('\n');
        } else {
            out.push_str("    ");
            out.push_str(&line);
            out.push('\n');
        }
    }
    out
}

/// A print of a value under its name, as the worksheet prints (`print("vlv = ", vlv)`);
/// `indexed` for a per-light value.
fn print(name: &str, indexed: bool) -> String {
    if indexed {
        format!("print(f\"{name}[⟨p⟩] = \", {name}[⟨i⟩])")
    } else {
        format!("print(\"{name} = \", {name})")
    }
}

/// The notebook's cells for `doc`'s scene (front side; the back side of two-sided
/// lighting follows in cells of its own).
pub fn cells(doc: &Document, key: &Key) -> Vec<Cell> {
    let scene = &doc.scene;
    let needs = Needs::of(scene, key);
    let n = needs.lights;
    let mut cells = vec![
        Cell::Markdown(t!(
            "nb-title",
            scene = escape::markdown::text(&crate::formats::library::localised_name(&doc.name)),
            rules = needs.rules.to_string()
        )),
        Cell::Markdown(t!("nb-vertex")),
        Cell::Code("import math as m\nimport numpy as np".into()),
        Cell::Code(format!(
            "gw = 1024\ngh = 768\n{} = {}\n{} = {}",
            Q::VertexPos.name(),
            array4(scene.vertex.position),
            Q::VertexNormal.name(),
            array4(scene.vertex.normal.extend(0.0))
        )),
        Cell::Markdown(t!("nb-light-material")),
        Cell::Code(light_positions(scene)),
        Cell::Code(givens(scene, &needs)),
    ];
    if let Some(settings) = settings(&needs) {
        cells.push(Cell::Markdown(t!("nb-settings")));
        cells.push(Cell::Code(settings));
    }
    cells.push(Cell::Markdown(t!("nb-modelview")));
    cells.push(Cell::Code(modelview(scene, &needs)));
    cells.push(Cell::Markdown(t!("nb-vectors")));
    cells.push(Cell::Code(vectors(scene, &needs)));
    cells.push(Cell::Markdown(t!("nb-ambient")));
    cells.push(Cell::Code(per_light(n, &["Iamb"], &format!("Iamb[⟨i⟩] = Lamb[⟨i⟩]*matAmb\n{}", print("Iamb", true)))));
    cells.push(Cell::Markdown(t!("nb-diffuse")));
    cells.push(Cell::Code(diffuse(n, "")));
    cells.push(Cell::Markdown(specular_markdown(&needs)));
    cells.push(Cell::Code(specular(&needs, n, "")));
    cells.push(Cell::Markdown(t!("nb-attenuation")));
    cells.push(Cell::Code(attenuation(&needs)));
    if needs.spot {
        cells.push(Cell::Markdown(t!("nb-spot")));
        cells.push(Cell::Code(spot(&needs)));
    }
    cells.push(Cell::Markdown(t!("nb-final")));
    cells.push(Cell::Code(final_colour(scene, &needs, "")));
    if needs.two_sided {
        cells.push(Cell::Markdown(t!("nb-back")));
        cells.push(Cell::Code(back_side(scene, &needs)));
    }
    cells.push(Cell::Markdown(t!("nb-self-check")));
    cells.push(Cell::Code(self_check()));
    cells
}

/// The last cell, commented out: the Python package `phonglab` checks the values this
/// notebook computed, step by step, in the language the notebook was written in. The `;`
/// keeps Jupyter from showing its True or False under the table it prints.
fn self_check() -> String {
    let lang = crate::locale::current().lang.code();
    format!("# import phonglab; phonglab.check(globals(), lang=\"{lang}\");")
}

/// `lightPos`: one array, or a list of them.
fn light_positions(scene: &Scene) -> String {
    per_light_given(scene, Q::LightPos, |l| array4(l.position))
}

/// A given per light: `name = value;` for one light, `name = [v0, v1]` for several.
fn per_light_given(scene: &Scene, q: Quantity, value: impl Fn(&Light) -> String) -> String {
    let name = q.name();
    if scene.lights.len() == 1 {
        format!("{name} = {};", value(&scene.lights[0]))
    } else {
        format!("{name} = [{}]", scene.lights.iter().map(value).collect::<Vec<_>>().join(", "))
    }
}

/// The light and material cell: the worksheet's givens, and what this scene adds.
fn givens(scene: &Scene, needs: &Needs) -> String {
    let mut s = String::new();
    s.push('\n');
    s.push_str(&per_light_given(scene, Q::LightAmbient, |l| colour(l.ambient)));
    s.push('\n');
    s.push_str(&per_light_given(scene, Q::LightDiffuse, |l| colour(l.diffuse)));
    s.push('\n');
    s.push_str(&per_light_given(scene, Q::LightSpecular, |l| colour(l.specular)));
    s.push('\n');
    for (k, q) in [Q::AttConstant, Q::AttLinear, Q::AttQuadratic].into_iter().enumerate() {
        s.push_str(&per_light_given(scene, q, |l| {
            let v = num(l.attenuation[k]);
            if k == 0 && !v.contains(['.', 'e']) { format!("{v}.") } else { v }
        }));
        s.push('\n');
    }
    s.push('\n');
    if needs.spot {
        s.push_str(&per_light_given(scene, Q::SpotDirection, |l| array4(l.spot_direction.extend(0.0))));
        s.push('\n');
        s.push_str(&per_light_given(scene, Q::SpotCutoff, |l| num(l.spot_cutoff)));
        s.push('\n');
        s.push_str(&per_light_given(scene, Q::SpotExponent, |l| num(l.spot_exponent)));
        s.push('\n');
    } else {
        // The worksheet's own lines, commented out: no light here is a spotlight.
        let [dir, cutoff, coef] = [Q::SpotDirection, Q::SpotCutoff, Q::SpotExponent].map(Q::name);
        s.push_str(&format!("#{dir} = [0 0 0 0];\n#{cutoff} = 90;\n#{coef} = 60;\n"));
    }
    s.push('\n');
    // The materials as lit: where GL_COLOR_MATERIAL tracks a colour, the worksheet's
    // variable holds the current colour (the calculation has no glColor of its own).
    if let Some(cm) = &scene.color_material {
        let color = fmt_value(&cm.color.to_array(), 8);
        s.push_str(&t!("nb-color-material-comment", mode = cm.mode.gl(), face = cm.face.gl(), color = color));
        s.push('\n');
    }
    s.push_str(&material(&scene.lit_material(Side::Front), "", needs.rules.emission()));
    if back_written(scene) {
        s.push('\n');
        s.push_str(&material(&scene.lit_material(Side::Back), "Back", needs.rules.emission()));
    }
    if needs.rules.scene_ambient() {
        s.push_str(&format!("\n{} = {};\n", Q::SceneAmbient.name(), colour(scene.light_model.ambient)));
    }
    s.trim_end().to_string() + "\n"
}

/// One side's material: `matAmb`, `matDif`, `matSpec`, `ns` (and `matEmi`, `matAlpha`).
fn material(m: &Material, suffix: &str, emission: bool) -> String {
    let name = crate::model::materials::classic()
        .iter()
        .find(|c| {
            c.material.ambient.truncate() == m.ambient.truncate()
                && c.material.diffuse.truncate() == m.diffuse.truncate()
                && c.material.specular.truncate() == m.specular.truncate()
                && c.material.shininess == m.shininess
        })
        .map(|c| c.name.clone());
    let mut s = match name {
        Some(n) => format!("#{n}\n"),
        None => String::new(),
    };
    let mut line = |q: Quantity, value: String| s.push_str(&format!("{}{suffix} = {value};\n", q.name()));
    line(Q::MatAmbient, colour(m.ambient));
    line(Q::MatDiffuse, colour(m.diffuse));
    line(Q::MatSpecular, colour(m.specular));
    line(Q::Shininess, shininess(m.shininess));
    if emission {
        line(Q::MatEmission, colour(m.emission));
    }
    if m.diffuse.w != 1.0 {
        line(Q::MatAlpha, num(m.diffuse.w));
    }
    s
}

/// The settings the worksheet does not have, as variables (written only when the scene
/// departs from the worksheet's): what the cells below were written for.
fn settings(needs: &Needs) -> Option<String> {
    let mut lines = Vec::new();
    // The worksheet's own rules need no line.
    let rules = match needs.rules.set {
        RuleSet::Worksheet => None,
        RuleSet::OpenGl => Some("opengl"),
        RuleSet::PhongDemo => Some("phong-demo"),
    };
    if let Some(rules) = rules {
        lines.push(format!("rules = {}", string(rules)));
    }
    if !needs.rules.specular_is_the_sets() {
        lines.push(format!("specular = {}", string(needs.rules.specular.name())));
    }
    if needs.normals != NormalMode::Normalize {
        let m = if needs.normals == NormalMode::AsIs { "as-is" } else { "rescale" };
        lines.push(format!("normalMode = {}", string(m)));
    }
    if needs.two_sided {
        lines.push("twoSided = True".into());
    }
    if needs.separate_specular {
        lines.push("separateSpecular = True".into());
    }
    (!lines.is_empty()).then(|| lines.join("\n"))
}

/// `mview`, and each light's modelview where it differs.
fn modelview(scene: &Scene, needs: &Needs) -> String {
    let mut s = format!("{} = {};\n", Q::Modelview.name(), matrix(&scene.eye_from_object()));
    if needs.light_mview {
        s.push_str(&t!("nb-light-mview-comment"));
        s.push('\n');
        s.push_str(&per_light_given(scene, Q::LightModelview, |l| matrix(&scene.eye_from_light(l))));
        s.push('\n');
    }
    s.push_str("\nprint(\"modelview = \\n\", mview)");
    s
}

/// The normal, the positions, `vlv` and `vov`.
fn vectors(scene: &Scene, needs: &Needs) -> String {
    let n = needs.lights;
    let mut s = String::new();
    match needs.rules.normal_transform() {
        NormalTransform::Modelview => s.push_str("vertexNormal = np.matmul(mview, vertexNormal)\n"),
        NormalTransform::InverseTranspose => {
            s.push_str(&t!("nb-normal-matrix-comment"));
            s.push_str("\nnormalMatrix = np.linalg.inv(mview[:3, :3]).T\n");
            s.push_str("vertexNormal = np.append(np.matmul(normalMatrix, vertexNormal[:3]), 0)\n");
        }
    }
    match scene.normal_mode {
        NormalMode::Normalize => s.push_str("vertexNormal = vertexNormal/np.linalg.norm(vertexNormal)\n"),
        NormalMode::Rescale => s.push_str(
            "#GL_RESCALE_NORMAL\nvertexNormal = vertexNormal/np.linalg.norm(np.linalg.inv(mview[:3, :3])[2])\n",
        ),
        NormalMode::AsIs => s.push_str(&format!("{}\n", t!("nb-normal-as-is-comment"))),
    }
    s.push_str("print(\"vertexNormal = \", vertexNormal)\n\n");
    let light_m = if needs.light_mview { "lightMview[⟨i⟩]" } else { "mview" };
    s.push_str("vertexPos = np.matmul(mview, vertexPos)\n");
    if needs.divide_w {
        s.push_str("vertexPos = vertexPos/vertexPos[3]\n");
    }
    s.push_str("print(\"vertexPos = \", vertexPos)\n\n");
    let light_point = if needs.divide_w { "lightPos[⟨i⟩]/lightPos[⟨i⟩][3]" } else { "lightPos[⟨i⟩]" };
    let body = format!(
        "lightPos[⟨i⟩] = np.matmul({light_m}, lightPos[⟨i⟩])\n{}\n\nif (lightPos[⟨i⟩][-1] == 0):\n    vlv[⟨i⟩] = lightPos[⟨i⟩]\nelse:\n    vlv[⟨i⟩] = ({light_point} - vertexPos)\n\nvlv[⟨i⟩] = vlv[⟨i⟩]/np.linalg.norm(vlv[⟨i⟩])\n{}\n",
        print("lightPos", true),
        print("vlv", true)
    );
    if n == 1 {
        s.push_str(&per_light(1, &[], &body));
    } else {
        // The list of positions is transformed in place, entry by entry.
        s.push_str(&per_light(n, &["vlv"], &body));
    }
    s.push('\n');
    let local = scene.light_model.local_viewer;
    if needs.rules.viewer_from_eye_plane() || local {
        s.push_str("#localViewer\n#true\n");
        s.push_str(if local { "obs = np.array([0, 0, 0, 1])\n" } else { "#obs = np.array([0, 0, 0, 1])\n" });
        s.push_str("\n#false\n");
        s.push_str(if local {
            "#obs = vertexPos*np.array([1, 1, 0, 1])\n"
        } else {
            "obs = vertexPos*np.array([1, 1, 0, 1])\n"
        });
        s.push_str("\nvov = (obs - vertexPos)\nvov = vov/np.linalg.norm(vov)\n");
    } else {
        s.push_str(&t!("nb-infinite-viewer-comment"));
        s.push_str("\n#obs = np.array([0, 0, 0, 1])\nvov = np.array([0, 0, 1, 0])\n");
    }
    s.push_str("print(\"vov = \", vov)");
    s
}

/// The diffuse cell, the worksheet's (θ past 90 degrees gives 0); `suffix` names the back
/// side's values.
fn diffuse(n: usize, suffix: &str) -> String {
    let normal = if suffix.is_empty() { "vertexNormal" } else { "-vertexNormal" };
    let mat = format!("matDif{}", if suffix.is_empty() { "" } else { "Back" });
    let ct = format!("cosTheta{suffix}");
    let idif = format!("Idif{suffix}");
    let body = format!(
        "{ct}[⟨i⟩] = np.dot({normal}, vlv[⟨i⟩]);\n{}\n{}\ntheta = m.acos(min(max({ct}[⟨i⟩], -1), 1));\nif (theta > m.pi*0.5):\n    {idif}[⟨i⟩] = np.array([0, 0, 0, 0])\nelse:\n    {idif}[⟨i⟩] = (Ldif[⟨i⟩]*{mat})*{ct}[⟨i⟩]\n\n{}",
        print(&ct, true),
        t!("nb-acos-comment"),
        print(&idif, true)
    );
    per_light(n, &[ct.as_str(), idif.as_str()], &body)
}

/// The specular cell: Blinn-Phong's H (the worksheet's) or Phong's R, gated as the rules
/// say.
fn specular(needs: &Needs, n: usize, suffix: &str) -> String {
    let back = !suffix.is_empty();
    let normal = if back { "-vertexNormal" } else { "vertexNormal" };
    let mat = if back { "matSpecBack" } else { "matSpec" };
    let ns = if back { "nsBack" } else { "ns" };
    let ct = format!("cosTheta{suffix}");
    let ispec = format!("Ispec{suffix}");
    let (vector, cos_name, cos_line, assigned) = match needs.vector {
        SpecularVector::Halfway => {
            let cos = format!("cosBeta{suffix}");
            let lines = if back {
                format!("{cos}[⟨i⟩] = np.dot({normal}, H[⟨i⟩])\n{}\n", print(&cos, true))
            } else {
                format!(
                    "H[⟨i⟩] = (vlv[⟨i⟩] + vov)\nH[⟨i⟩] = H[⟨i⟩]/np.linalg.norm(H[⟨i⟩])\n{}\n{cos}[⟨i⟩] = np.dot({normal}, H[⟨i⟩])\n{}\n",
                    print("H", true),
                    print(&cos, true)
                )
            };
            (lines, cos.clone(), "beta", if back { vec![cos] } else { vec!["H".to_string(), cos] })
        }
        SpecularVector::Reflection => {
            let cos = format!("cosAlpha{suffix}");
            let dot = if needs.rules.reflect_clamped() {
                "max(np.dot(vertexNormal, vlv[⟨i⟩]), 0)"
            } else {
                "np.dot(vertexNormal, vlv[⟨i⟩])"
            };
            // R is formed with the front normal on both sides, as the engine forms it.
            let lines = if back {
                format!("{cos}[⟨i⟩] = np.dot(R[⟨i⟩], vov)\n{}\n", print(&cos, true))
            } else {
                format!(
                    "R[⟨i⟩] = 2*{dot}*vertexNormal - vlv[⟨i⟩]\n{}\n{cos}[⟨i⟩] = np.dot(R[⟨i⟩], vov)\n{}\n",
                    print("R", true),
                    print(&cos, true)
                )
            };
            (lines, cos.clone(), "alpha", if back { vec![cos] } else { vec!["R".to_string(), cos] })
        }
    };
    // What multiplies the power, after it.
    let scale = match needs.term {
        SpecularTerm::Zero | SpecularTerm::Plain => String::new(),
        // Energy-conserving Blinn-Phong.
        SpecularTerm::Normalised => format!("*({ns} + 8)/(8*m.pi)"),
    };
    let power = match needs.rules.specular_gate() {
        SpecularGate::None => format!("{ispec}[⟨i⟩] = (Lspec[⟨i⟩]*{mat})*(max({cos_name}[⟨i⟩], 0)**{ns}){scale}\n"),
        SpecularGate::LitSide => format!(
            "{}\nif ({ct}[⟨i⟩] <= 0):\n    {ispec}[⟨i⟩] = np.array([0, 0, 0, 0])\nelse:\n    {ispec}[⟨i⟩] = (Lspec[⟨i⟩]*{mat})*(max({cos_name}[⟨i⟩], 0)**{ns}){scale}\n",
            t!("nb-gate-lit-side-comment")
        ),
        SpecularGate::PositiveCosine => format!(
            "{cos_line} = m.acos(min(max({cos_name}[⟨i⟩], -1), 1))\nif ({cos_line} > m.pi*0.5 or {cos_line} < 0):\n    {ispec}[⟨i⟩] = np.array([0, 0, 0, 0])\nelse:\n    {ispec}[⟨i⟩] = (Lspec[⟨i⟩]*{mat})*({cos_name}[⟨i⟩]**{ns}){scale}\n"
        ),
    };
    let mut names: Vec<&str> = assigned.iter().map(String::as_str).collect();
    names.push(&ispec);
    let body = format!("{vector}{power}\n{}", print(&ispec, true));
    per_light(n, &names, &body)
}

/// The specular cell's explanation for the scene's model.
fn specular_markdown(needs: &Needs) -> String {
    let model = match needs.vector {
        SpecularVector::Halfway => t!("nb-specular-blinn"),
        SpecularVector::Reflection => t!("nb-specular-phong"),
    };
    match needs.term {
        SpecularTerm::Zero | SpecularTerm::Plain => model,
        SpecularTerm::Normalised => format!("{model}\n\n{}", t!("nb-specular-normalised")),
    }
}

/// `d` and `at`, per light.
fn attenuation(needs: &Needs) -> String {
    let light_point = if needs.divide_w { "lightPos[⟨i⟩]/lightPos[⟨i⟩][3]" } else { "lightPos[⟨i⟩]" };
    let body = format!(
        "d[⟨i⟩] = np.linalg.norm({light_point} - vertexPos);\n\nif lightPos[⟨i⟩][-1] == 0:\n    at[⟨i⟩] = 1\nelse:\n    at[⟨i⟩] = atC[⟨i⟩] + atLin[⟨i⟩]*d[⟨i⟩] + atQuad[⟨i⟩]*d[⟨i⟩]*d[⟨i⟩]\n    {}\n{}",
        print("d", true),
        print("at", true)
    );
    // A directional light has no d (the worksheet computes it unused): printed only for the others.
    per_light(needs.lights, &["d", "at"], &body)
}

/// The spotlight factor, per light (1 for a light that is not a spotlight).
fn spot(needs: &Needs) -> String {
    let light_m = if needs.light_mview { "lightMview[⟨i⟩]" } else { "mview" };
    let cone = format!(
        "if spotCutoff[⟨i⟩] == 180:\n    spot[⟨i⟩] = 1\nelse:\n    spotDir = np.matmul({light_m}[:3, :3], lightSpotDir[⟨i⟩][:3])\n    spotDir = spotDir/np.linalg.norm(spotDir)\n    cosSpot = np.dot(-vlv[⟨i⟩][:3], spotDir)\n    if cosSpot >= m.cos(m.radians(spotCutoff[⟨i⟩])):\n        spot[⟨i⟩] = max(cosSpot, 0)**spotCoef[⟨i⟩]\n    else:\n        spot[⟨i⟩] = 0\n{}",
        print("spot", true)
    );
    per_light(needs.lights, &["spot"], &cone)
}

/// I: the worksheet's `(Iamb + Idif + Ispec)/at` for its own shape; else each light's
/// share, summed with the scene ambient and emission the rules keep. Then the colour as
/// drawn.
fn final_colour(scene: &Scene, needs: &Needs, suffix: &str) -> String {
    let back = !suffix.is_empty();
    let n = needs.lights;
    let mut s = String::new();
    let sep = needs.separate_specular;
    let (iamb, idif, ispec) = if back { ("IambBack", "IdifBack", "IspecBack") } else { ("Iamb", "Idif", "Ispec") };
    let (i_name, ilight, isec) = (format!("I{suffix}"), format!("Ilight{suffix}"), format!("Isec{suffix}"));
    if needs.worksheet_shape() && !back {
        s.push_str("I = (Iamb + Idif + Ispec)/at\n");
    } else {
        // Without a spotlight, each light's spot factor is 1 (explain prints it so).
        let no_spot = if !needs.spot && !back {
            format!("spot[⟨i⟩] = 1  {}\n{}\n", t!("nb-no-spot-comment"), print("spot", true))
        } else {
            String::new()
        };
        let spot = "spot[⟨i⟩]*";
        let body = no_spot.clone()
            + &if sep {
                format!(
                    "{ilight}[⟨i⟩] = {spot}({iamb}[⟨i⟩] + {idif}[⟨i⟩])/at[⟨i⟩]\n{}\n{isec}[⟨i⟩] = {spot}{ispec}[⟨i⟩]/at[⟨i⟩]",
                    print(&ilight, true)
                )
            } else {
                format!(
                    "{ilight}[⟨i⟩] = {spot}({iamb}[⟨i⟩] + {idif}[⟨i⟩] + {ispec}[⟨i⟩])/at[⟨i⟩]\n{}",
                    print(&ilight, true)
                )
            };
        let mut assigned: Vec<&str> = if sep { vec![&ilight, &isec] } else { vec![&ilight] };
        if !no_spot.is_empty() {
            assigned.insert(0, "spot");
        }
        s.push_str(&per_light(n, &assigned, &body));
        s.push('\n');
        let lights_sum = if n == 1 { ilight.clone() } else { format!("sum({ilight})") };
        if needs.opengl_terms {
            let (mat_amb, mat_emi) = if back { ("matAmbBack", "matEmiBack") } else { ("matAmb", "matEmi") };
            s.push_str(&format!("Iscene{suffix} = {mat_amb}*sceneAmb\nprint(\"Iscene{suffix} = \", Iscene{suffix})\n"));
            s.push_str(&format!("Iemi{suffix} = {mat_emi}\nprint(\"Iemi{suffix} = \", Iemi{suffix})\n"));
            if n == 0 {
                s.push_str(&format!("{i_name} = Iemi{suffix} + Iscene{suffix}\n"));
            } else {
                s.push_str(&format!("{i_name} = Iemi{suffix} + Iscene{suffix} + {lights_sum}\n"));
            }
        } else if n == 0 {
            s.push_str(&format!("{i_name} = np.array([0, 0, 0, 0])\n"));
        } else {
            s.push_str(&format!("{i_name} = {lights_sum}\n"));
        }
    }
    s.push_str(&format!("print(\"{i_name} = \", {i_name})\n"));
    let alpha_var = if back { "matAlphaBack" } else { "matAlpha" };
    // OpenGL's lit alpha is the diffuse colour's as lit: the current colour's where
    // GL_COLOR_MATERIAL tracks the diffuse (the material cell writes `matAlpha` from it).
    let alpha_m = scene.lit_material(if back { Side::Back } else { Side::Front });
    let alpha = if alpha_m.diffuse.w == 1.0 { "1".to_string() } else { alpha_var.to_string() };
    let sum = if sep {
        let isec_sum = if n == 1 { isec.clone() } else { format!("sum({isec})") };
        s.push_str(&format!("{isec} = {isec_sum}\nprint(\"{isec} = \", {isec})\n"));
        format!("{i_name} + {isec}")
    } else {
        i_name.clone()
    };
    s.push_str(&format!(
        "\n{}\nglColor{suffix} = np.append(np.clip(({sum})[:3], 0, 1), {alpha})\nprint(\"glColor{suffix} = \", glColor{suffix})",
        t!("nb-glcolor-comment")
    ));
    s
}

/// Does the material cell write the back side's material (`matAmbBack` ...)? Where the
/// scene has one, or where `GL_COLOR_MATERIAL` tracks one side only (the sides then
/// differ).
fn back_written(scene: &Scene) -> bool {
    scene.back_material.is_some() || scene.color_material.is_some_and(|cm| cm.face != Face::FrontAndBack)
}

/// The back side of two-sided lighting: the same terms with `-vertexNormal` and the back
/// material, printed with `Back` after their names. The cells read the back material's
/// names (`matAmbBack` ...) always: a scene without a back material names the front's
/// values so, in one line.
fn back_side(scene: &Scene, needs: &Needs) -> String {
    let n = needs.lights;
    let mut s = String::new();
    if !back_written(scene) {
        let mut names = vec!["matAmb", "matDif", "matSpec", "ns"];
        // Written by the material cell only where the rules have emission, or the alpha is not 1.
        if needs.rules.emission() {
            names.push("matEmi");
        }
        if scene.lit_material(Side::Front).diffuse.w != 1.0 {
            names.push("matAlpha");
        }
        let backs: Vec<String> = names.iter().map(|n| format!("{n}Back")).collect();
        s.push_str(&format!("{} = {}\n\n", backs.join(", "), names.join(", ")));
    }
    s.push_str(&per_light(
        n,
        &["IambBack"],
        &format!("IambBack[⟨i⟩] = Lamb[⟨i⟩]*matAmbBack\n{}", print("IambBack", true)),
    ));
    s.push('\n');
    s.push_str(&diffuse(n, "Back"));
    s.push('\n');
    s.push_str(&specular(needs, n, "Back"));
    s.push('\n');
    s.push_str(&final_colour(scene, needs, "Back"));
    s
}

/// The notebook as one Python script (what `jupyter nbconvert --to script` writes): the
/// markdown as comments, the code cells one after the other. It runs as the notebook does,
/// and `phonglab import` reads it back.
pub fn script(cells: &[Cell]) -> String {
    let mut out = String::from("#!/usr/bin/env python3\n");
    for cell in cells {
        match cell {
            Cell::Markdown(text) => {
                out.push('\n');
                for line in text.strip_suffix('\n').unwrap_or(text).split('\n') {
                    out.push_str(if line.is_empty() { "#" } else { "# " });
                    out.push_str(&escape::python::comment(line));
                    out.push('\n');
                }
            }
            Cell::Code(code) => {
                out.push_str("\n# In[ ]:\n\n");
                out.push_str(code.trim_end());
                out.push('\n');
            }
        }
    }
    out
}
