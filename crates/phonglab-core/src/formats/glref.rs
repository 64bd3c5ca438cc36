//! The glref case schema (docs/lighting.md): JSON cases in, lit colours out.
//!
//! A file is a list of cases or `{"cases": [...]}`. Every field is optional and takes
//! OpenGL's default; colours are rgb or rgba; numbers may be strings ("NaN", "Infinity",
//! "1e18"). A case that does not fit the schema is an error of that case alone.
//!
//! The reader is strict, so that a typo cannot change a result in silence: an unknown key
//! is refused with the closest known name (`constant_atenuation` -> did you mean
//! `constant_attenuation`?), an `id` must be a string and unique, and an empty case `{}`
//! is refused. The harness's own record of a result (`result`) is read for its four
//! colours and otherwise left as the harness wrote it.

use glam::{DMat4, DVec3, DVec4};
use serde_json::{Map, Value, json};
use thiserror::Error;

use crate::equation::lighting::{Engine, EvalOptions};
use crate::model::rules::Rules;
use crate::model::scene::{
    ColorMaterial, ColorMaterialMode, Face, Light, LightModel, LightPlacement, MAX_LIGHTS, Material, NormalMode, Scene,
    Vertex,
};
use crate::model::transform::mat4_from_rows;
use crate::numerics::real::Real;
use crate::numerics::strict;

