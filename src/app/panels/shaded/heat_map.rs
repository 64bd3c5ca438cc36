//! The error heat map beside the shaded view: the view against the cost study's f64
//! per-pixel reference, computed in the background whenever the view changes.

use egui::{ColorImage, TextureHandle, TextureOptions, Ui};
use phonglab_core::ShadedSetup;
use phonglab_core::cost::{self, ErrorStats, Progress, Setup, Timing};

use crate::app::editing::worker::Worker;
use crate::paint::cost_chart::{BACKGROUND, HEAT_FULL_SCALE};
use crate::{locale, t};

/// Image size of the app's study and heat map, in pixels (the CLI's default is larger).
/// Smaller in the browser, where the study runs on the page's one thread, before the next
/// frame ([`crate::platform::threads`]).
pub const APP_SIZE: usize = if crate::platform::threads::BACKGROUND { 256 } else { 128 };

/// A heat map of one view against the reference.
pub struct HeatMap {
    /// What it was computed for (the scene, the view, the options).
    pub key: ShadedSetup,
    /// Its error figures.
    pub error: ErrorStats,
    /// Milliseconds per frame of the view at this size.
    pub ms: f64,
    image: ColorImage,
    texture: Option<TextureHandle>,
}

/// The heat map's switch, the last map and the one being computed.
#[derive(Default)]
pub struct HeatMapState {
    /// Show the heat map beside the picture.
    pub on: bool,
    /// The last heat map.
    pub heat: Option<HeatMap>,
    running: Option<(ShadedSetup, Worker<HeatMap>)>,
    /// Why the last one failed.
    pub error: Option<String>,
}

impl HeatMapState {
    /// Is one being computed?
    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// Collects a finished map; returns whether one is still being computed.
    pub fn poll(&mut self) -> bool {
        if let Some((_, w)) = &self.running
            && let Some(r) = w.poll()
        {
            match r {
                Ok(Some(h)) => self.heat = Some(h),
                Ok(None) => {}
                Err(e) => self.error = Some(t!("heat-map-failed", error = e.clone())),
            }
            self.running = None;
        }
        self.running.is_some()
    }

    /// Makes sure a heat map of the shaded view `shaded` is on its way (or there).
    pub fn want(&mut self, shaded: &ShadedSetup) {
        let key = shaded;
        if self.heat.as_ref().is_some_and(|h| h.key == *key) || self.running.as_ref().is_some_and(|(k, _)| k == key) {
            return;
        }
        if self.running.is_some() {
            // One at a time: the newest view is asked for when this one is done.
            return;
        }
        let (shaded, k) = (shaded.clone(), key.clone());
        // The heat map follows every edit: one thread, so the UI's own renders stay quick.
        let worker = Worker::spawn(1, move |progress| {
            let setup = Setup::new(&shaded, APP_SIZE, BACKGROUND);
            if !progress(&Progress { done: 0, total: 2, what: "reference".into() }) {
                return Ok(None);
            }
            let reference = cost::reference(&setup).map_err(|e| e.to_string())?;
            if !progress(&Progress { done: 1, total: 2, what: "the view".into() }) {
                return Ok(None);
            }
            let view = &shaded.view;
            let m = cost::measure_view(&setup, view, view.shading, shaded.options, &reference, Timing::ONCE)
                .map_err(|e| e.to_string())?;
            let rgba = cost::heat_map_rgba(&m.map, &reference, HEAT_FULL_SCALE);
            let image = ColorImage::from_rgba_unmultiplied([reference.size, reference.size], &rgba);
            Ok(Some(HeatMap { key: k, error: m.error, ms: m.ms, image, texture: None }))
        });
        self.running = Some((key.clone(), worker));
    }
}

/// The heat map beside the shaded view, `side` points square, with its caption.
pub fn heat_map_ui(ui: &mut Ui, heat_map: &mut HeatMapState, side: f32) {
    ui.vertical(|ui| {
        let Some(h) = &mut heat_map.heat else {
            ui.small(t!("heat-map-computing"));
            return;
        };
        let tex = h
            .texture
            .get_or_insert_with(|| ui.ctx().load_texture("error heat map", h.image.clone(), TextureOptions::NEAREST));
        let caption = ui.small(t!(
            "heat-map-caption",
            mean = locale::decimal(&format!("{:.2}", h.error.mean)),
            max = format!("{:.0}", h.error.max),
            share = locale::decimal(&format!("{:.1}", 100.0 * h.error.share_over_one)),
            white = HEAT_FULL_SCALE.to_string()
        ));
        ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(caption.id);
    });
}
