//! The pixel probe: why one pixel of the shaded view is the colour it is.
//!
//! | symbol | here | what it is |
//! |---|---|---|
//! | `b_k` | [`Probe::weights`] | perspective-correct barycentrics of the mesh triangle's vertex k |
//! | `c_k` | [`GouraudPixel::vertex_colours`] | vertex k's colour as Gouraud interpolates it |
//! | `n~` | [`PhongPixel::normal_interpolated`] | `sum_k b_k n_k`, before normalising |
//! | `n` | [`PhongPixel::normal`] | `n~ / |n~|`, the normal the fragment is lit with |
//! | `P` | [`PhongPixel::position`] | `sum_k b_k P_k`, the fragment in eye space |
//! | `c` | [`Probe::unclamped`] | the colour that reached the framebuffer |
//! | | [`Probe::rgba8`] | `round(255 clamp(c, 0, 1))`, the pixel as stored |
//!
//! The stored value is the renderer's own ([`Renderer::sample`]: the pixel shaded again
//! alone by the resolve's arithmetic), so it is the rendered pixel bit for bit. The terms
//! beside it ([`Terms`]) are the lighting engine's worked breakdown in f64 at the same
//! point: for Phong at the fragment, for Gouraud each vertex's terms interpolated with the
//! same weights, for Flat at the face's centroid. They add up to the colour before any
//! clamp (`tests/all/probe.rs`); the term channels (`channels.rs`) are
//! these terms at every pixel.

use glam::{DVec3, Vec3};

use crate::equation::breakdown::{SideTerms, VertexLighting};
use crate::equation::lighting::{Engine, Renormalize};
use crate::equation::plan::{Key, Program};
use crate::model::error::SceneError;
use crate::model::scene::{LightId, Side, Vertex};
use crate::model::view::ShadingMode;
use crate::raster::render::{Job, Renderer, Surface};

/// One light's share of a pixel, after its attenuation and spot factor.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct LightShare {
    /// `GL_LIGHTi`.
    pub index: LightId,
    /// `att_i`: 1 for a directional light.
    pub attenuation: f64,
    /// `spot_i`: 1 when not a spotlight.
    pub spot: f64,
    /// `n . L` (negative facing away).
    pub n_dot_l: f64,
    /// The specular cosine, `n . H` (or `R . V` under Phong's rule).
    pub n_dot_h: f64,
    /// `att_i spot_i a_cm a_cli`.
    pub ambient: [f64; 3],
    /// `att_i spot_i max(n . L, 0) d_cm d_cli`.
    pub diffuse: [f64; 3],
    /// `att_i spot_i f_i max(n . H, 0)^s_rm s_cm s_cli`.
    pub specular: [f64; 3],
}

/// The lighting equation's terms at a point: they add up to the colour before any clamp.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Terms {
    /// `e_cm`.
    pub emission: [f64; 3],
    /// `a_cm a_cs`.
    pub scene_ambient: [f64; 3],
    /// Each enabled light's share, in light order.
    pub lights: Vec<LightShare>,
}

impl Terms {
    /// The terms of one side of an engine breakdown.
    pub fn of(lit: &VertexLighting<f64>, side: Side) -> Self {
        let colour = match side {
            Side::Front => &lit.front,
            Side::Back => &lit.back,
        };
        let lights = lit
            .lights()
            .iter()
            .map(|l| {
                let st: &SideTerms<f64> = match side {
                    Side::Front => &l.front,
                    Side::Back => &l.back,
                };
                let scale = |v: DVec3| (v * l.scale).to_array();
                LightShare {
                    index: LightId(l.index),
                    attenuation: l.attenuation,
                    spot: l.spot.factor,
                    n_dot_l: st.n_dot_l,
                    n_dot_h: st.spec_cos,
                    ambient: scale(st.ambient),
                    diffuse: scale(st.diffuse),
                    specular: scale(st.specular * st.f),
                }
            })
            .collect();
        Self { emission: colour.emission.to_array(), scene_ambient: colour.scene_ambient.to_array(), lights }
    }

