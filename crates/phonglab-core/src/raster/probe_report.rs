//! The probe told as lines, in the reader's language and under the worksheet's names: what
//! `phonglab probe` prints and the shaded view's probe shows.

use crate::equation::plan::{Program, Stage};
use crate::locale::{num, tr};
use crate::model::rules::SpecularVector;
use crate::model::scene::LightId;
use crate::model::view::ShadingMode;
use crate::model::vocabulary::Quantity;
use crate::raster::probe::{Probe, ProbeShading};
use crate::t;

/// One line of the report: a label, the worksheet's name (or empty) and the value; `depth`
/// indents it under the line above.
#[derive(Clone, Debug, PartialEq)]
pub struct ReportLine {
    /// What it is, in the reader's language.
    pub label: String,
    /// The worksheet's (or the specification's) name for it, or empty.
    pub name: String,
    /// Its value.
    pub value: String,
    /// 0 for a heading-level line, 1 under it.
    pub depth: u8,
    /// The mesh vertex it is about, when it is one (the window opens its calculation).
    pub vertex: Option<usize>,
}

fn line(label: String, name: &str, value: String, depth: u8) -> ReportLine {
    ReportLine { label, name: name.to_string(), value, depth, vertex: None }
}

/// A vector of numbers, 4 significant digits each: `(0.1, 0.2, 0.3)`.
pub fn numbers(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| num(*x, 4)).collect();
    format!("({})", parts.join("; "))
}

/// The shading's name.
fn mode_name(mode: ShadingMode) -> String {
    mode.shading().label().to_string()
}

/// The whole report of one probe.
pub fn report(p: &Probe) -> Vec<ReportLine> {
    let mut out = vec![line(
        t!("probe-pixel", x = p.x as i64, y = p.y as i64, shading = mode_name(p.mode)),
        "",
        t!(
            "probe-triangle",
            triangle = p.triangle as i64,
            a = p.vertices[0] as i64,
            b = p.vertices[1] as i64,
            c = p.vertices[2] as i64
        ),
        0,
    )];
    out.push(line(tr(if p.back { "probe-back-face" } else { "probe-front-face" }), "", String::new(), 1));
    out.push(line(tr("probe-weights"), "b0, b1, b2", numbers(&p.weights), 0));
    match &p.shading {
        ProbeShading::Gouraud(g) => {
            let heading = if g.clamped { "probe-vertex-colours" } else { "probe-vertex-colours-unclamped" };
            out.push(line(tr(heading), "", String::new(), 0));
            for k in 0..3 {
                let mut l = line(
                    t!("probe-vertex", vertex = p.vertices[k] as i64),
                    &format!("c{k}"),
                    numbers(&g.vertex_colours[k]),
                    1,
                );
                l.vertex = Some(p.vertices[k]);
                out.push(l);
            }
            out.push(line(tr("probe-weighted-sum"), "b0 c0 + b1 c1 + b2 c2", numbers(&g.weighted_sum), 0));
        }
        ProbeShading::Phong(f) => {
            out.push(line(
                tr("probe-normal-interpolated"),
                "b0 n0 + b1 n1 + b2 n2",
                numbers(&f.normal_interpolated),
                0,
            ));
            out.push(line(tr("probe-normal-length"), "|n|", num(f.normal_length, 6), 1));
            let label = if f.renormalised { "probe-normal" } else { "probe-normal-as-interpolated" };
            out.push(line(tr(label), "n", numbers(&f.normal), 0));
            out.push(line(tr("probe-position"), "P", numbers(&f.position), 0));
        }
        ProbeShading::Flat(f) => {
            out.push(line(tr("probe-flat-centroid"), "P", numbers(&f.centroid), 0));
            out.push(line(tr("probe-flat-normal"), "n", numbers(&f.normal), 0));
            let mut l = line(
                t!("probe-provoking", vertex = f.provoking_vertex as i64),
                "GL_FLAT",
                numbers(&f.provoking_colour),
                1,
            );
            l.vertex = Some(f.provoking_vertex);
            out.push(l);
        }
    }
    terms_lines(p, &mut out);
    out.push(line(tr("probe-unclamped"), "c", numbers(&p.unclamped), 0));
    let bytes: Vec<String> = p.rgba8.iter().map(u8::to_string).collect();
    out.push(line(tr("probe-stored"), "round(255 clamp(c, 0, 1))", format!("({})", bytes.join(", ")), 0));
    out
}

