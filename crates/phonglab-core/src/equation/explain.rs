//! The worked calculation: a breakdown as numbered steps in the worksheet's order.
//!
//! Order (the worksheet's): transformed normal N, L, V, ambient, diffuse, H, specular,
//! attenuation, I — with the steps the worksheet leaves implicit (eye-space positions,
//! d, the cosines, spot, each light's contribution, scene ambient, emission) in between.
//! The CLI prints [`Explanation::to_text`]; the app draws the same steps and copies
//! [`Explanation::to_markdown`].

use std::fmt::Write as _;

use crate::model::vocabulary::Quantity::{self, self as Q};
use crate::t;

use crate::equation::breakdown::{LightTerms, Limit, Limits, SideColor, SideTerms, VertexLighting};
use crate::equation::lighting::EvalOptions;
use crate::equation::plan::{Key, Program, SpecularTerm, Stage, Viewer};
use crate::model::rules::SpecularVector;
use crate::model::scene::{ColorMaterialMode, LightId, Scene};
use crate::numerics::elementary;
use crate::numerics::real::{Real, Vec3Ops};

/// Which face side to explain (the model's side, named here too).
pub use crate::model::scene::Side;

/// What a step computes; the app colours steps and the plot's vectors by kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StepKind {
    /// N.
    Normal,
    /// P, the vertex in eye space.
    Position,
    /// The light's position in eye space.
    LightPosition,
    /// L = VP.
    L,
    /// d = |VP|.
    Distance,
    /// V.
    V,
    /// a_cm a_cli.
    Ambient,
    /// n . L.
    CosTheta,
    /// max(n.L, 0) d_cm d_cli.
    Diffuse,
    /// H.
    H,
    /// R.
    R,
    /// n . H or R . V.
    CosBeta,
    /// The specular term.
    Specular,
    /// `at = k0 + k1 d + k2 d²`, the worksheet's, which divides (OpenGL's att is 1/at).
    Attenuation,
    /// spot.
    Spot,
    /// spot (ambient + diffuse + specular) / at.
    Contribution,
    /// a_cm a_cs.
    SceneAmbient,
    /// e_cm.
    Emission,
    /// The primary colour I.
    Primary,
    /// The secondary colour.
    Secondary,
    /// rgba as OpenGL delivers it, clamped.
    Clamped,
}

impl Limit {
    /// The step a limit is shown beside.
    pub fn step_kind(self) -> StepKind {
        match self {
            Limit::ZeroNormal | Limit::NormalScaled | Limit::SingularModelview => StepKind::Normal,
            Limit::VertexAtInfinity => StepKind::Position,
            Limit::VertexAtEye => StepKind::V,
            Limit::LightAtVertex | Limit::LightDirectionZero => StepKind::L,
            Limit::DistanceScaled => StepKind::Distance,
            Limit::AttenuationInfinite => StepKind::Attenuation,
            Limit::SpotDirectionZero | Limit::SpotAtVertex => StepKind::Spot,
            Limit::HalfwayZero => StepKind::H,
            Limit::InfinitiesCancelled => StepKind::Primary,
        }
    }
}

/// One line of the worked calculation.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// What it computes.
    pub kind: StepKind,
    /// The light it belongs to (`None`: the vertex or the total).
    pub light: Option<usize>,
    /// A title, e.g. "Transformed normal".
    pub title: String,
    /// The variable name the worksheet prints it under, e.g. `vertexNormal`.
    pub name: String,
    /// The formula, e.g. `N = (M^-1)^T n`.
    pub formula: String,
    /// The value: 1 number, or a vector/colour printed worksheet-style with 4 components;
    /// `None` where the step does not apply (e.g. d for a directional light).
    pub value: Option<Vec<f64>>,
    /// Why the value is absent, or what limit the engine took here.
    pub notes: Vec<String>,
}

/// A whole worked calculation.
#[derive(Clone, Debug, PartialEq)]
pub struct Explanation {
    /// One line describing what was explained.
    pub heading: String,
    /// The steps in order.
    pub steps: Vec<Step>,
}

fn dir4<S: Real>(v: S::V3) -> Vec<f64> {
    vec![v.x().to_f64(), v.y().to_f64(), v.z().to_f64(), 0.0]
}

pub use crate::locale::fmt_sig;

