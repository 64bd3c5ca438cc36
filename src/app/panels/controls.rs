//! The controls: lights, material, light model, vertex, camera and rules. Every widget
//! edits a copy of the document; the caller applies it (or refuses it).

use crate::app::widgets::fields::combo_ui;
use crate::t;
use egui::{CollapsingHeader, Ui};
use glam::{DMat4, DVec3, DVec4};
use phonglab_core::scene::{ColorMaterial, ColorMaterialMode, Face, Side};
use phonglab_core::transform::{mat4_from_rows, mat4_rows};
use phonglab_core::vocabulary::Quantity as Q;
use phonglab_core::{
    CameraSpec, Document, Light, LightPlacement, MAX_LIGHTS, Material, NormalMode, RuleSet, Rules, SpecularModel,
    materials,
};

use crate::app::widgets::fields::{color_ui, number_ui, slider_ui, vec3_ui, vec4_ui};
use crate::app::widgets::number_field::NumberField;

/// The controls' own choice: the light whose controls are shown.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ControlsState {
    /// The light shown (kept within the scene's lights when it loses some).
    pub selected_light: usize,
}

/// All the controls, in collapsible sections.
pub fn controls_ui(ui: &mut Ui, doc: &mut Document, state: &mut ControlsState) {
    CollapsingHeader::new(t!("controls-rules")).id_salt("rules").default_open(true).show(ui, |ui| rules_ui(ui, doc));
    CollapsingHeader::new(t!("controls-lights"))
        .id_salt("lights")
        .default_open(true)
        .show(ui, |ui| lights_ui(ui, doc, state));
    CollapsingHeader::new(t!("controls-material"))
        .id_salt("material")
        .default_open(true)
        .show(ui, |ui| material_section_ui(ui, doc));
    CollapsingHeader::new(t!("controls-light-model"))
        .id_salt("light model")
        .default_open(true)
        .show(ui, |ui| light_model_ui(ui, doc));
    CollapsingHeader::new(t!("controls-vertex")).id_salt("vertex").default_open(true).show(ui, |ui| vertex_ui(ui, doc));
    CollapsingHeader::new(t!("controls-camera"))
        .id_salt("camera")
        .default_open(false)
        .show(ui, |ui| camera_ui(ui, doc));
}

/// Rule set and specular model.
pub fn rules_ui(ui: &mut Ui, doc: &mut Document) {
    let rules = &mut doc.scene.rules;
    combo_ui(ui, &t!("rule-set"), rules.set.label(), |ui| {
        for r in RuleSet::ALL {
            // A rule set comes with its specular model (as the G key and its scene do).
            if ui.selectable_label(rules.set == r, r.label()).clicked() && rules.set != r {
                *rules = Rules::of_set(r);
            }
        }
    });
    combo_ui(ui, &t!("specular-model"), rules.specular.label(), |ui| {
        for m in SpecularModel::ALL {
            ui.selectable_value(&mut rules.specular, m, m.label());
        }
    });
    // In the body's size (a smaller type was 9 points at the projector).
    ui.label(match rules.set {
        RuleSet::OpenGl => {
            t!("rules-opengl-summary")
        }
        RuleSet::Worksheet => {
            t!("rules-worksheet-summary")
        }
        RuleSet::PhongDemo => {
            t!("rules-demo-summary")
        }
    });
}

fn placement_label(p: &LightPlacement) -> String {
    match p {
        LightPlacement::Eye => t!("placement-eye"),
        LightPlacement::World => t!("placement-world"),
        LightPlacement::Object => t!("placement-object"),
        LightPlacement::Matrix(_) => t!("placement-matrix"),
    }
}

/// The spot direction, in the coordinates light `l` is placed in, that aims it at the
/// shaded view's object (its origin), so a new spotlight lights what is on screen; `None`
/// for a directional light or a light at the object.
pub fn aim_at_object(doc: &Document, l: &Light) -> Option<DVec3> {
    let shaded = doc.shaded_scene();
    let object = shaded.eye_from_object() * DVec4::W;
    let in_light = shaded.eye_from_light(l).inverse() * object;
    if l.position.w == 0.0 || in_light.w == 0.0 {
        return None;
    }
    (in_light.truncate() / in_light.w - l.position.truncate() / l.position.w).try_normalize()
}

