//! The quiz's picture question, "What is wrong with this picture?": a sphere drawn right
//! and drawn with one mistake ([`phonglab_core::misconception`]); the student picks the
//! cause among the seven; Check says whether it is right and shows the key, the probe's
//! numbers at the pixel where the pictures differ most.

use egui::{ColorImage, RichText, TextureHandle, TextureOptions, Ui};
use phonglab_core::misconception::{self, Misconception};

use crate::app::widgets::palette;
use crate::t;

/// The pictures' side in pixels.
const PX: usize = 160;

/// One picture question and the student's answer.
#[derive(Clone)]
pub struct WrongQuestion {
    /// The mistake drawn.
    pub kind: Misconception,
    /// The cause picked (an index into [`Misconception::ALL`]).
    pub picked: Option<usize>,
    /// The answer has been checked.
    pub checked: bool,
    /// Check was just pressed: the verdict is brought into view once.
    show_verdict: bool,
    key: Vec<String>,
    images: [ColorImage; 2],
    textures: Option<[TextureHandle; 2]>,
}

impl std::fmt::Debug for WrongQuestion {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("WrongQuestion").field("kind", &self.kind).field("picked", &self.picked).finish_non_exhaustive()
    }
}

impl PartialEq for WrongQuestion {
    fn eq(&self, o: &Self) -> bool {
        (self.kind, self.picked, self.checked) == (o.kind, o.picked, o.checked)
    }
}

impl WrongQuestion {
    /// The question of mistake `kind`, its pictures drawn.
    pub fn new(kind: Misconception) -> Result<Self, String> {
        let case = misconception::case(kind);
        let drawn = case.draw(PX)?;
        let key = misconception::key_lines(&case, &drawn);
        let image = |rgba: &[u8]| ColorImage::from_rgba_unmultiplied([PX, PX], rgba);
        let images = [image(&drawn.correct), image(&drawn.bugged)];
        Ok(Self { kind, picked: None, checked: false, show_verdict: false, key, images, textures: None })
    }

    /// Is the answer picked the mistake drawn?
    pub fn right(&self) -> bool {
        self.picked.and_then(|i| Misconception::ALL.get(i)) == Some(&self.kind)
    }
}

/// The question: both pictures side by side, the causes to pick from, Check, and after it
/// the verdict and the key.
pub fn wrong_question_ui(ui: &mut Ui, q: &mut WrongQuestion) {
    ui.label(RichText::new(t!("wrong-title")).strong());
    let side = ((ui.available_width() - 12.0) / 2.0).clamp(80.0, 320.0);
    let textures = q.textures.get_or_insert_with(|| {
        let [a, b] = q.images.clone();
        [
            ui.ctx().load_texture("wrong: right", a, TextureOptions::LINEAR),
            ui.ctx().load_texture("wrong: mistaken", b, TextureOptions::LINEAR),
        ]
    });
    ui.horizontal_top(|ui| {
        for (tex, caption) in textures.iter().zip([t!("wrong-drawn-right"), t!("wrong-drawn-wrong")]) {
            ui.vertical(|ui| {
                let label = ui.small(&caption);
                let id = label.id;
                ui.add(egui::Image::new((tex.id(), egui::vec2(side, side)))).labelled_by(id);
            });
        }
    });
    ui.label(t!("wrong-question"));
    for (i, m) in Misconception::ALL.iter().enumerate() {
        let text = m.choice();
        if ui.radio(q.picked == Some(i), text).clicked() {
            (q.picked, q.checked) = (Some(i), false);
        }
    }
    if ui.add_enabled(q.picked.is_some(), egui::Button::new(t!("wrong-check"))).clicked() {
        q.checked = true;
        q.show_verdict = true;
    }
    if q.checked {
        let (text, colour) = if q.right() {
            (t!("wrong-right-answer"), palette::ink(ui, palette::V))
        } else {
            (t!("wrong-wrong-answer"), palette::ink(ui, palette::ERROR))
        };
        let verdict = ui.colored_label(colour, RichText::new(text).strong());
        let mut shown = verdict.rect;
        for (k, line) in q.key.iter().enumerate() {
            let r = ui.label(line).rect;
            if k == 0 {
                shown = shown.union(r);
            }
        }
        // The verdict came in below the fold: scroll just enough to show it and the key's
        // first line (the cause), once; the choices stay above as far as they fit.
        if std::mem::take(&mut q.show_verdict) {
            ui.scroll_to_rect(shown, None);
        }
    }
}