/// The file as a whole could not be read as cases.
#[derive(Debug, Error)]
pub enum FileError {
    /// Not JSON.
    #[error("not valid JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// JSON, but neither a list nor an object with a "cases" list.
    #[error("expected a list of cases or an object {{\"cases\": [...]}}, found {0}")]
    Shape(&'static str),
}

/// One case did not fit the schema.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{field}: {message}")]
pub struct CaseError {
    /// The offending field, e.g. `lights[1].position`.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

fn err(field: &str, message: impl Into<String>) -> CaseError {
    CaseError { field: field.to_string(), message: message.into() }
}

/// A colour result as the harness writes it: rgba.
pub type Rgba4 = [f64; 4];

/// The lit colours of one case (Mesa's, embedded in generated files, or ours).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaseColors {
    /// Primary colour of a front-facing primitive.
    pub front: Rgba4,
    /// Secondary colour, front.
    pub front_secondary: Rgba4,
    /// Primary colour of a back-facing primitive.
    pub back: Rgba4,
    /// Secondary colour, back.
    pub back_secondary: Rgba4,
}

/// One parsed case.
#[derive(Clone, Debug)]
pub struct Case {
    /// The case's `id` (or `case<index>` when it has none).
    pub id: String,
    /// The scene, with the case's vertex as the scene's vertex.
    pub scene: Scene,
    /// Mesa's result when the file embeds one.
    pub expected: Option<CaseColors>,
    /// The case's tags (generated files).
    pub tags: Vec<String>,
}

/// Splits a file into its raw case objects.
pub fn raw_cases(text: &str) -> Result<Vec<Value>, FileError> {
    let v: Value = serde_json::from_str(text)?;
    match v {
        Value::Array(a) => Ok(a),
        Value::Object(mut o) => match o.remove("cases") {
            Some(Value::Array(a)) => Ok(a),
            Some(_) => Err(FileError::Shape("\"cases\" that is not a list")),
            None => Err(FileError::Shape("an object without \"cases\"")),
        },
        Value::Null => Err(FileError::Shape("null")),
        Value::Bool(_) => Err(FileError::Shape("a boolean")),
        Value::Number(_) => Err(FileError::Shape("a number")),
        Value::String(_) => Err(FileError::Shape("a string")),
    }
}

/// Each case's id with the case, or why it does not fit the schema.
pub type ParsedCases = Vec<(String, Result<Case, CaseError>)>;

/// Parses a file: `Err` when the file is not a case file; otherwise one result per case.
/// A case whose id an earlier case already has is an error of its own.
pub fn parse_cases(text: &str) -> Result<ParsedCases, FileError> {
    let mut ids = CaseIds::default();
    Ok(raw_cases(text)?.iter().enumerate().map(|(i, raw)| ids.parse(raw, i)).collect())
}

/// The ids seen so far in a file, so that a repeated one is refused: the only thing a
/// reader keeps from case to case.
#[derive(Default)]
struct CaseIds {
    seen: std::collections::HashSet<String>,
}

impl CaseIds {
    /// The `i`-th case's id (as written, for the result) and the case or why not.
    fn parse(&mut self, raw: &Value, i: usize) -> (String, Result<Case, CaseError>) {
        let id = match raw.get("id") {
            Some(Value::String(s)) => s.clone(),
            Some(other) => strict::shortened(&other.to_string(), 40),
            None => format!("case{i}"),
        };
        let parsed = parse_case(raw, i).and_then(|c| {
            if self.seen.insert(c.id.clone()) {
                Ok(c)
            } else {
                Err(err("id", format!("{:?} is the id of an earlier case; ids must be unique", c.id)))
            }
        });
        (id, parsed)
    }
}

/// Reads a case file from `reader` as a stream, one case at a time: `each` is called with
/// every case's id and the case (or why it does not fit the schema), in order, and only
/// one case is in memory at once, so a file of any number of cases takes the memory of
/// one case (and of the ids, to refuse a repeated one). Returns the number of cases.
///
/// `each` has run for the cases before the place where a file that is not JSON breaks;
/// a caller that must not act on part of a file reads it once with [`count_cases`] first.
pub fn for_each_case<R: std::io::Read>(
    reader: R,
    each: impl FnMut(String, Result<Case, CaseError>),
) -> Result<usize, FileError> {
    let mut ids = CaseIds::default();
    let mut each = each;
    stream::cases(std::io::BufReader::with_capacity(1 << 16, reader), &mut |raw: Value, i: usize| {
        let (id, parsed) = ids.parse(&raw, i);
        each(id, parsed);
    })
}

/// Checks that `reader` holds a case file (JSON, a list or `{"cases": [...]}`) and counts
/// its cases, one at a time, without keeping any (nor building any: each is read past).
pub fn count_cases<R: std::io::Read>(reader: R) -> Result<usize, FileError> {
    measure_cases(reader).map(|(n, _)| n)
}

/// [`count_cases`], and the bytes of the largest case (with the separator before it): what
/// [`for_each_case`] then holds in memory at once is in proportion to it.
pub fn measure_cases<R: std::io::Read>(reader: R) -> Result<(usize, u64), FileError> {
    let read = std::rc::Rc::new(std::cell::Cell::new(0u64));
    let counted = stream::Counted { inner: std::io::BufReader::with_capacity(1 << 16, reader), read: read.clone() };
    let (mut before, mut largest) = (0u64, 0u64);
    let n = stream::cases(counted, &mut |_: stream::Skip, _: usize| {
        largest = largest.max(read.get() - before);
        before = read.get();
    })?;
    Ok((n, largest))
}

mod stream;

/// The keys a case may have.
pub const CASE_KEYS: &[&str] = &[
    "id",
    "tags",
    "note",
    "modelview",
    "light_modelview",
    "vertex",
    "normal",
    "lights",
    "light",
    "material",
    "back_material",
    "color_material",
    "light_model_ambient",
    "local_viewer",
    "two_sided",
    "separate_specular",
    "normalize",
    "rescale_normal",
    "result",
];

/// The keys a light may have.
pub const LIGHT_KEYS: &[&str] = &[
    "position",
    "ambient",
    "diffuse",
    "specular",
    "spot_direction",
    "spot_cutoff",
    "spot_exponent",
    "constant_attenuation",
    "linear_attenuation",
    "quadratic_attenuation",
];

/// The keys a material may have (`name` is a label, not GL state).
pub const MATERIAL_KEYS: &[&str] = &["name", "ambient", "diffuse", "specular", "emission", "shininess"];

/// Refuses a key of `o` that is not one of `known`, suggesting the closest.
fn known_keys(o: &Map<String, Value>, known: &[&str], field: &str) -> Result<(), CaseError> {
    for k in o.keys() {
        if !known.contains(&k.as_str()) {
            let at = if field.is_empty() { k.clone() } else { format!("{field}.{k}") };
            let hint = match strict::closest(k, known.iter().copied()) {
                Some(c) => format!("; did you mean {c:?}?"),
                None => format!("; the keys are {}", known.join(", ")),
            };
            return Err(err(&strict::shortened(&at, 80), format!("unknown key{hint}")));
        }
    }
    Ok(())
}

/// A number, or a string holding one ("NaN", "Infinity", "-Infinity", "1e18").
pub fn number(v: &Value, field: &str) -> Result<f64, CaseError> {
    match v {
        Value::Number(n) => n.as_f64().ok_or_else(|| err(field, "number out of range")),
        Value::String(s) => {
            let t = s.trim();
            match t.to_ascii_lowercase().as_str() {
                "nan" | "+nan" | "-nan" => Ok(f64::NAN),
                "infinity" | "+infinity" | "inf" | "+inf" => Ok(f64::INFINITY),
                "-infinity" | "-inf" => Ok(f64::NEG_INFINITY),
                _ => t.parse().map_err(|_| err(field, format!("{s:?} is not a number"))),
            }
        }
        other => Err(err(field, format!("expected a number, found {other}"))),
    }
}

fn numbers(v: &Value, field: &str, lens: &[usize]) -> Result<Vec<f64>, CaseError> {
    let a = v.as_array().ok_or_else(|| err(field, format!("expected a list, found {v}")))?;
    if !lens.contains(&a.len()) {
        let want: Vec<String> = lens.iter().map(std::string::ToString::to_string).collect();
        return Err(err(field, format!("expected {} numbers, found {}", want.join(" or "), a.len())));
    }
    a.iter().enumerate().map(|(i, x)| number(x, &format!("{field}[{i}]"))).collect()
}

fn rgba(v: &Value, field: &str) -> Result<DVec4, CaseError> {
    let n = numbers(v, field, &[3, 4])?;
    Ok(DVec4::new(n[0], n[1], n[2], n.get(3).copied().unwrap_or(1.0)))
}

fn vec3(v: &Value, field: &str) -> Result<DVec3, CaseError> {
    let n = numbers(v, field, &[3])?;
    Ok(DVec3::new(n[0], n[1], n[2]))
}

fn point(v: &Value, field: &str) -> Result<DVec4, CaseError> {
    let n = numbers(v, field, &[3, 4])?;
    Ok(DVec4::new(n[0], n[1], n[2], n.get(3).copied().unwrap_or(1.0)))
}

fn mat4(v: &Value, field: &str) -> Result<DMat4, CaseError> {
    let rows = v.as_array().ok_or_else(|| err(field, "expected 4 rows of 4 numbers"))?;
    if rows.len() != 4 {
        return Err(err(field, format!("expected 4 rows, found {}", rows.len())));
    }
    let mut m = [[0.0; 4]; 4];
    for (i, r) in rows.iter().enumerate() {
        let n = numbers(r, &format!("{field}[{i}]"), &[4])?;
        m[i].copy_from_slice(&n);
    }
    Ok(mat4_from_rows(m))
}

fn boolean(v: &Value, field: &str) -> Result<bool, CaseError> {
    match v {
        Value::Bool(b) => Ok(*b),
        Value::Number(n) if n.as_f64() == Some(0.0) => Ok(false),
        Value::Number(n) if n.as_f64() == Some(1.0) => Ok(true),
        other => Err(err(field, format!("expected true or false, found {other}"))),
    }
}

fn object<'a>(v: &'a Value, field: &str) -> Result<&'a Map<String, Value>, CaseError> {
    v.as_object().ok_or_else(|| err(field, format!("expected an object, found {v}")))
}

