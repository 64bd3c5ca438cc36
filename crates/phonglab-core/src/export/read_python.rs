//! Reading a worksheet-style notebook (`.ipynb`) or script (`.py`) back into a scene.
//!
//! What is read: the assignments of the worksheet's givens (`vertexPos`, `vertexNormal`,
//! `lightPos`, `Lamb`, `Ldif`, `Lspec`, `atC`, `atLin`, `atQuad`, `lightSpotDir`,
//! `spotCutoff`, `spotCoef`, `matAmb`, `matDif`, `matSpec`, `ns`, `mview`) and of the names
//! the exported notebooks add (`lightMview`, `matEmi`, `matAlpha`, `sceneAmb`, the back
//! material's `...Back`, and the settings `rules`, `specular`, `normalMode`, `twoSided`,
//! `separateSpecular`), as Python would run them, top to bottom: numbers, simple
//! arithmetic (`0.2*128`), `np.array([...])` of numbers or of rows, lists of them (one
//! per light), strings, `True`/`False`, and names assigned before (`mview = mview5`).
//! The local viewer is the worksheet's own switch: the active line `obs = np.array([0,
//! 0, 0, 1])`. Comments (the commented-out alternatives) are ignored, and so are the
//! computing lines (`vertexNormal = np.matmul(mview, vertexNormal)`, anything indented).
//! A given whose value cannot be read is reported with its line, and so is a given the
//! file lacks (the worksheet's value is used); nothing else is lost. A given that is not a
//! finite number (`1e999`, `0/0`) is refused so, naming it.
//!
//! The file may be hostile, so reading it is bounded: an expression nests at most
//! [`MAX_DEPTH`] deep (brackets, calls, signs, powers), a value holds at most
//! [`MAX_ELEMENTS`] numbers, strings and lists and [`MAX_BYTES`] bytes of strings, and all
//! the names assigned together hold at most [`MAX_TOTAL_ELEMENTS`] and [`MAX_TOTAL_BYTES`]
//! (a list that repeats the one before grows four times a line: its fifteenth line would be
//! a billion numbers). Passing a limit stops the reading, naming the line.

use std::collections::BTreeMap;

use glam::{DMat4, DVec3, DVec4};

use crate::formats::document::Document;
use crate::model::camera::CameraSpec;
use crate::model::rules::{Rules, SpecularModel};
use crate::model::scene::{Light, LightPlacement, Material, NormalMode, Scene, Vertex};
use crate::model::vocabulary::Quantity::{self, self as Q};
use crate::t;

mod expression;

use expression::{Failure, Size, Value, evaluate};
pub use expression::{MAX_BYTES, MAX_DEPTH, MAX_ELEMENTS, MAX_TOKENS};

/// The scene read, and what the reader has to say about the file (each naming a line).
#[derive(Clone, Debug)]
pub struct Imported {
    /// The scene, under the worksheet's rules unless the file says otherwise.
    pub doc: Document,
    /// Lines that could not be read, and givens the file lacks.
    pub notices: Vec<String>,
    /// The givens refused as not finite numbers, each with its place (`vertexPos (line 3)`;
    /// their notices are among `notices`): `check` refuses such work rather than check the
    /// worksheet's value in its place.
    pub not_finite: Vec<String>,
    /// The givens a line changes in a way the reader does not follow (`lightPos[2] *= 2`,
    /// `lightPos += d`), each with its place: `check` refuses such work rather than check a
    /// value Python never used.
    pub not_followed: Vec<String>,
}

impl Imported {
    /// Why the work cannot be checked from what was read, in the user's words: a given
    /// that is not a finite number, or one changed in place, is refused, named, never
    /// checked as the worksheet's value put in its place or a value Python never used.
    pub fn not_checkable(&self) -> Option<String> {
        if !self.not_finite.is_empty() {
            return Some(t!("check-given-not-finite", givens = self.not_finite.join("; ")));
        }
        (!self.not_followed.is_empty()).then(|| t!("check-given-not-followed", givens = self.not_followed.join("; ")))
    }
}

