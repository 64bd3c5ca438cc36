//! phonglab's core for Python: the extension module `phonglab._core` of the package
//! `phonglab` (python/phonglab/ wraps it with NumPy arrays and Jupyter displays).
//!
//! Conversions only: every value is computed by `phonglab_core`, every message is the
//! core's catalogue's, in the language the caller names.

mod check;
mod files;

use glam::{DVec3, DVec4};
use phonglab_core::explain::{Side, explain};
use phonglab_core::locale::{Lang, Locale, with_locale};
use phonglab_core::render::Renderer;
use phonglab_core::{Document, Engine, EvalOptions, Light, Material, PowFn, Real, Scene, library, presets};
use pyo3::create_exception;
use pyo3::exceptions::{PyMemoryError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyBytes;

create_exception!(
    phonglab,
    SceneError,
    PyValueError,
    "A scene, or a value given for one, that phonglab refuses; the message is the command line's."
);

/// The `SceneError` that says `message`, its control characters written visibly (`\u{1B}`,
/// as the command line writes them to the terminal): a scene file's line or a file's name
/// quoted in a message never sends an escape sequence to the notebook or the terminal.
fn scene_error(message: impl ToString) -> PyErr {
    SceneError::new_err(phonglab_core::escape::terminal::lines(&message.to_string()))
}

/// `what=value`: not one of `names` (`what` ends in `=`, as a Python argument): the message every refused name gets.
fn unknown(what: &str, value: &str, names: &str) -> PyErr {
    // A number as Python writes it (`size=0`), a name quoted (`object="cube"`).
    let shown = if value.parse::<f64>().is_ok() { value.to_string() } else { format!("{value:?}") };
    scene_error(phonglab_core::t!("python-unknown-value", what = what, value = shown, names = names))
}

/// The locale of `lang` ("en", "pt-PT", "pt-BR").
fn locale_of(lang: &str) -> PyResult<Locale> {
    Lang::parse(lang).map(Locale::of).ok_or_else(|| unknown("lang=", lang, "en, pt-PT, pt-BR"))
}

/// Sets the language of every message phonglab gives from now on in this process (a
/// refusal's `SceneError`, the worked calculation where no `lang=` is given): "en",
/// "pt-PT" or "pt-BR", the command line's catalogue.
#[pyfunction]
fn set_language(lang: &str) -> PyResult<()> {
    phonglab_core::locale::set_default(locale_of(lang)?);
    Ok(())
}

/// The language messages are given in now ("en", "pt-PT" or "pt-BR").
#[pyfunction]
fn language() -> &'static str {
    phonglab_core::locale::current().lang.code()
}

/// A scene: the document the app holds (lighting state, camera, shaded view).
#[pyclass(name = "Scene", module = "phonglab._core", from_py_object)]
#[derive(Clone)]
pub struct PyScene {
    doc: Document,
}