    /// `sum_k w_k terms_k`: Gouraud's terms at a pixel, from its vertices'.
    pub fn blend(terms: [&Terms; 3], w: [f64; 3]) -> Self {
        let mix3 = |f: &dyn Fn(&Terms) -> [f64; 3]| -> [f64; 3] {
            std::array::from_fn(|c| (0..3).map(|k| w[k] * f(terms[k])[c]).sum())
        };
        let lights = (0..terms[0].lights.len())
            .map(|i| {
                let mix = |f: &dyn Fn(&LightShare) -> f64| (0..3).map(|k| w[k] * f(&terms[k].lights[i])).sum();
                let mix3 = |f: &dyn Fn(&LightShare) -> [f64; 3]| -> [f64; 3] {
                    std::array::from_fn(|c| (0..3).map(|k| w[k] * f(&terms[k].lights[i])[c]).sum())
                };
                LightShare {
                    index: terms[0].lights[i].index,
                    attenuation: mix(&|l| l.attenuation),
                    spot: mix(&|l| l.spot),
                    n_dot_l: mix(&|l| l.n_dot_l),
                    n_dot_h: mix(&|l| l.n_dot_h),
                    ambient: mix3(&|l| l.ambient),
                    diffuse: mix3(&|l| l.diffuse),
                    specular: mix3(&|l| l.specular),
                }
            })
            .collect();
        Self { emission: mix3(&|t| t.emission), scene_ambient: mix3(&|t| t.scene_ambient), lights }
    }

    /// Their sum: the colour (rgb) before any clamp.
    pub fn sum(&self) -> [f64; 3] {
        std::array::from_fn(|c| {
            self.emission[c]
                + self.scene_ambient[c]
                + self.lights.iter().map(|l| l.ambient[c] + l.diffuse[c] + l.specular[c]).sum::<f64>()
        })
    }

    /// The lights that reach the point: a share of light on the side it shows.
    pub fn lights_reaching(&self) -> usize {
        self.lights.iter().filter(|l| l.attenuation * l.spot > 0.0 && l.n_dot_l > 0.0).count()
    }
}

/// Gouraud at a pixel: the three vertex colours and their weighted sum.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct GouraudPixel {
    /// Each vertex's colour as it is interpolated: OpenGL clamps primary and secondary to
    /// [0, 1] at the vertex (a shader's varying is not clamped).
    pub vertex_colours: [[f64; 4]; 3],
    /// Each vertex's colour before that clamp.
    pub vertex_unclamped: [[f64; 4]; 3],
    /// `sum_k b_k c_k`, in f64.
    pub weighted_sum: [f64; 4],
    /// The rules clamp vertex colours (OpenGL's do; a shader's varying is not clamped).
    pub clamped: bool,
}

/// Phong (and the demo's Flat) at a pixel: the fragment's interpolated inputs, as the
/// renderer computed them (f32).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PhongPixel {
    /// The interpolated normal before normalising (the demo's Flat: the face's normal).
    pub normal_interpolated: [f64; 3],
    /// Its length.
    pub normal_length: f64,
    /// The normal the fragment is lit with.
    pub normal: [f64; 3],
    /// It was brought back to unit length (the Phong demo's shader does not).
    pub renormalised: bool,
    /// The interpolated eye-space position.
    pub position: [f64; 3],
}

/// Flat at a pixel: the face's one colour, lit at its centroid with its plane's normal.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct FlatPixel {
    /// The face's centroid in eye space.
    pub centroid: [f64; 3],
    /// Its plane's unit normal in eye space (on the side shown).
    pub normal: [f64; 3],
    /// OpenGL's `GL_FLAT` takes its colour from the provoking vertex, the triangle's
    /// last: that mesh vertex.
    pub provoking_vertex: usize,
    /// And the colour `GL_FLAT` would give (clamped per vertex).
    pub provoking_colour: [f64; 4],
}

/// How the shading made the pixel.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(untagged)]
pub enum ProbeShading {
    /// Gouraud.
    Gouraud(GouraudPixel),
    /// Phong, or the demo's Flat (lit per fragment).
    Phong(PhongPixel),
    /// Flat, one colour a face.
    Flat(FlatPixel),
}

/// Everything about one pixel.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Probe {
    /// The pixel, x from the left.
    pub x: usize,
    /// y from the top.
    pub y: usize,
    /// The shading.
    pub mode: ShadingMode,
    /// The mesh triangle.
    pub triangle: usize,
    /// Its vertices (mesh indices), in the mesh's order.
    pub vertices: [usize; 3],
    /// It faces away from the viewer.
    pub back: bool,
    /// The side lit: the back only with two-sided lighting (written as its index, 0 or 1).
    #[serde(serialize_with = "side_index")]
    pub side: Side,
    /// `b_k`, perspective-correct, as the renderer computed them.
    pub weights: [f64; 3],
    /// The colour that reached the framebuffer, before its clamp.
    pub unclamped: [f64; 4],
    /// The pixel as stored.
    pub rgba8: [u8; 4],
    /// The equation's terms at the pixel.
    pub terms: Terms,
    /// How the shading made it (its fields sit beside the others in JSON).
    #[serde(flatten)]
    pub shading: ProbeShading,
    /// The scene's worked program ([`Program::worked`]): the forms of its terms, which the
    /// report names.
    #[serde(skip)]
    pub program: Program,
}