/// Formats a value worksheet-style: a scalar alone, a vector as `[a b c d]`; a value that
/// is not finite as NumPy prints it (`inf`, `-inf`, `nan`: code, the same in every
/// language, never the English word `Infinity`).
pub fn fmt_value(v: &[f64], sig: usize) -> String {
    let one = |x: f64| match x {
        x if x.is_nan() => "nan".to_string(),
        x if x.is_infinite() => if x > 0.0 { "inf" } else { "-inf" }.to_string(),
        x => fmt_sig(x, sig),
    };
    if v.len() == 1 {
        one(v[0])
    } else {
        let parts: Vec<String> = v.iter().map(|x| one(*x)).collect();
        format!("[{}]", parts.join(" "))
    }
}

/// `v` as printed with `sig` significant digits on a handout: a component smaller than
/// the largest one's last printed digit (below `max |v| * 10^-sig`) is 0 there (a
/// rotation's `cos 90° = 6.123234e-17` next to a 1), and -0 is 0.
pub fn printed_components(v: &[f64], sig: usize) -> Vec<f64> {
    let largest = v.iter().filter(|x| x.is_finite()).fold(0.0f64, |m, x| m.max(x.abs()));
    let floor = largest * elementary::powi(10.0, -(sig as i32));
    v.iter().map(|&x| if x == 0.0 || x.abs() < floor { 0.0 } else { x }).collect()
}

/// [`fmt_value`] for handouts (exercise sheets and keys): [`printed_components`] first.
pub fn fmt_printed(v: &[f64], sig: usize) -> String {
    fmt_value(&printed_components(v, sig), sig)
}

/// What a modelview that is not a rotation does to the worksheet's normal (which it
/// transforms by M itself, where OpenGL uses (M^-1)^T): the rows' angles and lengths, and
/// how far apart the two normals point.
pub fn modelview_note(check: &crate::model::transform::RotationCheck) -> String {
    use crate::locale::num;
    let deg = |a: f64| format!("{}°", num(a, 3));
    let gap = match check.normal_gap {
        Some(g) if g >= 0.05 => t!("mview-note-gap", angle = deg(g)),
        Some(g) => t!("mview-note-small-gap", angle = format!("{}°", num(g, 2))),
        None => t!("mview-note-singular"),
    };
    let lengths = check.row_lengths.map(|l| num(l, 5)).join("; ");
    if check.is_rotation() {
        return t!("mview-note-rotation", lengths = lengths, gap = gap);
    }
    let skew: Vec<String> = check
        .skewed_rows()
        .iter()
        .map(|(i, j, a)| t!("mview-note-rows", first = i.to_string(), second = j.to_string(), angle = deg(*a)))
        .collect();
    let rows = if skew.is_empty() { t!("mview-note-rows-square") } else { skew.join(", ") };
    t!("mview-note-not-rotation", rows = rows, lengths = lengths, gap = gap)
}

struct Builder {
    steps: Vec<Step>,
}

/// The forms of the terms the steps write, read off the scene's worked program
/// ([`Program::worked`], every term a person computes by hand) for the side explained: how
/// V is formed, and each light's specular vector and term. The values come from the
/// breakdown; which formula each step shows, from here.
struct Forms {
    viewer: Viewer,
    lights: Vec<LightForms>,
}

/// One light's specular, as its stages say it.
#[derive(Clone, Copy)]
struct LightForms {
    vector: SpecularVector,
    term: SpecularTerm,
}

impl Forms {
    /// Walks `program` for side `side`.
    fn of(program: &Program, side: Side) -> Forms {
        let mut forms = Forms { viewer: Viewer::Infinite, lights: Vec::new() };
        for &stage in &program.stages {
            forms.take(stage, side);
        }
        forms
    }

    fn light(&mut self, i: LightId) -> &mut LightForms {
        if self.lights.len() <= i.index() {
            let blank = LightForms { vector: SpecularVector::Halfway, term: SpecularTerm::Plain };
            self.lights.resize(i.index() + 1, blank);
        }
        &mut self.lights[i.index()]
    }