/// Why nothing could be read at all.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ImportError {
    /// An `.ipynb` that is not a notebook.
    #[error("{0}")]
    NotANotebook(String),
    /// No given of the worksheet at all: not a worksheet-style file.
    #[error("{0}")]
    NoGivens(String),
    /// A line passed one of the reader's limits (nesting, size): the file is not read.
    #[error("{0}")]
    TooLarge(String),
}

/// The most numbers, strings and lists all the names assigned hold together.
pub const MAX_TOTAL_ELEMENTS: usize = 1_000_000;
/// The most bytes of strings all the names assigned hold together.
pub const MAX_TOTAL_BYTES: usize = 16 << 20;

/// phonglab's own settings a notebook may assign beside the worksheet's givens.
const SETTINGS: [&str; 5] = ["rules", "specular", "normalMode", "twoSided", "separateSpecular"];

/// Is `name` read as a given: a worksheet quantity given before the calculation (the
/// back material's too, `matDifBack`), or one of phonglab's settings?
fn is_given(name: &str) -> bool {
    Quantity::givens().any(|q| q.name() == name)
        || Quantity::MATERIAL.iter().any(|q| q.back_name() == name)
        || SETTINGS.contains(&name)
}

/// A line of code and where it is (`line 7`, or `cell 4, line 2` in a notebook).
struct SourceLine {
    text: String,
    place: String,
}

/// Reads `text`, a notebook when `notebook` is true (its code cells, in order), else a
/// Python script. `name` names the scene.
pub fn read(text: &str, notebook: bool, name: &str) -> Result<Imported, ImportError> {
    let lines = if notebook { notebook_lines(text)? } else { script_lines(text) };
    let mut env: BTreeMap<String, Value> = BTreeMap::new();
    let mut given: BTreeMap<String, (Value, String)> = BTreeMap::new();
    let mut notices = Vec::new();
    let mut local_viewer = false;
    let mut refused = Vec::new();
    let mut not_finite = Vec::new();
    let mut not_followed = Vec::new();
    let mut total = Size::default();
    for line in &lines {
        if let Some(name) = changed_in_place(&line.text).filter(|n| is_given(n)) {
            not_followed.push(format!("{name} ({})", line.place));
            notices.push(t!(
                "import-unreadable",
                place = line.place.clone(),
                line = crate::numerics::strict::quoted_line(&line.text),
                reason = t!("import-changed-in-place")
            ));
            continue;
        }
        let Some((lhs, rhs)) = assignment(&line.text) else { continue };
        let value = match evaluate(rhs, &env) {
            Err(Failure::Limit(why)) => return Err(too_large(line, &why)),
            Err(Failure::Unreadable(why)) => Err(why),
            Ok(v) => {
                total = total.plus(v.size());
                if let Some(limit) = total.passes(MAX_TOTAL_ELEMENTS, MAX_TOTAL_BYTES) {
                    return Err(too_large(line, &t!("import-limit-total", limit = limit)));
                }
                Ok(v)
            }
        };
        if lhs == "obs" {
            // The worksheet's switch: the active `obs` line says which viewer.
            local_viewer = !rhs.contains(Q::VertexPos.name())
                && value.as_ref().is_ok_and(|v| v.numbers() == Some(vec![0.0, 0.0, 0.0, 1.0]));
            continue;
        }
        let is_given = is_given(lhs);
        match value {
            Ok(v) => {
                if is_given && let Some(x) = v.first_not_finite() {
                    // A given that is not a finite number is refused; later lines may still
                    // assign it.
                    let notice = t!(
                        "import-not-finite",
                        place = line.place.clone(),
                        name = lhs,
                        value = crate::locale::num(x, 8)
                    );
                    not_finite.push(format!("{lhs} ({})", line.place));
                    notices.push(notice);
                    given.remove(lhs);
                    refused.push(lhs.to_string());
                } else if is_given {
                    given.insert(lhs.to_string(), (v.clone(), line.place.clone()));
                }
                env.insert(lhs.to_string(), v);
            }
            // A computing line (it uses NumPy's functions, or the name itself): the
            // worksheet's calculation, not a given.
            Err(_) if computing(lhs, rhs) => {}
            Err(e) if is_given => notices.push(t!(
                "import-unreadable",
                place = line.place.clone(),
                line = crate::numerics::strict::quoted_line(&line.text),
                reason = e
            )),
            Err(_) => {}
        }
    }
    let assigned = given.keys().chain(&refused);
    if !assigned.into_iter().any(|k| {
        [Q::VertexPos, Q::VertexNormal, Q::LightPos, Q::MatDiffuse, Q::Modelview].iter().any(|q| q.name() == k.as_str())
    }) {
        return Err(ImportError::NoGivens(t!("import-no-givens")));
    }
    let mut r = Reader { given, notices, refused };
    let doc = r.document(name, local_viewer);
    Ok(Imported { doc, notices: r.notices, not_finite, not_followed })
}

