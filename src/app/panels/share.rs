//! Share: the scene as a link and as a QR code for the class (File → Share link…). The link
//! carries the scene in its fragment ([`phonglab_core::export::share`]), with the choices
//! the sharer ticks: the language shown, presenting, the term shown. It opens the page the
//! app runs in (the browser), or the published site (the desktop, editable). Copy puts it on
//! the clipboard; the QR code is drawn large, for the back of a room.

use egui::Ui;
use phonglab_core::Document;
use phonglab_core::channels::Channel;
use phonglab_core::export::share::{self, Shared};

use crate::app::editing::message::Message;
use crate::t;

/// The window's own state: open, the page, the choices, and the QR code drawn last.
#[derive(Default)]
pub struct ShareState {
    /// The window is open.
    pub open: bool,
    /// The page the link opens (empty: the page the app runs in, or the published site).
    pub base: String,
    /// The link asks for the language shown now.
    pub with_language: bool,
    /// The link opens presenting.
    pub presenting: bool,
    /// The link shows the term shown now in place of the picture.
    pub with_channel: bool,
    /// The QR code drawn for the link last made (made again when the link changes).
    qr: Option<(String, egui::TextureHandle)>,
    /// The link last made and what it was made of: made again only when one of them
    /// changes, not every frame the window is open (a scene's TOML, deflated and encoded).
    made: Option<(LinkInputs, Result<String, String>)>,
}

/// What a link is made of, to know when to make it again.
struct LinkInputs {
    doc: Document,
    base: String,
    choices: [bool; 3],
    lang: crate::locale::Lang,
    channel: Option<Channel>,
}

/// What the window shares besides the document: the window's choices as they are now.
pub struct Shown {
    /// The language shown.
    pub lang: crate::locale::Lang,
    /// The term shown in place of the picture, if one is.
    pub channel: Option<Channel>,
}

impl ShareState {
    /// Opens the window, its choices following the window's now.
    pub fn open_with(&mut self, presenting: bool) {
        self.open = true;
        self.with_language = true;
        self.presenting = presenting;
        self.with_channel = true;
    }

    /// The page the link opens: the one typed, else the page the app runs in, else the
    /// published site.
    pub fn base(&self) -> String {
        let typed = self.base.trim();
        if !typed.is_empty() {
            return typed.to_string();
        }
        crate::platform::page::own_address().unwrap_or_else(|| share::DEFAULT_BASE.to_string())
    }

    /// The link for `doc` with the choices ticked, made again only when what it is made of
    /// has changed since the last.
    fn link_kept(&mut self, doc: &Document, shown: &Shown) -> Result<String, String> {
        let choices = [self.with_language, self.presenting, self.with_channel];
        let same = |m: &LinkInputs| {
            m.doc == *doc
                && m.base == self.base
                && m.choices == choices
                && m.lang == shown.lang
                && m.channel == shown.channel
        };
        // Compared in place: the document is cloned only when the link is made again.
        if let Some((_, link)) = self.made.as_ref().filter(|(m, _)| same(m)) {
            return link.clone();
        }
        let link = self.link(doc, shown);
        let inputs =
            LinkInputs { doc: doc.clone(), base: self.base.clone(), choices, lang: shown.lang, channel: shown.channel };
        self.made = Some((inputs, link.clone()));
        link
    }

    /// The link for `doc` with the choices ticked.
    pub fn link(&self, doc: &Document, shown: &Shown) -> Result<String, String> {
        let s = Shared {
            lang: self.with_language.then(|| shown.lang.code().to_string()),
            present: self.presenting,
            channel: shown.channel.filter(|_| self.with_channel).map(|c| c.name().to_string()),
            ..Shared::of(doc.clone())
        };
        share::link(&self.base(), &s).map_err(|e| e.to_string())
    }
}

