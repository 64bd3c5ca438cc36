//! What accuracy costs in time: each shading at several tessellations, f32 against f64,
//! and the approximations people use, each timed and compared with a reference image.
//!
//! | symbol | meaning |
//! |---|---|
//! | reference | per-pixel Phong in **f64** on a very fine tessellation ([`reference_view`]): the colour each pixel should have |
//! | error of a pixel | `|c / 255 - ref|` per channel, `c` the 8-bit colour drawn, `ref` the reference clamped to [0, 1] |
//! | mean, max | over the pixels either image covers (silhouette differences count), in units of 1/255 |
//! | share > 1/255 | the share of those pixels whose worst channel is off by more than 1/255 |
//! | ms | median time per frame of [`Renderer::render`] (all threads of the current pool) |
//!
//! An 8-bit image of the exact colours is itself up to 0.5/255 off: "off by more than
//! 1/255" means an error that a display can show. The error figures are deterministic;
//! only the times depend on the machine.

use web_time::Instant;

use glam::Vec3;

use crate::equation::lighting::{Engine, EvalOptions, Renormalize};
use crate::mesh::Mesh;
use crate::model::error::SceneError;
use crate::model::scene::{Scene, Vertex};
use crate::model::view::{ObjectKind, Shading, View};
use crate::numerics::pow::PowFn;
use crate::raster::render::{Image, Job, Renderer};
use crate::raster::shaded::ShadedSetup;
use crate::specialise::lighter::Lighter;

/// What is studied: a document's shaded view as the app and the CLI draw it (its scene, as
/// [`crate::formats::document::Document::shaded_scene`] gives it, where the object is drawn,
/// and the view: the object, its demo normals and cylinder caps; the tessellation is
/// varied), drawn `size` pixels square on `background`.
#[derive(Clone, Copy, Debug)]
pub struct Setup<'a> {
    /// The shaded view.
    pub shaded: &'a ShadedSetup,
    /// Width and height of the images, in pixels.
    pub size: usize,
    /// Colour of uncovered pixels.
    pub background: [f32; 3],
}

impl<'a> Setup<'a> {
    /// The study of `shaded`, `size` pixels square on `background`.
    pub fn new(shaded: &'a ShadedSetup, size: usize, background: [f32; 3]) -> Self {
        Setup { shaded, size, background }
    }

    /// The view studied.
    pub fn view(&self) -> &'a View {
        &self.shaded.view
    }

    /// What the renderer draws for `mesh` in this setup: the shaded view's job (no
    /// culling, as the study compares every covered pixel) with `shading` and `options`.
    pub fn job<'m>(&self, mesh: &'m Mesh, shading: Shading, options: EvalOptions) -> Job<'m>
    where
        'a: 'm,
    {
        let view = &self.shaded.view;
        let mode = crate::model::view::ShadingMode::of(shading, view.flat_normal);
        Job { mode, options, background: self.background, ..self.shaded.job(mesh) }
    }
}

/// The five tessellation levels studied per object, coarse to fine: sphere slices and
/// stacks, teapot quads per patch side, cylinder slices (with a quarter as many stacks).
/// A mesh file has the one tessellation it was made with, at every level.
pub fn levels(object: ObjectKind) -> [u32; 5] {
    match object {
        ObjectKind::Sphere | ObjectKind::Cylinder => [8, 16, 32, 64, 128],
        ObjectKind::Teapot => [1, 2, 4, 7, 14],
        ObjectKind::Obj => [1; 5],
    }
}

/// The level of the reference image (finer than anything a frame would use).
pub fn reference_level(object: ObjectKind) -> u32 {
    match object {
        ObjectKind::Sphere | ObjectKind::Cylinder => 400,
        ObjectKind::Teapot => 48,
        ObjectKind::Obj => 1,
    }
}

