//! The shaded view's toolbar (the object and the shading are the top bar's): the switches,
//! the view's options (the renderer, the tessellation, the pipeline's choices, a mesh file)
//! and the Phong demo's departures as switches.

use egui::Ui;
use phonglab_core::library::DemoDeparture;
use phonglab_core::{Document, FlatNormal, Framing, ObjectKind, View};

use super::cache::{DrawnBy, ShadedCache};
use super::context::Shaded;
use super::gpu;
use crate::t;

/// The pipeline's choices where OpenGL and the Phong demo differ, and the demo's
/// departures as switches: each flipped one is corrected in a second picture beside the
/// demo's own.
fn pipeline_ui(ui: &mut Ui, view: &mut View) {
    egui::CollapsingHeader::new(t!("pipeline")).id_salt("pipeline").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            let l = ui.label(t!("picture"));
            egui::ComboBox::from_id_salt("framing")
                .selected_text(view.framing.label())
                .show_ui(ui, |ui| {
                    for f in Framing::ALL {
                        ui.selectable_value(&mut view.framing, f, f.label());
                    }
                })
                .response
                .labelled_by(l.id);
            ui.checkbox(&mut view.phong_renormalize, t!("phong-renormalises"))
                .on_hover_text(t!("phong-renormalises-hover"));
            let mut derivative = view.flat_normal == FlatNormal::ScreenDerivatives;
            if ui
                .checkbox(&mut derivative, t!("flat-derivatives"))
                .on_hover_text(t!("flat-derivatives-hover"))
                .changed()
            {
                view.flat_normal = if derivative { FlatNormal::ScreenDerivatives } else { FlatNormal::Face };
            }
        });
    });
}

/// The demo's departures as switches (only those the document makes): one row that stays
/// where it is whatever is switched, and the reasons folded into one line that opens on a
/// click.
///
/// They stand across the whole centre, above the pictures, so that switching one (which
/// puts a second picture beside the first) moves nothing.
pub fn departures_ui(ui: &mut Ui, doc: &Document, fixes: &mut [bool; 3]) {
    let departures: Vec<DemoDeparture> = DemoDeparture::ALL.into_iter().filter(|d| d.present_in(doc)).collect();
    if departures.is_empty() {
        return;
    }
    ui.horizontal_wrapped(|ui| {
        ui.label(t!("correct-the-demo"));
        for (k, d) in DemoDeparture::ALL.into_iter().enumerate() {
            if departures.contains(&d) {
                ui.checkbox(&mut fixes[k], d.fix_label()).on_hover_text(d.why());
            }
        }
    });
    egui::CollapsingHeader::new(t!("why-demo-differs")).id_salt("departures").default_open(false).show(ui, |ui| {
        ui.small(t!("why-demo-differs-intro"));
        for d in DemoDeparture::ALL {
            if departures.contains(&d) {
                ui.small(format!("{}: {}", d.fix_label(), d.why()));
            }
        }
    });
}

/// The mesh's resolution and the pipeline's choices.
fn view_options_ui(ui: &mut Ui, view: &mut View) {
    ui.horizontal_wrapped(|ui| {
        let count = |ui: &mut Ui, label: &str, v: &mut u32, r: std::ops::RangeInclusive<u32>| {
            crate::app::widgets::fields::whole_number_ui(ui, label, v, r);
        };
        match view.object {
            ObjectKind::Sphere => {
                count(ui, &t!("sphere-slices"), &mut view.sphere_slices, phonglab_core::view::SLICES_RANGE);
                count(ui, &t!("sphere-stacks"), &mut view.sphere_stacks, phonglab_core::view::SLICES_RANGE);
            }
            ObjectKind::Teapot => count(ui, &t!("teapot-grid"), &mut view.teapot_grid, phonglab_core::view::GRID_RANGE),
            ObjectKind::Cylinder => {
                count(ui, &t!("cylinder-slices"), &mut view.cylinder_slices, phonglab_core::view::SLICES_RANGE);
                count(ui, &t!("cylinder-stacks"), &mut view.cylinder_stacks, phonglab_core::view::STACKS_RANGE);
                ui.checkbox(&mut view.cylinder_caps, t!("caps"));
            }
            ObjectKind::Obj => {
                if let Ok(o) = view.obj_mesh() {
                    ui.small(t!("mesh-triangles", count = o.mesh.triangle_count(), notes = o.notes.join("; ")));
                }
            }
        }
    });
    pipeline_ui(ui, view);
}

/// The least side the picture keeps under the opened View options (points): they scroll
/// in what is left. (At 1024x600 with a term's legend under the picture, 45 % of the part
/// for the options left the picture 64 points, its caption over three lines.)
pub const PICTURE_KEEP: f32 = 160.0;

