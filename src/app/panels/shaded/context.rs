//! What the shaded view is given: its own options, and the parts of the app's state it
//! reads and writes, borrowed for a frame ([`Shaded`]); what it asks back ([`Asked`]).

use phonglab_core::library::DemoDeparture;
use phonglab_core::{Document, PowFn};

use super::gpu::{GpuInfo, RendererChoice};
use super::heat_map::HeatMapState;
use crate::app::editing::editor::Editor;

/// The shaded view's own choices, kept between frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShadedOptions {
    /// Which of the Phong demo's departures the corrected picture corrects, in the order
    /// of [`phonglab_core::library::DemoDeparture::ALL`].
    pub demo_fixes: [bool; 3],
    /// Which renderer draws the view.
    pub renderer: RendererChoice,
    /// The OBJ file path typed under View options.
    pub obj_path: String,
    /// View options are open (under the toolbar).
    pub options_open: bool,
    /// The pixel probe.
    pub probe: super::probe_window::ProbeState,
    /// The term shown instead of the picture, if one is.
    pub channel: Option<phonglab_core::channels::Channel>,
    /// The window's spin ("Auto-rotate"): the spin the view had before the window began to
    /// turn it, and the spin after its last turn ([`crate::app::panels::student_picture::filed`]).
    pub spun: Option<(f64, f64)>,
}

/// What the shaded view reads and writes, borrowed from the shell: the document (edited
/// through [`Editor`]), the view's own options, its heat map, and what it
/// only reads (the power function, whether the class is being presented to, the GPU).
pub struct Shaded<'a> {
    /// The document, its history and the message.
    pub edit: Editor<'a>,
    /// The view's own choices.
    pub view_options: &'a mut ShadedOptions,
    /// The error heat map beside the picture.
    pub heat_map: &'a mut HeatMapState,
    /// The power function the pictures are drawn with.
    pub pow: PowFn,
    /// Presenting: the toolbar shows the object and the shading only.
    pub presenting: bool,
    /// The GPU eframe runs on, when there is one.
    pub gpu: Option<&'a GpuInfo>,
}

/// What the view asks the shell for besides its edits: a mesh file to open.
#[derive(Debug, Default)]
pub struct Asked {
    /// Where the picture (and the one beside it) was drawn.
    pub rects: Vec<egui::Rect>,
    /// The mesh file typed under View options, to open.
    pub open_obj: Option<std::path::PathBuf>,
    /// The arrows drawn at the worked calculation's vertex.
    pub arrows: Vec<super::arrow_on_object::ArrowOnObject>,
    /// Where each spotlight's cone meets the object (its rim's bounds) on the picture.
    pub cones: Vec<egui::Rect>,
}

/// `doc` with each departure switched on in `fixes` (and present in `doc`) corrected, or
/// `None` when there is nothing to correct.
pub fn corrected_document(doc: &Document, fixes: &[bool; 3]) -> Option<Document> {
    let mut c = doc.clone();
    let mut any = false;
    for (d, on) in DemoDeparture::ALL.into_iter().zip(fixes) {
        if *on && d.present_in(doc) {
            d.correct(&mut c);
            any = true;
        }
    }
    any.then_some(c)
}