/// The numbers a field path names: `light.I.FIELD`, `material.FIELD`, `vertex.FIELD`.
enum Field<'a> {
    Light(usize, &'a str),
    Material(&'a str),
    Vertex(&'a str),
}

fn parse_field(path: &str) -> PyResult<Field<'_>> {
    let parts: Vec<&str> = path.split('.').collect();
    match parts.as_slice() {
        ["light", i, f] => i.parse().map(|i| Field::Light(i, f)).map_err(|_| unknown("light=", i, "0, 1, ...")),
        ["material", f] => Ok(Field::Material(f)),
        ["vertex", f] => Ok(Field::Vertex(f)),
        _ => Err(unknown("field=", path, "light.I.FIELD, material.FIELD, vertex.FIELD")),
    }
}

const LIGHT_FIELDS: &str =
    "ambient, diffuse, specular, position, spot_direction, spot_cutoff, spot_exponent, attenuation";
const MATERIAL_FIELDS: &str = "ambient, diffuse, specular, emission, shininess";

fn v4(v: DVec4) -> Vec<f64> {
    v.to_array().to_vec()
}

fn light_get(l: &Light, f: &str) -> PyResult<Vec<f64>> {
    Ok(match f {
        "ambient" => v4(l.ambient),
        "diffuse" => v4(l.diffuse),
        "specular" => v4(l.specular),
        "position" => v4(l.position),
        "spot_direction" => l.spot_direction.to_array().to_vec(),
        "spot_cutoff" => vec![l.spot_cutoff],
        "spot_exponent" => vec![l.spot_exponent],
        "attenuation" => l.attenuation.to_vec(),
        _ => return Err(unknown("light=", f, LIGHT_FIELDS)),
    })
}

fn material_get(m: &Material, f: &str) -> PyResult<Vec<f64>> {
    Ok(match f {
        "ambient" => v4(m.ambient),
        "diffuse" => v4(m.diffuse),
        "specular" => v4(m.specular),
        "emission" => v4(m.emission),
        "shininess" => vec![m.shininess],
        _ => return Err(unknown("material=", f, MATERIAL_FIELDS)),
    })
}

/// `values` as `N` numbers, or the message naming `field`, with what such a field holds
/// where one is often given short: a colour's alpha, a light position's w.
fn exactly<const N: usize>(field: &str, values: &[f64]) -> PyResult<[f64; N]> {
    values.try_into().map_err(|_| wrong_length(field, values.len(), &N.to_string()))
}

/// `field`: `count` numbers given where `expected` are: the message, with a hint by the
/// field's kind (a colour's alpha, a light position's w, a normal's or a vertex's parts).
fn wrong_length(field: &str, count: usize, expected: &str) -> PyErr {
    let part = field.rsplit('.').next().unwrap_or(field);
    let hint = match part {
        "ambient" | "diffuse" | "specular" | "emission" if count == 3 => phonglab_core::t!("python-hint-alpha"),
        "position" if field.starts_with("lights") => phonglab_core::t!("python-hint-w"),
        "normal" | "light(normal=)" => phonglab_core::t!("python-hint-normal"),
        "position" | "light(vertex=)" => phonglab_core::t!("python-hint-vertex"),
        _ => String::new(),
    };
    scene_error(phonglab_core::t!(
        "python-wrong-length",
        field = field,
        count = count,
        expected = expected,
        hint = hint
    ))
}

/// "3 or 4", in the current language: what a vertex position takes.
fn either_3_or_4() -> String {
    phonglab_core::t!("python-either-3-or-4")
}

/// Sets light field `f` to `x`; `name` is the field as Python names it (`lights[0].position`).
fn light_set(l: &mut Light, f: &str, name: &str, x: &[f64]) -> PyResult<()> {
    match f {
        "ambient" => l.ambient = DVec4::from_array(exactly(name, x)?),
        "diffuse" => l.diffuse = DVec4::from_array(exactly(name, x)?),
        "specular" => l.specular = DVec4::from_array(exactly(name, x)?),
        "position" => l.position = DVec4::from_array(exactly(name, x)?),
        "spot_direction" => l.spot_direction = DVec3::from_array(exactly(name, x)?),
        "spot_cutoff" => l.spot_cutoff = exactly::<1>(name, x)?[0],
        "spot_exponent" => l.spot_exponent = exactly::<1>(name, x)?[0],
        "attenuation" => l.attenuation = exactly(name, x)?,
        _ => return Err(unknown("light=", f, LIGHT_FIELDS)),
    }
    Ok(())
}

/// Sets material field `f` to `x`; `name` is the field as Python names it.
fn material_set(m: &mut Material, f: &str, name: &str, x: &[f64]) -> PyResult<()> {
    match f {
        "ambient" => m.ambient = DVec4::from_array(exactly(name, x)?),
        "diffuse" => m.diffuse = DVec4::from_array(exactly(name, x)?),
        "specular" => m.specular = DVec4::from_array(exactly(name, x)?),
        "emission" => m.emission = DVec4::from_array(exactly(name, x)?),
        "shininess" => m.shininess = exactly::<1>(name, x)?[0],
        _ => return Err(unknown("material=", f, MATERIAL_FIELDS)),
    }
    Ok(())
}

fn light_index(scene: &Scene, i: usize) -> PyResult<usize> {
    if i < scene.lights.len() {
        return Ok(i);
    }
    Err(scene_error(phonglab_core::t!("python-no-such-light", light = i, count = scene.lights.len())))
}

#[pymethods]
impl PyScene {
    /// Reads a scene file's text (TOML); `folder` is where a relative mesh path is read from.
    #[staticmethod]
    #[pyo3(signature = (text, folder=None))]
    fn from_toml(text: &str, folder: Option<std::path::PathBuf>) -> PyResult<Self> {
        let cap = phonglab_core::files::read::MAX_SCENE_BYTES;
        let what = phonglab_core::t!("file-kind-scenes");
        phonglab_core::files::read::within_cap("Scene.from_toml(text)", text.len() as u64, cap, &what)
            .map_err(scene_error)?;
        let doc = Document::from_toml_in(text, folder.as_deref()).map_err(scene_error)?;
        Ok(PyScene { doc })
    }

    /// The worksheet's scene with modelview `n` (1 to 5).
    #[staticmethod]
    fn worksheet(n: i64) -> PyResult<Self> {
        if !(1..=5).contains(&n) {
            return Err(unknown("worksheet=", &n.to_string(), "1, 2, 3, 4, 5"));
        }
        let scene = presets::worksheet(n as usize);
        let name = phonglab_core::t!("doc-worksheet", k = n.to_string());
        Ok(PyScene { doc: Document::from_scene(&name, phonglab_core::CameraSpec::Worksheet(n as u8), scene) })
    }

    /// A ready-made scene: "worksheet" (the app's start scene) or "phong-demo".
    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        let doc = match name {
            "worksheet" => Document::default(),
            "phong-demo" => library::phong_demo_document(),
            other => return Err(unknown("preset=", other, "worksheet, phong-demo")),
        };
        Ok(PyScene { doc })
    }

    /// Reads a scene file as the command line does: a regular file of at most 1 MiB,
    /// opened without waiting (a FIFO, a device or a folder refused at once), UTF-8; a
    /// relative mesh path read from the file's folder.
    #[staticmethod]
    fn load(path: std::path::PathBuf) -> PyResult<Self> {
        Ok(PyScene { doc: files::load(&path).map_err(scene_error)? })
    }

    /// Reads the worksheet-style notebook (.ipynb) or script (.py) at `path` as
    /// `phonglab import` does (at most 16 MiB, a regular file; nothing in it is run): (the
    /// scene, named after the file, and notices of lines not read).
    #[staticmethod]
    fn import_file(path: std::path::PathBuf) -> PyResult<(Self, Vec<String>)> {
        let imported = files::import(&path).map_err(scene_error)?;
        // Said as `phonglab import` says them: a control character (an escape sequence, a
        // bell, a direction override) quoted from the file written visibly, `\u{1B}`.
        let notices = imported.notices.iter().map(|n| phonglab_core::escape::terminal::lines(n)).collect();
        Ok((PyScene { doc: imported.doc }, notices))
    }

    /// Writes the scene file at `path` as the app's Save does: whole or not at all (a
    /// temporary file renamed over it, a file replaced keeping its permissions), through a link
    /// to the file it names, refused onto a FIFO, a device, a folder or the scene's mesh.
    /// `code`: the notebook or script the scene was imported from, never written over.
    #[pyo3(signature = (path, code=None))]
    fn save(&self, path: std::path::PathBuf, code: Option<std::path::PathBuf>) -> PyResult<()> {
        files::save(&self.doc, &path, code.as_deref()).map_err(scene_error)
    }

    /// The modelview (object to eye), 16 numbers row by row.
    fn modelview(&self) -> Vec<f64> {
        self.doc.scene.eye_from_object().transpose().to_cols_array().to_vec()
    }

    /// Sets the modelview to the matrix given row by row (16 numbers): the camera becomes
    /// that matrix typed in (the app's Camera → Matrix) and the object's own transform the
    /// identity, so that the modelview is the matrix; checked as the app checks it.
    fn set_modelview(&mut self, rows: Vec<f64>) -> PyResult<()> {
        let rows: [f64; 16] = exactly("modelview", &rows)?;
        let m = glam::DMat4::from_cols_array(&rows).transpose();
        let mut doc = self.doc.clone();
        doc.camera = phonglab_core::CameraSpec::Matrix(m);
        doc.scene.eye_from_world = m;
        doc.scene.world_from_object = glam::DMat4::IDENTITY;
        doc.validate().map_err(scene_error)?;
        self.doc = doc;
        Ok(())
    }

    /// Reads the scene a notebook's text (`notebook` true: .ipynb) or a script's sets up,
    /// as the app's Import does: (the scene, notices of lines not read).
    #[staticmethod]
    fn from_notebook(text: &str, notebook: bool, name: &str) -> PyResult<(Self, Vec<String>)> {
        let imported = phonglab_core::export::read_python::read(text, notebook, name).map_err(scene_error)?;
        // Said as `phonglab import` says them: a control character (an escape sequence, a
        // bell, a direction override) quoted from the file written visibly, `\u{1B}`.
        let notices = imported.notices.iter().map(|n| phonglab_core::escape::terminal::lines(n)).collect();
        Ok((PyScene { doc: imported.doc }, notices))
    }

    /// The scene file's text (TOML), every value explicit.
    fn to_toml(&self) -> PyResult<String> {
        self.doc.to_toml().map_err(scene_error)
    }

    /// The scene's title.
    #[getter]
    fn name(&self) -> String {
        self.doc.name.clone()
    }

    /// Renames the scene (its title in explain, the window and a share link), checked as
    /// a scene file's name is.
    #[setter]
    fn set_name(&mut self, name: &str) -> PyResult<()> {
        let mut doc = self.doc.clone();
        doc.name = name.to_string();
        doc.validate().map_err(scene_error)?;
        self.doc = doc;
        Ok(())
    }

    /// How many lights are enabled.
    fn light_count(&self) -> usize {
        self.doc.scene.lights.len()
    }

    /// The numbers of `path` (`light.0.position`, `material.diffuse`, `vertex.normal`).
    fn get(&self, path: &str) -> PyResult<Vec<f64>> {
        let s = &self.doc.scene;
        match parse_field(path)? {
            Field::Light(i, f) => light_get(&s.lights[light_index(s, i)?], f),
            Field::Material(f) => material_get(&s.material, f),
            Field::Vertex("position") => Ok(v4(s.vertex.position)),
            Field::Vertex("normal") => Ok(s.vertex.normal.to_array().to_vec()),
            Field::Vertex(f) => Err(unknown("vertex=", f, "position, normal")),
        }
    }

    /// Sets `path` to `values`, checked as the app checks an edit: a refused value raises
    /// `SceneError` and leaves the scene as it was. `shown` names the value in a message
    /// where the user gave it otherwise (`light(normal=)`).
    #[pyo3(signature = (path, values, shown=None))]
    fn set(&mut self, path: &str, values: Vec<f64>, shown: Option<&str>) -> PyResult<()> {
        let mut doc = self.doc.clone();
        let s = &mut doc.scene;
        match parse_field(path)? {
            Field::Light(i, f) => {
                let i = light_index(s, i)?;
                light_set(&mut s.lights[i], f, &format!("lights[{i}].{f}"), &values)?;
            }
            Field::Material(f) => material_set(&mut s.material, f, &format!("material.{f}"), &values)?,
            // x, y, z alone: w = 1, as `light(scene, vertex=[x, y, z])` takes it.
            Field::Vertex("position") => {
                s.vertex.position = match values[..] {
                    [x, y, z] => DVec4::new(x, y, z, 1.0),
                    [x, y, z, w] => DVec4::new(x, y, z, w),
                    _ => return Err(wrong_length(shown.unwrap_or("vertex.position"), values.len(), &either_3_or_4())),
                }
            }
            // The worksheet writes a normal as a direction, (x, y, z, 0): its w of 0 dropped.
            Field::Vertex("normal") => {
                s.vertex.normal = match values[..] {
                    [x, y, z] | [x, y, z, 0.0] => DVec3::new(x, y, z),
                    _ => return Err(wrong_length(shown.unwrap_or("vertex.normal"), values.len(), "3")),
                }
            }
            Field::Vertex(f) => return Err(unknown("vertex=", f, "position, normal")),
        }
        doc.validate().map_err(scene_error)?;
        self.doc = doc;
        Ok(())
    }

    /// An independent copy, exactly this scene (no file read again).
    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __repr__(&self) -> String {
        format!("phonglab.Scene({:?})", self.doc.name)
    }
}