/// `{"face": "GL_FRONT_AND_BACK", "mode": "GL_AMBIENT_AND_DIFFUSE", "color": [r, g, b, a]}`:
/// `glColorMaterial(face, mode)`, `glEnable(GL_COLOR_MATERIAL)` and `glColor4f(color)`
/// (each key optional: OpenGL's initial face and mode, white).
fn color_material(v: &Value, field: &str) -> Result<ColorMaterial, CaseError> {
    let o = object(v, field)?;
    known_keys(o, &["face", "mode", "color"], field)?;
    let mut cm = ColorMaterial::default();
    for (k, x) in o {
        let f = format!("{field}.{k}");
        let name = || x.as_str().ok_or_else(|| err(&f, format!("expected a GL enum name, found {x}")));
        match k.as_str() {
            "face" => {
                let n = name()?;
                cm.face = [Face::Front, Face::Back, Face::FrontAndBack]
                    .into_iter()
                    .find(|c| c.gl() == n)
                    .ok_or_else(|| err(&f, format!("{n}: GL_FRONT, GL_BACK or GL_FRONT_AND_BACK")))?;
            }
            "mode" => {
                let n = name()?;
                cm.mode = ColorMaterialMode::ALL
                    .into_iter()
                    .find(|c| c.gl() == n)
                    .ok_or_else(|| err(&f, format!("{n}: not a glColorMaterial mode")))?;
            }
            _ => cm.color = rgba(x, &f)?,
        }
    }
    Ok(cm)
}

