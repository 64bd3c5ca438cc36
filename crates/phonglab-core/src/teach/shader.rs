//! The shader a scene compiles to: GLSL 3.30 and WGSL generated from the specialised
//! plan's stage list ([`Program`]), as Mesa's `ffvertex_prog.c` builds a vertex program
//! from the fixed-function state.
//!
//! Only the stages the scene's key calls for appear: no cone test without a spotlight, no
//! attenuation at (1, 0, 0), a constant L and H for a directional light under an infinite
//! viewer, no power at shininess 0. Values a slider moves without changing the key (light
//! positions and colours, the material, attenuation factors) are uniforms; what the key
//! fixes (how many lights, which are positional, the rules) is folded into the code. Each
//! line carries the number of the worked calculation's step it computes.
//!
//! Gouraud lights in the vertex shader and interpolates the colour; Phong passes the
//! eye-space position and normal and lights each fragment. Colours are clamped as OpenGL
//! clamps vertex colours (the Phong demo's rules do not).

use std::fmt::Write as _;

use crate::equation::explain::{Explanation, StepKind};
use crate::equation::lighting::EvalOptions;
use crate::equation::plan::{Key, Program, SourceKind, SpecularTerm, Stage, Viewer};
use crate::model::rules::{NormalTransform, SpecularGate, SpecularVector};
use crate::model::scene::{ColorMaterialMode, LightId, Scene, Side};

/// The shading language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadingLanguage {
    /// GLSL `#version 330 core`.
    Glsl,
    /// WGSL (WebGPU).
    Wgsl,
}

/// Where the lighting runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderShading {
    /// Per vertex, the colour interpolated.
    Gouraud,
    /// Per fragment, the position and normal interpolated.
    Phong,
}

/// A generated program: the vertex stage and, for Phong, the fragment stage (for Gouraud,
/// a fragment stage that writes the interpolated colour).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shader {
    /// The vertex shader.
    pub vertex: String,
    /// The fragment shader.
    pub fragment: String,
    /// The uniforms it declares, in order: (name, GLSL type: `mat4`, `mat3`, `vec4`, `vec3`
    /// or `float`); [`uniform_value`] gives each one's value.
    pub uniforms: Vec<(String, &'static str)>,
}

impl Shader {
    /// Both stages, one after the other, as `phonglab shader` prints them. WGSL keeps both
    /// entry points in one module, so it is printed once.
    pub fn text(&self, lang: ShadingLanguage) -> String {
        match lang {
            ShadingLanguage::Glsl => {
                let (v, f) = (crate::t!("shader-vertex-shader"), crate::t!("shader-fragment-shader"));
                format!("// ---- {v} ----\n{}\n// ---- {f} ----\n{}", self.vertex, self.fragment)
            }
            ShadingLanguage::Wgsl => self.vertex.clone(),
        }
    }
}

/// Syntax per language.
struct Syn {
    lang: ShadingLanguage,
}

impl Syn {
    fn vec3(&self) -> &'static str {
        if self.lang == ShadingLanguage::Glsl { "vec3" } else { "vec3<f32>" }
    }
    fn vec4(&self) -> &'static str {
        if self.lang == ShadingLanguage::Glsl { "vec4" } else { "vec4<f32>" }
    }
    /// A new variable.
    fn var(&self, ty: &str, name: &str, e: &str) -> String {
        match self.lang {
            ShadingLanguage::Glsl => format!("{ty} {name} = {e};"),
            ShadingLanguage::Wgsl => format!("var {name}: {} = {e};", self.wty(ty)),
        }
    }
    fn wty(&self, ty: &str) -> String {
        match ty {
            "float" => "f32".into(),
            "bool" => "bool".into(),
            "vec3" => "vec3<f32>".into(),
            "vec4" => "vec4<f32>".into(),
            other => other.into(),
        }
    }
    /// A uniform's reference.
    fn u(&self, name: &str) -> String {
        match self.lang {
            ShadingLanguage::Glsl => format!("u_{name}"),
            ShadingLanguage::Wgsl => format!("u.{name}"),
        }
    }
    /// `c ? a : b`.
    fn select(&self, c: &str, a: &str, b: &str) -> String {
        match self.lang {
            ShadingLanguage::Glsl => format!("(({c}) ? ({a}) : ({b}))"),
            ShadingLanguage::Wgsl => format!("select({b}, {a}, {c})"),
        }
    }
}

/// The worked calculation's number of the first step of `kind` (for `light`).
fn step_no(ex: &Explanation, kind: StepKind, light: Option<LightId>) -> String {
    let light = light.map(LightId::index);
    match ex.steps.iter().position(|s| s.kind == kind && (light.is_none() || s.light == light)) {
        Some(k) => crate::t!("shader-step", n = (k + 1).to_string()),
        None => String::new(),
    }
}

