//! A student's picture checked, in Compare: A the right picture of the scene shown, B the
//! student's, and their difference ([`difference_image`]), above them the diagnosis of
//! [`phonglab_core::teach::diagnose`] in words (the verdict, the closest cause, its score).

use egui::{RichText, Ui};
use phonglab_core::teach::diagnose::{Diagnosis, Tried, Verdict, most_common_first, picture_shows, same_picture_said};
use phonglab_core::teach::picture_match::difference_image;

use crate::t;

/// A student's picture diagnosed against the scene shown.
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
}

impl StudentPicture {
    /// The picture `image` (RGBA8, `size` square) from `file`, as `d` diagnosed it.
    pub fn new(file: String, size: usize, image: Vec<u8>, d: &Diagnosis) -> StudentPicture {
        let diff = difference_image(&d.picture, &image);
        StudentPicture {
            file,
            size,
            verdict: d.verdict.name(),
            said: Said::of(d),
            pictures: [d.picture.clone(), image, diff],
            textures: None,
        }
    }

    /// The diagnosis in words, one line a finding, in the language shown now.
    pub fn lines(&self) -> Vec<String> {
        verdict_lines(&self.said)
    }
}

/// What a diagnosis found, kept as numbers: the verdict, the right picture's score, and
/// the mistakes named (each with where it was made and its score): the closest first; for
/// an unexplained picture the closest tried, if any matched.
#[derive(Clone, Debug)]
struct Said {
    verdict: Verdict,
    right: f64,
    named: Vec<Tried>,
    /// The first causes when they draw the same picture.
    same: Vec<Tried>,
    /// What the picture's shape shows, in words, when it is not the scene's picture.
    shape: Option<String>,
    /// The verdict "right" in words when it allows for a lossy saving.
    lossy: Option<String>,
}

impl Said {
    fn of(d: &Diagnosis) -> Said {
        let named = match d.verdict {
            Verdict::Right => Vec::new(),
            Verdict::Wrong => d.causes.clone(),
            Verdict::Unexplained => d.tried.first().filter(|t| t.matched.is_some()).copied().into_iter().collect(),
        };
        let shape = d.shape.map(|s| s.words(d.right.score));
        let named = if shape.is_some() { Vec::new() } else { named };
        Said {
            verdict: d.verdict,
            right: d.right.score,
            named,
            same: d.same_picture.clone(),
            shape,
            lossy: d.lossy_words(),
        }
    }
}

/// A share of pixels as a percentage in the user's decimal mark.
fn percent(score: f64) -> String {
    crate::locale::decimal(&format!("{:.1} %", 100.0 * score))
}

/// The diagnosis in words: the verdict with the closest cause and its score, the others.
fn verdict_lines(d: &Said) -> Vec<String> {
    let right = percent(d.right);
    let named = |t: &Tried| (t.words(), t.label(), percent(t.matched.map_or(0.0, |m| m.score)));
    match d.verdict {
        Verdict::Right => vec![d.lossy.clone().unwrap_or_else(|| t!("diagnose-verdict-right", score = right))],
        Verdict::Wrong => {
            // As `phonglab diagnose` says it: what a picture that several causes draw
            // shows, the most common named, the others in one line, then the rest.
            let tie = most_common_first(&d.same);
            let mut out: Vec<String> = picture_shows(&tie).into_iter().collect();
            let Some(first) = tie.first().or(d.named.first()) else { return out };
            let (cause, id, score) = named(first);
            out.push(t!("diagnose-verdict-wrong", cause = cause, id = id, score = score, right = right.clone()));
            out.extend(same_picture_said(&d.same));
            for c in d.named.iter().filter(|c| *c != first && !tie.contains(c)) {
                let (cause, id, score) = named(c);
                out.push(t!("diagnose-also", cause = cause, id = id, score = score));
            }
            out
        }
        Verdict::Unexplained if d.shape.is_some() => d.shape.iter().cloned().collect(),
        Verdict::Unexplained => {
            let (cause, id, score) = d.named.first().map(named).unwrap_or_default();
            vec![t!("diagnose-verdict-unexplained", right = right, cause = cause, id = id, score = score)]
        }
    }
}

/// The student's picture in Compare: the diagnosis, then A, B and the difference side by
/// side; Clear returns Compare to the scenes. Returns where the pictures went.
pub fn student_picture_ui(ui: &mut Ui, picture: &mut Option<StudentPicture>) -> Vec<egui::Rect> {
    let Some(p) = picture.as_mut() else { return Vec::new() };
    let mut clear = false;
    ui.horizontal_wrapped(|ui| {
        ui.heading(t!("student-picture-heading", file = p.file.clone()));
        clear = ui.button(t!("student-clear")).on_hover_text(t!("student-clear-hover")).clicked();
    });
    let wrong = p.verdict != "right";
    // The pictures first get their width's share, down to a floor; the diagnosis the
    // height left above them, scrolling when it is longer (its first line at the top).
    let avail = ui.available_size();
    let body = ui.text_style_height(&egui::TextStyle::Body);
    let row = body * 2.0;
    let side_w = ((avail.x - 36.0) / 3.0).max(48.0);
    let floor = side_w.min((avail.y - row) * 0.6).max(48.0);
    let text_max = (avail.y - row - floor - 2.0 * ui.spacing().item_spacing.y).max(body * 3.0);
    egui::ScrollArea::vertical().id_salt("student-diagnosis").max_height(text_max).auto_shrink([false, true]).show(
        ui,
        |ui| {
            for line in p.lines() {
                let mut text = RichText::new(line).strong();
                if wrong {
                    text = text.color(super::student_column::wrong_ink(ui));
                }
                ui.add(egui::Label::new(text).wrap());
            }
        },
    );
    let size = p.size;
    let textures = p.textures.get_or_insert_with(|| {
        let names = ["student-right", "student-picture", "student-difference"];
        std::array::from_fn(|k| {
            let image = egui::ColorImage::from_rgba_unmultiplied([size, size], &p.pictures[k]);
            ui.ctx().load_texture(names[k], image, egui::TextureOptions::NEAREST)
        })
    });
    let side = side_w.min(ui.available_height() - row).max(48.0);
    let titles = [t!("student-picture-right"), t!("student-picture-theirs"), t!("compare-difference")];
    let rects = ui.columns(3, |cols| {
        (0..3)
            .map(|k| {
                let label = cols[k].label(RichText::new(&titles[k]).strong());
                let image = egui::Image::new((textures[k].id(), egui::vec2(side, side)));
                cols[k].add(image).labelled_by(label.id).rect
            })
            .collect::<Vec<_>>()
    });
    if clear {
        *picture = None;
    }
    rects
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