fn material(v: &Value, field: &str) -> Result<Material, CaseError> {
    let o = object(v, field)?;
    known_keys(o, MATERIAL_KEYS, field)?;
    let mut m = Material::default();
    for (k, x) in o {
        let f = format!("{field}.{k}");
        match k.as_str() {
            "ambient" => m.ambient = rgba(x, &f)?,
            "diffuse" => m.diffuse = rgba(x, &f)?,
            "specular" => m.specular = rgba(x, &f)?,
            "emission" => m.emission = rgba(x, &f)?,
            "shininess" => m.shininess = number(x, &f)?,
            _ => {} // "name", a label
        }
    }
    Ok(m)
}

fn light(v: &Value, index: usize, placement: &LightPlacement) -> Result<Light, CaseError> {
    let field = format!("lights[{index}]");
    let o = object(v, &field)?;
    known_keys(o, LIGHT_KEYS, &field)?;
    let mut l = Light { placement: placement.clone(), ..Light::gl_default(index) };
    for (k, x) in o {
        let f = format!("{field}.{k}");
        match k.as_str() {
            "ambient" => l.ambient = rgba(x, &f)?,
            "diffuse" => l.diffuse = rgba(x, &f)?,
            "specular" => l.specular = rgba(x, &f)?,
            "position" => l.position = point(x, &f)?,
            "spot_direction" => l.spot_direction = vec3(x, &f)?,
            "spot_cutoff" => l.spot_cutoff = number(x, &f)?,
            "spot_exponent" => l.spot_exponent = number(x, &f)?,
            "constant_attenuation" => l.attenuation[0] = number(x, &f)?,
            "linear_attenuation" => l.attenuation[1] = number(x, &f)?,
            "quadratic_attenuation" => l.attenuation[2] = number(x, &f)?,
            _ => {} // refused above
        }
    }
    Ok(l)
}

