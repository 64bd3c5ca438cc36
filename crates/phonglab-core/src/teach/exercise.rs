//! Exercises in the worksheet's style: a scene drawn at random from "nice" numbers, screened
//! so that no answer hinges on rounding, with its answer key.
//!
//! A draw takes integer coordinates, one of the 24 classic materials, a rotation by whole
//! degrees about a coordinate axis and an integer translation, and attenuations and spot
//! parameters from short lists. It is kept only when
//!
//! - the scene uses exactly the effects asked for, read off the specialised plan's
//!   [`Key`] (so the check is the one the evaluator itself makes);
//! - no step's value differs between f32 and f64 by more than 1e-6 (relative to the
//!   value, for values above 1);
//! - some light reaches the surface (an exercise of ambient terms alone is not worth doing);
//! - it is not near a discontinuity: every |n·L| and every |n·H| at least 1e-3, every
//!   light at least 1e-3 from the vertex, and the vertex at least 1e-3 (in cosine) from a
//!   spotlight's cone edge;
//!
//! and otherwise drawn again. The random numbers are SplitMix64, so a seed gives the same
//! exercises on every machine.

use glam::{DMat4, DVec3, DVec4};

use crate::equation::explain::{Explanation, Side, explain};
use crate::equation::lighting::{Engine, EvalOptions};
use crate::equation::plan::{Key, Stage, Viewer};
use crate::formats::document::Document;
use crate::model::camera::CameraSpec;
use crate::model::materials;
use crate::model::rules::Rules;
use crate::model::scene::{Light, LightModel, LightPlacement, NormalMode, Scene, Vertex};
use crate::model::vocabulary::Quantity as Q;
use crate::numerics::elementary;

/// An effect an exercise can be asked to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Effect {
    /// A positional light (w = 1): L and d vary with the vertex.
    Positional,
    /// Attenuation other than (1, 0, 0) on a positional light.
    Attenuation,
    /// A spotlight.
    Spot,
    /// A local viewer.
    LocalViewer,
    /// Two-sided lighting.
    TwoSided,
    /// More than one light.
    SeveralLights,
}

impl Effect {
    /// Every effect, in the order of the difficulty levels.
    pub const ALL: [Effect; 6] = [
        Effect::Positional,
        Effect::Attenuation,
        Effect::Spot,
        Effect::LocalViewer,
        Effect::TwoSided,
        Effect::SeveralLights,
    ];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Effect::Positional => "positional",
            Effect::Attenuation => "attenuation",
            Effect::Spot => "spot",
            Effect::LocalViewer => "local-viewer",
            Effect::TwoSided => "two-sided",
            Effect::SeveralLights => "several-lights",
        }
    }

    /// The effect in words, in the reader's language (an exercise set's index).
    pub fn label(self) -> String {
        match self {
            Effect::Positional => crate::t!("exercise-effect-positional"),
            Effect::Attenuation => crate::t!("exercise-effect-attenuation"),
            Effect::Spot => crate::t!("exercise-effect-spot"),
            Effect::LocalViewer => crate::t!("exercise-effect-local-viewer"),
            Effect::TwoSided => crate::t!("exercise-effect-two-sided"),
            Effect::SeveralLights => crate::t!("exercise-effect-several-lights"),
        }
    }

    /// The effect named `s`.
    pub fn parse(s: &str) -> Option<Effect> {
        Effect::ALL.into_iter().find(|e| e.name() == s.trim())
    }

    /// The effects a scene uses, read off the program its key compiles to (what the
    /// evaluator runs), in the order of [`Effect::ALL`].
    pub fn of_key(key: &Key) -> Vec<Effect> {
        let mut out = Vec::new();
        for &stage in &key.program().stages {
            for effect in Effect::of_stage(stage) {
                if !out.contains(&effect) {
                    out.push(effect);
                }
            }
        }
        out.sort();
        out
    }

    /// The effects a stage of the evaluator's program shows a scene uses.
    fn of_stage(stage: Stage) -> Vec<Effect> {
        // A stage of a light after the first: there are several.
        let several = stage.light().filter(|i| i.index() > 0).map(|_| Effect::SeveralLights);
        let own = match stage {
            Stage::TransformNormal
            | Stage::RescaleNormal
            | Stage::NormalizeNormal
            | Stage::NormalizeNormalFast
            | Stage::TransformPosition
            | Stage::TransformPositionProjective
            | Stage::TranslatePosition
            | Stage::ZeroNormals
            | Stage::LightConstant(_)
            | Stage::SpotPower(_)
            | Stage::Halfway(_)
            | Stage::HalfwayConstant(_)
            | Stage::Reflect(_)
            | Stage::SceneColor => None,
            Stage::ViewVector(viewer) => match viewer {
                Viewer::Local => Some(Effect::LocalViewer),
                Viewer::EyePlane | Viewer::Infinite => None,
            },
            Stage::LightVector(_) => Some(Effect::Positional),
            Stage::Attenuate(_) => Some(Effect::Attenuation),
            Stage::SpotCone(_) => Some(Effect::Spot),
            Stage::DiffuseCosine(_, side)
            | Stage::SpecularCosine(_, side, _)
            | Stage::Power(_, side)
            | Stage::Sum(_, side, _) => match side {
                Side::Front => None,
                Side::Back => Some(Effect::TwoSided),
            },
        };
        own.into_iter().chain(several).collect()
    }
}