/// `view` tessellated at `level` (see [`levels`]).
pub fn view_at(view: &View, level: u32) -> View {
    let mut v = view.clone();
    match v.object {
        ObjectKind::Sphere => (v.sphere_slices, v.sphere_stacks) = (level, level),
        ObjectKind::Teapot => v.teapot_grid = level,
        ObjectKind::Cylinder => (v.cylinder_slices, v.cylinder_stacks) = (level, (level / 4).max(1)),
        ObjectKind::Obj => {}
    }
    v
}

/// The reference's view: [`reference_level`].
pub fn reference_view(view: &View) -> View {
    view_at(view, reference_level(view.object))
}

/// The reference image: each pixel's exact colour.
#[derive(Clone, Debug)]
pub struct Reference {
    /// Width and height.
    pub size: usize,
    /// Per pixel: covered by the object.
    pub covered: Vec<bool>,
    /// Per pixel: the colour, clamped to [0, 1] (the 8-bit background where uncovered).
    pub rgb: Vec<[f64; 3]>,
    /// Triangles of the reference mesh.
    pub triangles: usize,
}

/// Renders the reference: the fine mesh drawn by the plain renderer
/// ([`crate::raster::reference`]) with Phong shading in f64: every covered pixel lit by the
/// general engine with the eye-space position and normal interpolated at that point of the
/// mesh triangle, the normal renormalised exactly.
pub fn reference(setup: &Setup<'_>) -> Result<Reference, SceneError> {
    let mesh = reference_view(setup.view()).mesh();
    let options = EvalOptions { renormalize: crate::equation::lighting::Renormalize::Exact, ..EvalOptions::default() };
    let job = setup.job(&mesh, Shading::Phong, options);
    let size = setup.size.max(1);
    let colours = crate::raster::reference::colours(&job, size, size)?;
    let bg = setup.background.map(|c| to_u8(c) as f64 / 255.0);
    Ok(Reference {
        size,
        covered: colours.iter().map(Option::is_some).collect(),
        rgb: colours.iter().map(|c| c.map_or(bg, |c| [0, 1, 2].map(|k| c[k].clamp(0.0, 1.0)))).collect(),
        triangles: mesh.triangle_count(),
    })
}

/// How far an image is from the reference, in units of 1/255.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ErrorStats {
    /// Mean absolute difference per channel.
    pub mean: f64,
    /// Largest absolute difference of any channel.
    pub max: f64,
    /// Share (0 to 1) of pixels whose worst channel is off by more than 1/255.
    pub share_over_one: f64,
    /// Pixels compared (covered by either image).
    pub pixels: usize,
}

/// Each pixel's worst-channel error in units of 1/255 (0 where neither image covers it).
/// `image` is a frame whose visibility was kept ([`Renderer::keep_visibility`]); where it
/// was not, its pixels count as covered.
pub fn error_map(image: &Image, reference: &Reference) -> Vec<f32> {
    (0..reference.rgb.len())
        .map(|i| {
            let (x, y) = (i % reference.size, i / reference.size);
            if !reference.covered[i] && image.covered(x, y) == Some(false) {
                return 0.0;
            }
            let c = image.rgb(x, y);
            (0..3).map(|k| (c[k] as f64 - 255.0 * reference.rgb[i][k]).abs()).fold(0.0, f64::max) as f32
        })
        .collect()
}

/// [`ErrorStats`] of `image` against `reference` (same size; `image` as for [`error_map`]).
pub fn error(image: &Image, reference: &Reference) -> ErrorStats {
    let (mut sum, mut max, mut over, mut n) = (0.0, 0.0f64, 0usize, 0usize);
    for i in 0..reference.rgb.len() {
        let (x, y) = (i % reference.size, i / reference.size);
        if !reference.covered[i] && image.covered(x, y) == Some(false) {
            continue;
        }
        let c = image.rgb(x, y);
        let mut worst = 0.0f64;
        for (got, want) in c.iter().zip(reference.rgb[i]) {
            let d = (*got as f64 - 255.0 * want).abs();
            sum += d;
            worst = worst.max(d);
        }
        max = max.max(worst);
        over += usize::from(worst > 1.0);
        n += 1;
    }
    if n == 0 {
        return ErrorStats::default();
    }
    ErrorStats { mean: sum / (3 * n) as f64, max, share_over_one: over as f64 / n as f64, pixels: n }
}