    /// What one stage says of the steps' formulas.
    fn take(&mut self, stage: Stage, side: Side) {
        match stage {
            // Their steps' formulas follow the scene (the normal's transform and mode) or
            // the breakdown (a positional light's L and d, a spotlight's cone), or have one
            // form (the cosines, the power, the scene's colour, which the rules keep).
            Stage::TransformNormal
            | Stage::RescaleNormal
            | Stage::NormalizeNormal
            | Stage::NormalizeNormalFast
            | Stage::TransformPosition
            | Stage::TransformPositionProjective
            | Stage::TranslatePosition
            | Stage::ZeroNormals
            | Stage::LightVector(_)
            | Stage::LightConstant(_)
            | Stage::Attenuate(_)
            | Stage::SpotCone(_)
            | Stage::SpotPower(_)
            | Stage::DiffuseCosine(..)
            | Stage::SpecularCosine(..)
            | Stage::Power(..)
            | Stage::SceneColor => {}
            Stage::ViewVector(viewer) => self.viewer = viewer,
            Stage::Halfway(i) | Stage::HalfwayConstant(i) => self.light(i).vector = SpecularVector::Halfway,
            Stage::Reflect(i) => self.light(i).vector = SpecularVector::Reflection,
            Stage::Sum(i, on, term) => {
                if on == side {
                    self.light(i).term = term;
                }
            }
        }
    }

    /// Light `index`'s forms (the scene's own index, as the breakdown numbers lights).
    fn of_light(&self, index: usize) -> LightForms {
        self.lights
            .get(index)
            .copied()
            .unwrap_or(LightForms { vector: SpecularVector::Halfway, term: SpecularTerm::Plain })
    }
}

impl Builder {
    /// A step finding `q` (for light `light`, its names ending in `sfx`), titled with the
    /// quantity's label.
    fn push(
        &mut self,
        kind: StepKind,
        light: Option<usize>,
        q: Quantity,
        sfx: &str,
        formula: &str,
        value: Option<Vec<f64>>,
    ) {
        self.push_titled(kind, light, &q.label(), q, sfx, formula, value);
    }

    /// [`Builder::push`] with a title of its own (the worksheet reuses a given's name for
    /// its value in eye space: `vertexPos`, `vertexNormal`, `lightPos`).
    #[allow(clippy::too_many_arguments)]
    fn push_titled(
        &mut self,
        kind: StepKind,
        light: Option<usize>,
        title: &str,
        q: Quantity,
        sfx: &str,
        formula: &str,
        value: Option<Vec<f64>>,
    ) {
        self.steps.push(Step {
            kind,
            light,
            title: title.into(),
            name: format!("{}{sfx}", q.name()),
            formula: formula.into(),
            value,
            notes: Vec::new(),
        });
    }

    fn note(&mut self, s: impl Into<String>) {
        if let Some(last) = self.steps.last_mut() {
            last.notes.push(s.into());
        }
    }
}

/// Builds the worked calculation of `lit` (computed from `scene`) for one side.
pub fn explain<S: Real>(scene: &Scene, lit: &VertexLighting<S>, side: Side) -> Explanation {
    let mut b = Builder { steps: Vec::new() };
    let back = side == Side::Back && scene.light_model.two_sided;
    let program = Program::worked(&Key::of(scene, EvalOptions::default()));
    let forms = Forms::of(&program, Side::back_if(back));
    normal_step(&mut b, scene, lit, back);
    position_step(&mut b, scene, lit);
    if lit.lights().is_empty() {
        view_step(&mut b, &forms, lit);
    }
    for (k, t) in lit.lights().iter().enumerate() {
        light_steps(&mut b, scene, &forms, lit, t, k == 0, back);
    }
    total_steps(&mut b, scene, lit, back);
    let n = lit.lights().len();
    let side = if back { t!("side-back") } else { t!("side-front") };
    let heading = t!(
        "explain-heading",
        side = side,
        lights = t!("lights-count", count = n),
        precision = S::NAME,
        rules = scene.rules.to_string()
    );
    Explanation { heading, steps: b.steps }
}

/// Notes on the step just pushed: those of `limits` (the vertex's, or a light's) the
/// engine took at `kind`.
fn limit_notes(b: &mut Builder, limits: Limits, kind: StepKind) {
    for l in limits.iter().filter(|l| l.step_kind() == kind) {
        b.note(l.message());
    }
}

/// The index a light's names carry (`vlv[1]`), where there is more than one light.
fn light_suffix<S: Real>(lit: &VertexLighting<S>, t: &LightTerms<S>) -> String {
    if lit.lights().len() > 1 { format!("[{}]", t.index) } else { String::new() }
}