/// The difficulty levels: each adds to the one before.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// One directional light, infinite viewer.
    Directional = 1,
    /// One positional light with attenuation.
    Positional = 2,
    /// A positional, attenuated spotlight.
    Spotlight = 3,
    /// Two or three lights, two-sided lighting, a local viewer.
    TwoSidedSeveral = 4,
}

impl Level {
    /// The level numbered `n` (1 to 4).
    pub fn from_number(n: u8) -> Option<Level> {
        [Level::Directional, Level::Positional, Level::Spotlight, Level::TwoSidedSeveral]
            .get(n.checked_sub(1)? as usize)
            .copied()
    }

    /// The effects of the level.
    pub fn effects(self) -> Vec<Effect> {
        match self {
            Level::Directional => vec![],
            Level::Positional => vec![Effect::Positional, Effect::Attenuation],
            Level::Spotlight => vec![Effect::Positional, Effect::Attenuation, Effect::Spot],
            Level::TwoSidedSeveral => vec![
                Effect::Positional,
                Effect::Attenuation,
                Effect::LocalViewer,
                Effect::TwoSided,
                Effect::SeveralLights,
            ],
        }
    }
}

/// SplitMix64: small, fast, and the same on every machine.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator from `seed`.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// An integer in `lo..=hi`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }

    /// One of `items`.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.next_u64() as usize % items.len()]
    }

    /// A non-zero integer vector with components in `-k..=k`.
    fn int_vec(&mut self, k: i64) -> DVec3 {
        loop {
            let v = DVec3::new(self.int(-k, k) as f64, self.int(-k, k) as f64, self.int(-k, k) as f64);
            if v != DVec3::ZERO {
                return v;
            }
        }
    }
}

/// What to generate.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// Exactly these effects (sorted, no repeats).
    pub effects: Vec<Effect>,
    /// The rules the answers follow.
    pub rules: Rules,
}

impl Spec {
    /// A level's effects under `rules`.
    pub fn level(level: Level, rules: Rules) -> Spec {
        Spec { effects: level.effects(), rules }
    }
}

/// One exercise: its scene and its answer key.
#[derive(Clone, Debug)]
pub struct Exercise {
    /// The scene, with a description of its modelview as its camera.
    pub doc: Document,
    /// The modelview in words, e.g. "rotate 30 degrees about y, then translate (0, 0, -40)".
    pub modelview: String,
    /// The classic material's name, e.g. "gold".
    pub material: String,
    /// The worked calculation in f64: the answer key.
    pub key: Explanation,
    /// Draws rejected before this one was kept (by the screen).
    pub redraws: usize,
}

/// A rotation about axis `axis` (0 x, 1 y, 2 z) by `degrees`, then a translation.
fn modelview(axis: usize, degrees: i64, t: DVec3) -> DMat4 {
    let a = (degrees as f64).to_radians();
    let r = match axis {
        0 => elementary::rotation_x(a),
        1 => elementary::rotation_y(a),
        _ => elementary::rotation_z(a),
    };
    DMat4::from_translation(t) * r
}