/// An error map as an RGBA8 heat map: black (exact) through red and yellow to white at
/// `full_scale` (in 1/255); uncovered pixels dark blue-grey.
pub fn heat_map_rgba(map: &[f32], reference: &Reference, full_scale: f32) -> Vec<u8> {
    const STOPS: [[f32; 3]; 5] =
        [[0.0, 0.0, 0.0], [0.45, 0.0, 0.55], [0.9, 0.1, 0.1], [1.0, 0.85, 0.0], [1.0, 1.0, 1.0]];
    let mut out = Vec::with_capacity(map.len() * 4);
    for (i, &e) in map.iter().enumerate() {
        if e == 0.0 && !reference.covered[i] {
            out.extend([24, 26, 34, 255]);
            continue;
        }
        let t = (e / full_scale).clamp(0.0, 1.0) * (STOPS.len() - 1) as f32;
        let k = (t as usize).min(STOPS.len() - 2);
        let f = t - k as f32;
        let c = [0, 1, 2].map(|j| STOPS[k][j] + (STOPS[k + 1][j] - STOPS[k][j]) * f);
        out.extend([to_u8(c[0]), to_u8(c[1]), to_u8(c[2]), 255]);
    }
    out
}

fn to_u8(c: f32) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// Which question a variant answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Question {
    /// Which shading, how fine a mesh.
    Shading,
    /// Does f64 change anything visible (Phong at the reference's tessellation, in f32).
    Precision,
    /// What an approximation saves and costs (Phong at the middle level).
    Approximation,
}

/// One way to draw the object.
#[derive(Clone, Debug, PartialEq)]
pub struct Variant {
    /// A short name in English, the key of data (the CSV's `variant` column), e.g.
    /// "Gouraud 32" or "Phong 32, Schlick pow"; [`Variant::name`] is for people.
    pub label: String,
    /// The approximation's message id, for [`Question::Approximation`].
    pub approximation: Option<&'static str>,
    /// The shading.
    pub shading: Shading,
    /// The tessellation level ([`levels`]).
    pub level: u32,
    /// Numerical choices (the approximations).
    pub options: EvalOptions,
    /// What it is for.
    pub question: Question,
}

impl Variant {
    /// The name for people, in the current language: "Phong 32, pow de Schlick".
    pub fn name(&self) -> String {
        match (self.question, self.approximation) {
            (Question::Approximation, Some(id)) => {
                format!("{} {}, {}", self.shading.label(), self.level, crate::locale::tr(id))
            }
            _ => self.label.clone(),
        }
    }
}

/// The variants studied for `object`: Flat, Gouraud and Phong at each of [`levels`];
/// Phong in f32 at the reference's level; and at the middle level, Phong with each
/// approximation (llvmpipe's and Schlick's pow, the fast rsqrt, no renormalisation).
pub fn variants(object: ObjectKind) -> Vec<Variant> {
    let mut v = Vec::new();
    for level in levels(object) {
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            v.push(Variant {
                label: format!("{} {level}", shading.label()),
                approximation: None,
                shading,
                level,
                options: EvalOptions::default(),
                question: Question::Shading,
            });
        }
    }
    let r = reference_level(object);
    v.push(Variant {
        label: format!("Phong {r} (f32)"),
        approximation: None,
        shading: Shading::Phong,
        level: r,
        options: EvalOptions::default(),
        question: Question::Precision,
    });
    let mid = levels(object)[2];
    let approx = [
        ("llvmpipe pow", "cost-approx-llvmpipe-pow", EvalOptions::with_pow(PowFn::Llvmpipe)),
        ("Schlick pow", "cost-approx-schlick-pow", EvalOptions::with_pow(PowFn::Schlick)),
        (
            "fast rsqrt",
            "cost-approx-fast-rsqrt",
            EvalOptions { renormalize: Renormalize::FastRsqrt, ..EvalOptions::default() },
        ),
        (
            "no renormalisation",
            "cost-approx-no-renormalisation",
            EvalOptions { renormalize: Renormalize::Skip, ..EvalOptions::default() },
        ),
    ];
    for (name, id, options) in approx {
        v.push(Variant {
            label: format!("Phong {mid}, {name}"),
            approximation: Some(id),
            shading: Shading::Phong,
            level: mid,
            options,
            question: Question::Approximation,
        });
    }
    v
}

