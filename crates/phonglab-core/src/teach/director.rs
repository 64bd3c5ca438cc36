//! The director's view: the scene seen from outside, as 3D segments and marks in one chosen
//! space (object, world or eye), for the window to project and draw.
//!
//! | what | drawn as | from |
//! |---|---|---|
//! | the eye | a point, its frustum (near plane = the viewport, far plane cut to the scene) | `clip_from_eye`'s inverse on the NDC cube's corners |
//! | a directional light | parallel rays across the scene | its direction in eye space |
//! | a positional light | a point, rings where its attenuation factor `1/at` falls to 50 % and 10 % | `at = k0 + k1 d + k2 d² = 1/f` |
//! | a spotlight | its cone, rims at a quarter, half, three quarters and all of the cutoff, each as bright as `cos^s_rl` there | OpenGL 2.1 eq. 2.6 |
//! | the worked vertex | N, L, V, H, all one length in the space shown (so their foreshortening is true) | the engine's breakdown |
//! | its surface | a small square in the tangent plane, moved as points | `display_from_object` |
//! | `M n` | a second normal, where it differs from `(M^-1)^T n` by more than half a degree | the worksheet's rule |
//!
//! Points go between spaces by the scene's matrices: eye from object `M = eye_from_world *
//! world_from_object`; directions between points (L, V) as differences of points; normals
//! by the inverse transpose. In object space `M n` and the true normal coincide; in eye
//! space under an uneven modelview (the worksheet's mview3 and mview4) the square turns
//! and shears, the true normal stays perpendicular to it, and `M n` does not.

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::equation::lighting::Engine;
use crate::mesh::Mesh;
use crate::model::error::SceneError;
use crate::model::rules::NormalTransform;
use crate::model::scene::Scene;

/// The space the director's view shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Space {
    /// The object's own coordinates (before the modelview).
    Object,
    /// The world (after the model transform, before the camera's).
    #[default]
    World,
    /// Eye space: the eye at the origin looking down -z.
    Eye,
}

impl Space {
    /// Every space, in the switch's order.
    pub const ALL: [Space; 3] = [Space::Object, Space::World, Space::Eye];

    /// Its label's message id.
    pub fn message_id(self) -> &'static str {
        match self {
            Space::Object => "space-object",
            Space::World => "space-world",
            Space::Eye => "space-eye",
        }
    }
}

/// What a segment or mark is: its colour and meaning in the window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// The object's mesh.
    Object,
    /// The eye.
    Eye,
    /// The frustum's edges.
    Frustum,
    /// The near plane: the viewport.
    Viewport,
    /// Light `i` (its position, or a directional light's rays).
    Light(usize),
    /// A ring of light `i` where its attenuation factor `1/at` is `f` (0.5 or 0.1).
    Ring(usize, f64),
    /// Light `i`'s spot cone; `strength` is `cos^s_rl` at this rim (1 on the axis).
    Cone(usize, f64),
    /// The vertex's normal, `(M^-1)^T n`.
    Normal,
    /// `M n`, the normal transformed as a point would be.
    NaiveNormal,
    /// L towards light `i`.
    ToLight(usize),
    /// V, towards the eye.
    ToEye,
    /// H for light `i`.
    Halfway(usize),
    /// The small square of surface around the vertex.
    Patch,
    /// The worked vertex.
    Vertex,
}

/// A line from `a` to `b` in the space shown.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// One end.
    pub a: DVec3,
    /// The other.
    pub b: DVec3,
    /// What it is.
    pub kind: Kind,
}

/// A point with a name.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mark {
    /// Where.
    pub at: DVec3,
    /// What.
    pub kind: Kind,
}