/// One uniform: name and GLSL type.
type Uniform = (String, &'static str);

/// The lighting code for the stages of `program` (statements, each with its step), writing
/// `color_front` (and `color_back` when two-sided); the uniforms it reads are added to
/// `uniforms`.
fn lighting(
    scene: &Scene,
    key: &Key,
    program: &Program,
    ex: &Explanation,
    s: &Syn,
    uniforms: &mut Vec<Uniform>,
) -> Vec<String> {
    let mut body = Body { scene, key, program, ex, s, uniforms, lines: Vec::new() };
    for side in body.sides() {
        let side = side.index();
        let zero = format!("{}(0.0)", s.vec3());
        body.lines.push(s.var("vec3", &format!("sum{side}"), &zero));
        if key.separate_specular {
            // GL_SEPARATE_SPECULAR_COLOR: the specular terms go to a secondary colour of their own.
            body.lines.push(s.var("vec3", &format!("spec{side}"), &zero));
        }
    }
    for &stage in &program.stages {
        body.stage(stage);
    }
    body.colors();
    body.lines
}

/// The lighting code being written: the scene and its program, and the statements so far.
struct Body<'a> {
    scene: &'a Scene,
    key: &'a Key,
    program: &'a Program,
    ex: &'a Explanation,
    s: &'a Syn,
    uniforms: &'a mut Vec<Uniform>,
    lines: Vec<String>,
}