/// One draw for `spec` (not yet screened).
fn draw(rng: &mut Rng, spec: &Spec) -> (Scene, String, String) {
    let has = |e: Effect| spec.effects.contains(&e);
    let axis = rng.int(0, 2) as usize;
    let degrees = rng.pick(&[0, 15, 20, 30, 45, 60, -30, -45, 90]);
    let t = DVec3::new(0.0, 0.0, -(rng.int(2, 8) * 10) as f64);
    let m = modelview(axis, degrees, t);
    let words = crate::t!(
        "exercise-modelview",
        degrees = degrees.to_string(),
        axis = ["x", "y", "z"][axis],
        translation = format!("({}, {}, {})", t.x, t.y, t.z)
    );
    let named = &materials::classic()[rng.int(0, 23) as usize];
    let lights_n = if has(Effect::SeveralLights) { rng.int(2, 3) as usize } else { 1 };
    let vertex_pos = rng.int_vec(10);
    // The normal faces the viewer's side in object space, so the surface is usually lit.
    let normal = rng.int_vec(2);
    let mut lights = Vec::new();
    for i in 0..lights_n {
        let positional = has(Effect::Positional) && (i == 0 || rng.int(0, 1) == 1);
        let position = if positional {
            // Somewhere in front of the vertex, along its normal.
            (vertex_pos + normal.normalize() * rng.int(10, 30) as f64 + rng.int_vec(8)).round().extend(1.0)
        } else {
            (normal.normalize() * 4.0 + rng.int_vec(2)).round().extend(0.0)
        };
        let attenuation = if has(Effect::Attenuation) && positional {
            rng.pick(&[[1.0, 0.01, 0.0], [1.0, 0.0, 0.001], [1.0, 0.01, 0.001], [0.5, 0.02, 0.0]])
        } else {
            [1.0, 0.0, 0.0]
        };
        let gray = |v: f64| DVec4::new(v, v, v, 1.0);
        let mut l = Light {
            ambient: gray(rng.pick(&[0.0, 0.2, 0.5, 1.0])),
            diffuse: gray(rng.pick(&[0.5, 0.8, 1.0])),
            specular: gray(rng.pick(&[0.5, 1.0])),
            position: if position.w == 0.0 && position.truncate() == DVec3::ZERO { DVec4::Z } else { position },
            attenuation,
            placement: LightPlacement::World,
            ..Light::gl_default(i)
        };
        if has(Effect::Spot) && positional && i == 0 {
            // Aimed near the vertex, the cone wide enough to hold it.
            let aim = (vertex_pos - l.position.truncate() + rng.int_vec(2)).round();
            l.spot_direction = if aim == DVec3::ZERO { -DVec3::Z } else { aim };
            l.spot_cutoff = rng.pick(&[20.0, 30.0, 45.0, 60.0]);
            l.spot_exponent = rng.pick(&[0.0, 2.0, 5.0, 10.0, 20.0]);
        }
        lights.push(l);
    }
    let scene = Scene {
        light_model: LightModel {
            ambient: DVec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: has(Effect::LocalViewer),
            two_sided: has(Effect::TwoSided),
            separate_specular: false,
        },
        lights,
        material: named.material.clone(),
        back_material: None,
        color_material: None,
        eye_from_world: m,
        world_from_object: DMat4::IDENTITY,
        normal_mode: NormalMode::Normalize,
        rules: spec.rules,
        vertex: Vertex { position: vertex_pos.extend(1.0), normal },
    };
    (scene, words, named.name.clone())
}

