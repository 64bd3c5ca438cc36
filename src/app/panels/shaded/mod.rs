//! The shaded view: the sphere, teapot or cylinder under the document's lights and
//! material, Flat, Gouraud or Phong, rendered by the core's CPU renderer (or on the GPU).
//!
//! Drag to orbit, scroll to zoom; auto-rotate spins the object 0.5 degrees a frame, as the
//! Phong demo does. Clicking the surface makes the nearest mesh vertex the vertex of the
//! worked calculation, with this view's camera and spin, so both panels show one vertex.
//!
//! Its parts: what it is given ([`context`]), the toolbar and options (`toolbar`), the
//! pictures (`pictures`, their `captions`), what the pointer does on them and what is drawn over them
//! (`overlay`; the lights, `light_marks`; both through `screen`), the renderer's cache ([`cache`]) and the GPU's picture ([`gpu`]).

mod arrow_on_object;
pub mod cache;
mod captions;
pub mod channel_view;
pub mod context;
pub mod gpu;
pub mod heat_map;
mod light_marks;
mod overlay;
mod pictures;
pub mod probe_window;
mod screen;
mod toolbar;

use egui::Ui;

pub use arrow_on_object::ArrowOnObject;
pub use cache::{DrawnBy, ShadedCache, ViewCache, Viewed, mesh_for};
pub use captions::{CaptionRoom, caption_room, drawn_caption};
pub use context::{Asked, Shaded, ShadedOptions, corrected_document};
pub use overlay::vector_arrows;
pub use toolbar::departures_ui;

use crate::app::editing::evaluated::Evaluated;

/// The view's controls and the image (beside it, the corrected picture or the heat map),
/// with N, L, V and H (or R) drawn at the worked calculation's vertex and the lights as
/// markers that can be dragged.
///
/// Returns where the picture (and the one beside it) was drawn, and a mesh file to open.
pub fn shaded_ui(ui: &mut Ui, state: &mut Shaded<'_>, cache: &mut ShadedCache, eval: &Evaluated) -> Asked {
    let open_obj = toolbar::toolbar_ui(ui, state, cache);
    // The view's mesh, looked up once for the frame (after the toolbar, which may change
    // the object), and handed to the pictures, the overlay and the probe.
    let mesh = mesh_for(&mut cache.main.mesh, &state.edit.doc.view).clone();
    let shown = pictures::pictures_ui(ui, state, cache, mesh);
    let rects = std::iter::once(shown.response.rect).chain(shown.second).collect();
    let (arrows, cones) = overlay::interaction_ui(ui, state, cache, &shown, eval);
    overlay::probe_ui(ui, state, cache, &shown);
    let asked = probe_window::probe_window_ui(ui.ctx(), &mut state.view_options.probe);
    if let Some(i) = asked.vertex {
        open_vertex(state, &shown.mesh, i);
    }
    Asked { rects, open_obj, arrows, cones }
}

/// Makes mesh vertex `i` of the view the worked calculation's vertex (as a click on the
/// surface does), saying so.
fn open_vertex(state: &mut Shaded<'_>, mesh: &phonglab_core::mesh::Mesh, i: usize) {
    let (Some(p), Some(n)) = (mesh.positions.get(i), mesh.normals.get(i)) else { return };
    let c = state.edit.doc.with_vertex_as_shaded(phonglab_core::Vertex::from_f32(*p, *n));
    if state.edit.apply(c) {
        let object = state.edit.doc.view.object.label().to_lowercase();
        *state.edit.message = Some(crate::app::editing::message::Message::Info(crate::t!(
            "picked-vertex",
            index = i.to_string(),
            object = object
        )));
    }
}