/// Parses one case object (`index` names it when it has no id).
pub fn parse_case(raw: &Value, index: usize) -> Result<Case, CaseError> {
    let o = object(raw, &format!("cases[{index}]"))?;
    if o.is_empty() {
        return Err(err(
            &format!("cases[{index}]"),
            "an empty case: every value would be OpenGL's default; give at least an id and a vertex or a light",
        ));
    }
    known_keys(o, CASE_KEYS, "")?;
    let get = |k: &str| o.get(k).filter(|v| !v.is_null());
    let id = match get("id") {
        None => format!("case{index}"),
        Some(Value::String(s)) if !s.is_empty() => s.clone(),
        Some(other) => {
            return Err(err(
                "id",
                format!("an id is a non-empty string, not {}", strict::shortened(&other.to_string(), 40)),
            ));
        }
    };
    if get("lights").is_some() && get("light").is_some() {
        return Err(err("light", "give either \"lights\" (a list) or \"light\" (one), not both"));
    }
    let modelview = get("modelview").map(|v| mat4(v, "modelview")).transpose()?.unwrap_or(DMat4::IDENTITY);
    let placement = match get("light_modelview") {
        Some(v) => LightPlacement::Matrix(mat4(v, "light_modelview")?),
        None => LightPlacement::Object,
    };
    let lights_raw: Vec<&Value> = match (get("lights"), get("light")) {
        (Some(v), _) => v.as_array().ok_or_else(|| err("lights", "expected a list"))?.iter().collect(),
        (None, Some(v)) => vec![v],
        (None, None) => Vec::new(),
    };
    if lights_raw.len() > MAX_LIGHTS {
        return Err(err("lights", format!("{} lights: OpenGL has at most {MAX_LIGHTS}", lights_raw.len())));
    }
    let lights = lights_raw.iter().enumerate().map(|(i, v)| light(v, i, &placement)).collect::<Result<Vec<_>, _>>()?;
    let flag = |k: &str| get(k).map(|v| boolean(v, k)).transpose().map(|b| b.unwrap_or(false));
    let normal_mode = if flag("normalize")? {
        NormalMode::Normalize
    } else if flag("rescale_normal")? {
        NormalMode::Rescale
    } else {
        NormalMode::AsIs
    };
    let scene = Scene {
        light_model: LightModel {
            ambient: get("light_model_ambient")
                .map(|v| rgba(v, "light_model_ambient"))
                .transpose()?
                .unwrap_or(LightModel::default().ambient),
            local_viewer: flag("local_viewer")?,
            two_sided: flag("two_sided")?,
            separate_specular: flag("separate_specular")?,
        },
        lights,
        material: get("material").map(|v| material(v, "material")).transpose()?.unwrap_or_default(),
        back_material: get("back_material").map(|v| material(v, "back_material")).transpose()?,
        color_material: get("color_material").map(|v| color_material(v, "color_material")).transpose()?,
        eye_from_world: modelview,
        world_from_object: DMat4::IDENTITY,
        normal_mode,
        rules: Rules::OPENGL,
        vertex: Vertex {
            position: get("vertex").map(|v| point(v, "vertex")).transpose()?.unwrap_or(DVec4::W),
            normal: get("normal").map(|v| vec3(v, "normal")).transpose()?.unwrap_or(DVec3::Z),
        },
    };
    let expected = get("result").map(expected_colors).transpose()?;
    let tags = get("tags")
        .and_then(Value::as_array)
        .map(|a| a.iter().filter_map(Value::as_str).map(str::to_string).collect())
        .unwrap_or_default();
    Ok(Case { id, scene, expected, tags })
}

fn expected_colors(v: &Value) -> Result<CaseColors, CaseError> {
    let c = |k: &str| -> Result<Rgba4, CaseError> {
        let x = v.get(k).ok_or_else(|| err(&format!("result.{k}"), "missing"))?;
        let n = numbers(x, &format!("result.{k}"), &[4])?;
        Ok([n[0], n[1], n[2], n[3]])
    };
    Ok(CaseColors {
        front: c("front")?,
        front_secondary: c("front_secondary")?,
        back: c("back")?,
        back_secondary: c("back_secondary")?,
    })
}

/// Evaluates a scene's vertex in precision `S` into the four result colours.
/// `Err` carries the message of a parameter OpenGL refuses.
pub fn evaluate<S: Real>(
    scene: &Scene,
    options: EvalOptions,
    clamp: bool,
) -> Result<CaseColors, crate::model::error::SceneError> {
    let lit = Engine::<S>::with_options(scene, options)?.light(&scene.vertex);
    let pick = |c: &crate::equation::breakdown::SideColor<S>| {
        let (p, s) = if clamp { (c.primary_clamped(), c.secondary_clamped()) } else { (c.primary, c.secondary) };
        (p.map(S::to_f64), s.map(S::to_f64))
    };
    let (front, front_secondary) = pick(&lit.front);
    let (back, back_secondary) = pick(&lit.back);
    Ok(CaseColors { front, front_secondary, back, back_secondary })
}