/// One step of the worked calculation: (worksheet name, title, formula, value, light, the
/// value as the worked calculation prints it).
type StepRow = (String, String, String, Option<Vec<f64>>, Option<usize>, String);

fn steps_of<S: Real>(scene: &Scene) -> PyResult<(Vec<StepRow>, String, String)> {
    let lit = Engine::<S>::light_scene_vertex(scene).map_err(scene_error)?;
    let ex = explain(scene, &lit, Side::Front);
    finite_or_refused::<S>(scene, &ex)?;
    let rows = ex.steps.iter().map(|s| {
        let shown = s.value.as_deref().map(|v| phonglab_core::explain::fmt_value(v, 8)).unwrap_or_default();
        (s.name.clone(), s.title.clone(), s.formula.clone(), s.value.clone(), s.light, shown)
    });
    Ok((rows.collect(), ex.to_text(8), ex.to_markdown(8)))
}

/// The worked calculation of the scene's vertex: its steps, as text and as Markdown, in
/// `lang`, at `precision` ("f64" or "f32").
#[pyfunction]
#[pyo3(signature = (scene, precision="f64", lang="en"))]
fn light(scene: &PyScene, precision: &str, lang: &str) -> PyResult<(Vec<StepRow>, String, String)> {
    with_locale(locale_of(lang)?, || match precision {
        "f64" => steps_of::<f64>(&scene.doc.scene),
        "f32" => steps_of::<f32>(&scene.doc.scene),
        other => Err(unknown("precision=", other, "f64, f32")),
    })
}