/// The error for a line that passed a limit: its place, its text (shortened) and why.
fn too_large(line: &SourceLine, why: &str) -> ImportError {
    let text = crate::numerics::strict::quoted_line(&line.text);
    ImportError::TooLarge(t!("import-too-large", place = line.place.clone(), line = text, reason = why))
}

/// The code cells' lines of a notebook.
fn notebook_lines(text: &str) -> Result<Vec<SourceLine>, ImportError> {
    let nb: serde_json::Value = serde_json::from_str(text)
        .map_err(|e| ImportError::NotANotebook(t!("import-not-notebook", reason = e.to_string())))?;
    let cells = nb["cells"]
        .as_array()
        .ok_or_else(|| ImportError::NotANotebook(t!("import-not-notebook", reason = t!("import-no-cells"))))?;
    let mut out = Vec::new();
    for (c, cell) in cells.iter().enumerate() {
        if cell["cell_type"] != "code" {
            continue;
        }
        let source = match &cell["source"] {
            serde_json::Value::String(s) => s.clone(),
            serde_json::Value::Array(parts) => parts.iter().filter_map(|p| p.as_str()).collect(),
            _ => String::new(),
        };
        for (k, line) in code_lines(&source) {
            out.push(SourceLine { text: line, place: t!("import-place-cell", cell = c + 1, line = k + 1) });
        }
    }
    Ok(out)
}

/// The lines of `source` as Python reads their names: each in its NFKC form (Python reads
/// `ｌｉｇｈｔＰｏｓ` as `lightPos`), with their numbers (from 0), less the lines that start
/// inside a triple-quoted string (`"""` ... `"""` is text, not code, though it looks
/// like an assignment).
fn code_lines(source: &str) -> Vec<(usize, String)> {
    let nfkc = icu_normalizer::ComposingNormalizerBorrowed::new_nfkc();
    let mut open: Option<&str> = None;
    let mut out = Vec::new();
    for (k, line) in source.lines().enumerate() {
        let starts_inside = open.is_some();
        open = after_line(line, open);
        if !starts_inside {
            out.push((k, nfkc.normalize(line).into_owned()));
        }
    }
    out
}