/// A number as JSON, with non-finite values as the strings "NaN", "Infinity", "-Infinity".
pub fn json_number(x: f64) -> Value {
    if x.is_nan() {
        json!("NaN")
    } else if x == f64::INFINITY {
        json!("Infinity")
    } else if x == f64::NEG_INFINITY {
        json!("-Infinity")
    } else {
        json!(x)
    }
}

/// One result object: `{"id", "front", "front_secondary", "back", "back_secondary", "error"}`,
/// colours `null` when `error` is set.
pub fn result_json(id: &str, r: &Result<CaseColors, String>) -> Value {
    let arr = |c: &Rgba4| Value::Array(c.iter().map(|x| json_number(*x)).collect());
    match r {
        Ok(c) => json!({
            "id": id,
            "front": arr(&c.front),
            "front_secondary": arr(&c.front_secondary),
            "back": arr(&c.back),
            "back_secondary": arr(&c.back_secondary),
            "error": Value::Null,
        }),
        Err(e) => json!({
            "id": id, "front": null, "front_secondary": null, "back": null, "back_secondary": null, "error": e,
        }),
    }
}

/// A scene as one glref case (the inverse of [`parse_case`] for what OpenGL can express),
/// so any scene can be checked against a real OpenGL with the harness. The schema has one
/// `light_modelview` for all lights, so each light is written already in eye space (its
/// position by the modelview current when it was placed, its spot direction by that
/// matrix's upper 3x3, as `glLight` does) under the identity. The rule set and the
/// specular model are not GL state: a case always means OpenGL's rules.
pub fn case_json(id: &str, scene: &Scene) -> Value {
    let rows = |m: &DMat4| Value::Array(crate::model::transform::mat4_rows(m).iter().map(|r| nums(r)).collect());
    let v4 = |v: DVec4| nums(&v.to_array());
    let v3 = |v: DVec3| nums(&v.to_array());
    let material = |m: &Material| {
        json!({
            "ambient": v4(m.ambient), "diffuse": v4(m.diffuse), "specular": v4(m.specular),
            "emission": v4(m.emission), "shininess": json_number(m.shininess),
        })
    };
    let lights: Vec<Value> = scene
        .lights
        .iter()
        .map(|l| {
            let m = scene.eye_from_light(l);
            json!({
                "position": v4(m * l.position),
                "ambient": v4(l.ambient),
                "diffuse": v4(l.diffuse),
                "specular": v4(l.specular),
                "spot_direction": v3(glam::DMat3::from_mat4(m) * l.spot_direction),
                "spot_cutoff": json_number(l.spot_cutoff),
                "spot_exponent": json_number(l.spot_exponent),
                "constant_attenuation": json_number(l.attenuation[0]),
                "linear_attenuation": json_number(l.attenuation[1]),
                "quadratic_attenuation": json_number(l.attenuation[2]),
            })
        })
        .collect();
    let mut case = json!({
        "id": id,
        "modelview": rows(&scene.eye_from_object()),
        "light_modelview": rows(&DMat4::IDENTITY),
        "vertex": v4(scene.vertex.position),
        "normal": v3(scene.vertex.normal),
        "lights": lights,
        "material": material(&scene.material),
        "light_model_ambient": v4(scene.light_model.ambient),
        "local_viewer": scene.light_model.local_viewer,
        "two_sided": scene.light_model.two_sided,
        "separate_specular": scene.light_model.separate_specular,
        "normalize": scene.normal_mode == NormalMode::Normalize,
        "rescale_normal": scene.normal_mode == NormalMode::Rescale,
    });
    if let (Some(b), Value::Object(o)) = (&scene.back_material, &mut case) {
        o.insert("back_material".into(), material(b));
    }
    if let (Some(cm), Value::Object(o)) = (&scene.color_material, &mut case) {
        o.insert("color_material".into(), json!({"face": cm.face.gl(), "mode": cm.mode.gl(), "color": v4(cm.color)}));
    }
    case
}