/// A side in the probe's JSON: its index, 0 front or 1 back, as the renderer's sample has it.
fn side_index<S: serde::Serializer>(side: &Side, out: S) -> Result<S::Ok, S::Error> {
    out.serialize_u64(side.index() as u64)
}

/// The lighting engine's breakdowns of a mesh's vertices, computed as they are asked for.
pub struct Surfaces<'a> {
    job: &'a Job<'a>,
    engine: Engine<f64>,
    lit: Vec<Option<VertexLighting<f64>>>,
}

impl<'a> Surfaces<'a> {
    /// For the mesh and scene of `job`.
    pub fn new(job: &'a Job<'a>) -> Result<Self, SceneError> {
        let engine = Engine::<f64>::with_options(job.scene, job.options)?;
        Ok(Self { job, engine, lit: vec![None; job.mesh.positions.len()] })
    }

    /// Vertex `i`'s breakdown.
    pub fn vertex(&mut self, i: usize) -> &VertexLighting<f64> {
        let mesh = self.job.mesh;
        let engine = &self.engine;
        self.lit[i].get_or_insert_with(|| engine.light(&Vertex::from_f32(mesh.positions[i], mesh.normals[i])))
    }

    /// The terms at a surface point (triangle and perspective-correct weights) as the
    /// shading computes them: interpolated from the vertices' (Gouraud), lit at the point
    /// from the interpolated position and normal (Phong), with the face's normal (the
    /// demo's Flat) or at the face's centroid (Flat).
    pub fn terms_at(&mut self, s: &Surface, side: Side) -> Terms {
        self.terms_and_normal_at(s, side).0
    }

    /// [`Surfaces::terms_at`], and the unit normal the point is lit with (Gouraud: the
    /// vertices' normals interpolated and normalised, for the normal channel).
    pub fn terms_and_normal_at(&mut self, s: &Surface, side: Side) -> (Terms, [f64; 3]) {
        let ids = self.job.mesh.triangles[s.triangle].map(|i| i as usize);
        let w = s.barycentrics.map(f64::from);
        let lit: [VertexLighting<f64>; 3] = ids.map(|i| *self.vertex(i));
        let blend = |f: &dyn Fn(&VertexLighting<f64>) -> DVec3| -> DVec3 { (0..3).map(|k| f(&lit[k]) * w[k]).sum() };
        let pos = blend(&|l| l.pos_in_eye);
        let (terms, n) = match self.job.mode {
            ShadingMode::Gouraud => {
                let t = lit.each_ref().map(|l| Terms::of(l, side));
                (Terms::blend(t.each_ref(), w), blend(&|l| l.normal_in_eye).normalize_or_zero())
            }
            ShadingMode::Phong => {
                let n = renormalised(blend(&|l| l.normal_transformed), self.job.options.renormalize);
                (Terms::of(&self.engine.light_eye(pos.extend(1.0), n), side), n)
            }
            ShadingMode::FlatDerivatives => {
                let n = face_normal(&lit) * if s.back { 1.0 } else { -1.0 };
                (Terms::of(&self.engine.light_eye(pos.extend(1.0), n), side), n)
            }
            ShadingMode::FlatProvoking => {
                let at = *self.vertex(self.job.mesh.provoking_vertex(s.triangle) as usize);
                (Terms::of(&at, side), at.normal_in_eye.normalize_or_zero())
            }
            ShadingMode::FlatFace => {
                let centroid = (lit[0].pos_in_eye + lit[1].pos_in_eye + lit[2].pos_in_eye) / 3.0;
                let n = face_normal(&lit);
                (Terms::of(&self.engine.light_eye(centroid.extend(1.0), n), side), n)
            }
        };
        // The side shown faces the other way on the back.
        match side {
            Side::Front => (terms, n.to_array()),
            Side::Back => (terms, (-n).to_array()),
        }
    }
}

/// Phong's interpolated normal as the fragment uses it: brought back to unit length, or
/// (as the Phong demo's shader) as interpolated.
fn renormalised(n: DVec3, how: Renormalize) -> DVec3 {
    if how == Renormalize::Skip { n } else { n.normalize_or_zero() }
}