/// Step 1: the transformed normal (reversed on the back side), with what the worksheet's
/// `M n` does where M is not a rotation.
fn normal_step<S: Real>(b: &mut Builder, scene: &Scene, lit: &VertexLighting<S>, back: bool) {
    let rules = scene.rules;
    let n = lit.normal_in_eye;
    let n_shown = if back { -n } else { n };
    let by_m = rules.normal_transform() == crate::model::rules::NormalTransform::Modelview;
    let nformula = match (scene.normal_mode, by_m) {
        (crate::model::scene::NormalMode::AsIs, false) => t!("formula-normal-gl"),
        (crate::model::scene::NormalMode::Normalize, false) => t!("formula-normal-gl-normalize"),
        (crate::model::scene::NormalMode::Rescale, false) => t!("formula-normal-gl-rescale"),
        (crate::model::scene::NormalMode::AsIs, true) => t!("formula-normal-ws"),
        (crate::model::scene::NormalMode::Normalize, true) => t!("formula-normal-ws-normalize"),
        (crate::model::scene::NormalMode::Rescale, true) => t!("formula-normal-ws-rescale"),
    };
    let ntitle = if back { t!("step-normal-back") } else { t!("step-normal") };
    b.push_titled(StepKind::Normal, None, &ntitle, Q::VertexNormal, "", &nformula, Some(dir4::<S>(n_shown)));
    limit_notes(b, lit.limits, StepKind::Normal);
    if by_m {
        // Where the worksheet's M n and OpenGL's (M^-1)^T n part: say how far M is from a
        // rotation, and what that does to N.
        let m = scene.eye_from_object();
        let check = crate::model::transform::RotationCheck::of(&m, scene.vertex.normal);
        if check.departure() > 1e-12 {
            b.note(modelview_note(&check));
        }
    }
}

/// Step 2: the vertex in eye space.
fn position_step<S: Real>(b: &mut Builder, scene: &Scene, lit: &VertexLighting<S>) {
    let p = lit.pos_in_eye;
    // A point at infinity (w = 0) is not divided by its w: it stays a direction, w = 0.
    let w = if scene.vertex.position.w == 0.0 { 0.0 } else { 1.0 };
    b.push_titled(
        StepKind::Position,
        None,
        &t!("step-position"),
        Q::VertexPos,
        "",
        &t!("formula-position"),
        Some(vec![p.x, p.y, p.z, w]),
    );
    limit_notes(b, lit.limits, StepKind::Position);
    if scene.eye_from_object() == crate::model::transform::phong_demo_eye_from_object() {
        b.note(t!("note-demo-space"));
    }
}

/// The view vector V (after the first light's distance, as the worksheet computes it).
fn view_step<S: Real>(b: &mut Builder, forms: &Forms, lit: &VertexLighting<S>) {
    let vformula = match forms.viewer {
        Viewer::Local => t!("formula-v-local"),
        Viewer::EyePlane => t!("formula-v-worksheet"),
        Viewer::Infinite => t!("formula-v-infinite"),
    };
    b.push(StepKind::V, None, Q::V, "", &vformula, Some(dir4::<S>(lit.v)));
    limit_notes(b, lit.limits, StepKind::V);
    if forms.viewer == Viewer::EyePlane && lit.pos_in_eye.z > 0.0 {
        b.note(t!("note-vov-behind"));
    }
}

/// One light's steps: its position, L, d (then V, for the first light), the ambient,
/// diffuse and specular terms, attenuation, the spot factor and the light's share.
fn light_steps<S: Real>(
    b: &mut Builder,
    scene: &Scene,
    forms: &Forms,
    lit: &VertexLighting<S>,
    t: &LightTerms<S>,
    first: bool,
    back: bool,
) {
    light_vector_steps(b, lit, t);
    if first {
        view_step(b, forms, lit);
    }
    term_steps(b, scene, forms.of_light(t.index), lit, t, back);
    share_steps(b, scene, lit, t, back);
}

/// The light in eye space, L and d.
fn light_vector_steps<S: Real>(b: &mut Builder, lit: &VertexLighting<S>, t: &LightTerms<S>) {
    let i = Some(t.index);
    let sfx = light_suffix(lit, t);
    let pe = t.pos_in_eye;
    b.push_titled(
        StepKind::LightPosition,
        i,
        &t!("step-light-position"),
        Q::LightPos,
        &sfx,
        &t!("formula-light-position"),
        Some(pe.to_array().to_vec()),
    );
    let lformula = if t.positional { t!("formula-l-positional") } else { t!("formula-l-directional") };
    b.push(StepKind::L, i, Q::L, &sfx, &lformula, Some(dir4::<S>(t.l)));
    limit_notes(b, t.limits, StepKind::L);
    let dval = t.distance.map(|d| vec![d.to_f64()]);
    b.push(StepKind::Distance, i, Q::Distance, &sfx, "d = |lightPos − vertexPos|", dval);
    if t.distance.is_none() {
        b.note(t!("note-no-distance"));
    }
    limit_notes(b, t.limits, StepKind::Distance);
}

