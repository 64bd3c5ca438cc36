//! Stage 2: triangles clipped, faced, culled and snapped to fixed point; Flat's face colours.
//!
//! Clipping is in homogeneous clip space (Sutherland-Hodgman): always against the near
//! and far planes (`-w <= z <= w`, so no vertex reaches w <= 0), and against x and y only
//! when a vertex lies beyond a guard band of 8 viewports (so fixed-point coordinates stay
//! small). Each clipped vertex carries its barycentric coordinates in the original
//! triangle, so the resolve stage interpolates the original vertices' attributes.

use glam::{Vec3, Vec4};
use rayon::prelude::*;

use super::Job;
use super::outcodes::{BEYOND_GUARD, GUARD, OUTSIDE_DEPTH, OUTSIDE_PLANES};
use super::vertices::Vertices;
use crate::model::view::ShadingMode;
use crate::specialise::lighter::Lighter;

pub use super::window::SUBPIXEL_BITS;
use super::window::{ONE, WindowVert, to_window};

/// A triangle ready to rasterise, in image space (y down), ordered so that its signed
/// area `(x1-x0)(y2-y0) - (x2-x0)(y1-y0)` is positive.
///
/// 76 bytes: a million of them are written by setup and read by binning, drawing and
/// the resolve every frame, so the corners are kept in 32 bits (a corner lies within
/// the guard band, under 5 viewports from the centre: 2^31 / 256 / 5 is over a million
/// pixels) and widened to 64 for the edge functions' products ([`RasterTri::xy`]), and
/// where its corners lie in the mesh triangle is a number ([`Corners`]): the mesh
/// triangle's own corners for all but the few triangles clipping cut.
#[derive(Clone, Copy, Debug, Default)]
pub struct RasterTri {
    /// Fixed-point x and y of the three vertices.
    pub x: [i32; 3],
    /// Fixed-point y.
    pub y: [i32; 3],
    /// Window depth in [0, 1].
    pub z: [f32; 3],
    /// 1/w, for perspective-correct interpolation.
    pub inv_w: [f32; 3],
    /// Each vertex's barycentric coordinates in the original mesh triangle.
    pub corners: Corners,
    /// The mesh triangle.
    pub orig: u32,
    /// Faces away from the viewer (drawn with the back side's colours).
    pub back: bool,
    /// Pixel bounding box (inclusive), clamped to the image.
    pub x0: i32,
    /// Last column.
    pub x1: i32,
    /// First row.
    pub y0: i32,
    /// Last row.
    pub y1: i32,
}

impl RasterTri {
    /// The slot of a mesh triangle that gives no raster triangle: an empty box of rows
    /// (binning skips it), marked a back face.
    pub const HOLE: RasterTri = RasterTri {
        x: [0; 3],
        y: [0; 3],
        z: [0.0; 3],
        inv_w: [0.0; 3],
        corners: Corners(0),
        orig: 0,
        back: true,
        x0: 0,
        x1: -1,
        y0: 0,
        y1: -1,
    };

    /// A slot with no triangle ([`RasterTri::HOLE`]).
    #[inline(always)]
    pub fn is_hole(&self) -> bool {
        self.y0 > self.y1
    }

    /// The corners' fixed-point x and y, widened for the edge functions' products.
    #[inline(always)]
    pub fn xy(&self) -> ([i64; 3], [i64; 3]) {
        (self.x.map(i64::from), self.y.map(i64::from))
    }
}

/// Where a raster triangle's three corners lie in its mesh triangle, as barycentric
/// coordinates: the mesh triangle's own corners in its order (0), or with the last two
/// swapped to turn it counter-clockwise on the screen (1), or, for a triangle that
/// clipping cut, entry `k` of the frame's [`ClippedCorners`] (`k + 2`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Corners(u32);

/// The clipped triangles' corners in their mesh triangles, for [`Corners`] to point into.
#[derive(Default)]
pub struct ClippedCorners(Vec<[[f32; 3]; 3]>);