/// The plane's unit normal of three lit vertices, counter-clockwise (mesh order) outward.
fn face_normal(lit: &[VertexLighting<f64>; 3]) -> DVec3 {
    let [a, b, c] = lit.each_ref().map(|l| l.pos_in_eye);
    (b - a).cross(c - a).normalize_or_zero()
}

/// A vertex colour as Gouraud interpolates it: each of primary and secondary clamped to
/// [0, 1] where the rules clamp vertex colours, then added.
fn vertex_colour(lit: &VertexLighting<f64>, side: Side, clamp: bool) -> [f64; 4] {
    let s = match side {
        Side::Front => &lit.front,
        Side::Back => &lit.back,
    };
    if !clamp {
        return s.sum();
    }
    let (p, q) = (s.primary_clamped(), s.secondary_clamped());
    [p[0] + q[0], p[1] + q[1], p[2] + q[2], p[3]]
}

/// Probes pixel (`x`, `y`) of the frame `renderer` last drew from `job`: `None` where no
/// triangle covers it.
pub fn probe(renderer: &Renderer, job: &Job<'_>, x: usize, y: usize) -> Result<Option<Probe>, SceneError> {
    let Some(sample) = renderer.sample(job, x, y) else {
        return Ok(None);
    };
    let mut surfaces = Surfaces::new(job)?;
    let surface = Surface { triangle: sample.triangle, barycentrics: sample.barycentrics, back: sample.back };
    // The renderer's sample names the side by its index (0 front, 1 back).
    let side = Side::back_if(sample.side == 1);
    let terms = surfaces.terms_at(&surface, side);
    let vertices = job.mesh.triangles[sample.triangle].map(|i| i as usize);
    let weights = sample.barycentrics.map(f64::from);
    let clamp = job.scene.rules.clamps_vertex_colors();
    let lit: [VertexLighting<f64>; 3] = vertices.map(|i| *surfaces.vertex(i));
    let shading = match job.mode {
        ShadingMode::Gouraud => {
            let vertex_colours = lit.each_ref().map(|l| vertex_colour(l, side, clamp));
            let weighted_sum = std::array::from_fn(|c| (0..3).map(|k| weights[k] * vertex_colours[k][c]).sum());
            ProbeShading::Gouraud(GouraudPixel {
                vertex_colours,
                vertex_unclamped: lit.each_ref().map(|l| vertex_colour(l, side, false)),
                weighted_sum,
                clamped: clamp,
            })
        }
        ShadingMode::Phong | ShadingMode::FlatDerivatives => {
            let raw = sample.normal.unwrap_or(Vec3::ZERO).as_dvec3();
            let how = if job.mode == ShadingMode::Phong { job.options.renormalize } else { Renormalize::Exact };
            ProbeShading::Phong(PhongPixel {
                normal_interpolated: raw.to_array(),
                normal_length: raw.length(),
                normal: renormalised(raw, how).to_array(),
                renormalised: how != Renormalize::Skip,
                position: sample.position.unwrap_or(Vec3::ZERO).as_dvec3().to_array(),
            })
        }
        ShadingMode::FlatFace => {
            let n = face_normal(&lit) * if side == Side::Back { -1.0 } else { 1.0 };
            ProbeShading::Flat(FlatPixel {
                centroid: ((lit[0].pos_in_eye + lit[1].pos_in_eye + lit[2].pos_in_eye) / 3.0).to_array(),
                normal: n.to_array(),
                provoking_vertex: vertices[2],
                provoking_colour: vertex_colour(&lit[2], side, clamp),
            })
        }
        ShadingMode::FlatProvoking => {
            let provoking = job.mesh.provoking_vertex(sample.triangle) as usize;
            let at = *surfaces.vertex(provoking);
            let n = at.normal_in_eye.normalize_or_zero() * if side == Side::Back { -1.0 } else { 1.0 };
            ProbeShading::Flat(FlatPixel {
                centroid: at.pos_in_eye.to_array(),
                normal: n.to_array(),
                provoking_vertex: provoking,
                provoking_colour: vertex_colour(&at, side, clamp),
            })
        }
    };
    Ok(Some(Probe {
        x,
        y,
        mode: job.mode,
        triangle: sample.triangle,
        vertices,
        back: sample.back,
        side,
        weights,
        unclamped: sample.colour.map(f64::from),
        rgba8: sample.rgba8,
        terms,
        shading,
        program: Program::worked(&Key::of(job.scene, job.options)),
    }))
}