/// The smallest of 1, 2 and 5 times a power of ten that is at least `x`.
pub fn nice_ceiling(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 || x.is_infinite() {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0].into_iter().map(|k| k * p).find(|v| *v >= x * (1.0 - 1e-12)).unwrap_or(10.0 * p)
}

/// The light position sliders' range, ±this: twice the scene's own size (the worked
/// vertex, the lights, the view's object of radius about 1), rounded up to 1, 2 or 5 times
/// a power of ten. A one-unit teapot gets ±5 (a slider's pixel is a few hundredths), the
/// worksheet's vertex at -512 gets ±2000. Typed values are not bounded by it; one beyond it
/// widens the range.
pub fn position_range(doc: &Document) -> f64 {
    let extent = |p: DVec4| if p.w == 0.0 { 0.0 } else { (p.truncate() / p.w).abs().max_element() };
    let lights = doc.scene.lights.iter().map(|l| extent(l.position)).fold(0.0, f64::max);
    let m = extent(doc.scene.vertex.position).max(lights).max(1.0);
    nice_ceiling(2.0 * m).max(5.0)
}

fn lights_ui(ui: &mut Ui, doc: &mut Document, state: &mut ControlsState) {
    let range = position_range(doc);
    let aims: Vec<Option<DVec3>> = doc.scene.lights.iter().map(|l| aim_at_object(doc, l)).collect();
    let lights = &mut doc.scene.lights;
    // The buttons come first, in their own id scope, so their ids do not move when a
    // tab is added (a click aimed at the last frame's button would miss).
    ui.push_id("light buttons", |ui| {
        ui.horizontal_wrapped(|ui| {
            if ui.add_enabled(lights.len() < MAX_LIGHTS, egui::Button::new(t!("add-light"))).clicked() {
                let mut l = Light::gl_default(lights.len());
                // A visible default: a white directional light from the upper right.
                l.diffuse = DVec4::ONE;
                l.specular = DVec4::ONE;
                l.position = DVec4::new(1.0, 1.0, 1.0, 0.0);
                lights.push(l);
                state.selected_light = lights.len() - 1;
            }
            if ui.add_enabled(!lights.is_empty(), egui::Button::new(t!("remove-light"))).clicked() {
                let i = state.selected_light.min(lights.len() - 1);
                lights.remove(i);
                state.selected_light = i.saturating_sub(1);
            }
            let count = t!("lights-of-max", count = lights.len(), max = MAX_LIGHTS.to_string());
            ui.add(egui::Label::new(count).wrap_mode(egui::TextWrapMode::Extend));
        });
    });
    ui.horizontal_wrapped(|ui| {
        for i in 0..lights.len() {
            ui.selectable_value(&mut state.selected_light, i, t!("light-tab", index = i.to_string()));
        }
    });
    if lights.is_empty() {
        ui.label(t!("no-lights"));
        return;
    }
    let i = state.selected_light.min(lights.len() - 1);
    let l = &mut lights[i];
    ui.separator();

    let mut directional = l.position.w == 0.0;
    if ui.checkbox(&mut directional, t!("directional")).changed() {
        l.position.w = if directional { 0.0 } else { 1.0 };
    }
    for (name, v) in
        [(t!("light-x"), &mut l.position.x), (t!("light-y"), &mut l.position.y), (t!("light-z"), &mut l.position.z)]
    {
        slider_ui(ui, &name, v, -range..=range, false);
    }
    combo_ui(ui, &t!("light-fixed-to"), placement_label(&l.placement), |ui| {
        for p in [LightPlacement::Eye, LightPlacement::World, LightPlacement::Object] {
            let label = placement_label(&p);
            ui.selectable_value(&mut l.placement, p, label);
        }
    });

    color_ui(ui, &Q::LightAmbient.label(), &mut l.ambient, false);
    color_ui(ui, &Q::LightDiffuse.label(), &mut l.diffuse, false);
    color_ui(ui, &Q::LightSpecular.label(), &mut l.specular, false);

    ui.add_enabled_ui(!directional, |ui| {
        slider_ui(ui, &Q::AttConstant.label(), &mut l.attenuation[0], 0.0..=10.0, true);
        slider_ui(ui, &Q::AttLinear.label(), &mut l.attenuation[1], 0.0..=1.0, true);
        slider_ui(ui, &Q::AttQuadratic.label(), &mut l.attenuation[2], 0.0..=0.1, true);
    });
    if directional {
        ui.small(t!("attenuation-positional-only"));
    }

    let mut spot = l.is_spot();
    if ui.checkbox(&mut spot, t!("spotlight")).on_hover_text(t!("spotlight-hover")).changed() {
        l.spot_cutoff = if spot { 30.0 } else { 180.0 };
        if let (true, Some(Some(aim))) = (spot, aims.get(i)) {
            l.spot_direction = *aim;
        }
    }
    if spot {
        vec3_ui(ui, &Q::SpotDirection.label(), &mut l.spot_direction, 0.01);
        slider_ui(ui, &Q::SpotCutoff.label(), &mut l.spot_cutoff, 0.0..=90.0, false);
        slider_ui(ui, &Q::SpotExponent.label(), &mut l.spot_exponent, 0.0..=128.0, false);
    }
}