/// Why a draw is not kept (`None`: it is).
pub fn screen(scene: &Scene, spec: &Spec) -> Option<String> {
    let mut want = spec.effects.clone();
    want.sort();
    want.dedup();
    let key = Key::of(scene, EvalOptions::default());
    let mut got = Effect::of_key(&key);
    got.sort();
    if got != want {
        return Some(format!("uses {got:?}, not {want:?}"));
    }
    let e64 = match Engine::<f64>::new(scene) {
        Ok(e) => e.light(&scene.vertex),
        Err(e) => return Some(format!("refused: {e}")),
    };
    let e32 = match Engine::<f32>::new(scene) {
        Ok(e) => e.light(&scene.vertex),
        Err(e) => return Some(format!("refused: {e}")),
    };
    if !e64.all_limits().is_empty() {
        return Some("a limit was taken".into());
    }
    let sides: &[Side] = if scene.light_model.two_sided { &[Side::Front, Side::Back] } else { &[Side::Front] };
    for &side in sides {
        let (a, b) = (explain(scene, &e64, side), explain(scene, &e32, side));
        for (sa, sb) in a.steps.iter().zip(&b.steps) {
            match (&sa.value, &sb.value) {
                (Some(x), Some(y)) => {
                    for (p, q) in x.iter().zip(y) {
                        if !p.is_finite() || (p - q).abs() > 1e-6 * p.abs().max(1.0) {
                            return Some(format!("{}: f32 and f64 differ ({p} against {q})", sa.name));
                        }
                    }
                }
                (None, None) => {}
                _ => return Some(format!("{}: defined in one precision only", sa.name)),
            }
        }
    }
    // Near a discontinuity?
    for t in e64.lights() {
        for side in [&t.front, &t.back].into_iter().take(sides.len()) {
            if side.n_dot_l.abs() < 1e-3 {
                return Some("n.L within 1e-3 of 0".into());
            }
            if side.spec_cos.abs() < 1e-3 {
                return Some("the specular cosine within 1e-3 of 0".into());
            }
        }
    }
    // Worth doing: some light reaches the side explained (or, two-sided, either side).
    let lit = e64.lights().iter().any(|t| t.front.n_dot_l > 0.0 || (sides.len() > 1 && t.back.n_dot_l > 0.0));
    if !lit {
        return Some("unlit: no light reaches the surface".into());
    }
    let p = e64.pos_in_eye;
    for l in &scene.lights {
        let lp = scene.light_pos_in_eye(l);
        if lp.w != 0.0 && (lp.truncate() / lp.w - p).length() < 1e-3 {
            return Some("a light within 1e-3 of the vertex".into());
        }
        if l.is_spot() && lp.w != 0.0 {
            let dir = (scene.eye_from_light(l).transform_vector3(l.spot_direction)).normalize();
            let to_vertex = (p - lp.truncate() / lp.w).normalize();
            if (dir.dot(to_vertex) - elementary::cos(l.spot_cutoff.to_radians())).abs() < 1e-3 {
                return Some("the vertex within 1e-3 of the cone's edge".into());
            }
            if dir.dot(to_vertex) < elementary::cos(l.spot_cutoff.to_radians()) {
                return Some("the vertex outside the cone (no light to compute)".into());
            }
        }
    }
    None
}

/// The most draws made for one exercise before giving up.
pub const MAX_DRAWS: usize = 10_000;

/// `count` exercises from `seed`, numbered from 1.
pub fn generate(seed: u64, count: usize, spec: &Spec) -> Result<Vec<Exercise>, String> {
    draw_each(seed, count, spec, "exercise", |rng, k| {
        let (scene, words, material) = draw(rng, spec);
        if screen(&scene, spec).is_some() {
            return Ok(None);
        }
        let doc = Document::from_scene(
            &crate::t!("exercise-name", number = k.to_string(), seed = seed.to_string()),
            CameraSpec::Matrix(scene.eye_from_world),
            scene,
        );
        let lit = Engine::<f64>::new(&doc.scene).map_err(|e| e.to_string())?.light(&doc.scene.vertex);
        let key = explain(&doc.scene, &lit, Side::Front);
        Ok(Some(Exercise { doc, modelview: words, material, key, redraws: 0 }))
    })
}

