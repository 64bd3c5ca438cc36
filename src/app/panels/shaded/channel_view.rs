//! One term of the lighting equation in place of the picture (`phonglab render --channel`
//! in the window): its false-colour image, kept until the scene, the view or the channel
//! changes, and its legend, a colour bar with the numbers at its ends and middle.

use egui::{Color32, ColorImage, TextureHandle, TextureOptions, Ui};
use phonglab_core::channels::{self, Channel, ChannelImage, ColourMap};
use phonglab_core::mesh::Mesh;
use phonglab_core::plan::{Key, Program};
use phonglab_core::render::Renderer;
use phonglab_core::{Document, PowFn};

use crate::{locale, t};

/// The channel image's side in pixels: enough to read a term's shape, small enough to
/// compute on every edit (each pixel is the f64 engine's worked breakdown).
pub const CHANNEL_PX: usize = if crate::platform::threads::BACKGROUND { 192 } else { 128 };

/// The last channel image, what it shows, and its false-colour texture.
#[derive(Default)]
pub struct ChannelView {
    key: Option<(Document, PowFn, Channel)>,
    image: Option<ChannelImage>,
    texture: Option<TextureHandle>,
    /// The range the texture's false colour spans.
    pub range: (f64, f64),
    coloured: Option<(f64, f64)>,
    renderer: Renderer,
}

impl ChannelView {
    /// Computes `channel` for `doc`'s shaded view (of `mesh`, the view's) unless it is
    /// already there; returns its own range ([`ChannelImage::range`]).
    pub fn prepare(&mut self, doc: &Document, mesh: &Mesh, pow: PowFn, channel: Channel) -> Result<(f64, f64), String> {
        let key = (doc.clone(), pow, channel);
        if self.key.as_ref() != Some(&key) || self.image.is_none() {
            let setup = doc.shaded_setup(pow);
            let job = setup.job(mesh);
            self.renderer.keep_visibility(true);
            self.renderer.render(&job, CHANNEL_PX, CHANNEL_PX).map_err(|e| e.to_string())?;
            let image = channels::channel_image(&self.renderer, &job, channel, None).map_err(|e| e.to_string())?;
            self.image = Some(image);
            self.key = Some(key);
            self.coloured = None;
        }
        Ok(self.image.as_ref().map_or((0.0, 1.0), ChannelImage::range))
    }

    /// The prepared channel's name's message id, as its scene's rules form it (`N·H`, or
    /// Phong's `R·V`); `channel`'s own before one is prepared.
    pub fn name_id(&self, channel: Channel) -> &'static str {
        self.image.as_ref().filter(|i| i.channel == channel).map_or(channel.message_id(), |i| i.message_id)
    }

    /// The prepared channel in false colour over `range` (two pictures compared share
    /// one), coloured again only when the channel or the range changed.
    pub fn texture(&mut self, ctx: &egui::Context, range: (f64, f64)) -> Option<&TextureHandle> {
        let image = self.image.as_ref()?;
        if self.coloured != Some(range) || self.texture.is_none() {
            let bg = self
                .key
                .as_ref()
                .map_or([0; 3], |(d, ..)| d.view.background.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8));
            let rgba = image.false_colour_over(ColourMap::Viridis, bg, range);
            let picture = ColorImage::from_rgba_unmultiplied([image.width, image.height], &rgba);
            match &mut self.texture {
                Some(t) => t.set(picture, TextureOptions::LINEAR),
                None => self.texture = Some(ctx.load_texture("term channel", picture, TextureOptions::LINEAR)),
            }
            (self.coloured, self.range) = (Some(range), range);
        }
        self.texture.as_ref()
    }
}

/// The program the scene `doc` compiles to in the shaded view (with power function
/// `pow`): what names its terms, as the command line's channels do.
pub fn program_of(doc: &Document, pow: PowFn) -> Program {
    Key::of(&doc.shaded_scene(), doc.view.eval_options(pow)).program()
}

/// `channel`'s name's message id in `doc`'s shaded view (with power function `pow`): the
/// specular cosine as the scene's rules form it (`N·H`, or Phong's `R·V`).
pub fn name_id(channel: Channel, doc: &Document, pow: PowFn) -> &'static str {
    channel.message_id_for(&program_of(doc, pow))
}

/// A channel's name for the scenes whose programs are `programs`: the specular cosine as
/// their rules form it (`N·H`, or Phong's `R·V`), both where two scenes differ.
pub fn channel_name(channel: Channel, programs: &[&Program]) -> String {
    let mut ids: Vec<&str> = programs.iter().map(|p| channel.message_id_for(p)).collect();
    ids.dedup();
    if ids.is_empty() {
        ids.push(channel.message_id());
    }
    ids.iter().map(|id| locale::tr(id)).collect::<Vec<_>>().join(" / ")
}