/// The triple-quoted string still open after `line`, given the one open before it.
fn after_line(line: &str, mut open: Option<&'static str>) -> Option<&'static str> {
    let mut rest = line;
    loop {
        if let Some(q) = open {
            let Some(end) = rest.find(q) else { return open };
            rest = &rest[end + 3..];
            open = None;
            continue;
        }
        // Outside a triple-quoted string: a comment ends the line; a one-line string is
        // skipped to its closing quote (a backslash escapes).
        let i = rest.find(['#', '"', '\''])?;
        let c = rest[i..].chars().next().unwrap_or('#');
        if c == '#' {
            return None;
        }
        let tail = &rest[i..];
        if tail.starts_with("\"\"\"") || tail.starts_with("'''") {
            open = Some(if c == '"' { "\"\"\"" } else { "'''" });
            rest = &tail[3..];
            continue;
        }
        let mut escaped = false;
        let close = tail[1..].char_indices().find(|&(_, ch)| {
            let hit = ch == c && !escaped;
            escaped = ch == '\\' && !escaped;
            hit
        });
        match close {
            Some((j, _)) => rest = &tail[1 + j + 1..],
            None => return None,
        }
    }
}

/// The name a top-level line changes in place, not by `name = expression`:
/// `lightPos[2] = 5`, `lightPos[2] *= 2`, `lightPos += d`.
fn changed_in_place(line: &str) -> Option<&str> {
    if line.starts_with([' ', '\t', '#']) {
        return None;
    }
    let code = strip_comment(line).trim();
    let name_end = code.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(code.len());
    let (name, rest) = code.split_at(name_end);
    if name.is_empty() {
        return None;
    }
    let rest = rest.trim_start();
    let rest = if rest.starts_with('[') {
        let close = rest.find(']')?;
        let after = rest[close + 1..].trim_start();
        // `name[i] = ...`: a subscript assigned.
        if after.starts_with('=') && !after.starts_with("==") {
            return Some(name);
        }
        after
    } else {
        rest
    };
    let ops = ["+=", "-=", "*=", "/=", "//=", "%=", "**=", "@=", "&=", "|=", "^=", ">>=", "<<="];
    ops.iter().any(|op| rest.starts_with(op)).then_some(name)
}

/// A script's lines.
fn script_lines(text: &str) -> Vec<SourceLine> {
    code_lines(text)
        .into_iter()
        .map(|(k, line)| SourceLine { text: line, place: t!("import-place-line", line = k + 1) })
        .collect()
}

/// `name = expression` at the start of a line (not indented, not a comment, not `==`),
/// the comment and a final `;` removed.
fn assignment(line: &str) -> Option<(&str, &str)> {
    if line.starts_with([' ', '\t', '#']) {
        return None;
    }
    let code = strip_comment(line).trim().trim_end_matches(';').trim();
    let (lhs, rhs) = code.split_once('=')?;
    let lhs = lhs.trim();
    if rhs.starts_with('=') || lhs.is_empty() || !lhs.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return None;
    }
    if lhs.ends_with(['<', '>', '!']) {
        return None;
    }
    Some((lhs, rhs.trim()))
}

/// The line without its `#` comment (a `#` inside a string is kept).
fn strip_comment(line: &str) -> &str {
    let mut quote = None;
    for (i, c) in line.char_indices() {
        match (quote, c) {
            (None, '#') => return &line[..i],
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), c) if c == q => quote = None,
            _ => {}
        }
    }
    line
}

/// Does the right-hand side compute (NumPy's functions, `m.` functions, the name itself)?
fn computing(lhs: &str, rhs: &str) -> bool {
    let words = ["np.matmul", "np.linalg", "np.dot", "np.append", "np.clip", "m.acos", "np.cross", "sum("];
    words.iter().any(|w| rhs.contains(w))
        || rhs.split(|c: char| !c.is_ascii_alphanumeric() && c != '_').any(|w| w == lhs)
}

/// Builds the scene from the givens, reporting what is missing or malformed.
struct Reader {
    given: BTreeMap<String, (Value, String)>,
    notices: Vec<String>,
    /// Givens refused for a value that is not finite (already reported, so not "missing").
    refused: Vec<String>,
}

impl Reader {
    /// How many lights: the length of a list of positions, else one.
    fn light_count(&self) -> usize {
        match self.given.get(Q::LightPos.name()) {
            Some((Value::List(items), _)) if items.iter().all(|v| matches!(v, Value::List(_))) => items.len(),
            _ => 1,
        }
    }

    /// A given's value for light `i` (of `n`): the list's entry where the given is one
    /// value per light (one nesting deeper than a single value), else the one value.
    fn per_light(&self, name: &str, i: usize, n: usize) -> Option<(Value, String)> {
        let (v, place) = self.given.get(name)?;
        let single_depth = match Quantity::named(name) {
            Some(Q::LightModelview) => 2,
            Some(Q::AttConstant | Q::AttLinear | Q::AttQuadratic | Q::SpotCutoff | Q::SpotExponent) => 0,
            _ => 1,
        };
        match v {
            Value::List(items) if n > 1 && items.len() == n && v.depth() == single_depth + 1 => {
                Some((items[i].clone(), place.clone()))
            }
            _ => Some((v.clone(), place.clone())),
        }
    }

    fn missing(&mut self, name: &str, default: String) {
        if self.refused.iter().any(|r| r == name) {
            return;
        }
        self.notices.push(t!("import-missing", name = name, value = default));
    }