/// How long to time each variant.
///
/// Each variant is timed in `rounds` passes over all the variants in turn, so that a
/// slow spell of a shared machine hits every variant alike rather than the few timed
/// during it; the figure kept is the lowest of the per-round medians.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// At least this many timed frames per round (after one untimed).
    pub min_frames: u32,
    /// And at least this long per round.
    pub min_seconds: f64,
    /// But no more frames per round than this.
    pub max_frames: u32,
    /// Passes over all the variants (at least one).
    pub rounds: u32,
}

impl Timing {
    /// Enough for stable figures on a quiet machine: 3 rounds of at least 0.15 s.
    pub const CAREFUL: Timing = Timing { min_frames: 5, min_seconds: 0.15, max_frames: 200, rounds: 3 };
    /// Quick, for the app's background study.
    pub const QUICK: Timing = Timing { min_frames: 3, min_seconds: 0.1, max_frames: 60, rounds: 1 };
    /// One frame each: tests, which check the error figures only.
    pub const ONCE: Timing = Timing { min_frames: 1, min_seconds: 0.0, max_frames: 1, rounds: 1 };
}

/// One measured variant.
#[derive(Clone, Debug)]
pub struct CostPoint {
    /// What was drawn.
    pub variant: Variant,
    /// Triangles in its mesh.
    pub triangles: usize,
    /// Milliseconds per frame: the lowest of the per-round medians ([`Timing`]).
    pub ms: f64,
    /// Its error against the reference.
    pub error: ErrorStats,
}

/// Renders `variant`, timing it; returns the point and the last frame's error map.
pub fn measure(
    setup: &Setup<'_>,
    variant: &Variant,
    reference: &Reference,
    timing: Timing,
) -> Result<(CostPoint, Vec<f32>), SceneError> {
    let view = view_at(setup.view(), variant.level);
    let m = measure_view(setup, &view, variant.shading, variant.options, reference, timing)?;
    Ok((CostPoint { variant: variant.clone(), triangles: m.triangles, ms: m.ms, error: m.error }, m.map))
}

/// One way of drawing, measured: see [`measure_view`].
#[derive(Clone, Debug)]
pub struct Measured {
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Median milliseconds per frame.
    pub ms: f64,
    /// Error against the reference.
    pub error: ErrorStats,
    /// Per-pixel worst-channel error, in 1/255 ([`error_map`]).
    pub map: Vec<f32>,
}

/// Renders the object of `view` (its own tessellation) with `shading` and `options` at
/// the reference's size, timing it, and compares the last frame with the reference.
pub fn measure_view(
    setup: &Setup<'_>,
    view: &View,
    shading: Shading,
    options: EvalOptions,
    reference: &Reference,
    timing: Timing,
) -> Result<Measured, SceneError> {
    let mesh = view.mesh();
    let job = setup.job(&mesh, shading, options);
    let size = reference.size;
    let mut renderer = Renderer::new();
    let ms = time_job(&mut renderer, &job, size, timing)?;
    // Timed as every frame is drawn; the frame compared keeps its visibility.
    renderer.keep_visibility(true);
    let (image, _) = renderer.render(&job, size, size)?;
    Ok(Measured {
        triangles: mesh.triangle_count(),
        ms,
        error: error(image, reference),
        map: error_map(image, reference),
    })
}