/// One side's material; the colours `GL_COLOR_MATERIAL` tracks there (`tracks`) are shown
/// but greyed, with why.
fn material_ui(ui: &mut Ui, m: &mut Material, back: bool, tracks: impl Fn(ColorMaterialMode) -> bool) {
    // "Material shininess" (the quantity's own label) or "Back shininess", as one
    // message each.
    let label = |field: &str| {
        let side = if back { "back" } else { "material" };
        crate::locale::tr(&format!("{side}-{field}"))
    };
    let quantity = |q: Q, field: &str| if back { label(field) } else { q.label() };
    let current = materials::name_of(m);
    let shown = current.map_or_else(|| t!("material-custom"), materials::display_name);
    combo_ui(ui, &label("preset"), shown, |ui| {
        for named in materials::classic() {
            let name = materials::display_name(&named.name);
            if ui.selectable_label(current == Some(named.name.as_str()), name).clicked() {
                *m = named.material.clone();
            }
        }
    });
    let colours = [
        (ColorMaterialMode::Ambient, quantity(Q::MatAmbient, "ambient"), &mut m.ambient, false),
        (ColorMaterialMode::Diffuse, quantity(Q::MatDiffuse, "diffuse"), &mut m.diffuse, true),
        (ColorMaterialMode::Specular, quantity(Q::MatSpecular, "specular"), &mut m.specular, false),
        (ColorMaterialMode::Emission, quantity(Q::MatEmission, "emission"), &mut m.emission, false),
    ];
    for (property, label, c, alpha) in colours {
        let tracked = tracks(property);
        let r = ui.add_enabled_ui(!tracked, |ui| color_ui(ui, &label, c, alpha));
        if tracked {
            r.response.on_disabled_hover_text(t!("color-material-tracked"));
        }
    }
    slider_ui(ui, &quantity(Q::Shininess, "shininess"), &mut m.shininess, 0.0..=128.0, false);
}

fn material_section_ui(ui: &mut Ui, doc: &mut Document) {
    let cm = doc.scene.color_material;
    let tracks = |side: Side| move |p: ColorMaterialMode| cm.is_some_and(|cm| cm.tracks(p, side));
    material_ui(ui, &mut doc.scene.material, false, tracks(Side::Front));
    color_material_ui(ui, doc);
    if doc.scene.light_model.two_sided {
        let mut separate = doc.scene.back_material.is_some();
        if ui.checkbox(&mut separate, t!("separate-back-material")).changed() {
            doc.scene.back_material = separate.then(|| doc.scene.material.clone());
        }
        if let Some(b) = &mut doc.scene.back_material {
            material_ui(ui, b, true, tracks(Side::Back));
        }
    }
}