fn nums(v: &[f64]) -> Value {
    Value::Array(v.iter().map(|x| json_number(*x)).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first pass reads past each case without building it, but refuses what the
    /// second would (nesting past 128), so a broken file prints nothing; and it measures
    /// the largest case.
    #[test]
    fn the_first_pass_measures_the_largest_case_and_refuses_what_the_second_would() {
        let nested = |depth: usize| format!("{{\"id\":\"b\",\"tags\":{}0{}}}", "[".repeat(depth), "]".repeat(depth));
        let deep = format!("[{{\"id\":\"a\"}},{}]", nested(200));
        assert!(count_cases(deep.as_bytes()).is_err());
        let mut seen = 0;
        assert!(for_each_case(deep.as_bytes(), |_, _| seen += 1).is_err() && seen == 1, "as the second pass does");
        let fine = format!("[{{\"id\":\"a\"}}, {}]", nested(100));
        let (n, largest) = measure_cases(fine.as_bytes()).unwrap();
        assert_eq!(n, 2);
        let size = nested(100).len() as u64;
        assert!((size..size + 4).contains(&largest), "{largest} for a case of {size} bytes");
    }

    #[test]
    fn a_scene_written_as_a_case_lights_the_same() {
        // Lights placed in the eye, the world and the object, one a spotlight, two-sided
        // with a back material, under a modelview that is not a rigid motion.
        let mut s = crate::model::presets::LightingBench::EightSpots.scene();
        s.lights.truncate(3);
        s.lights[1].placement = LightPlacement::Eye;
        s.lights[2].placement = LightPlacement::Object;
        s.world_from_object = DMat4::from_scale(DVec3::new(1.0, 2.0, 0.5)) * DMat4::from_rotation_z(0.3);
        s.light_model.two_sided = true;
        s.back_material = Some(crate::model::materials::by_name("jade").unwrap().clone());
        s.vertex = Vertex { position: DVec4::new(0.3, 0.2, 0.9, 1.0), normal: DVec3::new(0.2, 0.3, 0.9) };
        let back = parse_case(&case_json("x", &s), 0).unwrap();
        let (a, b) = (
            evaluate::<f64>(&s, EvalOptions::default(), false).unwrap(),
            evaluate::<f64>(&back.scene, EvalOptions::default(), false).unwrap(),
        );
        for (x, y) in [(a.front, b.front), (a.back, b.back), (a.front_secondary, b.front_secondary)] {
            for k in 0..4 {
                assert!((x[k] - y[k]).abs() < 1e-12, "{x:?} vs {y:?}");
            }
        }
        assert!(a.front[0] > 0.05 && a.back[1] > 0.0, "lit: {a:?}");
    }

    #[test]
    fn defaults_are_opengl_defaults() {
        let c = parse_case(&json!({"lights": [{}, {}]}), 0).unwrap();
        assert_eq!(c.id, "case0");
        assert_eq!(c.scene.lights[0].diffuse, DVec4::ONE);
        assert_eq!(c.scene.lights[1].diffuse, DVec4::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(c.scene.material, Material::default());
        assert_eq!(c.scene.light_model.ambient, DVec4::new(0.2, 0.2, 0.2, 1.0));
    }

    #[test]
    fn numbers_may_be_strings_and_colours_rgb() {
        let c = parse_case(&json!({"vertex": ["1e18", 0, "-Infinity"], "material": {"diffuse": [1, "NaN", 0]}}), 3)
            .unwrap();
        assert_eq!(c.scene.vertex.position, DVec4::new(1e18, 0.0, f64::NEG_INFINITY, 1.0));
        assert!(c.scene.material.diffuse.y.is_nan());
        assert_eq!(c.scene.material.diffuse.w, 1.0);
    }

    #[test]
    fn schema_errors_name_the_field() {
        let e = parse_case(&json!({"lights": [{"position": [1, 2]}]}), 0).unwrap_err();
        assert_eq!(e.field, "lights[0].position");
        let e = parse_case(&json!({"modelview": [[1, 0, 0, 0]]}), 0).unwrap_err();
        assert_eq!(e.field, "modelview");
        let e = parse_case(&json!({"normal": [0, "x", 1]}), 0).unwrap_err();
        assert_eq!(e.field, "normal[1]");
    }

    #[test]
    fn unknown_keys_are_refused_with_the_closest_name() {
        let e = parse_case(&json!({"id": "a", "lights": [{"constant_atenuation": 2}]}), 0).unwrap_err();
        assert_eq!(e.field, "lights[0].constant_atenuation");
        assert!(e.message.contains("did you mean \"constant_attenuation\""), "{e}");
        let e = parse_case(&json!({"id": "a", "vertx": [0, 0, 0]}), 0).unwrap_err();
        assert!(e.message.contains("\"vertex\""), "{e}");
        let e = parse_case(&json!({"id": "a", "material": {"shine": 3}}), 0).unwrap_err();
        assert_eq!(e.field, "material.shine");
        let e = parse_case(&json!({"id": "a", "zzzzzz": 1}), 0).unwrap_err();
        assert!(e.message.contains("the keys are id, tags"), "{e}");
        assert!(
            parse_case(&json!({"id": "a", "material": {"name": "bronze"}}), 0).is_ok(),
            "a material's name is a label"
        );
    }

    #[test]
    fn ids_are_strings_kept_as_given_and_unique() {
        let e = parse_case(&json!({}), 4).unwrap_err();
        assert_eq!(e.field, "cases[4]");
        let e = parse_case(&json!({"id": 123, "vertex": [0, 0, 0]}), 0).unwrap_err();
        assert!(e.field == "id" && e.message.contains("123"), "{e}");
        let cases = parse_cases(
            r#"[{"id": "x", "vertex": [0,0,0]}, {"id": "y"}, {"id": "x", "normal": [0,1,0]}, {"vertex": [1,1,1]}]"#,
        )
        .unwrap();
        let ids: Vec<&str> = cases.iter().map(|(id, _)| id.as_str()).collect();
        assert_eq!(ids, ["x", "y", "x", "case3"]);
        assert!(cases[0].1.is_ok() && cases[1].1.is_ok() && cases[3].1.is_ok());
        assert!(cases[2].1.as_ref().unwrap_err().message.contains("earlier case"));
        let e = parse_case(&json!({"id": "a", "light": {}, "lights": []}), 0).unwrap_err();
        assert!(e.message.contains("not both"), "{e}");
    }

    #[test]
    fn numbers_parse_exactly() {
        // serde_json's fast path is 1 ulp off here; the cases at 1e6 and 1e18 depend on exact inputs.
        let c = parse_case(&json!({"vertex": [-1.9267785549163818, 0.1, 3.0]}), 0).unwrap();
        assert_eq!(c.scene.vertex.position.x, -1.9267785549163818_f64);
        assert_eq!(c.scene.vertex.position.x as f32 as f64, c.scene.vertex.position.x, "an f32 value");
        assert_eq!(c.scene.vertex.position.y.to_bits(), 0.1f64.to_bits());
    }

    #[test]
    fn file_shapes() {
        assert_eq!(raw_cases("[{}, {}]").unwrap().len(), 2);
        assert_eq!(raw_cases("{\"cases\": [{}], \"meta\": 1}").unwrap().len(), 1);
        assert!(matches!(raw_cases("{\"x\": 1}"), Err(FileError::Shape(_))));
        assert!(matches!(raw_cases("[1,"), Err(FileError::Json(_))));
    }

    #[test]
    fn non_finite_numbers_are_written_as_strings() {
        assert_eq!(json_number(f64::NAN), json!("NaN"));
        assert_eq!(json_number(f64::NEG_INFINITY), json!("-Infinity"));
        assert_eq!(json_number(0.5), json!(0.5));
    }
}