impl ClippedCorners {
    /// The mesh triangle's corners, in its order.
    const OWN: [[f32; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    /// The same with the last two swapped.
    const TURNED: [[f32; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]];

    /// The barycentrics of triangle `t`'s corners in its mesh triangle.
    #[inline(always)]
    pub fn of(&self, t: &RasterTri) -> [[f32; 3]; 3] {
        match t.corners.0 {
            0 => Self::OWN,
            1 => Self::TURNED,
            k => self.0[k as usize - 2],
        }
    }
}

/// Per-frame results of stage 2.
#[derive(Default)]
pub struct Setup {
    /// Triangles to rasterise: one slot per mesh triangle, in its order (a hole where it
    /// gives none: [`RasterTri::is_hole`]), then the further pieces of those clipping cut
    /// into several, chunk by chunk ([`Setup::extra`] says where each chunk's are).
    pub tris: Vec<RasterTri>,
    /// For each chunk of [`GRAIN`] mesh triangles, where its further pieces are in `tris`.
    pub extra: Vec<std::ops::Range<u32>>,
    /// How many triangles are not holes.
    pub drawn: usize,
    /// Where the corners of the triangles clipping cut lie in their mesh triangles.
    pub corners: ClippedCorners,
    /// Flat shading: each mesh triangle's colour (clamped sum) per side.
    pub face_color: [Vec<[f32; 4]>; 2],
    /// Flat shading from screen derivatives: each mesh triangle's unit normal in eye
    /// space, `(b - a) x (c - a)` (counter-clockwise from outside: outward).
    pub face_normal: Vec<Vec3>,
    per_face: Vec<FaceChunk>,
}

/// Mesh triangles set up a chunk at a time.
pub const GRAIN: usize = 256;

/// What one chunk of mesh triangles gives besides its slots (`setup_faces`): the further
/// pieces of the triangles clipping cut into several, the corners of all it cut (numbered
/// within the chunk until they are gathered), and how many slots are not holes.
#[derive(Default)]
pub struct FaceChunk {
    tris: Vec<RasterTri>,
    corners: Vec<[[f32; 3]; 3]>,
    /// Which triangles point into `corners`: a slot's index in the chunk, or a piece's in
    /// `tris` with [`FaceChunk::PIECE`] set.
    cut: Vec<u32>,
    drawn: usize,
}

impl FaceChunk {
    const PIECE: u32 = 1 << 31;

    fn clear(&mut self) {
        self.tris.clear();
        self.corners.clear();
        self.cut.clear();
        self.drawn = 0;
    }
}

/// Where one chunk of mesh triangles goes: one slot each, and the rest.
pub struct ChunkOut<'a> {
    /// The chunk's slots in [`Setup::tris`].
    pub slots: &'a mut [RasterTri],
    /// The rest.
    pub rest: &'a mut FaceChunk,
}

#[derive(Clone, Copy, Default)]
struct ClipVert {
    clip: Vec4,
    bary: [f32; 3],
}

/// A convex polygon of at most 9 vertices (a triangle clipped by 6 planes), on the stack.
#[derive(Clone, Copy, Default)]
struct Poly {
    v: [ClipVert; 9],
    n: usize,
}

impl Poly {
    fn push(&mut self, c: ClipVert) {
        if self.n < self.v.len() {
            self.v[self.n] = c;
            self.n += 1;
        }
    }