impl Body<'_> {
    /// Declares the uniform `name` of GLSL type `ty` (once) and gives its reference.
    fn uni(&mut self, name: String, ty: &'static str) -> String {
        if !self.uniforms.iter().any(|(n, _)| *n == name) {
            self.uniforms.push((name.clone(), ty));
        }
        self.s.u(&name)
    }

    /// A new variable `name = e`, with the worked calculation's step of `kind` (for `light`)
    /// and a note after it.
    fn var(&mut self, ty: &str, name: &str, e: &str, kind: StepKind, light: Option<LightId>, note: &str) {
        let line = format!("{} // {}{note}", self.s.var(ty, name, e), step_no(self.ex, kind, light));
        self.lines.push(line);
    }

    /// The sides lit: both when two-sided, else the front.
    fn sides(&self) -> &'static [Side] {
        if self.key.two_sided { &Side::ALL } else { &Side::ALL[..1] }
    }

    /// The material a side reads: `back` where the scene has a back material, else `mat`.
    fn material(&self, side: Side) -> &'static str {
        if side == Side::Back && self.scene.back_material.is_some() { "back" } else { "mat" }
    }

    /// A material colour of `side` (`ambient`, `diffuse` or `specular`, of GLSL type
    /// `ty`): its uniform, or, where `GL_COLOR_MATERIAL` tracks it on that side, the
    /// current colour's (`u_color`, as `glColor` sets it).
    fn material_color(&mut self, side: Side, what: &str, ty: &'static str) -> String {
        let property = match what {
            "ambient" => ColorMaterialMode::Ambient,
            "diffuse" => ColorMaterialMode::Diffuse,
            _ => ColorMaterialMode::Specular,
        };
        if let Some(cm) = &self.scene.color_material
            && cm.tracks(property, side)
        {
            let c = self.uni("color".into(), "vec4");
            return if ty == "vec4" { c } else { format!("{c}.xyz") };
        }
        let m = self.material(side);
        self.uni(format!("{m}_{what}"), ty)
    }

    /// The normal a side's cosines use.
    fn normal(side: Side) -> &'static str {
        match side {
            Side::Front => "N",
            Side::Back => "-N",
        }
    }

    /// V in the specular cosines: the view vector where the program forms one, else the
    /// infinite viewer's (0, 0, 1).
    fn view(&self) -> String {
        if has_view_vector(self.program) { "V".to_string() } else { format!("{}(0.0, 0.0, 1.0)", self.s.vec3()) }
    }

    /// Where the rules let the specular term through (OpenGL: the lit side; the worksheet: a
    /// positive cosine; the demo: always).
    fn gate_open(&self, i: LightId, side: Side) -> String {
        let side = side.index();
        match self.scene.rules.specular_gate() {
            SpecularGate::LitSide => format!("ndl{i}_{side} > 0.0"),
            SpecularGate::PositiveCosine => format!("spec_cos{i}_{side} > 0.0"),
            SpecularGate::None => "true".to_string(),
        }
    }

    /// The statements of one stage (none for the transforms, which the prologue or the
    /// vertex stage does).
    fn stage(&mut self, stage: Stage) {
        match stage {
            Stage::TransformNormal
            | Stage::TransformPosition
            | Stage::TransformPositionProjective
            | Stage::TranslatePosition
            | Stage::RescaleNormal => {}
            Stage::NormalizeNormal | Stage::NormalizeNormalFast => {
                let line = format!("N = normalize(N); // {}", step_no(self.ex, StepKind::Normal, None));
                self.lines.push(line);
            }
            Stage::ZeroNormals => {
                let n_ok = self.s.var("bool", "n_ok", "dot(N, N) > 0.0");
                self.lines.push(format!("{n_ok} // {}", crate::t!("shader-note-zero-normal")));
            }
            Stage::ViewVector(viewer) => self.view_vector(viewer),
            Stage::LightVector(i) => self.light_vector(i),
            Stage::LightConstant(i) => {
                let l = self.uni(format!("light{i}_direction"), "vec3");
                let note = format!(" ({})", crate::t!("shader-note-directional-l"));
                self.var("vec3", &format!("L{i}"), &l, StepKind::L, Some(i), &note);
            }
            Stage::Attenuate(i) => {
                let k = self.uni(format!("light{i}_attenuation"), "vec3");
                let e = format!("1.0 / ({k}.x + {k}.y * d{i} + {k}.z * d{i} * d{i})");
                self.var("float", &format!("att{i}"), &e, StepKind::Attenuation, Some(i), "");
            }
            Stage::SpotCone(i) => self.spot_cone(i),
            Stage::SpotPower(i) => {
                let ex = self.uni(format!("light{i}_spot_exponent"), "float");
                let pw = self.s.select(&format!("in_cone{i}"), &format!("pow(max(spot_cos{i}, 0.0), {ex})"), "0.0");
                self.var("float", &format!("spot{i}"), &pw, StepKind::Spot, Some(i), "");
            }
            Stage::Halfway(i) => {
                let e = format!("normalize(L{i} + {})", self.view());
                self.var("vec3", &format!("H{i}"), &e, StepKind::H, Some(i), "");
            }
            Stage::HalfwayConstant(i) => {
                let h = self.uni(format!("light{i}_halfway"), "vec3");
                let note = format!(" ({})", crate::t!("shader-note-one-h"));
                self.var("vec3", &format!("H{i}"), &h, StepKind::H, Some(i), &note);
            }
            Stage::Reflect(i) => {
                let dot = if self.scene.rules.reflect_clamped() {
                    format!("max(dot(N, L{i}), 0.0)")
                } else {
                    format!("dot(N, L{i})")
                };
                self.var("vec3", &format!("R{i}"), &format!("2.0 * {dot} * N - L{i}"), StepKind::R, Some(i), "");
            }
            Stage::DiffuseCosine(i, side) => {
                let e = format!("dot({}, L{i})", Self::normal(side));
                let s = side.index();
                self.var("float", &format!("ndl{i}_{s}"), &e, StepKind::CosTheta, Some(i), "");
            }
            Stage::SpecularCosine(i, side, vector) => {
                let e = match vector {
                    SpecularVector::Halfway => format!("dot({}, H{i})", Self::normal(side)),
                    SpecularVector::Reflection => format!("dot(R{i}, {})", self.view()),
                };
                let s = side.index();
                self.var("float", &format!("spec_cos{i}_{s}"), &e, StepKind::CosBeta, Some(i), "");
            }
            Stage::Power(i, side) => {
                let sh = self.uni(format!("{}_shininess", self.material(side)), "float");
                let s = side.index();
                let e =
                    self.s.select(&self.gate_open(i, side), &format!("pow(max(spec_cos{i}_{s}, 0.0), {sh})"), "0.0");
                self.var("float", &format!("pf{i}_{s}"), &e, StepKind::Specular, Some(i), "");
            }
            Stage::Sum(i, side, term) => self.sum(i, side, term),
            Stage::SceneColor => {
                let c = self.uni("scene_color".into(), "vec3");
                for side in self.sides() {
                    let side = side.index();
                    let step = step_no(self.ex, StepKind::SceneAmbient, None);
                    let note = crate::t!("shader-note-emission-ambient");
                    self.lines.push(format!("sum{side} = sum{side} + {c}; // {step} ({note})"));
                }
            }
        }
    }

    /// V: towards the eye from P (local viewer), the worksheet's axis, or OpenGL's
    /// infinite viewer's.
    fn view_vector(&mut self, viewer: Viewer) {
        let e = match viewer {
            Viewer::Local => "normalize(-P)".to_string(),
            Viewer::EyePlane => format!("{}(0.0, 0.0, -sign(P.z))", self.s.vec3()),
            Viewer::Infinite => format!("{}(0.0, 0.0, 1.0)", self.s.vec3()),
        };
        self.var("vec3", "V", &e, StepKind::V, None, " (V)");
    }

    /// A positional light's direction: the vector to it, its length d, and L.
    fn light_vector(&mut self, i: LightId) {
        let p = self.uni(format!("light{i}_position"), "vec4");
        self.var("vec3", &format!("toL{i}"), &format!("{p}.xyz / {p}.w - P"), StepKind::L, Some(i), "");
        self.var("float", &format!("d{i}"), &format!("length(toL{i})"), StepKind::Distance, Some(i), " (d)");
        self.var("vec3", &format!("L{i}"), &format!("toL{i} / d{i}"), StepKind::L, Some(i), " (L)");
    }

    /// A spotlight's cosine to its axis and the cone test.
    fn spot_cone(&mut self, i: LightId) {
        let dir = self.uni(format!("light{i}_spot_direction"), "vec3");
        let cut = self.uni(format!("light{i}_spot_cos_cutoff"), "float");
        let cos = format!("dot(-L{i}, normalize({dir}))");
        let note = format!(" ({})", crate::t!("shader-note-spot-cosine"));
        self.var("float", &format!("spot_cos{i}"), &cos, StepKind::Spot, Some(i), &note);
        let test = format!("spot_cos{i} >= {cut}");
        let note = format!(" ({})", crate::t!("shader-note-cone-test"));
        self.var("bool", &format!("in_cone{i}"), &test, StepKind::Spot, Some(i), &note);
    }

    /// Light `i`'s share on `side`: its ambient, diffuse and specular terms, scaled by its
    /// attenuation and spot factor, added to the side's sum.
    fn sum(&mut self, i: LightId, side: Side, term: SpecularTerm) {
        let (la, ld, ls) = (
            self.uni(format!("light{i}_ambient"), "vec3"),
            self.uni(format!("light{i}_diffuse"), "vec3"),
            self.uni(format!("light{i}_specular"), "vec3"),
        );
        let (ma, md) = (self.material_color(side, "ambient", "vec3"), self.material_color(side, "diffuse", "vec4"));
        let s = side.index();
        let mut terms = format!("{la} * {ma} + {ld} * {md}.xyz * max(ndl{i}_{s}, 0.0)");
        let mut specular = None;
        // What multiplies the specular term: nothing, or energy-conserving Blinn-Phong's
        // (s + 8) / (8 pi).
        let normalisation = match term {
            SpecularTerm::Zero => None,
            SpecularTerm::Plain => Some(String::new()),
            SpecularTerm::Normalised => {
                let sh = self.uni(format!("{}_shininess", self.material(side)), "float");
                Some(format!(" * (({sh} + 8.0) / (8.0 * 3.14159265))"))
            }
        };
        if let Some(normalisation) = normalisation {
            let ms = self.material_color(side, "specular", "vec3");
            // The power (or 1 at shininess 0) where the gate lets it through.
            let pf = if self.program.has(Stage::Power(i, side)) {
                format!("pf{i}_{s}")
            } else {
                self.s.select(&self.gate_open(i, side), "1.0", "0.0")
            };
            if self.key.separate_specular {
                specular = Some(format!("{ls} * {ms} * {pf}{normalisation}"));
            } else {
                terms.push_str(&format!(" + {ls} * {ms} * {pf}{normalisation}"));
            }
        }
        let mut scale = String::new();
        if self.program.has(Stage::Attenuate(i)) {
            scale.push_str(&format!("att{i} * "));
        }
        if self.program.has(Stage::SpotPower(i)) {
            scale.push_str(&format!("spot{i} * "));
        }
        let lit = if self.program.has(Stage::ZeroNormals) {
            self.s.select("n_ok", &format!("{scale}({terms})"), &format!("{scale}({la} * {ma})"))
        } else {
            format!("{scale}({terms})")
        };
        let step = step_no(self.ex, StepKind::Contribution, Some(i));
        self.lines.push(format!("sum{s} = sum{s} + {lit}; // {step}"));
        if let Some(spec) = specular {
            let lit = if self.program.has(Stage::ZeroNormals) {
                self.s.select("n_ok", &format!("{scale}({spec})"), &format!("{}(0.0)", self.s.vec3()))
            } else {
                format!("{scale}({spec})")
            };
            let step = step_no(self.ex, StepKind::Secondary, None);
            let note = crate::t!("shader-note-secondary");
            self.lines.push(format!("spec{s} = spec{s} + {lit}; // {step} ({note})"));
        }
    }

    /// Each side's colour: its sum (clamped where the rules clamp vertex colours) with the
    /// diffuse alpha.
    fn colors(&mut self) {
        let clamp = self.scene.rules.clamps_vertex_colors();
        let (v3, v4) = (self.s.vec3(), self.s.vec4());
        for &side in self.sides() {
            let md = self.material_color(side, "diffuse", "vec4");
            let side = side.index();
            let clamped = |v: &str| if clamp { format!("clamp({v}, {v3}(0.0), {v3}(1.0))") } else { v.to_string() };
            // With a separate specular colour, each colour is clamped on its own and the two
            // are added (OpenGL's colour sum): what the rasteriser interpolates.
            let rgb = if self.key.separate_specular {
                format!("{} + {}", clamped(&format!("sum{side}")), clamped(&format!("spec{side}")))
            } else {
                clamped(&format!("sum{side}"))
            };
            let e = format!("{v4}({rgb}, {md}.w)");
            let note = format!(" ({})", crate::t!("shader-note-alpha"));
            self.var("vec4", &format!("color{side}"), &e, StepKind::Primary, None, &note);
        }
    }
}

