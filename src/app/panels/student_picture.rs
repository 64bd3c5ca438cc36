//! A student's picture checked, in Compare: A the right picture of the scene shown, B the
//! student's, and their difference ([`difference_image`], the places the diagnosis names
//! boxed on it), above them the diagnosis of [`phonglab_core::teach::diagnose`] in words
//! (the verdict, the closest cause, its score) and what the difference image shows.

use egui::{Color32, RichText, Ui};
use phonglab_core::teach::diagnose::Diagnosis;
use phonglab_core::teach::diagnose::said::{Said, difference_said};
use phonglab_core::teach::picture_match::{Difference, difference_image};

use phonglab_core::Document;
use phonglab_core::raster::shaded::ShadedSetup;

use crate::t;

/// A student's picture diagnosed against the scene shown when it was opened (or checked
/// again); while the scene shown is another, its verdict is hidden ([`StudentPicture::stale`]).
pub struct StudentPicture {
    /// The file's name, as shown (printable).
    pub file: String,
    /// Its width and height in pixels.
    pub size: usize,
    /// The verdict: `right`, `wrong` or `unexplained`.
    pub verdict: &'static str,
    /// The diagnosis as found, said in words when shown ([`StudentPicture::lines`]), so in
    /// the language shown then.
    said: Said,
    /// The right picture, the student's and the difference (RGBA8).
    pictures: [Vec<u8>; 3],
    /// Their textures, once made.
    textures: Option<[egui::TextureHandle; 3]>,
    /// The gain the difference is shown at.
    pub gain: u32,
    /// The difference image's numbers (its pixels are in `pictures`) and the boxes drawn on
    /// it, said under the diagnosis ([`difference_said`]).
    difference: (Difference, usize),
    /// The places the diagnosis names, in the picture's pixels: drawn over the difference
    /// image on the screen ([`boxes_over`]), at any scale, rather than into its pixels (a
    /// dashed line one pixel wide vanished when the picture was shown at a third of its size).
    boxes: Vec<phonglab_core::teach::picture_match::Boxed>,
    /// The right picture's setup it was diagnosed against ([`picture_setup`]).
    checked: ShadedSetup,
    /// Whether the window had spun the view: the picture was checked at the scene's own
    /// spin, not the one shown ([`filed`]), and says so.
    unspun: bool,
}

/// The scene `doc` as its file and its program draw it: the turn the window's spin gave
/// the object since `spun` began ([`crate::app::panels::shaded::ShadedOptions::spun`])
/// taken back. A student's program draws the scene's own view, not the one shown.
pub fn filed(doc: &Document, spun: Option<(f64, f64)>) -> std::borrow::Cow<'_, Document> {
    match spun {
        Some((start, last)) if last == doc.view.spin_degrees && start != last => {
            let mut d = doc.clone();
            d.view.spin_degrees = start;
            std::borrow::Cow::Owned(d)
        }
        _ => std::borrow::Cow::Borrowed(doc),
    }
}

/// What the right picture of `doc` is drawn from, as the diagnosis draws it (the exact
/// power), the worked calculation's vertex left out (it draws nothing).
pub fn picture_setup(doc: &Document) -> ShadedSetup {
    let mut s = doc.shaded_setup(phonglab_core::PowFn::Exact);
    s.scene.vertex = Document::default().scene.vertex;
    s
}

impl StudentPicture {
    /// The picture `image` (RGBA8, `size` square) from `file`, as `d` diagnosed it.
    /// `doc` is the scene it was diagnosed against ([`filed`]); `unspun`, whether that is
    /// not the spin the window shows.
    pub fn new(
        file: String,
        size: usize,
        image: Vec<u8>,
        d: &Diagnosis,
        doc: &Document,
        unspun: bool,
    ) -> StudentPicture {
        let said = Said::of(d);
        let mut difference = difference_image(&d.picture, &image);
        let boxes = said.boxes();
        let diff = std::mem::take(&mut difference.rgba);
        StudentPicture {
            file,
            size,
            verdict: d.verdict.name(),
            said,
            pictures: [d.picture.clone(), image, diff],
            textures: None,
            checked: picture_setup(doc),
            unspun,
            gain: difference.gain,
            difference: (difference, boxes.len()),
            boxes,
        }
    }

    /// Was it diagnosed against another scene than `doc` (another object, other rules, a
    /// changed light...)? Then its verdict is not this scene's.
    pub fn stale(&self, doc: &Document) -> bool {
        picture_setup(doc) != self.checked
    }

    /// The places the diagnosis names, in the picture's pixels (drawn over the difference).
    pub fn boxes(&self) -> &[phonglab_core::teach::picture_match::Boxed] {
        &self.boxes
    }

    /// The student's picture (RGBA8), to diagnose again.
    pub fn image(&self) -> &[u8] {
        &self.pictures[1]
    }

    /// Why no verdict is shown while the scene shown is not the one it was checked against.
    pub fn stale_note(&self) -> String {
        t!("student-picture-stale", file = self.file.clone())
    }