/// The ambient, diffuse and specular terms, with cos(θ), H or R, and the specular cosine.
fn term_steps<S: Real>(
    b: &mut Builder,
    scene: &Scene,
    forms: LightForms,
    lit: &VertexLighting<S>,
    t: &LightTerms<S>,
    back: bool,
) {
    let (rules, i) = (scene.rules, Some(t.index));
    let sign = if back { "-" } else { "" };
    let sfx = light_suffix(lit, t);
    let st: &SideTerms<S> = if back { &t.back } else { &t.front };
    b.push(
        StepKind::Ambient,
        i,
        Q::Ambient,
        &sfx,
        "Iamb = Lamb · matAmb   (OpenGL: a_cl · a_cm)",
        Some(dir4::<S>(st.ambient)),
    );
    color_material_note(b, scene, back, ColorMaterialMode::Ambient);
    b.push(
        StepKind::CosTheta,
        i,
        Q::CosTheta,
        &sfx,
        &format!("cosTheta = {sign}vertexNormal · vlv   (OpenGL: {sign}n · L)"),
        Some(vec![st.n_dot_l.to_f64()]),
    );
    b.push(
        StepKind::Diffuse,
        i,
        Q::Diffuse,
        &sfx,
        "Idif = Ldif · matDif · max(cosTheta, 0)   (OpenGL: d_cl · d_cm · max(n · L, 0))",
        Some(dir4::<S>(st.diffuse)),
    );
    color_material_note(b, scene, back, ColorMaterialMode::Diffuse);
    let cos = match forms.vector {
        SpecularVector::Halfway => {
            b.push(
                StepKind::H,
                i,
                Q::H,
                &sfx,
                "H = normalize(vlv + vov)   (OpenGL: h = normalize(L + V))",
                Some(dir4::<S>(t.h)),
            );
            limit_notes(b, t.limits, StepKind::H);
            b.push(
                StepKind::CosBeta,
                i,
                Q::CosBeta,
                &sfx,
                &format!("cosBeta = {sign}vertexNormal · H   (OpenGL: {sign}n · h)"),
                Some(vec![st.spec_cos.to_f64()]),
            );
            "cosBeta"
        }
        SpecularVector::Reflection => {
            b.push(
                StepKind::R,
                i,
                Q::R,
                &sfx,
                &if rules.reflect_clamped() {
                    t!("formula-r-demo")
                } else {
                    "R = 2 (vertexNormal · vlv) vertexNormal − vlv".to_string()
                },
                Some(dir4::<S>(t.r)),
            );
            b.push(StepKind::CosBeta, i, Q::CosAlpha, &sfx, "cosAlpha = R · vov", Some(vec![st.spec_cos.to_f64()]));
            "cosAlpha"
        }
    };
    let gate = match rules.specular_gate() {
        crate::model::rules::SpecularGate::LitSide => t!("gate-lit-side"),
        crate::model::rules::SpecularGate::PositiveCosine => t!("gate-positive", cos = cos),
        crate::model::rules::SpecularGate::None => t!("gate-none"),
    };
    let f = crate::locale::num(st.f.to_f64(), 8);
    let formula = match forms.term {
        SpecularTerm::Zero | SpecularTerm::Plain => t!("formula-specular", gate = gate, f = f, cos = cos),
        SpecularTerm::Normalised => t!("formula-specular-normalised", gate = gate, f = f, cos = cos),
    };
    b.push(StepKind::Specular, i, Q::Specular, &sfx, &formula, Some(dir4::<S>(st.specular)));
    color_material_note(b, scene, back, ColorMaterialMode::Specular);
}