/// The prologue that brings N and P to eye space from object space (Gouraud's vertex
/// shader), for the stages the program has.
fn prologue(scene: &Scene, program: &Program, ex: &Explanation, s: &Syn, uniforms: &mut Vec<Uniform>) -> Vec<String> {
    let mut o = Vec::new();
    let by_m = scene.rules.normal_transform() == NormalTransform::Modelview;
    uniforms.push(("normal_matrix".into(), "mat3"));
    let (nm, mv) = (s.u("normal_matrix"), s.u("eye_from_object"));
    let what = if by_m { crate::t!("shader-note-normal-by-m") } else { "(M^-1)^T".to_string() };
    let n_in = if s.lang == ShadingLanguage::Glsl { "a_normal" } else { "input.normal" };
    let p_in = if s.lang == ShadingLanguage::Glsl { "a_position" } else { "input.position" };
    o.push(format!(
        "{} // {} ({what})",
        s.var("vec3", "N", &format!("{nm} * {n_in}")),
        step_no(ex, StepKind::Normal, None)
    ));
    if program.has(Stage::RescaleNormal) {
        uniforms.push(("rescale".into(), "float"));
        o.push(format!("N = {} * N; // {} (GL_RESCALE_NORMAL)", s.u("rescale"), step_no(ex, StepKind::Normal, None)));
    }
    let v4 = s.vec4();
    if program.has(Stage::TransformPositionProjective) {
        o.push(format!(
            "{} // {}",
            s.var("vec4", "Ph", &format!("{mv} * {v4}({p_in}, 1.0)")),
            step_no(ex, StepKind::Position, None)
        ));
        o.push(format!("{} // {}", s.var("vec3", "P", "Ph.xyz / Ph.w"), crate::t!("shader-note-projective")));
    } else if program.has(Stage::TranslatePosition) {
        o.push(format!(
            "{} // {} ({})",
            s.var("vec3", "P", &format!("{p_in} + {mv}[3].xyz")),
            step_no(ex, StepKind::Position, None),
            crate::t!("shader-note-translation")
        ));
    } else if program.has(Stage::TransformPosition) || has_view_vector(program) {
        o.push(format!(
            "{} // {} ({})",
            s.var("vec3", "P", &format!("({mv} * {v4}({p_in}, 1.0)).xyz")),
            step_no(ex, StepKind::Position, None),
            crate::t!("shader-note-affine")
        ));
    }
    o
}