/// Everything the director's view draws, in one space.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stage {
    /// The lines.
    pub segments: Vec<Segment>,
    /// The points.
    pub marks: Vec<Mark>,
    /// A sphere holding what matters (the vertex, the eye, the lights, the near plane), to
    /// frame the picture.
    pub centre: DVec3,
    /// Its radius.
    pub radius: f64,
    /// Where each ring of each light is: (light, fraction, radius).
    pub rings: Vec<(usize, f64, f64)>,
    /// The angle between `(M^-1)^T n` and `M n` in the space shown, in degrees.
    pub naive_normal_off_deg: f64,
    /// This scene's rules light the vertex with `M n` (the worksheet's), not the true normal.
    pub rules_use_naive: bool,
    /// Each light's position in the space shown (`None`: directional).
    pub lights: Vec<Option<DVec3>>,
}

/// Where light `i`'s attenuation factor `1/at = 1 / (k0 + k1 d + k2 d²)` falls to `f`: the distance d >= 0
/// with `k0 + k1 d + k2 d² = 1 / f`, if there is one (none when it never falls so far, or
/// is already there at d = 0).
pub fn ring_radius(k: [f64; 3], f: f64) -> Option<f64> {
    let target = 1.0 / f - k[0];
    if target <= 0.0 {
        return None;
    }
    let (a, b) = (k[2], k[1]);
    if a.abs() < 1e-300 {
        return (b > 0.0).then(|| target / b);
    }
    let disc = b * b + 4.0 * a * target;
    (disc >= 0.0).then(|| (-b + disc.sqrt()) / (2.0 * a)).filter(|d| *d > 0.0 && d.is_finite())
}

/// The stage of `scene` in `space`: the eye with the frustum of `clip_from_eye`, the lights,
/// the worked vertex and its vectors, and `mesh` (object space) when given.
pub fn stage(scene: &Scene, mesh: Option<&Mesh>, clip_from_eye: DMat4, space: Space) -> Result<Stage, SceneError> {
    let lit = Engine::<f64>::light_scene_vertex(scene)?;
    let eye_from_object = scene.eye_from_object();
    let display_from_eye = match space {
        Space::Eye => DMat4::IDENTITY,
        Space::World => scene.eye_from_world.inverse(),
        Space::Object => eye_from_object.inverse(),
    };
    let display_from_object = display_from_eye * eye_from_object;
    let point = |p: DVec3| display_from_eye.transform_point3(p);
    let mut st = Stage::default();

    // The vertex, and the length every vector is drawn at: a fifth of the distance to the
    // nearest light or the eye, in the space shown.
    let vertex = point(lit.pos_in_eye);
    let eye = point(DVec3::ZERO);
    let mut framed = vec![vertex, eye];
    let mut light_points = Vec::new();
    for (i, l) in scene.lights.iter().enumerate() {
        let p = scene.light_pos_in_eye(l);
        light_points.push((i, l, p));
        let at = (p.w != 0.0).then(|| point(p.truncate() / p.w));
        st.lights.push(at);
        framed.extend(at);
    }
    let reach = framed.iter().map(|p| p.distance(vertex)).filter(|d| *d > 0.0).fold(f64::INFINITY, f64::min);
    let len = if reach.is_finite() { 0.3 * reach } else { 1.0 };

    vectors(&mut st, scene, &lit, display_from_eye, display_from_object, vertex, len);
    frustum(&mut st, clip_from_eye, display_from_eye, &mut framed);
    let (centre, radius) = bounds(&framed);
    for (i, l, p) in light_points {
        light(&mut st, i, l, (p, scene.eye_from_light(l)), display_from_eye, vertex, radius);
    }
    if let Some(mesh) = mesh {
        let stride = (mesh.triangles.len() / 3000).max(1);
        for t in mesh.triangles.iter().step_by(stride) {
            let [a, b, c] = t.map(|i| display_from_object.transform_point3(mesh.positions[i as usize].as_dvec3()));
            for (a, b) in [(a, b), (b, c), (c, a)] {
                st.segments.push(Segment { a, b, kind: Kind::Object });
            }
        }
    }
    st.marks.push(Mark { at: eye, kind: Kind::Eye });
    st.marks.push(Mark { at: vertex, kind: Kind::Vertex });
    (st.centre, st.radius) = (centre, radius);
    Ok(st)
}