/// The Share window, while open.
pub fn share_window_ui(
    ctx: &egui::Context,
    s: &mut ShareState,
    doc: &Document,
    shown: &Shown,
    message: &mut Option<Message>,
) {
    if !s.open {
        return;
    }
    let screen = ctx.content_rect();
    // Large enough to scan from the back of a room when projected.
    let side = (screen.width().min(screen.height()) * 0.6).max(200.0);
    let mut open = true;
    egui::Window::new(t!("share-window"))
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .default_pos(egui::pos2(screen.left() + 24.0, screen.top() + 36.0))
        .show(ctx, |ui| share_ui(ui, s, doc, shown, side, message));
    s.open = open;
}

/// The choices and the link on the left, the QR code on the right.
fn share_ui(ui: &mut Ui, s: &mut ShareState, doc: &Document, shown: &Shown, side: f32, message: &mut Option<Message>) {
    ui.horizontal_top(|ui| {
        let link = ui.vertical(|ui| {
            ui.set_width(280.0);
            choices_ui(ui, s, shown);
            ui.separator();
            link_ui(ui, s, doc, shown, message)
        });
        match link.inner {
            Ok(link) => qr_ui(ui, s, &link, side),
            Err(e) => {
                ui.colored_label(crate::app::widgets::palette::ERROR, e);
            }
        }
    });
}

/// The page and what the link asks for.
fn choices_ui(ui: &mut Ui, s: &mut ShareState, shown: &Shown) {
    let label = ui.label(t!("share-page"));
    let hint = s.base();
    ui.add(egui::TextEdit::singleline(&mut s.base).hint_text(hint).desired_width(270.0))
        .labelled_by(label.id)
        .on_hover_text(t!("share-page-hover"));
    ui.checkbox(&mut s.with_language, t!("share-in-language", lang = shown.lang.name()));
    ui.checkbox(&mut s.presenting, t!("share-presenting"));
    if let Some(c) = shown.channel {
        ui.checkbox(&mut s.with_channel, t!("share-channel", term = crate::locale::tr(c.message_id())));
    }
}

/// The link itself, its length, and Copy; gives the link back.
fn link_ui(
    ui: &mut Ui,
    s: &mut ShareState,
    doc: &Document,
    shown: &Shown,
    message: &mut Option<Message>,
) -> Result<String, String> {
    let link = s.link_kept(doc, shown)?;
    let text = egui::RichText::new(&link).monospace().small();
    let shown_link = egui::ScrollArea::vertical()
        .max_height(160.0)
        .show(ui, |ui| ui.add(egui::Label::new(text).wrap().selectable(true)))
        .inner;
    crate::app::widgets::fields::landmark(ui.ctx(), "share-link", shown_link.rect);
    ui.label(egui::RichText::new(t!("share-length", length = link.chars().count() as i64)).small().weak());
    if ui.button(t!("share-copy")).on_hover_text(t!("share-copy-hover")).clicked() {
        ui.ctx().copy_text(link.clone());
        *message = Some(Message::Info(t!("share-copied", length = link.chars().count() as i64)));
    }
    Ok(link)
}

/// The QR code of `link`, `side` points square, crisp (one texel a module, not smoothed).
fn qr_ui(ui: &mut Ui, s: &mut ShareState, link: &str, side: f32) {
    if s.qr.as_ref().is_none_or(|(l, _)| l != link) {
        // Error correction L: a screen is not scratched, and the modules are larger for it.
        s.qr = crate::io::qr::qr_rgba_at(link, 1, qrcode::EcLevel::L).ok().map(|(n, rgba)| {
            let image = egui::ColorImage::from_rgba_unmultiplied([n, n], &rgba);
            (link.to_string(), ui.ctx().load_texture("share qr", image, egui::TextureOptions::NEAREST))
        });
    }
    let Some((_, texture)) = &s.qr else {
        ui.colored_label(crate::app::widgets::palette::ERROR, t!("share-qr-too-long"));
        return;
    };
    let (rect, response) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, t!("share-qr")));
    crate::app::widgets::fields::landmark(ui.ctx(), "share-qr", rect);
    let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
    ui.painter().image(texture.id(), rect, uv, egui::Color32::WHITE);
}