/// Does `program` form V (a `V` variable the cosines read)?
fn has_view_vector(program: &Program) -> bool {
    program.stages.iter().any(|s| matches!(s, Stage::ViewVector(_)))
}

/// The uniform declarations.
fn declare(s: &Syn, uniforms: &[Uniform]) -> String {
    let mut d = String::new();
    match s.lang {
        ShadingLanguage::Glsl => {
            for (n, t) in uniforms {
                let _ = writeln!(d, "uniform {t} u_{n};");
            }
        }
        ShadingLanguage::Wgsl => {
            let _ = writeln!(d, "struct Uniforms {{");
            for (n, t) in uniforms {
                let ty = match *t {
                    "mat4" => "mat4x4<f32>".to_string(),
                    "mat3" => "mat3x3<f32>".to_string(),
                    other => s.wty(other),
                };
                let _ = writeln!(d, "    {n}: {ty},");
            }
            let _ = writeln!(d, "}};\n@group(0) @binding(0) var<uniform> u: Uniforms;");
        }
    }
    d
}

fn indent(lines: &[String]) -> String {
    lines.iter().map(|l| format!("    {l}\n")).collect()
}

/// The program for `scene` under `options`, with the step numbers of the scene's own worked
/// calculation (front side), or why the scene does not evaluate.
pub fn generate_for(
    scene: &Scene,
    options: EvalOptions,
    lang: ShadingLanguage,
    shading: ShaderShading,
) -> Result<Shader, crate::model::error::SceneError> {
    let lit = crate::equation::lighting::Engine::<f64>::new(scene)?.light(&scene.vertex);
    let ex = crate::equation::explain::explain(scene, &lit, crate::equation::explain::Side::Front);
    Ok(generate(scene, options, &ex, lang, shading))
}

/// The program that draws `doc`'s shaded view: its scene as the view lights it (the view's
/// camera and spin, or the demo's object space) and the view's renormalisation. What the
/// app's Shader window shows, what its GPU view runs and what `phonglab shader` prints.
pub fn for_view(
    doc: &crate::formats::document::Document,
    lang: ShadingLanguage,
    shading: ShaderShading,
) -> Result<Shader, crate::model::error::SceneError> {
    generate_for(&doc.shaded_scene(), doc.view.eval_options(crate::numerics::pow::PowFn::Exact), lang, shading)
}