/// Refuses a worked calculation in f32 with a step that overflowed (a legal scene of very
/// large colours, say, past float32's ±3.4e38): a value infinite or NaN in f32 where the
/// same step is finite in f64 (a vertex at infinity stays explained, as in f64), the step
/// and its value named, never an infinity handed on as a result.
fn finite_or_refused<S>(scene: &Scene, ex: &phonglab_core::explain::Explanation) -> PyResult<()> {
    if size_of::<S>() != 4 {
        return Ok(());
    }
    let lit = Engine::<f64>::light_scene_vertex(scene).map_err(scene_error)?;
    let wide = explain(scene, &lit, Side::Front);
    let overflowed =
        |narrow: &[f64], wide: &[f64]| narrow.iter().zip(wide).any(|(n, w)| !n.is_finite() && w.is_finite());
    let bad = ex.steps.iter().zip(&wide.steps).find_map(|(s, w)| {
        let (v, vw) = (s.value.as_deref()?, w.value.as_deref()?);
        overflowed(v, vw).then(|| (s.name.clone(), phonglab_core::explain::fmt_value(v, 8)))
    });
    match bad {
        None => Ok(()),
        Some((step, value)) => {
            Err(scene_error(phonglab_core::t!("python-overflow", step = step, value = value, precision = "f32")))
        }
    }
}