/// N (true and, where it differs, `M n`), L, V and H at the vertex, `len` long each in the
/// space shown, and the square of surface around it.
fn vectors(
    st: &mut Stage,
    scene: &Scene,
    lit: &crate::equation::breakdown::VertexLighting<f64>,
    display_from_eye: DMat4,
    display_from_object: DMat4,
    vertex: DVec3,
    len: f64,
) {
    let linear = DMat3::from_mat4(display_from_eye);
    // A direction between points goes as the points do.
    let direction = |v: DVec3| (linear * v).normalize_or_zero() * len;
    // The object's normal in the space shown: by the inverse transpose (perpendicular to
    // the surface, OpenGL's), and as a point would go (`M n`, the worksheet's rule).
    let m = DMat3::from_mat4(display_from_object);
    let n_obj = scene.vertex.normal;
    let n = (m.inverse().transpose() * n_obj).normalize_or_zero() * len;
    st.segments.push(Segment { a: vertex, b: vertex + n, kind: Kind::Normal });
    let naive = (m * n_obj).normalize_or_zero() * len;
    st.naive_normal_off_deg = n.angle_between(naive).to_degrees();
    st.rules_use_naive = scene.rules.normal_transform() == NormalTransform::Modelview;
    if st.naive_normal_off_deg > 0.5 {
        st.segments.push(Segment { a: vertex, b: vertex + naive, kind: Kind::NaiveNormal });
    }
    st.segments.push(Segment { a: vertex, b: vertex + direction(lit.v), kind: Kind::ToEye });
    for (i, l) in lit.lights().iter().enumerate() {
        st.segments.push(Segment { a: vertex, b: vertex + direction(l.l), kind: Kind::ToLight(i) });
        st.segments.push(Segment { a: vertex, b: vertex + direction(l.h), kind: Kind::Halfway(i) });
    }
    // The surface: a square in the tangent plane of the object-space normal, as points.
    let n_obj = scene.vertex.normal.normalize_or_zero();
    let (t, b) = n_obj.any_orthonormal_pair();
    let p0 = scene.vertex.position.truncate() / scene.vertex.position.w.max(f64::MIN_POSITIVE);
    // Its side: `len` in the space shown, whatever the scale between them.
    let scale = len / (m * t).length().max(1e-300);
    let corners = [t + b, t - b, -t - b, -t + b].map(|c| display_from_object.transform_point3(p0 + c * 0.5 * scale));
    for k in 0..4 {
        st.segments.push(Segment { a: corners[k], b: corners[(k + 1) % 4], kind: Kind::Patch });
    }
}

/// The frustum of `clip_from_eye`: its near plane (the viewport) whole, its edges to the far
/// plane cut where it passes three times the other things' reach.
fn frustum(st: &mut Stage, clip_from_eye: DMat4, display_from_eye: DMat4, framed: &mut Vec<DVec3>) {
    let eye_from_clip = clip_from_eye.inverse();
    let corner = |x: f64, y: f64, z: f64| {
        let p = eye_from_clip * DVec4::new(x, y, z, 1.0);
        p.truncate() / p.w
    };
    let xy = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
    let near = xy.map(|(x, y)| corner(x, y, -1.0));
    let far = xy.map(|(x, y)| corner(x, y, 1.0));
    let (c0, r0) = bounds(framed);
    let cut = |p: DVec3| {
        let most = c0.length() + 3.0 * r0.max(near[0].length());
        if p.length() > most { p * (most / p.length()) } else { p }
    };
    let point = |p: DVec3| display_from_eye.transform_point3(p);
    for k in 0..4 {
        let (a, b) = (point(near[k]), point(near[(k + 1) % 4]));
        st.segments.push(Segment { a, b, kind: Kind::Viewport });
        let (fa, fb) = (point(cut(far[k])), point(cut(far[(k + 1) % 4])));
        st.segments.push(Segment { a: fa, b: fb, kind: Kind::Frustum });
        st.segments.push(Segment { a: point(DVec3::ZERO), b: fa, kind: Kind::Frustum });
        framed.push(a);
    }
}