/// The draw loop every kind of exercise shares: for exercise k (from 1) of `count`, one
/// random stream from `seed`, `attempt` draws a scene and screens it, giving the exercise
/// or `None` to set the draw aside; the draws set aside are counted into its `redraws`,
/// and after [`MAX_DRAWS`] of them the set is given up, naming the `kind` of exercise.
pub(crate) fn draw_each(
    seed: u64,
    count: usize,
    spec: &Spec,
    kind: &str,
    mut attempt: impl FnMut(&mut Rng, usize) -> Result<Option<Exercise>, String>,
) -> Result<Vec<Exercise>, String> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::new();
    for k in 1..=count {
        let mut redraws = 0;
        loop {
            if let Some(mut ex) = attempt(&mut rng, k)? {
                ex.redraws = redraws;
                out.push(ex);
                break;
            }
            redraws += 1;
            if redraws >= MAX_DRAWS {
                return Err(format!(
                    "{kind} {k}: no scene with {:?} passed the screen in {MAX_DRAWS} draws",
                    spec.effects
                ));
            }
        }
    }
    Ok(out)
}

/// A number as the sheet prints it: 8 significant digits, no trailing zeros.
fn num(x: f64) -> String {
    crate::locale::num(x, 8)
}

fn vec4(v: DVec4) -> String {
    crate::locale::decimal(&crate::equation::explain::fmt_printed(&[v.x, v.y, v.z, v.w], 8))
}

/// A colour as the worksheet writes it, `[r g b 0]`: every product of two colours (Iamb,
/// Idif, Ispec) then has 0 as its fourth component, as the key does.
fn colour4(c: DVec4) -> String {
    crate::locale::decimal(&crate::equation::explain::fmt_printed(&[c.x, c.y, c.z, 0.0], 8))
}

/// The rules an exercise is computed under, as its sheet says them.
pub fn rules_in_words(set: crate::model::rules::RuleSet) -> String {
    match set {
        crate::model::rules::RuleSet::Worksheet => crate::t!("sheet-rules-worksheet"),
        crate::model::rules::RuleSet::OpenGl => crate::t!("sheet-rules-opengl"),
        crate::model::rules::RuleSet::PhongDemo => crate::t!("sheet-rules-demo"),
    }
}

/// How a sheet numbers the steps it asks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Numbering {
    /// As the key's worked calculation numbers them (its own step numbers: 1, 2, 5, 9 …),
    /// so a sheet's step is found in the key by its number.
    Key,
    /// 1, 2, 3 … as the sheet asks them: an exam's, whose key lists the asked steps in the
    /// same numbers (as a Moodle question numbers its rows).
    Own,
}

/// The exercise sheet, in the worksheet's style: the givens under the worksheet's names,
/// then the steps to compute, each with a blank, numbered as the key numbers them.
pub fn sheet_markdown(ex: &Exercise) -> String {
    sheet_markdown_numbered(ex, Numbering::Key)
}