fn tables_of<S: Real>(scene: &Scene) -> PyResult<(String, String, String)> {
    let lit = Engine::<S>::light_scene_vertex(scene).map_err(scene_error)?;
    let ex = explain(scene, &lit, Side::Front);
    finite_or_refused::<S>(scene, &ex)?;
    Ok((ex.to_text(8), ex.to_markdown(8), phonglab_core::formats::explain_html::explanation_html(&ex, 8)))
}

/// The worked calculation of the scene's vertex as text, Markdown and HTML (a notebook's
/// display), in `lang` (its words and decimal mark), at `precision` ("f64" or "f32").
#[pyfunction]
#[pyo3(signature = (scene, precision="f64", lang="en"))]
fn explain_tables(scene: &PyScene, precision: &str, lang: &str) -> PyResult<(String, String, String)> {
    with_locale(locale_of(lang)?, || match precision {
        "f64" => tables_of::<f64>(&scene.doc.scene),
        "f32" => tables_of::<f32>(&scene.doc.scene),
        other => Err(unknown("precision=", other, "f64, f32")),
    })
}

/// A shape as Python writes a tuple: `(3,)`, `(2, 3)`.
fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    }
}

/// Refuses arrays that are not (N, 3), the same N for `positions` and `normals`.
fn check_shapes(positions: &[usize], normals: &[usize]) -> PyResult<()> {
    for (name, shape) in [("light_many(positions)", positions), ("light_many(normals)", normals)] {
        if shape.len() != 2 || shape[1] != 3 || positions.first() != shape.first() {
            return Err(scene_error(phonglab_core::t!("python-wrong-shape", name = name, shape = shape_text(shape))));
        }
    }
    Ok(())
}

/// A vector of `n` values, or Python's `MemoryError` where the memory cannot be had (an
/// allocation that fails ends in an exception, never in an abort of the process).
fn try_vec<T: Clone>(n: usize, value: T) -> PyResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| {
        PyMemoryError::new_err(phonglab_core::t!("python-no-memory", bytes = (n * size_of::<T>()).to_string()))
    })?;
    v.resize(n, value);
    Ok(v)
}

/// What `render` allocates at its peak for a `size` x `size` picture of `mesh`: the
/// command line's estimate for `phonglab render` (its memory budget: 16 bytes a pixel, 120
/// a vertex, 200 a triangle) and the picture handed to Python twice (its copy out of the
/// renderer and the `bytes`: 8 bytes a pixel).
fn render_bytes(size: usize, mesh: &phonglab_core::mesh::Mesh) -> u64 {
    let (pixels, vertices, triangles) =
        ((size * size) as u64, mesh.positions.len() as u64, mesh.triangle_count() as u64);
    pixels * (16 + 8) + vertices * (96 + 24) + triangles * (188 + 12)
}

/// Refuses, before drawing, a render whose memory cannot be had: twice its estimate
/// ([`render_bytes`]; the renderer's threads and the allocator's rounding come on top) is
/// asked for and given back at once, and where it cannot be had the answer is Python's
/// `MemoryError` with the estimate, never an abort of the process half-way.
fn memory_for_render(size: usize, mesh: &phonglab_core::mesh::Mesh) -> PyResult<()> {
    let needed = render_bytes(size, mesh);
    let mut probe: Vec<u8> = Vec::new();
    let asked = usize::try_from(needed.saturating_mul(2)).unwrap_or(usize::MAX);
    probe.try_reserve_exact(asked).map_err(|_| {
        PyMemoryError::new_err(phonglab_core::t!(
            "python-render-no-memory",
            size = size as i64,
            bytes = phonglab_core::mesh::obj::describe_bytes(needed)
        ))
    })
}