/// The opened View options' height: at most 45 % of the part's height, and no more than
/// leaves the picture [`PICTURE_KEEP`] with a four-line caption and its legend (when a term
/// is shown); at least two rows.
fn options_height(ui: &Ui, state: &Shaded<'_>) -> f32 {
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let legend = state.view_options.channel.map_or(0.0, |c| {
        let id = super::channel_view::name_id(c, state.edit.doc, state.pow);
        super::channel_view::legend_height(ui, c, id, PICTURE_KEEP)
    });
    // The caption's room is its longest variant's, four lines at that width in Portuguese
    // ("Esfera Gouraud: 0,8 ms por imagem no CPU", seen in the real window at 1024x600),
    // and the options' frame and spacing take about 40 points more.
    let keep = PICTURE_KEEP + 4.0 * body + legend + 40.0;
    let avail = ui.available_height();
    (avail - keep).min(0.45 * avail).max(2.0 * ui.spacing().interact_size.y)
}

/// The view's toolbar: not presenting, the switches and the view options; applies what
/// changed, and turns the object when it spins.
/// Returns the mesh file asked for, if one was.
pub(super) fn toolbar_ui(ui: &mut Ui, state: &mut Shaded<'_>, cache: &ShadedCache) -> Option<std::path::PathBuf> {
    let mut view = state.edit.doc.view.clone();
    let presenting = state.presenting;
    let mut open_obj_requested = None;
    if !presenting {
        // The object and the shading are the top bar's; presenting, the switches are in
        // the drawer and on the keys.
        // One row: the switches, and View options (opened below it).
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut view.auto_rotate, t!("auto-rotate")).on_hover_text(t!("auto-rotate-hover"));
            ui.checkbox(&mut view.demo_normals, t!("demo-normals")).on_hover_text(t!("demo-normals-hover"));
            ui.checkbox(&mut state.heat_map.on, t!("heat-map")).on_hover_text(t!("heat-map-hover"));
            ui.checkbox(&mut state.view_options.probe.on, t!("probe")).on_hover_text(t!("probe-hover"));
            let open = &mut state.view_options.options_open;
            if ui.selectable_label(*open, t!("view-options")).on_hover_text(t!("view-options-hover")).clicked() {
                *open = !*open;
            }
        });
    }
    if !presenting && state.view_options.options_open {
        // Opened, the options scroll within a part of the view's space, so the picture
        // stays on screen (smaller) rather than being pushed below the window.
        let most = options_height(ui, state);
        egui::Frame::group(ui.style()).show(ui, |ui| {
            egui::ScrollArea::vertical().max_height(most).show(ui, |ui| {
                // The term shown in place of the picture (Compare has its own).
                let program = super::channel_view::program_of(state.edit.doc, state.pow);
                super::channel_view::channel_ui(ui, &mut state.view_options.channel, &[&program]);
                renderer_ui(ui, state, &cache.main.drawn_by);
                view_options_ui(ui, &mut view);
                ui.horizontal_wrapped(|ui| {
                    let l = ui.label(t!("mesh-file"));
                    let field = ui
                        .add(
                            egui::TextEdit::singleline(&mut state.view_options.obj_path)
                                .desired_width(180.0)
                                .hint_text(t!("mesh-file-hint")),
                        )
                        .labelled_by(l.id);
                    let enter = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                    if ui.button(t!("show-mesh")).on_hover_text(t!("show-mesh-hover")).clicked() || enter {
                        open_obj_requested = Some(std::path::PathBuf::from(state.view_options.obj_path.trim()));
                    }
                });
            });
        });
    }
    if view != state.edit.doc.view {
        let mut c = state.edit.doc.clone();
        c.view = view;
        state.edit.apply(c);
    }

    // The spin is not an edit: it stays finite and in range, and must not clear a message.
    // A worked vertex on the object turns with it (its arrows stay on it).
    if state.edit.doc.view.auto_rotate {
        let on_object = super::overlay::vertex_on_object(state.edit.doc);
        let doc = &mut *state.edit.doc;
        let spin = doc.view.spin_degrees;
        // Where the window began to turn it, unless the spin was since set otherwise (a
        // file opened, an undo): a student's picture is checked at the scene's own.
        let start = match state.view_options.spun {
            Some((start, last)) if last == spin => start,
            _ => spin,
        };
        doc.view.spin_degrees = (spin + 0.5).rem_euclid(360.0);
        state.view_options.spun = Some((start, doc.view.spin_degrees));
        if on_object {
            *doc = doc.with_vertex_as_shaded(doc.scene.vertex);
        }
        ui.ctx().request_repaint();
    }
    open_obj_requested
}

/// The renderer choice, and who drew the last picture (and why not the GPU).
fn renderer_ui(ui: &mut Ui, state: &mut Shaded<'_>, drawn_by: &DrawnBy) {
    ui.horizontal_wrapped(|ui| {
        let l = ui.label(t!("renderer"));
        egui::ComboBox::from_id_salt("renderer")
            .selected_text(state.view_options.renderer.label())
            .show_ui(ui, |ui| {
                for c in gpu::RendererChoice::ALL {
                    ui.selectable_value(&mut state.view_options.renderer, c, c.label());
                }
            })
            .response
            .labelled_by(l.id)
            .on_hover_text(t!("renderer-hover"));
    });
    match drawn_by {
        DrawnBy::Gpu { adapter } => {
            ui.small(t!("drawn-gpu", adapter = adapter.clone()));
        }
        DrawnBy::Cpu { why } => {
            ui.small(t!("drawn-cpu", why = why.clone()));
        }
        DrawnBy::Nothing => {}
    }
}