    fn malformed(&mut self, name: &str, place: &str, want: &str) {
        self.notices.push(t!("import-malformed", name = name, place = place, want = want));
    }

    /// A vector of 3 or 4 numbers (the fourth, if any, returned as given).
    fn vec4(&mut self, name: &str, i: usize, n: usize, default: DVec4) -> DVec4 {
        match self.per_light(name, i, n) {
            None => {
                if i == 0 {
                    self.missing(name, crate::equation::explain::fmt_value(&default.to_array(), 8));
                }
                default
            }
            Some((v, place)) => match v.numbers().filter(|x| x.len() == 3 || x.len() == 4) {
                Some(x) => DVec4::new(x[0], x[1], x[2], x.get(3).copied().unwrap_or(default.w)),
                None => {
                    self.malformed(name, &place, &t!("import-want-vector"));
                    default
                }
            },
        }
    }

    /// A colour: rgb, alpha 1 (the worksheet writes 0 in the fourth component, unused).
    fn colour(&mut self, name: &str, i: usize, n: usize, default: DVec4) -> DVec4 {
        let c = self.vec4(name, i, n, default);
        DVec4::new(c.x, c.y, c.z, 1.0)
    }

    fn number(&mut self, name: &str, i: usize, n: usize, default: f64) -> f64 {
        match self.per_light(name, i, n) {
            None => default,
            Some((v, place)) => match v.numbers().filter(|x| x.len() == 1) {
                Some(x) => x[0],
                None => {
                    self.malformed(name, &place, &t!("import-want-number"));
                    default
                }
            },
        }
    }

    fn matrix(&mut self, v: &Value, name: &str, place: &str) -> Option<DMat4> {
        let rows: Option<Vec<Vec<f64>>> = match v {
            Value::List(rows) if rows.len() == 4 => rows.iter().map(Value::numbers).collect(),
            _ => None,
        };
        match rows.filter(|r| r.iter().all(|row| row.len() == 4)) {
            Some(r) => Some(crate::model::transform::mat4_from_rows([
                [r[0][0], r[0][1], r[0][2], r[0][3]],
                [r[1][0], r[1][1], r[1][2], r[1][3]],
                [r[2][0], r[2][1], r[2][2], r[2][3]],
                [r[3][0], r[3][1], r[3][2], r[3][3]],
            ])),
            None => {
                self.malformed(name, place, &t!("import-want-matrix"));
                None
            }
        }
    }

    fn string(&self, name: &str) -> Option<String> {
        match self.given.get(name) {
            Some((Value::Str(s), _)) => Some(s.clone()),
            _ => None,
        }
    }

    fn flag(&self, name: &str) -> bool {
        matches!(self.given.get(name), Some((Value::Bool(true), _)))
    }

    fn material(&mut self, suffix: &str, base: &Material) -> Material {
        let g = |q: Q| format!("{}{suffix}", q.name());
        let mut m = base.clone();
        m.ambient = self.colour(&g(Q::MatAmbient), 0, 1, base.ambient);
        m.diffuse = self.colour(&g(Q::MatDiffuse), 0, 1, base.diffuse);
        m.specular = self.colour(&g(Q::MatSpecular), 0, 1, base.specular);
        m.shininess = self.number(&g(Q::Shininess), 0, 1, base.shininess);
        if self.given.contains_key(&g(Q::MatEmission)) {
            m.emission = self.colour(&g(Q::MatEmission), 0, 1, base.emission);
        }
        m.diffuse.w = self.number(&g(Q::MatAlpha), 0, 1, 1.0);
        m
    }