/// `GL_COLOR_MATERIAL`: on or off, which colours track, on which faces, and the current
/// colour they track.
fn color_material_ui(ui: &mut Ui, doc: &mut Document) {
    let cm = &mut doc.scene.color_material;
    let mut on = cm.is_some();
    if ui.checkbox(&mut on, t!("color-material")).on_hover_text(t!("color-material-hover")).changed() {
        *cm = on.then(ColorMaterial::default);
    }
    let Some(cm) = cm else { return };
    combo_ui(ui, &t!("color-material-mode"), cm.mode.gl(), |ui| {
        for m in ColorMaterialMode::ALL {
            ui.selectable_value(&mut cm.mode, m, m.gl());
        }
    });
    combo_ui(ui, &t!("color-material-face"), cm.face.gl(), |ui| {
        for f in [Face::Front, Face::Back, Face::FrontAndBack] {
            ui.selectable_value(&mut cm.face, f, f.gl());
        }
    });
    color_ui(ui, &t!("color-material-color"), &mut cm.color, true);
}

fn light_model_ui(ui: &mut Ui, doc: &mut Document) {
    let lm = &mut doc.scene.light_model;
    color_ui(ui, &t!("scene-ambient"), &mut lm.ambient, false);
    ui.checkbox(&mut lm.local_viewer, t!("local-viewer"));
    ui.checkbox(&mut lm.two_sided, t!("two-sided"));
    ui.checkbox(&mut lm.separate_specular, t!("separate-specular"));
    let label = |m: NormalMode| match m {
        NormalMode::AsIs => t!("normals-as-is"),
        NormalMode::Normalize => "GL_NORMALIZE".to_string(),
        NormalMode::Rescale => "GL_RESCALE_NORMAL".to_string(),
    };
    let nm = &mut doc.scene.normal_mode;
    combo_ui(ui, &t!("normals"), label(*nm), |ui| {
        for m in [NormalMode::AsIs, NormalMode::Normalize, NormalMode::Rescale] {
            ui.selectable_value(nm, m, label(m));
        }
    });
}

fn vertex_ui(ui: &mut Ui, doc: &mut Document) {
    let v = &mut doc.scene.vertex;
    vec4_ui(ui, &t!("vertex"), &mut v.position, 1.0);
    vec3_ui(ui, &t!("normal"), &mut v.normal, 0.01);
    if ui.button(t!("normalise-normal")).clicked()
        && let Some(n) = v.normal.try_normalize()
    {
        v.normal = n;
    }
}

fn camera_ui(ui: &mut Ui, doc: &mut Document) {
    let kinds = [
        CameraSpec::Worksheet(5),
        CameraSpec::LookAt { eye: DVec3::new(0.0, 0.0, 5.0), centre: DVec3::ZERO, up: DVec3::Y },
        CameraSpec::OpenFrameworks { width: 1024.0, height: 768.0 },
        CameraSpec::Matrix(doc.scene.eye_from_world),
    ];
    let current = doc.camera.kind_label();
    combo_ui(ui, &t!("camera"), doc.camera.kind_name(), |ui| {
        for k in kinds {
            if ui.selectable_label(current == k.kind_label(), k.kind_name()).clicked() && current != k.kind_label() {
                doc.camera = k;
            }
        }
    });
    match &mut doc.camera {
        CameraSpec::Worksheet(i) => {
            ui.horizontal_wrapped(|ui| {
                for k in 1..=5u8 {
                    ui.radio_value(i, k, format!("mview{k}"));
                }
            });
            ui.small(worksheet_modelview_note(*i));
        }
        CameraSpec::LookAt { eye, centre, up } => {
            vec3_ui(ui, &t!("camera-eye"), eye, 0.05);
            vec3_ui(ui, &t!("camera-centre"), centre, 0.05);
            vec3_ui(ui, &t!("camera-up"), up, 0.05);
        }
        CameraSpec::OpenFrameworks { width, height } => {
            number_ui(ui, &t!("window-width"), width, 1.0);
            number_ui(ui, &t!("window-height"), height, 1.0);
            let d = phonglab_core::transform::of_camera_distance(*height);
            ui.small(t!("of-eye-distance", distance = crate::locale::num(d, 7)));
        }
        CameraSpec::Matrix(m) => matrix_ui(ui, m),
    }
    ui.separator();
    ui.label(t!("object-placement"));
    named_matrix_ui(ui, &mut doc.scene.world_from_object, &t!("object-matrix"));
}