/// Generates the program for `scene` (its key under `options`), with step numbers taken
/// from `ex` (the scene's worked calculation).
pub fn generate(
    scene: &Scene,
    options: EvalOptions,
    ex: &Explanation,
    lang: ShadingLanguage,
    shading: ShaderShading,
) -> Shader {
    let key = Key::of(scene, options);
    let s = Syn { lang };
    let uniforms: Vec<Uniform> = vec![("clip_from_object".into(), "mat4"), ("eye_from_object".into(), "mat4")];
    match shading {
        ShaderShading::Gouraud => gouraud(scene, &key, ex, &s, uniforms),
        ShaderShading::Phong => phong(scene, &key, options, ex, &s, uniforms),
    }
}

/// The comment that opens a stage's text.
fn header(what: &str, shading: ShaderShading) -> String {
    let name = match shading {
        ShaderShading::Gouraud => "Gouraud",
        ShaderShading::Phong => "Phong",
    };
    let head = crate::t!("shader-header", what = what, shading = name);
    head.lines().map(|l| format!("// {l}\n")).collect()
}

/// The comment that lists a program's stages.
fn stage_list(what: &str, program: &Program) -> String {
    let stages: Vec<String> = program.stages.iter().map(Stage::to_string).collect();
    format!("// {what}: {}\n", stages.join(" > "))
}

/// Gouraud: the vertex stage brings N and P to eye space and lights them; the fragment
/// stage writes the interpolated colour (of the side facing the eye, when two-sided).
fn gouraud(scene: &Scene, key: &Key, ex: &Explanation, s: &Syn, mut uniforms: Vec<Uniform>) -> Shader {
    let program = Program::compile(key, SourceKind::Object);
    let mut body = prologue(scene, &program, ex, s, &mut uniforms);
    body.extend(lighting(scene, key, &program, ex, s, &mut uniforms));
    let head = header(&crate::t!("shader-what-vertex-lighting"), ShaderShading::Gouraud);
    let list = stage_list(&crate::t!("shader-what-program"), &program);
    let (declared, body) = (declare(s, &uniforms), indent(&body));
    let two = key.two_sided;
    match s.lang {
        ShadingLanguage::Glsl => {
            let outs = if two { "out vec4 v_front;\nout vec4 v_back;\n" } else { "out vec4 v_front;\n" };
            let store = if two { "    v_front = color0;\n    v_back = color1;\n" } else { "    v_front = color0;\n" };
            let vertex = format!(
                "#version 330 core\n{head}{list}layout(location = 0) in vec3 a_position;\nlayout(location = 1) in vec3 a_normal;\n{declared}{outs}\nvoid main() {{\n{body}{store}    gl_Position = u_clip_from_object * vec4(a_position, 1.0);\n}}\n",
            );
            let pick = if two { "gl_FrontFacing ? v_front : v_back" } else { "v_front" };
            let ins = if two { "in vec4 v_front;\nin vec4 v_back;\n" } else { "in vec4 v_front;\n" };
            let fragment = format!(
                "#version 330 core\n{ins}out vec4 frag_color;\n\nvoid main() {{\n    frag_color = {pick};\n}}\n"
            );
            Shader { vertex, fragment, uniforms }
        }
        ShadingLanguage::Wgsl => {
            let back = if two { "    @location(1) back: vec4<f32>,\n" } else { "" };
            let store_back = if two { "    out.back = color1;\n" } else { "" };
            let pick = if two { "select(in.back, in.front, facing)" } else { "in.front" };
            let facing = if two { ", @builtin(front_facing) facing: bool" } else { "" };
            let module = format!(
                "{head}{list}{declared}\nstruct VertexIn {{\n    @location(0) position: vec3<f32>,\n    @location(1) normal: vec3<f32>,\n}};\n\nstruct VertexOut {{\n    @builtin(position) clip: vec4<f32>,\n    @location(0) front: vec4<f32>,\n{back}}};\n\n@vertex\nfn vs_main(input: VertexIn) -> VertexOut {{\n{body}    var out: VertexOut;\n    out.front = color0;\n{store_back}    out.clip = u.clip_from_object * vec4<f32>(input.position, 1.0);\n    return out;\n}}\n\n@fragment\nfn fs_main(in: VertexOut{facing}) -> @location(0) vec4<f32> {{\n    return {pick};\n}}\n",
            );
            Shader { vertex: module, fragment: String::new(), uniforms }
        }
    }
}