/// What the picture shows: the shaded view, or one term of the equation in false colour,
/// each term named as the rules of the scenes shown (`programs`) form it.
pub fn channel_ui(ui: &mut Ui, channel: &mut Option<Channel>, programs: &[&Program]) {
    let name = |c: Option<Channel>| c.map_or_else(|| t!("channel-picture"), |c| channel_name(c, programs));
    ui.horizontal(|ui| {
        let l = ui.label(t!("channel-show"));
        // As wide as what is left of the row, within reason: a narrow column keeps it whole.
        let width = (ui.available_width() - 8.0).clamp(80.0, 150.0);
        egui::ComboBox::from_id_salt("channel-show")
            .width(width)
            .truncate()
            .selected_text(name(*channel))
            .show_ui(ui, |ui| {
                ui.selectable_value(channel, None, name(None));
                for c in Channel::ALL {
                    ui.selectable_value(channel, Some(c), name(Some(c)));
                }
            })
            .response
            .labelled_by(l.id)
            .on_hover_text(t!("channel-hover"));
    });
}

/// What a channel shows, in words: the luminance of a colour term, a factor, a cosine, the
/// normal's axes, a count. The legend says it under the bar. `name_id`: the channel's
/// name's message id as the scene's rules form it ([`name_id`]): Phong's `R·V` is
/// explained as itself, not as `N·H`.
pub fn meaning(channel: Channel, name_id: &str) -> String {
    match channel {
        Channel::Normal => t!("channel-legend-normal"),
        c if c.components() == 3 => t!("channel-legend-luminance", channel = locale::tr(c.message_id())),
        Channel::Attenuation => t!("channel-legend-attenuation"),
        Channel::Spot => t!("channel-legend-spot"),
        Channel::NDotL => t!("channel-legend-n-dot-l"),
        Channel::NDotH if name_id == "channel-r-dot-v" => t!("channel-legend-r-dot-v"),
        Channel::NDotH => t!("channel-legend-n-dot-h"),
        _ => t!("channel-legend-light-count"),
    }
}

/// The colour bar's height, in points.
const BAR: f32 = 10.0;

/// The bar and its numbers' height, in points.
fn bar_height(ui: &Ui) -> f32 {
    BAR + 2.0 + ui.text_style_height(&egui::TextStyle::Body) + 2.0
}

/// What the legend says under the bar, laid out `width` points wide in body type.
fn meaning_height(ui: &Ui, channel: Channel, name_id: &str, width: f32) -> f32 {
    let font = egui::TextStyle::Body.resolve(ui.style());
    ui.fonts_mut(|f| f.layout(meaning(channel, name_id), font, Color32::WHITE, width).size().y)
}

/// The legend's height under a picture `width` points wide: the bar, its numbers and what
/// it shows (wrapped), all in body type. `name_id`: as for [`meaning`].
pub fn legend_height(ui: &Ui, channel: Channel, name_id: &str, width: f32) -> f32 {
    bar_height(ui) + meaning_height(ui, channel, name_id, width) + ui.spacing().item_spacing.y
}

/// The legend under a channel's picture, `width` points wide: the colour bar (viridis; the
/// normal's axes as red, green and blue) with its range's ends and middle, and under them
/// what the channel shows, in body type (`name_id`: as for [`meaning`]).
pub fn legend_ui(ui: &mut Ui, channel: Channel, name_id: &str, range: (f64, f64), width: f32) -> egui::Response {
    let (rect, resp) = ui.allocate_exact_size(egui::vec2(width, bar_height(ui)), egui::Sense::hover());
    let bar = egui::Rect::from_min_size(rect.min, egui::vec2(width, BAR));
    let painter = ui.painter_at(rect);
    let steps = 64;
    for i in 0..steps {
        let t = (i as f64 + 0.5) / steps as f64;
        let c = if channel == Channel::Normal {
            let v = (t * 255.0) as u8;
            Color32::from_rgb(v, v, v)
        } else {
            let [r, g, b] = ColourMap::Viridis.at(t);
            Color32::from_rgb(r, g, b)
        };
        let x0 = bar.left() + width * i as f32 / steps as f32;
        let x1 = bar.left() + width * (i + 1) as f32 / steps as f32;
        painter.rect_filled(egui::Rect::from_x_y_ranges(x0..=x1 + 0.5, bar.y_range()), 0.0, c);
    }
    let (lo, hi) = range;
    let text = ui.visuals().text_color();
    let font = egui::TextStyle::Body.resolve(ui.style());
    let y = bar.bottom() + 2.0;
    for (t, align) in [(0.0, egui::Align2::LEFT_TOP), (0.5, egui::Align2::CENTER_TOP), (1.0, egui::Align2::RIGHT_TOP)] {
        let v = lo + (hi - lo) * t;
        let x = bar.left() + width * t as f32;
        painter.text(egui::pos2(x, y), align, locale::num(v, 3), font.clone(), text);
    }
    let what = meaning(channel, name_id);
    let described =
        t!("channel-legend-range", what = what.clone(), low = locale::num(lo, 3), high = locale::num(hi, 3));
    resp.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &described));
    // What it shows, in the legend itself: wrapped to the picture's width, in body type.
    ui.scope(|ui| {
        ui.set_max_width(width);
        ui.add(egui::Label::new(egui::RichText::new(&what).text_style(egui::TextStyle::Body)).wrap());
    });
    resp
}