/// [`sheet_markdown`], its steps numbered as `numbering` says.
pub fn sheet_markdown_numbered(ex: &Exercise, numbering: Numbering) -> String {
    use std::fmt::Write as _;
    let s = &ex.doc.scene;
    let mut o = String::new();
    let _ = writeln!(o, "# {}\n", crate::formats::escape::markdown::text(&ex.doc.name));
    let _ = writeln!(o, "{}\n", crate::t!("sheet-compute", rules = rules_in_words(s.rules.set)));
    let _ = writeln!(o, "{}\n", crate::t!("sheet-colours"));
    if s.light_model.two_sided {
        // Which side to compute: the key's first, the one a Moodle question asks.
        let _ = writeln!(o, "{}\n", crate::t!("moodle-front-side"));
    }
    let _ = writeln!(o, "## {}\n", crate::t!("sheet-vertex"));
    let _ = writeln!(o, "- {} = {}", Q::VertexPos.name(), vec4(s.vertex.position));
    let _ = writeln!(o, "- {} = {}\n", Q::VertexNormal.name(), vec4(s.vertex.normal.extend(0.0)));
    let _ = writeln!(o, "## {}\n", crate::t!("sheet-modelview"));
    let (words, material) = (ex.modelview.as_str(), crate::model::materials::display_name(&ex.material));
    let _ = writeln!(o, "{words}:\n\n```");
    // As printed: an entry below the matrix's last printed digit is 0 (a rotation's
    // cos 90°), -0 is 0.
    let rows = crate::model::transform::mat4_rows(&s.eye_from_world);
    let printed = crate::equation::explain::printed_components(rows.as_flattened(), 8);
    for r in printed.chunks(4) {
        let _ = writeln!(o, "[{}]", r.iter().map(|x| format!("{:>12}", num(*x))).collect::<Vec<_>>().join(" "));
    }
    let _ = writeln!(o, "```\n");
    lights_markdown(&mut o, s);
    let m = &s.material;
    let _ = writeln!(o, "## {}\n", crate::t!("sheet-material", name = material));
    let _ = writeln!(o, "- {} = {}", Q::MatAmbient.name(), colour4(m.ambient));
    let _ = writeln!(o, "- {} = {}", Q::MatDiffuse.name(), colour4(m.diffuse));
    let _ = writeln!(o, "- {} = {}", Q::MatSpecular.name(), colour4(m.specular));
    let _ = writeln!(o, "- {} = {}\n", Q::Shininess.name(), num(m.shininess));
    let _ = writeln!(o, "## {}\n", crate::t!("sheet-light-model"));
    let lm = &s.light_model;
    let yes_no = |b: bool| if b { crate::t!("yes") } else { crate::t!("no") };
    let _ = writeln!(o, "- {}: {}", crate::t!("local-viewer"), yes_no(lm.local_viewer));
    let _ = writeln!(o, "- {}: {}", crate::t!("two-sided"), yes_no(lm.two_sided));
    if s.rules.scene_ambient() {
        let _ = writeln!(o, "- {} = {}", crate::t!("scene-ambient"), colour4(lm.ambient));
    }
    let _ = writeln!(o, "\n## {}\n", crate::t!("sheet-compute-heading"));
    let asked = (0..ex.key.steps.len()).filter(|k| crate::teach::quiz::asked(s, &ex.key, *k));
    for (row, k) in asked.enumerate() {
        let st = &ex.key.steps[k];
        let number = match numbering {
            Numbering::Key => k + 1,
            Numbering::Own => row + 1,
        };
        let _ = writeln!(o, "{number}. {}: `{}` = ________", st.title, st.name);
    }
    o
}

/// The lights of a sheet: each one's position or direction and the spotlight's direction,
/// with the note that they are in world coordinates, its colours, attenuation and cone.
fn lights_markdown(o: &mut String, s: &crate::model::scene::Scene) {
    use std::fmt::Write as _;
    for (i, l) in s.lights.iter().enumerate() {
        let _ = writeln!(o, "## {}\n", crate::t!("light-tab", index = i.to_string()));
        let what = if l.position.w == 0.0 { crate::t!("sheet-direction") } else { crate::t!("sheet-position") };
        let _ = writeln!(
            o,
            "- {} = {} ({})",
            Q::LightPos.name(),
            vec4(l.position),
            crate::t!("sheet-light-world", what = what)
        );
        let _ = writeln!(
            o,
            "- {} = {}, {} = {}, {} = {}",
            Q::LightAmbient.name(),
            colour4(l.ambient),
            Q::LightDiffuse.name(),
            colour4(l.diffuse),
            Q::LightSpecular.name(),
            colour4(l.specular)
        );
        if l.position.w != 0.0 {
            let [c, k1, k2] = l.attenuation;
            let [nc, n1, n2] = [Q::AttConstant, Q::AttLinear, Q::AttQuadratic].map(Q::name);
            let _ = writeln!(o, "- {nc} = {}, {n1} = {}, {n2} = {}", num(c), num(k1), num(k2));
        }
        if l.is_spot() {
            let note = crate::t!("sheet-light-world", what = crate::t!("sheet-direction"));
            let direction = vec4(l.spot_direction.extend(0.0));
            let _ = writeln!(o, "- {} = {direction} ({note})", Q::SpotDirection.name());
            let _ = writeln!(
                o,
                "- {} = {}, {} = {}",
                Q::SpotCutoff.name(),
                crate::t!("sheet-degrees", value = num(l.spot_cutoff)),
                Q::SpotExponent.name(),
                num(l.spot_exponent)
            );
        }
        let _ = writeln!(o);
    }
}