    fn document(&mut self, name: &str, local_viewer: bool) -> Document {
        let ws = crate::model::presets::worksheet(5);
        let mview = match self.given.get(Q::Modelview.name()).cloned() {
            Some((v, place)) => self.matrix(&v, Q::Modelview.name(), &place).unwrap_or(ws.eye_from_world),
            None => {
                self.missing(Q::Modelview.name(), "mview5".into());
                ws.eye_from_world
            }
        };
        let mut rules = match self.string("rules").as_deref() {
            Some("opengl") => Rules::OPENGL,
            Some("phong-demo") => Rules::PHONG_DEMO,
            _ => Rules::WORKSHEET,
        };
        if let Some(model) = self.string("specular").as_deref().and_then(SpecularModel::from_name) {
            rules.specular = model;
        }
        let normal_mode = match self.string("normalMode").as_deref() {
            Some("as-is") => NormalMode::AsIs,
            Some("rescale") => NormalMode::Rescale,
            _ => NormalMode::Normalize,
        };
        let n = self.light_count();
        let ws_light = &ws.lights[0];
        let mut lights = Vec::new();
        for i in 0..n {
            let mut l = Light {
                position: self.vec4(Q::LightPos.name(), i, n, ws_light.position),
                ambient: self.colour(Q::LightAmbient.name(), i, n, ws_light.ambient),
                diffuse: self.colour(Q::LightDiffuse.name(), i, n, ws_light.diffuse),
                specular: self.colour(Q::LightSpecular.name(), i, n, ws_light.specular),
                attenuation: [
                    self.number(Q::AttConstant.name(), i, n, ws_light.attenuation[0]),
                    self.number(Q::AttLinear.name(), i, n, ws_light.attenuation[1]),
                    self.number(Q::AttQuadratic.name(), i, n, ws_light.attenuation[2]),
                ],
                placement: LightPlacement::World,
                ..Light::gl_default(i)
            };
            if self.given.contains_key(Q::SpotCutoff.name()) {
                l.spot_cutoff = self.number(Q::SpotCutoff.name(), i, n, 180.0);
                l.spot_exponent = self.number(Q::SpotExponent.name(), i, n, 0.0);
                let d = self.vec4(Q::SpotDirection.name(), i, n, DVec4::new(0.0, 0.0, -1.0, 0.0));
                l.spot_direction = DVec3::new(d.x, d.y, d.z);
            }
            if let Some((v, place)) = self.per_light(Q::LightModelview.name(), i, n)
                && let Some(m) = self.matrix(&v, Q::LightModelview.name(), &place)
            {
                l.placement = if m == mview {
                    LightPlacement::World
                } else if m == DMat4::IDENTITY {
                    LightPlacement::Eye
                } else {
                    LightPlacement::Matrix(m)
                };
            }
            lights.push(l);
        }
        let material = self.material("", &ws.material);
        let has_back = [Q::MatAmbient, Q::MatDiffuse, Q::MatSpecular, Q::Shininess]
            .iter()
            .any(|q| self.given.contains_key(&q.back_name()));
        let back_material = has_back.then(|| self.material("Back", &material));
        let mut light_model = crate::model::scene::LightModel { local_viewer, ..Default::default() };
        light_model.two_sided = self.flag("twoSided");
        light_model.separate_specular = self.flag("separateSpecular");
        if self.given.contains_key(Q::SceneAmbient.name()) {
            light_model.ambient = self.colour(Q::SceneAmbient.name(), 0, 1, light_model.ambient);
        }
        let pos = self.vec4(Q::VertexPos.name(), 0, 1, ws.vertex.position);
        let normal = self.vec4(Q::VertexNormal.name(), 0, 1, ws.vertex.normal.extend(0.0));
        let scene = Scene {
            light_model,
            lights,
            material,
            back_material,
            color_material: None,
            eye_from_world: mview,
            world_from_object: DMat4::IDENTITY,
            normal_mode,
            rules,
            vertex: Vertex { position: pos, normal: DVec3::new(normal.x, normal.y, normal.z) },
        };
        let camera = (1..=5u8)
            .find(|&k| crate::model::transform::worksheet_modelview(k as usize) == Some(mview))
            .map_or(CameraSpec::Matrix(mview), CameraSpec::Worksheet);
        let mut doc = Document::from_scene(name, camera, scene);
        doc.view = Document::default().view;
        doc
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn script(text: &str) -> Result<Imported, ImportError> {
        read(text, false, "t")
    }

    /// The light's z in the scene read from `text`.
    fn light_z(text: &str) -> f64 {
        script(text).unwrap().doc.scene.lights[0].position.z
    }

    /// Python reads names in their NFKC form and ignores text in triple-quoted strings:
    /// the reader reads as Python runs (a hostile classmate's full-width `ｌｉｇｈｔＰｏｓ`
    /// and a `"""`-quoted given passed wrong work as right).
    #[test]
    fn names_are_read_as_python_reads_them_and_strings_are_not_code() {
        let base = "vertexPos = np.array([-512, -384, 0, 1])\nlightPos = np.array([0, 0, 90, 1])\n";
        assert_eq!(light_z(base), 90.0);
        assert_eq!(light_z(&format!("{base}ｌｉｇｈｔＰｏｓ = np.array([0, 0, 5, 1])\n")), 5.0);
        for quote in ["\"\"\"", "'''"] {
            let hidden = format!("{base}{quote}\nlightPos = np.array([0, 0, 7, 1])\n{quote}\n");
            assert_eq!(light_z(&hidden), 90.0, "{quote}");
            let after = format!("{base}x = {quote}a # b ' c{quote}\nlightPos = np.array([0, 0, 8, 1])\n");
            assert_eq!(light_z(&after), 8.0, "a closed one-line {quote} string");
        }
        let f_string = format!("{base}s = f\"\"\"\nlightPos = np.array([0, 0, 9, 1])\n\"\"\"\n");
        assert_eq!(light_z(&f_string), 90.0);
        let in_comment = format!("{base}# \"\"\" not a string\nlightPos = np.array([0, 0, 6, 1])\n");
        assert_eq!(light_z(&in_comment), 6.0);
    }

    /// A given changed in place is not followed: it is named, with its place, for `check`
    /// to refuse rather than check a value Python never used.
    #[test]
    fn a_given_changed_in_place_is_named() {
        let base = "vertexPos = np.array([-512, -384, 0, 1])\nlightPos = np.array([0, 0, 45, 1])\n";
        for change in
            ["lightPos[2] *= 2", "lightPos[2] = 90", "lightPos += np.array([0, 0, 45, 0])", "lightPos @= mview"]
        {
            let r = script(&format!("{base}{change}\n")).unwrap();
            assert_eq!(r.not_followed.len(), 1, "{change}");
            assert!(r.not_followed[0].starts_with("lightPos ("), "{:?}", r.not_followed);
        }
        for fine in ["lightPos = lightPos*2", "x = lightPos[2]", "vlv[0] = 1", "lightPos == 2", "    lightPos[2] = 1"] {
            assert!(script(&format!("{base}{fine}\n")).unwrap().not_followed.is_empty(), "{fine}");
        }
    }

    #[test]
    fn deep_nesting_is_refused_naming_its_line_not_overflowing_the_stack() {
        for deep in [
            format!("lightPos = {}1{}", "[".repeat(10_000), "]".repeat(10_000)),
            format!("lightPos = {}1", "-".repeat(50_000)),
            format!("lightPos = {}1{}", "np.array(".repeat(5_000), ")".repeat(5_000)),
            format!("x = 2{}", "**2".repeat(30_000)),
        ] {
            let text = format!("vertexPos = np.array([0, 0, 0, 1])\n{deep}\n");
            let e = script(&text).unwrap_err().to_string();
            assert!(e.starts_with("line 2: `") && e.contains("nests more than 32 deep"), "{e}");
        }
        // Within the limit, nesting reads as before.
        let ok = script(&format!("lightPos = {}[0, 0, 90, 1]{}\n", "(".repeat(20), ")".repeat(20))).unwrap();
        assert_eq!(ok.doc.scene.lights[0].position, DVec4::new(0.0, 0.0, 90.0, 1.0));
    }

    #[test]
    fn a_statement_of_too_many_tokens_is_refused_before_its_tree_is_built() {
        // `1+1+…`, `----…1` and `1**1**…` past the cap: refused while tokenizing (the work
        // and memory bounded by MAX_TOKENS, not by the line's megabytes), naming the line.
        let long = [
            format!("x = {}1", "1+".repeat(MAX_TOKENS)),
            format!("x = {}1", "-".repeat(2 * MAX_TOKENS)),
            format!("x = {}1", "1**".repeat(MAX_TOKENS)),
        ];
        for line in long {
            let e = script(&format!("vertexPos = [1, 2, 3, 1]\n{line}\n")).unwrap_err().to_string();
            assert!(e.starts_with("line 2: ") && e.contains("tokens"), "{}", &e[..e.len().min(300)]);
        }
        // A value of the most numbers, signed, is within it.
        let most = vec!["-0.5"; MAX_ELEMENTS - 1].join(", ");
        assert!(script(&format!("vertexPos = [1, 2, 3, 1]\nx = [{most}]\n")).is_ok());
    }

    #[test]
    fn exponential_growth_is_refused_at_the_line_that_passes_the_limit() {
        let mut text = String::from("a0 = [1, 2, 3, 4]\n");
        for i in 1..=15 {
            text.push_str(&format!("a{i} = [a{0}, a{0}, a{0}, a{0}]\n", i - 1));
        }
        text.push_str("lightPos = np.array(a15)\n");
        let e = script(&text).unwrap_err().to_string();
        // a6 holds 4^7 numbers and 1 + 4 + ... + 4^6 lists: the first past 10 000.
        assert!(e.starts_with("line 7: `a6 = [a5, a5, a5, a5]` holds more than 10 000"), "{e}");
        // Strings: a 100 kB string repeated grows past 1 MiB of bytes.
        let big = "x".repeat(100_000);
        let mut text = format!("s0 = '{big}'\n");
        for i in 1..=4 {
            text.push_str(&format!("s{i} = [s{0}, s{0}, s{0}, s{0}]\n", i - 1));
        }
        let e = script(&text).unwrap_err().to_string();
        assert!(e.starts_with("line 3: ") && e.contains("bytes of strings"), "{e}");
        // Many lines, each small, past the total.
        let mut text = String::from("a = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\nb = [a, a, a, a, a, a, a, a, a, a]\n");
        for i in 0..20_000 {
            text.push_str(&format!("c{i} = [b, b, b, b]\n"));
        }
        let e = script(&text).unwrap_err().to_string();
        assert!(e.contains("past what phonglab reads"), "{e}");
    }

    #[test]
    fn nan_and_infinity_as_numpy_math_and_float_write_them_are_refused_naming_the_given() {
        let text = "lightPos = np.array([0, 0, np.nan, 1])\nmatDif = float('nan')\nvertexPos = np.array([math.inf, 0, 0, 1])\nmatAmb = np.array([float(\"0.25\"), 0, 0, 1])\n";
        let r = script(text).unwrap();
        let notices = r.notices.join("\n");
        assert!(notices.contains("line 1: lightPos is NaN, not a finite number"), "{notices}");
        assert!(notices.contains("line 2: matDif is NaN, not a finite number"), "{notices}");
        assert!(notices.contains("line 3: vertexPos is Infinity, not a finite number"), "{notices}");
        assert_eq!(r.doc.scene.material.ambient.x, 0.25, "float(\"0.25\") is the number");
    }

    #[test]
    fn a_given_that_is_not_finite_is_refused_naming_it() {
        let text = "vertexPos = np.array([1e999, 0, 0, 1])\nlightPos = np.array([0/0, 0, 90, 1])\nmatDif = np.array([0.5, 0.5, 0.5, 1])\nns = -1e999\n";
        let r = script(text).unwrap();
        let notices = r.notices.join("\n");
        assert!(notices.contains("line 1: vertexPos is Infinity, not a finite number"), "{notices}");
        assert!(notices.contains("line 2: lightPos is NaN, not a finite number"), "{notices}");
        assert!(notices.contains("line 4: ns is -Infinity"), "{notices}");
        assert!(!notices.contains("vertexPos is not assigned"), "reported once: {notices}");
        let s = &r.doc.scene;
        assert_eq!(s.vertex.position, DVec4::new(-512.0, -384.0, 0.0, 1.0), "the worksheet's vertex");
        assert_eq!(s.lights[0].position, DVec4::new(0.0, 0.0, 90.0, 1.0), "the worksheet's light");
        assert_eq!(s.material.diffuse.x, 0.5, "the finite givens are read");
        assert!(!r.doc.to_toml().unwrap().contains("inf") && !r.doc.to_toml().unwrap().contains("nan"));
    }
}