/// Another round of timing for `variant` (see [`Timing`]): median ms per frame.
pub fn retime(setup: &Setup<'_>, variant: &Variant, size: usize, timing: Timing) -> Result<f64, SceneError> {
    let view = view_at(setup.view(), variant.level);
    let mesh = view.mesh();
    let job = setup.job(&mesh, variant.shading, variant.options);
    time_job(&mut Renderer::new(), &job, size, timing)
}

/// One untimed frame, then frames as `timing` asks; the median in milliseconds.
fn time_job(renderer: &mut Renderer, job: &Job<'_>, size: usize, timing: Timing) -> Result<f64, SceneError> {
    renderer.render(job, size, size)?;
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < timing.max_frames.max(1) as usize
        && (times.len() < timing.min_frames.max(1) as usize || start.elapsed().as_secs_f64() < timing.min_seconds)
    {
        let t = Instant::now();
        renderer.render(job, size, size)?;
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    Ok(times[times.len() / 2])
}

/// f32 against f64: the time per vertex of each evaluator and the largest difference.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PrecisionFigures {
    /// Vertices evaluated.
    pub vertices: usize,
    /// The general engine (full breakdown), f32, ns per vertex.
    pub general_f32_ns: f64,
    /// The general engine, f64, ns per vertex.
    pub general_f64_ns: f64,
    /// The specialised evaluator (what the renderer uses), f32, ns per vertex.
    pub specialised_f32_ns: f64,
    /// Largest |f32 - f64| of any channel of the colour sum, unclamped.
    pub max_error: f64,
    /// The same after clamping to [0, 1], in units of 1/255: what a display could show.
    pub max_error_shown_255: f64,
}

/// Lights every vertex of `mesh` in f32 and f64 and compares; timings are the best of
/// repeated runs of at least `min_seconds / 3` each.
pub fn precision(scene: &Scene, mesh: &Mesh, min_seconds: f64) -> Result<PrecisionFigures, SceneError> {
    let e32 = Engine::<f32>::new(scene)?;
    let e64 = Engine::<f64>::new(scene)?;
    let lighter = Lighter::new(scene, EvalOptions::default())?;
    let verts: Vec<Vertex> = mesh.positions.iter().zip(&mesh.normals).map(|(p, n)| Vertex::from_f32(*p, *n)).collect();
    let n = verts.len().max(1);
    let (mut max_error, mut max_shown) = (0.0f64, 0.0f64);
    for v in &verts {
        let (a, b) = (e32.light(v), e64.light(v));
        for (sa, sb) in [(&a.front, &b.front), (&a.back, &b.back)] {
            let (ca, cb) = (sa.sum(), sb.sum());
            for k in 0..3 {
                max_error = max_error.max((ca[k] as f64 - cb[k]).abs());
                max_shown = max_shown.max((ca[k].clamp(0.0, 1.0) as f64 - cb[k].clamp(0.0, 1.0)).abs());
            }
        }
    }
    let per_run = min_seconds.max(0.0) / 3.0;
    let time = |f: &mut dyn FnMut()| {
        let mut best = f64::INFINITY;
        let start = Instant::now();
        let mut runs = 0;
        while runs < 3 || start.elapsed().as_secs_f64() < per_run * 3.0 && runs < 1000 {
            let t = Instant::now();
            f();
            best = best.min(t.elapsed().as_secs_f64());
            runs += 1;
        }
        best * 1e9 / n as f64
    };
    let mut sink = 0.0f64;
    let general_f32_ns = time(&mut || verts.iter().for_each(|v| sink += e32.light(v).front.primary[0] as f64));
    let general_f64_ns = time(&mut || verts.iter().for_each(|v| sink += e64.light(v).front.primary[0]));
    let (pos, nrm): (Vec<Vec3>, Vec<Vec3>) = (mesh.positions.clone(), mesh.normals.clone());
    let mut out = vec![[0.0f32; 4]; pos.len()];
    let specialised_f32_ns = time(&mut || lighter.light_batch_sum(&pos, &nrm, &mut out, None));
    std::hint::black_box(sink);
    Ok(PrecisionFigures {
        vertices: verts.len(),
        general_f32_ns,
        general_f64_ns,
        specialised_f32_ns,
        max_error,
        max_error_shown_255: max_shown * 255.0,
    })
}