/// One light: a point with its rings, a spotlight's cone, or a directional light's rays.
fn light(
    st: &mut Stage,
    i: usize,
    l: &crate::model::scene::Light,
    (p, eye_from_light): (DVec4, DMat4),
    display_from_eye: DMat4,
    vertex: DVec3,
    radius: f64,
) {
    let point = |q: DVec3| display_from_eye.transform_point3(q);
    let linear = DMat3::from_mat4(display_from_eye);
    if p.w == 0.0 {
        // Parallel rays towards -direction, through the neighbourhood of the vertex.
        let d = (linear * -p.truncate()).normalize_or_zero();
        let (u, v) = d.any_orthonormal_pair();
        for (a, b) in [(0.0, 0.0), (1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)] {
            let through = vertex + (u * a + v * b) * 0.3 * radius;
            st.segments.push(Segment { a: through - d * radius, b: through, kind: Kind::Light(i) });
        }
        return;
    }
    let at_eye = p.truncate() / p.w;
    let at = point(at_eye);
    st.marks.push(Mark { at, kind: Kind::Light(i) });
    // Rings: three great circles of the sphere where 1/at is f. The distance is
    // the eye-space one (OpenGL attenuates there); the circles are drawn in eye space and
    // moved to the space shown, so an uneven modelview shows them as ellipses.
    for f in [0.5, 0.1] {
        let Some(r) = ring_radius(l.attenuation, f) else { continue };
        st.rings.push((i, f, r));
        for (u, v) in [(DVec3::X, DVec3::Y), (DVec3::Y, DVec3::Z), (DVec3::Z, DVec3::X)] {
            circle(st, |t| point(at_eye + (u * t.cos() + v * t.sin()) * r), Kind::Ring(i, f));
        }
    }
    if l.spot_cutoff < 180.0 {
        let axis = l.spot_direction.normalize_or_zero();
        // The spot direction goes by the upper 3x3 of the light's own modelview.
        let axis_eye = (DMat3::from_mat4(eye_from_light) * axis).normalize_or_zero();
        let axis_eye = if axis_eye == DVec3::ZERO { axis } else { axis_eye };
        let (u, v) = axis_eye.any_orthonormal_pair();
        let reach = (at_eye - display_from_eye.inverse().transform_point3(vertex)).length().max(1e-9) * 1.2;
        let cutoff = l.spot_cutoff.to_radians();
        for k in 1..=4 {
            let angle = cutoff * k as f64 / 4.0;
            let strength = angle.cos().max(0.0).powf(l.spot_exponent);
            let rim =
                |t: f64| point(at_eye + (axis_eye * angle.cos() + (u * t.cos() + v * t.sin()) * angle.sin()) * reach);
            circle(st, rim, Kind::Cone(i, strength));
            if k == 4 {
                for j in 0..8 {
                    let t = j as f64 * std::f64::consts::TAU / 8.0;
                    st.segments.push(Segment { a: at, b: rim(t), kind: Kind::Cone(i, strength) });
                }
            }
        }
    }
}

/// A closed curve of 48 segments through `at(t)`, t in [0, 2 pi).
fn circle(st: &mut Stage, at: impl Fn(f64) -> DVec3, kind: Kind) {
    let n = 48;
    for k in 0..n {
        let (t0, t1) = (k as f64, (k + 1) as f64);
        let step = std::f64::consts::TAU / n as f64;
        st.segments.push(Segment { a: at(t0 * step), b: at(t1 * step), kind });
    }
}

/// A sphere around the points: their centre and the largest distance from it.
fn bounds(points: &[DVec3]) -> (DVec3, f64) {
    if points.is_empty() {
        return (DVec3::ZERO, 1.0);
    }
    let centre = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    let radius = points.iter().map(|p| p.distance(centre)).fold(0.0, f64::max);
    (centre, if radius > 0.0 { radius } else { 1.0 })
}