fn matrix_ui(ui: &mut Ui, m: &mut DMat4) {
    named_matrix_ui(ui, m, "M");
}

/// A 4x4 grid of number fields, each named "{name} row r column c" for assistive
/// technology; four numbers typed into one field set its row.
fn named_matrix_ui(ui: &mut Ui, m: &mut DMat4, name: &str) {
    let mut rows = mat4_rows(m);
    let mut changed = false;
    egui::Grid::new(format!("{name} matrix")).show(ui, |ui| {
        ui.label("");
        for c in 0..4 {
            ui.small(t!("matrix-column", column = c.to_string()));
        }
        ui.end_row();
        for (r, row) in rows.iter_mut().enumerate() {
            ui.small(t!("matrix-row", name = name, row = r.to_string()));
            let (mut typed_row, mut refused) = (None, None);
            for (c, x) in row.iter_mut().enumerate() {
                let shown =
                    NumberField::new(x, t!("matrix-cell", name = name, row = r.to_string(), column = c.to_string()))
                        .show_in_row_ui(ui, 4);
                changed |= shown.response.changed();
                typed_row = typed_row.or(shown.row);
                refused = refused.or(shown.refused);
            }
            if let Some(all) = typed_row {
                row.iter_mut().zip(all).for_each(|(x, t)| *x = t);
            }
            if let Some(why) = refused {
                crate::app::widgets::number_field::refusal_ui(ui, &why);
            }
            ui.end_row();
        }
    });
    if changed {
        *m = mat4_from_rows(rows);
    }
}

/// A note on the worksheet's modelview `mview{k}`: what it is, and how far it is from a
/// rotation, measured ([`phonglab_core::transform::RotationCheck`]) with the worksheet's
/// normal (0, 0, 1): mview3 and mview4 are not rotations, and their M n and OpenGL's
/// (M^-1)^T n point 13.5° and 48° apart.
pub fn worksheet_modelview_note(k: u8) -> String {
    let what = match k {
        1 => t!("mview1-what"),
        2 => t!("mview2-what"),
        3 | 4 => t!("mview34-what"),
        _ => t!("mview5-what"),
    };
    let Some(m) = phonglab_core::transform::worksheet_modelview(usize::from(k)) else { return String::new() };
    let check = phonglab_core::transform::RotationCheck::of(&m, DVec3::Z);
    format!("mview{k}: {what}. {}.", phonglab_core::explain::modelview_note(&check))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_notes_on_mview3_and_mview4_say_they_are_not_rotations() {
        let n3 = worksheet_modelview_note(3);
        assert!(n3.contains("M is not a rotation: rows 1 and 3 are 72.3° apart, rows 2 and 3 are 55.2° apart"), "{n3}");
        assert!(n3.contains("points 13.5° away from OpenGL's (M^-1)^T n"), "{n3}");
        let n4 = worksheet_modelview_note(4);
        assert!(n4.contains("rows 1 and 3 are 120° apart, rows 2 and 3 are 41.5° apart"), "{n4}");
        assert!(n4.contains("points 48.5° away"), "{n4}");
        assert!(worksheet_modelview_note(5).contains("M is a rotation"));
        assert!(worksheet_modelview_note(2).contains("M is a rotation to the 6 digits"));
    }

    #[test]
    fn slider_ranges_follow_the_scene() {
        assert_eq!(nice_ceiling(3.0), 5.0);
        assert_eq!(nice_ceiling(1024.0), 2000.0);
        assert_eq!(nice_ceiling(17.8), 20.0);
        assert_eq!(nice_ceiling(100.0), 100.0);
        // The worksheet: the vertex at -512.
        assert_eq!(position_range(&Document::default()), 2000.0);
        // The Phong demo: the light at (-4, 0, -8) and a one-unit sphere.
        assert_eq!(position_range(&phonglab_core::library::phong_demo_document()), 20.0);
        let mut d = phonglab_core::library::phong_demo_document();
        d.scene.lights[0].position = DVec4::new(0.5, 0.5, 1.0, 1.0);
        d.scene.vertex.position = DVec4::new(0.0, 0.0, 0.5, 1.0);
        assert_eq!(position_range(&d), 5.0);
    }
}