/// Little-endian f32 triples as vectors, refused where a number is not finite (NaN, an
/// infinity, or a float64 beyond float32's range that became one): `name` and the row.
fn vectors(name: &str, bytes: &[u8]) -> PyResult<Vec<glam::Vec3>> {
    let float = |b: &[u8]| f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
    let mut out = try_vec(bytes.len() / 12, glam::Vec3::ZERO)?;
    for (row, (v, c)) in out.iter_mut().zip(bytes.chunks_exact(12)).enumerate() {
        *v = glam::Vec3::new(float(&c[0..4]), float(&c[4..8]), float(&c[8..12]));
        if !v.is_finite() {
            let shown = format!("[{}, {}, {}]", v.x, v.y, v.z);
            return Err(scene_error(phonglab_core::t!("python-not-finite-row", name = name, row = row, value = shown)));
        }
    }
    Ok(out)
}

/// Lights the vertices given as little-endian f32 bytes (positions and normals, arrays of
/// shapes `shapes`, (N, 3) each, in object space) through the specialised lighter, the GIL
/// released: N x 4 f32 colours (primary + secondary, unclamped; alpha the diffuse's).
/// A number that is not finite is refused, naming its row; memory that cannot be had is
/// `MemoryError`.
#[pyfunction]
fn light_many<'py>(
    py: Python<'py>,
    scene: &PyScene,
    positions: &[u8],
    normals: &[u8],
    shapes: (Vec<usize>, Vec<usize>),
) -> PyResult<Bound<'py, PyBytes>> {
    check_shapes(&shapes.0, &shapes.1)?;
    let (p, n) = (vectors("light_many(positions)", positions)?, vectors("light_many(normals)", normals)?);
    if p.len() != shapes.0[0] || n.len() != p.len() {
        return Err(scene_error(phonglab_core::t!(
            "python-wrong-shape",
            name = "light_many(positions)",
            shape = format!("({}, 3)", p.len())
        )));
    }
    let lighter = phonglab_core::lighter::Lighter::new(&scene.doc.scene, EvalOptions::with_pow(PowFn::Exact))
        .map_err(scene_error)?;
    let mut front = try_vec(p.len(), [0f32; 4])?;
    py.detach(|| lighter.light_batch_sum(&p, &n, &mut front, None));
    drop((p, n));
    // A colour past float32's range (a legal scene of very large colours): refused, its row named.
    if let Some(row) = front.iter().position(|c| c.iter().any(|x| !x.is_finite())) {
        let value = format!("{:?}", front[row]);
        return Err(scene_error(phonglab_core::t!(
            "python-overflow",
            step = format!("row {row}"),
            value = value,
            precision = "f32"
        )));
    }
    // Written straight into the bytes object Python receives.
    PyBytes::new_with(py, front.len() * 16, |out| {
        for (chunk, x) in out.chunks_exact_mut(4).zip(front.iter().flatten()) {
            chunk.copy_from_slice(&x.to_le_bytes());
        }
        Ok(())
    })
}

fn named<T: serde::de::DeserializeOwned>(what: &str, value: &str, names: &str) -> PyResult<T> {
    serde_json::from_value(serde_json::Value::String(value.to_string())).map_err(|_| unknown(what, value, names))
}

/// The document drawn: the scene's, with `object` and `shading` when given.
fn view_doc(scene: &PyScene, object: Option<&str>, shading: Option<&str>) -> PyResult<Document> {
    let mut doc = scene.doc.clone();
    if let Some(o) = object {
        doc.view.object = named("object=", o, "sphere, teapot, cylinder")?;
    }
    if let Some(s) = shading {
        doc.view.shading = named("shading=", s, "gouraud, phong, flat")?;
    }
    doc.validate().map_err(scene_error)?;
    Ok(doc)
}

/// A Python int as a whole number and as Python writes it (one beyond 64 bits, which
/// no picture has, as `i64::MIN`: refused by the range it is checked against).
fn whole(v: &Bound<'_, PyAny>) -> (i64, String) {
    (v.extract::<i64>().unwrap_or(i64::MIN), v.to_string())
}

/// The side of a square picture, 1 to 8192 pixels (`size=`, 512 when not given), or the
/// refusal naming it.
fn picture_size(size: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
    let Some(size) = size else { return Ok(512) };
    let (n, shown) = whole(size);
    match usize::try_from(n) {
        Ok(s) if (1..=8192).contains(&s) => Ok(s),
        _ => Err(unknown("size=", &shown, "1 ... 8192")),
    }
}

/// The shaded view as `phonglab render` draws it: (RGBA8 bytes, width, height).
#[pyfunction]
#[pyo3(signature = (scene, object=None, shading=None, size=None))]
fn render<'py>(
    py: Python<'py>,
    scene: &PyScene,
    object: Option<&str>,
    shading: Option<&str>,
    size: Option<&Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyBytes>, usize, usize)> {
    let size = picture_size(size)?;
    let doc = view_doc(scene, object, shading)?;
    let mesh = doc.view.mesh();
    memory_for_render(size, &mesh)?;
    let image = py.detach(move || {
        let setup = doc.shaded_setup(PowFn::Exact);
        let mut r = Renderer::new();
        r.render(&setup.job(&mesh), size, size).map(|(img, _)| (img.rgba.clone(), img.width, img.height))
    });
    let (rgba, w, h) = image.map_err(scene_error)?;
    Ok((PyBytes::new(py, &rgba), w, h))
}