/// Where `GL_COLOR_MATERIAL` tracks `property` on this side, a note on the step just
/// pushed: the material colour it used is the current colour, not `glMaterial`'s.
fn color_material_note(b: &mut Builder, scene: &Scene, back: bool, property: ColorMaterialMode) {
    let side = Side::back_if(back);
    let Some(cm) = scene.color_material.filter(|cm| cm.tracks(property, side)) else { return };
    let set = if back { scene.back() } else { &scene.material };
    let (q, was) = match property {
        ColorMaterialMode::Ambient => (Q::MatAmbient, set.ambient),
        ColorMaterialMode::Diffuse => (Q::MatDiffuse, set.diffuse),
        ColorMaterialMode::Specular => (Q::MatSpecular, set.specular),
        _ => (Q::MatEmission, set.emission),
    };
    let name = if back { q.back_name() } else { q.name().to_string() };
    b.note(t!(
        "note-color-material",
        mode = cm.mode.gl(),
        face = cm.face.gl(),
        name = name,
        color = fmt_value(&cm.color.to_array(), 6),
        set = fmt_value(&was.to_array(), 6)
    ));
}

/// Attenuation, the spot factor, and the light's share of the colour.
fn share_steps<S: Real>(b: &mut Builder, scene: &Scene, lit: &VertexLighting<S>, t: &LightTerms<S>, back: bool) {
    let i = Some(t.index);
    let sfx = light_suffix(lit, t);
    let st: &SideTerms<S> = if back { &t.back } else { &t.front };
    let aformula = if t.positional { t!("formula-at") } else { t!("formula-at-directional") };
    let at = t.attenuation.to_f64();
    b.push(
        StepKind::Attenuation,
        i,
        Q::Attenuation,
        &sfx,
        &aformula,
        Some(vec![if at == 0.0 { f64::INFINITY } else { 1.0 / at }]),
    );
    limit_notes(b, t.limits, StepKind::Attenuation);
    if t.spot.active {
        b.push(
            StepKind::Spot,
            i,
            Q::Spot,
            &sfx,
            &t!(
                "formula-spot",
                cutoff = crate::locale::num(t.spot.cos_cutoff.to_f64(), 8),
                angle = crate::locale::num(t.spot.cos_angle.to_f64(), 8)
            ),
            Some(vec![t.spot.factor.to_f64()]),
        );
    } else {
        b.push(StepKind::Spot, i, Q::Spot, &sfx, &t!("formula-spot-none"), Some(vec![1.0]));
    }
    limit_notes(b, t.limits, StepKind::Spot);
    let sep = scene.light_model.separate_specular;
    let cformula =
        if sep { t!("formula-share-separate") } else { "Ilight = spot · (Iamb + Idif + Ispec) / at".to_string() };
    b.push(StepKind::Contribution, i, Q::LightShare, &sfx, &cformula, Some(dir4::<S>(st.primary)));
}

/// The totals: the scene ambient and the emission where the rules keep them, I, the
/// secondary colour, and the colour as drawn.
fn total_steps<S: Real>(b: &mut Builder, scene: &Scene, lit: &VertexLighting<S>, back: bool) {
    let rules = scene.rules;
    let sc: &SideColor<S> = if back { &lit.back } else { &lit.front };
    if rules.scene_ambient() {
        b.push(
            StepKind::SceneAmbient,
            None,
            Q::SceneAmbientTerm,
            "",
            &t!("formula-scene-ambient"),
            Some(dir4::<S>(sc.scene_ambient)),
        );
    }
    if rules.emission() {
        b.push(StepKind::Emission, None, Q::EmissionTerm, "", "e_cm", Some(dir4::<S>(sc.emission)));
        color_material_note(b, scene, back, ColorMaterialMode::Emission);
    }
    let iformula = match (rules.scene_ambient(), rules.emission()) {
        (true, true) => t!("formula-i-opengl"),
        _ => t!("formula-i-worksheet"),
    };
    let pr = sc.primary.map(S::to_f64);
    b.push(StepKind::Primary, None, Q::Primary, "", &iformula, Some(vec![pr[0], pr[1], pr[2], 0.0]));
    limit_notes(b, lit.limits, StepKind::Primary);
    if scene.light_model.separate_specular {
        let s = sc.secondary.map(S::to_f64);
        b.push(StepKind::Secondary, None, Q::Secondary, "", &t!("formula-secondary"), Some(s.to_vec()));
    }
    let c = sc.sum();
    let c = [c[0], c[1], c[2], c[3]].map(|x| x.max(S::ZERO).min(S::ONE).to_f64());
    b.push(StepKind::Clamped, None, Q::Clamped, "", &t!("formula-clamped"), Some(c.to_vec()));
}