/// The terms: emission, scene ambient, and each light's scalars and shares.
fn terms_lines(p: &Probe, out: &mut Vec<ReportLine>) {
    let heading = if p.mode == ShadingMode::Gouraud { "probe-terms-interpolated" } else { "probe-terms" };
    out.push(line(tr(heading), "", String::new(), 0));
    let q = |q: Quantity| (q.label(), q.name());
    let (label, name) = q(Quantity::EmissionTerm);
    out.push(line(label, name, numbers(&p.terms.emission), 1));
    let (label, name) = q(Quantity::SceneAmbientTerm);
    out.push(line(label, name, numbers(&p.terms.scene_ambient), 1));
    for l in &p.terms.lights {
        out.push(line(t!("probe-light", index = l.index.index() as i64), "", String::new(), 0));
        // The worksheet's `at` (it divides), then the factor OpenGL multiplies by, 1/at.
        let (label, name) = q(Quantity::Attenuation);
        let at = if l.attenuation == 0.0 { f64::INFINITY } else { 1.0 / l.attenuation };
        out.push(line(label, name, num(at, 4), 1));
        out.push(line(tr("probe-attenuation-factor"), "", format!("1/{name} = {}", num(l.attenuation, 4)), 1));
        for (qq, v) in [
            (Quantity::Spot, l.spot),
            (Quantity::CosTheta, l.n_dot_l),
            (specular_cosine(&p.program, l.index), l.n_dot_h),
        ] {
            let (label, name) = q(qq);
            out.push(line(label, name, num(v, 4), 1));
        }
        // Each term as it reaches the colour: times the spot factor, divided by at.
        let spot = Quantity::Spot.name();
        for (qq, v) in
            [(Quantity::Ambient, l.ambient), (Quantity::Diffuse, l.diffuse), (Quantity::Specular, l.specular)]
        {
            let (label, name) = q(qq);
            out.push(line(label, &format!("{spot} · {name} / {}", Quantity::Attenuation.name()), numbers(&v), 1));
        }
    }
    out.push(line(tr("probe-terms-sum"), "", numbers(&p.terms.sum()), 0));
}

/// The quantity light `i`'s specular cosine is, as `program` forms it: `cosBeta` (n . H)
/// or Phong's `cosAlpha` (R . V).
fn specular_cosine(program: &Program, i: LightId) -> Quantity {
    let mut q = Quantity::CosBeta;
    for stage in program.of_light(i) {
        match stage {
            Stage::Halfway(_) | Stage::HalfwayConstant(_) => q = Quantity::CosBeta,
            Stage::Reflect(_) => q = Quantity::CosAlpha,
            Stage::SpecularCosine(_, _, vector) => {
                q = match vector {
                    SpecularVector::Halfway => Quantity::CosBeta,
                    SpecularVector::Reflection => Quantity::CosAlpha,
                }
            }
            // Lines of their own whatever the stages (attenuation, spot, n . L, the terms).
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
            | Stage::SpotCone(_)
            | Stage::SpotPower(_)
            | Stage::DiffuseCosine(..)
            | Stage::Power(..)
            | Stage::Sum(..)
            | Stage::SceneColor => {}
        }
    }
    q
}

/// The report as plain text, one line each, indented.
pub fn text(lines: &[ReportLine]) -> String {
    let mut s = String::new();
    for l in lines {
        let indent = "  ".repeat(l.depth as usize);
        let name = if l.name.is_empty() { String::new() } else { format!(" [{}]", l.name) };
        let value = if l.value.is_empty() { String::new() } else { format!(": {}", l.value) };
        s.push_str(&format!("{indent}{}{name}{value}\n", l.label));
    }
    s
}