/// Why pixel (x, y) of the shaded view is its colour: the probe's numbers as JSON text
/// (`{"covered": false}` off the object).
#[pyfunction]
#[pyo3(signature = (scene, x, y, object=None, shading=None, size=None))]
fn probe(
    scene: &PyScene,
    x: &Bound<'_, PyAny>,
    y: &Bound<'_, PyAny>,
    object: Option<&str>,
    shading: Option<&str>,
    size: Option<&Bound<'_, PyAny>>,
) -> PyResult<String> {
    let size = picture_size(size)?;
    let ((xn, xs), (yn, ys)) = (whole(x), whole(y));
    let inside = |v: i64| usize::try_from(v).ok().filter(|v| *v < size);
    let (Some(x), Some(y)) = (inside(xn), inside(yn)) else {
        return Err(unknown("x, y = ", &format!("{xs}, {ys}"), &format!("0 ... {}", size - 1)));
    };
    let doc = view_doc(scene, object, shading)?;
    let mesh = doc.view.mesh();
    let setup = doc.shaded_setup(PowFn::Exact);
    let job = setup.job(&mesh);
    let mut r = Renderer::new();
    r.render(&job, size, size).map_err(scene_error)?;
    let value = match phonglab_core::probe::probe(&r, &job, x, y).map_err(scene_error)? {
        None => serde_json::json!({ "x": x, "y": y, "covered": false }),
        Some(p) => {
            let mut v = serde_json::to_value(&p).map_err(scene_error)?;
            v["covered"] = true.into();
            v["size"] = size.into();
            v
        }
    };
    Ok(value.to_string())
}

/// The GLSL or WGSL program that draws the scene's shaded view (`phonglab shader`).
#[pyfunction]
#[pyo3(signature = (scene, target="glsl", shading="gouraud"))]
fn shader(scene: &PyScene, target: &str, shading: &str) -> PyResult<String> {
    use phonglab_core::shader::{ShaderShading, ShadingLanguage};
    let lang = match target {
        "glsl" => ShadingLanguage::Glsl,
        "wgsl" => ShadingLanguage::Wgsl,
        other => return Err(unknown("target=", other, "glsl, wgsl")),
    };
    let shading = match shading {
        "gouraud" => ShaderShading::Gouraud,
        "phong" => ShaderShading::Phong,
        other => return Err(unknown("shading=", other, "gouraud, phong")),
    };
    let s = phonglab_core::shader::for_view(&scene.doc, lang, shading).map_err(scene_error)?;
    Ok(s.text(lang))
}

/// The scene as a link to the browser build (`phonglab share`): on the page `base` (an
/// http(s) address), opening in `open_in` (en, pt-PT, pt-BR), presenting, showing the
/// term `channel`, as `phonglab share --base --open-in --present --channel` asks.
#[pyfunction]
#[pyo3(signature = (scene, base=phonglab_core::export::share::DEFAULT_BASE, open_in=None, present=false, channel=None))]
fn share_link(
    scene: &PyScene,
    base: &str,
    open_in: Option<&str>,
    present: bool,
    channel: Option<&str>,
) -> PyResult<String> {
    use phonglab_core::channels::Channel;
    use phonglab_core::export::share::{Shared, check_base, link};
    check_base(base).map_err(scene_error)?;
    if let Some(lang) = open_in {
        locale_of(lang).map_err(|_| unknown("open_in=", lang, "en, pt-PT, pt-BR"))?;
    }
    if let Some(c) = channel
        && !Channel::ALL.iter().any(|k| k.name() == c)
    {
        let names: Vec<&str> = Channel::ALL.iter().map(|k| k.name()).collect();
        return Err(unknown("channel=", c, &names.join(", ")));
    }
    let shared = Shared {
        lang: open_in.map(str::to_string),
        present,
        channel: channel.map(str::to_string),
        ..Shared::of(scene.doc.clone())
    };
    link(base, &shared).map_err(scene_error)
}

/// Checks a notebook's work as `phonglab check` does: `code` the cells run, in order (the
/// givens are read from it, nothing is run), `printed` its values as `name = value` lines.
/// `missing` the key's steps the notebook holds no value for. The table in `lang`, and
/// whether every step is right.
#[pyfunction]
#[pyo3(signature = (code, printed, missing, lang="en"))]
fn check_work(code: &str, printed: &str, missing: Vec<String>, lang: &str) -> PyResult<(String, bool)> {
    with_locale(locale_of(lang)?, || check::check_work(code, printed, missing)).map_err(scene_error)
}