    fn as_slice(&self) -> &[ClipVert] {
        &self.v[..self.n]
    }
}

fn lerp(a: &ClipVert, b: &ClipVert, t: f32) -> ClipVert {
    ClipVert {
        clip: a.clip + (b.clip - a.clip) * t,
        bary: [
            a.bary[0] + (b.bary[0] - a.bary[0]) * t,
            a.bary[1] + (b.bary[1] - a.bary[1]) * t,
            a.bary[2] + (b.bary[2] - a.bary[2]) * t,
        ],
    }
}

/// Clips a polygon against `dist(v) >= 0` (dist linear in clip space).
fn clip_plane(p: &Poly, dist: impl Fn(Vec4) -> f32) -> Poly {
    let poly = p.as_slice();
    let mut out = Poly::default();
    for i in 0..poly.len() {
        let (a, b) = (&poly[i], &poly[(i + 1) % poly.len()]);
        let (da, db) = (dist(a.clip), dist(b.clip));
        if da >= 0.0 {
            out.push(*a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(lerp(a, b, da / (da - db)));
        }
    }
    out
}

/// Are all three corners (their [`outcodes`](super::outcodes)) outside the same plane?
/// Then nothing of the triangle is visible.
#[inline(always)]
fn trivially_rejected(codes: [u8; 3]) -> bool {
    codes[0] & codes[1] & codes[2] & OUTSIDE_PLANES != 0
}

/// Which triangles a pixel can show: the back faces culled or not, and the depth test
/// (`GL_DEPTH_TEST`) on or off.
#[derive(Clone, Copy, Debug)]
struct Seen {
    cull_back: bool,
    depth_test: bool,
}

impl Seen {
    fn of(job: &Job<'_>) -> Seen {
        Seen { cull_back: job.cull_back, depth_test: job.depth_test }
    }
}

/// Without the depth test, the depth that lets each triangle cover the ones drawn before it
/// whatever their depth: flat, and strictly decreasing in the mesh's order (`1 - (i + 1)
/// 2^-23`, exact in f32 and above 0 for the first 2^23 - 1 triangles), so the depth buffer's
/// "less than" keeps the last drawn, as OpenGL does with the test off, in whatever order
/// the bands meet them.
fn depth_in_drawing_order(orig: u32) -> f32 {
    1.0 - (orig.min((1 << 23) - 2) as f32 + 1.0) * f32::EPSILON
}

/// The raster triangle of window vertices `v`, turned counter-clockwise on the screen
/// (its corners the mesh triangle's, in its order or turned: [`Corners`]); `None` if it
/// has no area, is a culled back face, or covers no pixel centre of the image.
#[inline(always)]
fn raster_tri(v: [WindowVert; 3], orig: u32, width: usize, height: usize, seen: Seen) -> Option<RasterTri> {
    let (a, b, c) = (v[0], v[1], v[2]);
    let area = (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1);
    if area == 0 {
        return None;
    }
    // OpenGL's counter-clockwise front faces (y up) have negative area with y down.
    let back = area > 0;
    if back && seen.cull_back {
        return None;
    }
    let (v, corners) = if area < 0 { ([v[0], v[2], v[1]], Corners(1)) } else { (v, Corners(0)) };
    let x0 = v[0].0.min(v[1].0).min(v[2].0);
    let x1 = v[0].0.max(v[1].0).max(v[2].0);
    let y0 = v[0].1.min(v[1].1).min(v[2].1);
    let y1 = v[0].1.max(v[1].1).max(v[2].1);
    // Pixels whose centres (p + 1/2) may be inside.
    let px0 = ((x0 - ONE / 2 + ONE - 1) >> SUBPIXEL_BITS).max(0) as i32;
    let px1 = ((x1 - ONE / 2) >> SUBPIXEL_BITS).min(width as i64 - 1) as i32;
    let py0 = ((y0 - ONE / 2 + ONE - 1) >> SUBPIXEL_BITS).max(0) as i32;
    let py1 = ((y1 - ONE / 2) >> SUBPIXEL_BITS).min(height as i64 - 1) as i32;
    if px0 > px1 || py0 > py1 {
        return None;
    }
    Some(RasterTri {
        x: [v[0].0 as i32, v[1].0 as i32, v[2].0 as i32],
        y: [v[0].1 as i32, v[1].1 as i32, v[2].1 as i32],
        z: if seen.depth_test { [v[0].2, v[1].2, v[2].2] } else { [depth_in_drawing_order(orig); 3] },
        inv_w: [v[0].3, v[1].3, v[2].3],
        corners,
        orig,
        back,
        x0: px0,
        x1: px1,
        y0: py0,
        y1: py1,
    })
}

/// Snaps a clipped polygon (fan) to raster triangles, their corners' barycentrics kept
/// in the chunk's own table: the first into the mesh triangle's slot (`at` in the chunk),
/// the others after the chunk's earlier pieces.
#[inline(always)]
fn emit(poly: &[ClipVert], orig: u32, width: usize, height: usize, seen: Seen, at: usize, out: &mut ChunkOut<'_>) {
    if poly.len() < 3 {
        return;
    }
    let (w, h) = (width as f32, height as f32);
    let mut win = [(0i64, 0i64, 0.0f32, 0.0f32); 9];
    for (o, v) in win.iter_mut().zip(poly) {
        *o = to_window(v.clip, w, h);
    }
    for k in 1..poly.len() - 1 {
        let idx = [0, k, k + 1];
        if let Some(mut t) = raster_tri(idx.map(|i| win[i]), orig, width, height, seen) {
            let (rest, b) = (&mut *out.rest, idx.map(|i| poly[i].bary));
            rest.corners.push(if t.corners == Corners(1) { [b[0], b[2], b[1]] } else { b });
            t.corners = Corners(rest.corners.len() as u32 + 1);
            rest.drawn += 1;
            if out.slots[at].is_hole() {
                rest.cut.push(at as u32);
                out.slots[at] = t;
            } else {
                rest.cut.push(FaceChunk::PIECE | rest.tris.len() as u32);
                rest.tris.push(t);
            }
        }
    }
}

impl Setup {
    /// How many of `tris` are the mesh triangles' slots (the rest are further pieces).
    pub fn slots(&self) -> usize {
        self.extra.first().map_or(self.tris.len(), |e| e.start as usize)
    }

    /// Clips, faces, culls and snaps every triangle of the job; lights faces for Flat.
    /// `setup_faces` does a chunk of faces into a vector (a copy of `setup_faces` for this
    /// processor and image, chosen by the caller).
    pub fn run(
        &mut self,
        job: &Job<'_>,
        verts: &Vertices,
        lighter: &Lighter,
        setup_faces: impl Fn(std::ops::Range<usize>, ChunkOut<'_>) + Sync,
    ) {
        let tris = &job.mesh.triangles;
        let chunks = tris.len().div_ceil(GRAIN);
        self.per_face.resize_with(chunks, FaceChunk::default);
        // Each chunk writes its mesh triangles' slots in place: no copy of a million
        // triangles into one array afterwards (it was a tenth of a frame).
        self.tris.resize(tris.len(), RasterTri::HOLE);
        self.tris.par_chunks_mut(GRAIN).zip(self.per_face.par_iter_mut()).enumerate().for_each(|(k, (slots, rest))| {
            let faces = k * GRAIN..k * GRAIN + slots.len();
            setup_faces(faces, ChunkOut { slots, rest });
        });
        // The few further pieces of clipped triangles after the slots, chunk by chunk, and
        // the clipped corners gathered, the triangles that point to them renumbered.
        self.corners.0.clear();
        self.extra.clear();
        self.drawn = 0;
        for (k, c) in self.per_face.iter().enumerate() {
            let (first, before) = (self.tris.len(), self.corners.0.len() as u32);
            self.tris.extend_from_slice(&c.tris);
            self.corners.0.extend_from_slice(&c.corners);
            self.extra.push(first as u32..self.tris.len() as u32);
            self.drawn += c.drawn;
            for &i in &c.cut {
                let at = if i & FaceChunk::PIECE != 0 {
                    first + (i & !FaceChunk::PIECE) as usize
                } else {
                    k * GRAIN + i as usize
                };
                self.tris[at].corners.0 += before;
            }
        }
        self.face_normals(job, verts);
        self.light_faces(job, verts, lighter);
    }

    /// The derivative Flat's per-face work: each face's plane normal (geometry alone: kept
    /// with the rasterised triangles). Part of [`Setup::run`].
    fn face_normals(&mut self, job: &Job<'_>, verts: &Vertices) {
        if job.mode != ShadingMode::FlatDerivatives {
            return;
        }
        let tris = &job.mesh.triangles;
        // Lit per fragment (resolve); here only each face's plane normal, on both threads.
        self.face_normal.resize(tris.len(), Vec3::ZERO);
        self.face_normal.par_chunks_mut(GRAIN).zip(tris.par_chunks(GRAIN)).for_each(|(out, ts)| {
            for (n, t) in out.iter_mut().zip(ts) {
                let [a, b, c] = t.map(|i| verts.eye[i as usize]);
                *n = face_normal(a, b, c);
            }
        });
    }

    /// Flat per face's per-face work: each face's colour. Part of [`Setup::run`]; alone
    /// when only the lighting changed and the rasterised triangles are kept.
    pub fn light_faces(&mut self, job: &Job<'_>, verts: &Vertices, lighter: &Lighter) {
        if job.mode == ShadingMode::FlatProvoking {
            return self.provoking_faces(job, verts);
        }
        if job.mode != ShadingMode::FlatFace {
            return;
        }
        let tris = &job.mesh.triangles;
        let corners_of = |t: &[u32; 3]| t.map(|i| verts.eye[i as usize]);
        // One evaluation per face: at its centroid, with its geometric normal. On both
        // threads, a chunk of faces at a time (a serial pass was most of Flat's setup at 3
        // million triangles).
        let two = job.scene.light_model.two_sided;
        for side in 0..2 {
            self.face_color[side].resize(tris.len(), [0.0; 4]);
        }
        let [front, back] = &mut self.face_color;
        front.par_chunks_mut(GRAIN).zip(back.par_chunks_mut(GRAIN)).zip(tris.par_chunks(GRAIN)).for_each(
            |((f, b), ts)| {
                let (mut pos, mut nrm) = ([Vec3::ZERO; GRAIN], [Vec3::ZERO; GRAIN]);
                for ((p, n), t) in pos.iter_mut().zip(&mut nrm).zip(ts) {
                    let [a, b, c] = corners_of(t);
                    (*p, *n) = ((a + b + c) / 3.0, face_normal(a, b, c));
                }
                let k = ts.len();
                lighter.light_batch_eye_sum(&pos[..k], &nrm[..k], f, if two { Some(b) } else { None });
                if !two {
                    b.copy_from_slice(f);
                }
            },
        );
    }

    /// `GL_FLAT`'s per-face work: each face the colour of its provoking vertex, lit per
    /// vertex as Gouraud lights it (clamped as the pipeline clamps it), both sides.
    fn provoking_faces(&mut self, job: &Job<'_>, verts: &Vertices) {
        let mesh = job.mesh;
        for (side, colours) in self.face_color.iter_mut().enumerate() {
            colours.clear();
            colours.extend(
                (0..mesh.triangles.len())
                    .map(|t| verts.color[side].get(mesh.provoking_vertex(t) as usize).copied().unwrap_or_default()),
            );
        }
    }
}

/// Clips, faces, culls and snaps the mesh triangles `faces` into their slots and the rest
/// of `out` (every slot written, a hole where a triangle gives none; the rest cleared
/// first). (Written once, `#[inline(always)]`; `copies` compiles it for each processor.)
#[inline(always)]
pub(super) fn setup_faces(
    job: &Job<'_>,
    verts: &Vertices,
    faces: std::ops::Range<usize>,
    width: usize,
    height: usize,
    mut out: ChunkOut<'_>,
) {
    out.rest.clear();
    let first = faces.start;
    for j in faces {
        let at = j - first;
        let t = job.mesh.triangles[j];
        // Written out: `array::map` was left as a call, once per triangle.
        let codes = [verts.codes[t[0] as usize], verts.codes[t[1] as usize], verts.codes[t[2] as usize]];
        if trivially_rejected(codes) {
            out.slots[at] = RasterTri::HOLE;
            continue;
        }
        let any = codes[0] | codes[1] | codes[2];
        let (depth, guard) = (any & OUTSIDE_DEPTH != 0, any & BEYOND_GUARD != 0);
        if !depth && !guard {
            // Nothing to clip (most triangles): the corners as they are, in window
            // coordinates already.
            let win = &verts.window;
            let v = [win[t[0] as usize], win[t[1] as usize], win[t[2] as usize]];
            match raster_tri(v, j as u32, width, height, Seen::of(job)) {
                Some(t) => (out.slots[at], out.rest.drawn) = (t, out.rest.drawn + 1),
                None => out.slots[at] = RasterTri::HOLE,
            }
            continue;
        }
        // Each corner with its barycentrics in the mesh triangle: (1, 0, 0) and so on.
        let c = [verts.clip[t[0] as usize], verts.clip[t[1] as usize], verts.clip[t[2] as usize]];
        let mut poly = Poly::default();
        for (k, &clip) in c.iter().enumerate() {
            let mut bary = [0.0; 3];
            bary[k] = 1.0;
            poly.push(ClipVert { clip, bary });
        }
        if depth {
            poly = clip_plane(&poly, |v| v.z + v.w);
            poly = clip_plane(&poly, |v| v.w - v.z);
        }
        if guard {
            for s in [1.0f32, -1.0] {
                poly = clip_plane(&poly, |v| GUARD * v.w - s * v.x);
                poly = clip_plane(&poly, |v| GUARD * v.w - s * v.y);
            }
        }
        out.slots[at] = RasterTri::HOLE;
        emit(poly.as_slice(), j as u32, width, height, Seen::of(job), at, &mut out);
    }
}

/// The unit normal of a face from its eye-space corners (zero when degenerate).
pub fn face_normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    (b - a).cross(c - a).normalize_or_zero()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The raster triangle stays 76 bytes (it was 136 with 64-bit corners and the
    /// barycentrics of its corners in it), and a corner at the guard band's edge of a
    /// 16 384-pixel view keeps its bits in 32.
    #[test]
    fn a_raster_triangle_is_76_bytes_and_its_corners_fit() {
        assert_eq!(std::mem::size_of::<RasterTri>(), 76);
        let (w, h) = (16_384.0, 16_384.0);
        let corner = to_window(Vec4::new(GUARD, -GUARD, 0.0, 1.0), w, h);
        assert_eq!(corner.0 as i32 as i64, corner.0);
        assert_eq!(corner.1 as i32 as i64, corner.1);
        assert!(corner.0 > 1 << 24, "{corner:?}");
    }

    /// Outcodes reject exactly the triangles with all three corners beyond one plane.
    #[test]
    fn trivially_rejected_means_all_corners_beyond_one_plane() {
        let mut words = crate::test_support::xorshift(0x2545f4914f6cdd1d);
        let mut next = move || (words() % 2001) as f32 / 500.0 - 2.0;
        let (mut rejected, mut kept) = (0, 0);
        for _ in 0..100_000 {
            let c = [0; 3].map(|_| Vec4::new(next(), next(), next(), 1.0));
            let all = |f: &dyn Fn(&Vec4) -> bool| c.iter().all(f);
            let want = all(&|v| v.x < -v.w)
                || all(&|v| v.x > v.w)
                || all(&|v| v.y < -v.w)
                || all(&|v| v.y > v.w)
                || all(&|v| v.z < -v.w)
                || all(&|v| v.z > v.w);
            assert_eq!(trivially_rejected(c.map(super::super::outcodes::code)), want, "{c:?}");
            if want { rejected += 1 } else { kept += 1 }
        }
        assert!(rejected > 1000 && kept > 1000, "{rejected} / {kept}");
        assert!(!trivially_rejected([Vec4::NAN; 3].map(super::super::outcodes::code)));
    }
}