impl Explanation {
    /// Plain text, one numbered step per two lines: title and formula, then `name = value`.
    pub fn to_text(&self, sig: usize) -> String {
        self.text_with(sig, fmt_value)
    }

    /// [`Explanation::to_text`] for a handout: every value as printed there
    /// ([`fmt_printed`]: no `6.123234e-17` where 0 belongs, no -0).
    pub fn to_handout_text(&self, sig: usize) -> String {
        self.text_with(sig, fmt_printed)
    }

    fn text_with(&self, sig: usize, fmt_value: fn(&[f64], usize) -> String) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.heading);
        for (k, st) in self.steps.iter().enumerate() {
            let _ = writeln!(s, "{:>2}. {:<28} {}", k + 1, st.title, st.formula);
            match &st.value {
                Some(v) => {
                    let _ = writeln!(s, "    {} = {}", st.name, crate::locale::decimal(&fmt_value(v, sig)));
                }
                None => {
                    let _ = writeln!(s, "    {} = n/a", st.name);
                }
            }
            for n in &st.notes {
                let _ = writeln!(s, "    {}", t!("note-line", note = n));
            }
        }
        s
    }

    /// The table's column headers (after `#`), in the user's language.
    pub fn columns() -> [String; 4] {
        [
            t!("explain-column-step"),
            t!("explain-column-formula"),
            t!("explain-column-value"),
            t!("explain-column-notes"),
        ]
    }

    /// A Markdown table of the steps: headers in the user's language, values in its
    /// decimal mark (as [`Explanation::to_text`]).
    pub fn to_markdown(&self, sig: usize) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "**{}**\n", self.heading);
        let _ = writeln!(s, "| # | {} |", Self::columns().join(" | "));
        let _ = writeln!(s, "|---|---|---|---|---|");
        for (k, st) in self.steps.iter().enumerate() {
            let v = st.value.as_ref().map_or_else(
                || "n/a".into(),
                |v| format!("`{} = {}`", st.name, crate::locale::decimal(&fmt_value(v, sig))),
            );
            let _ = writeln!(
                s,
                "| {} | {} | `{}` | {} | {} |",
                k + 1,
                st.title,
                st.formula.replace('|', "\\|"),
                v,
                st.notes.join("; ").replace('|', "\\|")
            );
        }
        s
    }

    /// The value of the first step with worksheet name `name`.
    pub fn value(&self, name: &str) -> Option<&[f64]> {
        self.steps.iter().find(|s| s.name == name).and_then(|s| s.value.as_deref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits_like_the_worksheet() {
        assert_eq!(fmt_sig(0.792205263, 8), "0.79220526");
        assert_eq!(fmt_sig(0.0994279500001, 8), "0.09942795");
        assert_eq!(fmt_sig(-0.24508850, 8), "-0.2450885");
        assert_eq!(fmt_sig(0.0, 8), "0");
        assert_eq!(fmt_sig(-0.0, 8), "0");
        assert_eq!(fmt_sig(0.6, 8), "0.6");
        assert_eq!(fmt_sig(4.5151920e28, 8), "4.515192e+28");
        assert_eq!(fmt_sig(1.1075480e-33, 8), "1.107548e-33");
        assert_eq!(fmt_sig(45151924.0, 8), "45151924");
        assert_eq!(fmt_sig(123456789.0, 8), "1.2345679e+8");
        assert_eq!(fmt_sig(f64::NEG_INFINITY, 8), "-Infinity");
        assert_eq!(fmt_value(&[0.0, 0.6, 0.8, 0.0], 8), "[0 0.6 0.8 0]");
    }

    #[test]
    fn a_vertex_at_infinity_is_shown_with_w_0_a_point_with_w_1() {
        let vertex_pos = |w: f64| {
            let mut scene = crate::model::presets::worksheet(5);
            scene.vertex.position = glam::DVec4::new(1.0, 2.0, 3.0, w);
            let lit = crate::equation::lighting::Engine::<f64>::light_scene_vertex(&scene).unwrap();
            let ex = explain(&scene, &lit, Side::Front);
            ex.steps.iter().find(|s| s.name == "vertexPos").and_then(|s| s.value.clone()).unwrap()
        };
        assert_eq!(vertex_pos(0.0)[3], 0.0);
        assert_eq!(vertex_pos(1.0)[3], 1.0);
        assert_eq!(vertex_pos(2.0)[3], 1.0, "divided by w");
    }
}