/// Phong: the vertex stage passes the eye-space position and normal; the fragment stage
/// lights each fragment (the side facing the eye, when two-sided).
fn phong(
    scene: &Scene,
    key: &Key,
    options: EvalOptions,
    ex: &Explanation,
    s: &Syn,
    mut uniforms: Vec<Uniform>,
) -> Shader {
    let program = Program::compile(key, SourceKind::EyeRaw(options.renormalize));
    let mut frag_uniforms: Vec<Uniform> = Vec::new();
    let body = indent(&lighting(scene, key, &program, ex, s, &mut frag_uniforms));
    let list = stage_list(&crate::t!("shader-what-program-fragment"), &program);
    uniforms.push(("normal_matrix".into(), "mat3"));
    let by_m = scene.rules.normal_transform() == NormalTransform::Modelview;
    let what = if by_m { crate::t!("shader-note-normal-by-m") } else { "(M^-1)^T".to_string() };
    let mut all = uniforms.clone();
    for u in frag_uniforms {
        if !all.contains(&u) {
            all.push(u);
        }
    }
    let (vertex_head, fragment_head) = (
        header(&crate::t!("shader-what-fragment-vertex-stage"), ShaderShading::Phong),
        header(&crate::t!("shader-what-fragment-lighting"), ShaderShading::Phong),
    );
    let (position, normal) = (step_no(ex, StepKind::Position, None), step_no(ex, StepKind::Normal, None));
    let two = key.two_sided;
    match s.lang {
        ShadingLanguage::Glsl => {
            let vertex = format!(
                "#version 330 core\n{vertex_head}layout(location = 0) in vec3 a_position;\nlayout(location = 1) in vec3 a_normal;\n{}out vec3 v_pos;\nout vec3 v_normal;\n\nvoid main() {{\n    vec4 Ph = u_eye_from_object * vec4(a_position, 1.0); // {position}\n    v_pos = Ph.xyz / Ph.w;\n    v_normal = u_normal_matrix * a_normal; // {normal} ({what})\n    gl_Position = u_clip_from_object * vec4(a_position, 1.0);\n}}\n",
                declare(s, &uniforms),
            );
            let side_pick =
                if two { "    frag_color = gl_FrontFacing ? color0 : color1;\n" } else { "    frag_color = color0;\n" };
            let fragment = format!(
                "#version 330 core\n{fragment_head}{list}{}in vec3 v_pos;\nin vec3 v_normal;\nout vec4 frag_color;\n\nvoid main() {{\n    vec3 P = v_pos;\n    vec3 N = v_normal;\n{body}{side_pick}}}\n",
                declare(s, &all),
            );
            Shader { vertex, fragment, uniforms: all }
        }
        ShadingLanguage::Wgsl => {
            let facing = if two { ", @builtin(front_facing) facing: bool" } else { "" };
            let pick = if two { "select(color1, color0, facing)" } else { "color0" };
            let module = format!(
                "{fragment_head}{list}{}\nstruct VertexIn {{\n    @location(0) position: vec3<f32>,\n    @location(1) normal: vec3<f32>,\n}};\n\nstruct VertexOut {{\n    @builtin(position) clip: vec4<f32>,\n    @location(0) pos: vec3<f32>,\n    @location(1) normal: vec3<f32>,\n}};\n\n@vertex\nfn vs_main(input: VertexIn) -> VertexOut {{\n    var out: VertexOut;\n    let Ph = u.eye_from_object * vec4<f32>(input.position, 1.0); // {position}\n    out.pos = Ph.xyz / Ph.w;\n    out.normal = u.normal_matrix * input.normal; // {normal} ({what})\n    out.clip = u.clip_from_object * vec4<f32>(input.position, 1.0);\n    return out;\n}}\n\n@fragment\nfn fs_main(in: VertexOut{facing}) -> @location(0) vec4<f32> {{\n    var P: vec3<f32> = in.pos;\n    var N: vec3<f32> = in.normal;\n{body}    return {pick};\n}}\n",
                declare(s, &all),
            );
            Shader { vertex: module, fragment: String::new(), uniforms: all }
        }
    }
}