/// The names of the steps the key of the cells `code` prints, in order (`vlv`, `vlv[0]`):
/// the only variables the self-check reads. Refuses code that cannot be checked, as
/// [`check_work`] does.
#[pyfunction]
#[pyo3(signature = (code, lang="en"))]
fn check_steps(code: &str, lang: &str) -> PyResult<Vec<String>> {
    with_locale(locale_of(lang)?, || check::steps(code)).map_err(scene_error)
}

/// Why the self-check cannot run, in `lang`: `no-cells` (no IPython `In`: not in
/// Jupyter), `run-first` (none of the worksheet's cells has run in this kernel),
/// `not-globals` (given `globals` or a text where `globals()` is meant).
#[pyfunction]
#[pyo3(signature = (why, lang="en"))]
fn check_refusal(why: &str, lang: &str) -> PyResult<String> {
    with_locale(locale_of(lang)?, || match why {
        "no-cells" => Ok(phonglab_core::t!("python-check-no-cells")),
        "run-first" => Ok(phonglab_core::t!("python-check-run-first")),
        "not-globals" => Ok(phonglab_core::t!("python-check-not-globals")),
        other => Err(unknown("why=", other, "no-cells, run-first, not-globals")),
    })
}

/// A note the self-check adds under its table, in `lang`: `why` names it ("reassigned":
/// the step `name` was assigned again after the cell that prints it).
#[pyfunction]
#[pyo3(signature = (why, name, lang="en"))]
fn check_note(why: &str, name: &str, lang: &str) -> PyResult<String> {
    with_locale(locale_of(lang)?, || match why {
        "reassigned" => Ok(phonglab_core::t!("python-check-reassigned", name = name)),
        other => Err(unknown("why=", other, "reassigned")),
    })
}

/// A refusal the package's Python side makes (a value of the wrong kind), in the current
/// language: `kind` names the message; `what` the argument or field, `value` what was given
/// (Python's `repr`), `names` what is taken, `guess` the likeliest name meant (or "").
#[pyfunction]
#[pyo3(signature = (kind, what, value, names="", guess=""))]
fn refusal(kind: &str, what: &str, value: &str, names: &str, guess: &str) -> PyResult<String> {
    let value = phonglab_core::escape::terminal::text(value);
    Ok(match kind {
        "not-real" => phonglab_core::t!("python-not-real", what = what, value = value),
        "not-integer" => phonglab_core::t!("python-not-integer", what = what, value = value),
        "not-a-scene" => phonglab_core::t!("python-not-a-scene", what = what, value = value),
        "not-a-name" => phonglab_core::t!("python-not-a-name", what = what, value = value),
        "edit-fields" => phonglab_core::t!("python-edit-fields", what = what, example = names),
        "no-field" if !guess.is_empty() => {
            phonglab_core::t!("python-no-field-guess", what = what, value = value, guess = guess, names = names)
        }
        "no-field" => phonglab_core::t!("python-no-field", what = what, value = value, names = names),
        "lights-fixed" => phonglab_core::t!("python-lights-fixed", value = value),
        "no-light" => phonglab_core::t!(
            "python-no-such-light",
            light = value.clone(),
            count = names.parse::<usize>().unwrap_or_default()
        ),
        other => {
            return Err(unknown(
                "kind=",
                other,
                "not-real, not-integer, not-a-scene, not-a-name, edit-fields, no-field, lights-fixed, no-light",
            ));
        }
    })
}

/// The extension module.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SceneError", m.py().get_type::<SceneError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(set_language, m)?)?;
    m.add_function(wrap_pyfunction!(language, m)?)?;
    m.add_function(wrap_pyfunction!(refusal, m)?)?;
    m.add_class::<PyScene>()?;
    m.add_function(wrap_pyfunction!(light, m)?)?;
    m.add_function(wrap_pyfunction!(light_many, m)?)?;
    m.add_function(wrap_pyfunction!(render, m)?)?;
    m.add_function(wrap_pyfunction!(probe, m)?)?;
    m.add_function(wrap_pyfunction!(shader, m)?)?;
    m.add_function(wrap_pyfunction!(share_link, m)?)?;
    m.add_function(wrap_pyfunction!(check_work, m)?)?;
    m.add_function(wrap_pyfunction!(check_steps, m)?)?;
    m.add_function(wrap_pyfunction!(explain_tables, m)?)?;
    m.add_function(wrap_pyfunction!(check_refusal, m)?)?;
    m.add_function(wrap_pyfunction!(check_note, m)?)?;
    Ok(())
}