    /// The diagnosis in words, one line a finding, in the language shown now: as
    /// `phonglab diagnose` says it ([`Said::lines`]).
    pub fn lines(&self) -> Vec<String> {
        let mut lines: Vec<String> = self.said.lines().iter().map(|l| one_line_pairs(l)).collect();
        if self.unspun {
            lines.push(t!("student-picture-unspun"));
        }
        let (d, boxes) = &self.difference;
        lines.push(t!("student-picture-difference-said", said = difference_said(d, *boxes)));
        lines
    }
}

/// `line` with each coordinate pair "(71, 207)" kept on one line: a no-break space after
/// its comma, so that a wrap never parts x from y.
pub fn one_line_pairs(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut in_pair = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '(' => in_pair = chars.peek().is_some_and(|n| n.is_ascii_digit() || *n == '-'),
            ')' => in_pair = false,
            ',' if in_pair && chars.peek() == Some(&' ') => {
                chars.next();
                out.push_str(",\u{a0}");
                continue;
            }
            c if in_pair && !(c.is_ascii_digit() || c == '-' || c == '.') => in_pair = false,
            _ => {}
        }
        out.push(c);
    }
    out
}

/// The student's picture in Compare: the diagnosis, then A, B and the difference side by
/// side; Clear returns Compare to the scenes. While the scene shown (`doc`) is not the one
/// it was checked against, a note says so in place of all that, with a button that sets
/// `recheck`. Returns where the pictures went.
pub fn student_picture_ui(
    ui: &mut Ui,
    picture: &mut Option<StudentPicture>,
    doc: &Document,
    recheck: &mut bool,
) -> Vec<egui::Rect> {
    let Some(p) = picture.as_mut() else { return Vec::new() };
    let mut clear = false;
    ui.horizontal_wrapped(|ui| {
        ui.heading(t!("student-picture-heading", file = p.file.clone()));
        clear = ui.button(t!("student-clear")).on_hover_text(t!("student-clear-hover")).clicked();
    });
    if p.stale(doc) {
        ui.add(egui::Label::new(RichText::new(p.stale_note()).strong()).wrap());
        *recheck = ui.button(t!("student-picture-recheck")).clicked();
        if clear {
            *picture = None;
        }
        return Vec::new();
    }
    let wrong = p.verdict != "right";
    let ink = wrong.then(|| super::student_column::wrong_ink(ui));
    let lines = p.lines();
    let texts = |size: f32| -> Vec<RichText> {
        lines
            .iter()
            .map(|line| {
                let text = RichText::new(line).strong().size(size);
                if let Some(ink) = ink { text.color(ink) } else { text }
            })
            .collect()
    };
    let avail = ui.available_size();
    let row = ui.text_style_height(&egui::TextStyle::Body) * 2.0;
    let side_w = ((avail.x - 36.0) / 3.0).max(48.0);
    let fit = diagnosis_fit(ui, &texts, avail, side_w, row);
    diagnosis_ui(ui, texts(fit.size), fit.height, fit.whole);
    let size = p.size;
    let textures = p.textures.get_or_insert_with(|| {
        let names = ["student-right", "student-picture", "student-difference"];
        std::array::from_fn(|k| {
            let image = egui::ColorImage::from_rgba_unmultiplied([size, size], &p.pictures[k]);
            ui.ctx().load_texture(names[k], image, egui::TextureOptions::NEAREST)
        })
    });
    let side = side_w.min(ui.available_height() - row).max(48.0);
    let titles = [
        t!("student-picture-right"),
        t!("student-picture-theirs"),
        t!("student-picture-difference", gain = p.gain.to_string()),
    ];
    let rects = ui.columns(3, |cols| {
        (0..3)
            .map(|k| {
                let label = cols[k].label(RichText::new(&titles[k]).strong());
                let image = egui::Image::new((textures[k].id(), egui::vec2(side, side)));
                let given = cols[k].add(image).labelled_by(label.id).rect;
                // The column gives the image its whole width; the picture is drawn side x side
                // from its top left (seen at 1024x600 in the light theme: a frame around the
                // column's width left a white strip beside each picture).
                let rect = egui::Rect::from_min_size(given.min, egui::vec2(side, side).min(given.size()));
                // Framed, as a picture on the dark theme needs: the difference is mostly black.
                cols[k].painter().rect_stroke(rect, 0.0, picture_frame(cols[k].visuals()), egui::StrokeKind::Outside);
                if k == 2 {
                    boxes_over(cols[k].painter(), rect, size, &p.boxes);
                }
                rect
            })
            .collect::<Vec<_>>()
    });
    if clear {
        *picture = None;
    }
    rects
}