/// The value a uniform of the generated program takes for `scene` drawn with
/// `clip_from_object`, as f32s in column-major order (a `mat3` as three columns of three),
/// or `None` for a name the generator does not use. Light positions and directions are in
/// eye space, as OpenGL keeps them.
pub fn uniform_value(scene: &Scene, clip_from_object: &glam::DMat4, name: &str) -> Option<Vec<f32>> {
    let f = |v: &[f64]| v.iter().map(|x| *x as f32).collect::<Vec<f32>>();
    let eye_from_object = scene.eye_from_object();
    let material = |m: &str| if m == "back" { scene.back() } else { &scene.material };
    if name == "color" {
        // GL_COLOR_MATERIAL's current colour (declared only where it tracks).
        return scene.color_material.map(|cm| f(&cm.color.to_array()));
    }
    if let Some(rest) = name.strip_prefix("light") {
        let (i, what) = rest.split_once('_')?;
        let l = scene.lights.get(i.parse::<usize>().ok()?)?;
        let pos = scene.light_pos_in_eye(l);
        return match what {
            "position" => Some(f(&pos.to_array())),
            "direction" => Some(f(&pos.truncate().normalize_or_zero().to_array())),
            "halfway" => Some(f(&(pos.truncate().normalize_or_zero() + glam::DVec3::Z).normalize_or_zero().to_array())),
            "ambient" => Some(f(&l.ambient.truncate().to_array())),
            "diffuse" => Some(f(&l.diffuse.truncate().to_array())),
            "specular" => Some(f(&l.specular.truncate().to_array())),
            "attenuation" => Some(f(&l.attenuation)),
            "spot_direction" => Some(f(&scene.eye_from_light(l).transform_vector3(l.spot_direction).to_array())),
            "spot_cos_cutoff" => Some(vec![crate::numerics::elementary::cos(l.spot_cutoff.to_radians()) as f32]),
            "spot_exponent" => Some(vec![l.spot_exponent as f32]),
            _ => None,
        };
    }
    if let Some((m, what)) = name.split_once('_').filter(|(m, _)| *m == "mat" || *m == "back") {
        let mat = material(m);
        return match what {
            "ambient" => Some(f(&mat.ambient.truncate().to_array())),
            "diffuse" => Some(f(&mat.diffuse.to_array())),
            "specular" => Some(f(&mat.specular.truncate().to_array())),
            "shininess" => Some(vec![mat.shininess as f32]),
            _ => None,
        };
    }
    match name {
        "clip_from_object" => Some(f(&clip_from_object.to_cols_array())),
        "eye_from_object" => Some(f(&eye_from_object.to_cols_array())),
        "normal_matrix" => {
            let nm = crate::model::transform::NormalMatrix::for_rules(&eye_from_object, scene.rules);
            Some(f(&nm.eye_from_object.to_cols_array()))
        }
        "rescale" => {
            Some(vec![crate::model::transform::NormalMatrix::for_rules(&eye_from_object, scene.rules).rescale as f32])
        }
        "scene_color" => {
            let m = &scene.lit_material(Side::Front);
            let e = if scene.rules.emission() { m.emission.truncate() } else { glam::DVec3::ZERO };
            let a = if scene.rules.scene_ambient() {
                m.ambient.truncate() * scene.light_model.ambient.truncate()
            } else {
                glam::DVec3::ZERO
            };
            Some(f(&(e + a).to_array()))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_uniform_a_program_declares_has_a_value() {
        let mut scenes = vec![crate::model::presets::worksheet(5), crate::model::presets::phong_demo()];
        let mut spot = crate::model::presets::worksheet(3);
        spot.lights[0].spot_cutoff = 30.0;
        spot.light_model.two_sided = true;
        scenes.push(spot);
        let mut dir = crate::model::presets::worksheet(5);
        dir.rules = crate::model::rules::Rules::OPENGL;
        dir.lights[0].position = glam::DVec4::new(0.0, 1.0, 1.0, 0.0);
        scenes.push(dir);
        for scene in &scenes {
            let lit = crate::equation::lighting::Engine::<f64>::new(scene).unwrap().light(&scene.vertex);
            let ex = crate::equation::explain::explain(scene, &lit, crate::equation::explain::Side::Front);
            for lang in [ShadingLanguage::Glsl, ShadingLanguage::Wgsl] {
                for shading in [ShaderShading::Gouraud, ShaderShading::Phong] {
                    let sh = generate(scene, EvalOptions::default(), &ex, lang, shading);
                    let us = &sh.uniforms;
                    assert!(us.iter().any(|(n, _)| n == "clip_from_object"), "{us:?}");
                    for (name, ty) in us {
                        // Declared in the source as listed.
                        let declared = match lang {
                            ShadingLanguage::Glsl => format!("uniform {ty} u_{name};"),
                            ShadingLanguage::Wgsl => format!("    {name}: "),
                        };
                        assert!(sh.vertex.contains(&declared) || sh.fragment.contains(&declared), "{name}");
                        let v = uniform_value(scene, &glam::DMat4::IDENTITY, name)
                            .unwrap_or_else(|| panic!("{name}: {ty}"));
                        let want = match *ty {
                            "mat4" => 16,
                            "mat3" => 9,
                            "vec4" => 4,
                            "vec3" => 3,
                            _ => 1,
                        };
                        assert_eq!(v.len(), want, "{name}: {ty}");
                    }
                }
            }
        }
        // Values are the scene's, in eye space.
        let s = crate::model::presets::worksheet(5);
        assert_eq!(uniform_value(&s, &glam::DMat4::IDENTITY, "light0_position").unwrap(), vec![0.0, 54.0, -888.0, 1.0]);
        assert_eq!(uniform_value(&s, &glam::DMat4::IDENTITY, "mat_shininess").unwrap(), vec![25.6]);
    }
}