/// How far a study has got.
#[derive(Clone, Debug, PartialEq)]
pub struct Progress {
    /// Steps done.
    pub done: usize,
    /// Steps in all.
    pub total: usize,
    /// What is being done now.
    pub what: String,
}

/// A finished study of one object.
#[derive(Clone, Debug)]
pub struct Study {
    /// The object.
    pub object: ObjectKind,
    /// Image size.
    pub size: usize,
    /// Triangles of the reference.
    pub reference_triangles: usize,
    /// Every variant, in [`variants`] order.
    pub points: Vec<CostPoint>,
    /// Each variant's error map, in the same order.
    pub error_maps: Vec<Vec<f32>>,
    /// The reference (for heat maps).
    pub reference: Reference,
    /// f32 against f64 on the vertices of the middle level's mesh.
    pub precision: PrecisionFigures,
}

/// Runs the whole study: the reference, then each variant, then the precision figures.
/// `progress` is told before each step; when it returns `false` the study stops and
/// `Ok(None)` is returned.
pub fn run(
    setup: &Setup<'_>,
    timing: Timing,
    progress: &mut dyn FnMut(&Progress) -> bool,
) -> Result<Option<Study>, SceneError> {
    let vs = variants(setup.view().object);
    let rounds = timing.rounds.max(1) as usize;
    let total = vs.len() * rounds + 2;
    let mut step = |done: usize, what: String| progress(&Progress { done, total, what });
    if !step(0, "reference (f64, per pixel, finest mesh)".into()) {
        return Ok(None);
    }
    let reference = reference(setup)?;
    let mut points = Vec::with_capacity(vs.len());
    let mut error_maps = Vec::with_capacity(vs.len());
    for (i, v) in vs.iter().enumerate() {
        if !step(i + 1, v.label.clone()) {
            return Ok(None);
        }
        let (p, map) = measure(setup, v, &reference, timing)?;
        points.push(p);
        error_maps.push(map);
    }
    for round in 1..rounds {
        for (i, (v, p)) in vs.iter().zip(&mut points).enumerate() {
            if !step(round * vs.len() + i + 1, format!("{} (timing round {})", v.label, round + 1)) {
                return Ok(None);
            }
            p.ms = p.ms.min(retime(setup, v, reference.size, timing)?);
        }
    }
    if !step(total - 1, "f32 against f64".into()) {
        return Ok(None);
    }
    let mid = view_at(setup.view(), levels(setup.view().object)[2]).mesh();
    let precision = precision(&setup.shaded.scene, &mid, timing.min_seconds)?;
    step(total, "done".into());
    Ok(Some(Study {
        object: setup.view().object,
        size: reference.size,
        reference_triangles: reference.triangles,
        points,
        error_maps,
        reference,
        precision,
    }))
}

/// The study as CSV: one row per variant.
pub fn to_csv(study: &Study) -> String {
    let mut s = String::from(
        "object,variant,question,shading,level,triangles,ms_per_frame,mean_error_255,max_error_255,share_over_1_255\n",
    );
    for p in &study.points {
        s.push_str(&format!(
            "{},{},{:?},{},{},{},{:.4},{:.4},{:.3},{:.6}\n",
            study.object.key(),
            csv_field(&p.variant.label),
            p.variant.question,
            p.variant.shading.label(),
            p.variant.level,
            p.triangles,
            p.ms,
            p.error.mean,
            p.error.max,
            p.error.share_over_one,
        ));
    }
    s
}

/// A CSV field ("Phong 32, fast rsqrt"): [`crate::formats::escape::csv::field`].
fn csv_field(s: &str) -> String {
    crate::formats::escape::csv::field(s)
}