/// Draws `boxes` (in the pixels of a `size`-square picture) over the picture shown in
/// `rect`: dashed magenta, two points wide, [`BOX_GAP`](phonglab_core::teach::picture_match::BOX_GAP)
/// pixels outside each place as `phonglab diagnose --diff` draws them, so that they show
/// whole at any scale.
pub fn boxes_over(
    painter: &egui::Painter,
    rect: egui::Rect,
    size: usize,
    boxes: &[phonglab_core::teach::picture_match::Boxed],
) {
    use phonglab_core::teach::picture_match::{BOX_GAP, BOX_INK};
    let scale = rect.width() / size.max(1) as f32;
    let at = |x: usize, y: usize| rect.min + egui::vec2(x as f32, y as f32) * scale;
    let stroke = egui::Stroke::new(2.0, Color32::from_rgb(BOX_INK[0], BOX_INK[1], BOX_INK[2]));
    for &((x0, y0), (x1, y1)) in boxes {
        let (from, to) =
            (at(x0.saturating_sub(BOX_GAP), y0.saturating_sub(BOX_GAP)), at(x1 + 1 + BOX_GAP, y1 + 1 + BOX_GAP));
        let corners = [from, egui::pos2(to.x, from.y), to, egui::pos2(from.x, to.y), from];
        let corners = corners.map(|c| c.clamp(rect.min, rect.max));
        painter.extend(egui::Shape::dashed_line(&corners, stroke, 6.0, 4.0));
    }
}

/// The frame drawn around each picture: a line in the theme's text colour, which shows on
/// the panel and on a black picture in either theme.
pub fn picture_frame(visuals: &egui::Visuals) -> egui::Stroke {
    egui::Stroke::new(1.0, visuals.widgets.noninteractive.fg_stroke.color)
}

/// How the diagnosis is shown above the pictures: its text's size, its height, and
/// whether that is all of it.
struct Fit {
    size: f32,
    height: f32,
    whole: bool,
}

/// How the diagnosis (`texts` at a size) fits above the pictures. Whole when the pictures
/// keep at least their floor below it (their width's share, down to a third of the height):
/// at the style's size if it fits, else in smaller type, never below egui's own size (the
/// window's when not presenting). At 1024x600, presenting, the longest diagnosis is 414
/// pixels high at 1.45 times, and three pictures 150 high with their titles need 185 of the
/// 514 left: beside the text they would need 555, or leave the text 690 wide (585 high).
/// Only when it does not fit at the least size does it scroll, leaving the pictures their
/// floor (its bar always shown and a cue under it).
fn diagnosis_fit(ui: &Ui, texts: &dyn Fn(f32) -> Vec<RichText>, avail: egui::Vec2, side_w: f32, row: f32) -> Fit {
    let gap = ui.spacing().item_spacing.y;
    let height = |size: f32| -> f32 {
        texts(size)
            .into_iter()
            .map(|t| {
                let text = egui::WidgetText::from(t);
                text.into_galley(ui, Some(egui::TextWrapMode::Wrap), avail.x, egui::TextStyle::Body).size().y + gap
            })
            .sum()
    };
    let body = egui::TextStyle::Body.resolve(ui.style()).size;
    let least = egui::TextStyle::Body.resolve(&egui::Style::default()).size.min(body);
    let floor = side_w.min((avail.y - row) / 3.0).max(48.0);
    let room = (avail.y - row - floor - 2.0 * gap).max(ui.text_style_height(&egui::TextStyle::Body) * 3.0);
    let mut size = body;
    loop {
        let needed = height(size);
        if needed <= room {
            return Fit { size, height: needed, whole: true };
        }
        if size <= least {
            return Fit { size, height: room, whole: false };
        }
        size = (size * 0.95).max(least);
    }
}

/// The diagnosis, `text_max` high; when it is not `whole`, in a scroll area whose bar is
/// always shown (a projector shows no hover), with a cue under it that more is below.
fn diagnosis_ui(ui: &mut Ui, texts: Vec<RichText>, text_max: f32, whole: bool) {
    let lines = |ui: &mut Ui| {
        for text in texts {
            ui.add(egui::Label::new(text).wrap());
        }
    };
    if whole {
        return lines(ui);
    }
    let cue = ui.text_style_height(&egui::TextStyle::Small) + ui.spacing().item_spacing.y;
    ui.scope(|ui| {
        ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
        egui::ScrollArea::vertical()
            .id_salt("student-diagnosis")
            .max_height(text_max - cue)
            .auto_shrink([false, true])
            .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
            .show(ui, lines);
    });
    ui.small(t!("student-picture-more"));
}

/// A student's picture refused, in Compare: its name, why (in the error's ink), and Clear.
pub fn refused_picture_ui(ui: &mut Ui, refused: &mut Option<(String, String)>) {
    let Some((file, why)) = refused.as_ref() else { return };
    let mut clear = false;
    ui.horizontal_wrapped(|ui| {
        ui.heading(t!("student-picture-heading", file = file.clone()));
        clear = ui.button(t!("student-clear")).on_hover_text(t!("student-clear-hover")).clicked();
    });
    let text = RichText::new(why).strong().color(super::student_column::wrong_ink(ui));
    ui.add(egui::Label::new(text).wrap());
    if clear {
        *refused = None;
    }
}
