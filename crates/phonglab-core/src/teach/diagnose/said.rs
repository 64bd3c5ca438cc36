//! A diagnosis in words, one finding a line: the same lines for `phonglab diagnose` and the
//! window's Compare, kept as numbers so that the window says them in the language shown
//! when it draws them.

use crate::locale::{Arg, tr_args};
use crate::teach::picture_match::{Boxed, Difference, Match, TOLERANCE};

use super::footprint::Footprint;
use super::within::{ROUNDING, Within};
use super::{
    Diagnosis, GROUPS_SAID, LOSSY, OFFSET_AT, Shape, Tried, Verdict, most_common_first, picture_shows,
    same_picture_said,
};

/// What a diagnosis found, kept as numbers: the verdict, the right picture's score, the
/// mistakes named (the closest first; for an unexplained picture the closest tried, if it
/// explains more of the picture than the right one) and what each verdict rests on.
#[derive(Clone, Debug, PartialEq)]
pub struct Said {
    /// The verdict.
    pub verdict: Verdict,
    /// The right picture's score.
    pub right: f64,
    /// The mistakes named.
    pub named: Vec<Tried>,
    /// The first causes when they draw the same picture.
    pub same: Vec<Tried>,
    /// What the picture's shape shows, when it is not the scene's picture.
    pub shape: Option<Shape>,
    /// The right picture's match within [`LOSSY`] levels when "right" allows a lossy saving.
    pub lossy: Option<Match>,
    /// Where a mistake that changes few pixels shows, when "wrong" rests on it.
    pub footprint: Option<Footprint>,
    /// How far a "right" picture is from the right one inside the object.
    pub within: Option<Within>,
    /// How much the difference from the right picture jumps at JPEG's blocks' edges
    /// ([`super::jpeg_grid`]).
    pub grid: f64,
    /// Where an unexplained picture is evenly off the right one beyond its losses.
    pub bias: Option<super::Bias>,
    /// How far the picture is from the cause's drawing and from the right one, when "wrong"
    /// rests on that ([`Diagnosis::nearer`]).
    pub nearer: Option<(f64, f64)>,
}

/// How a verdict is filed, for machines (`phonglab diagnose --json`'s `finding`): the
/// verdict, with "right" told apart by what it rests on.
pub fn finding(d: &Said) -> &'static str {
    match d.verdict {
        Verdict::Right if d.lossy.is_some() => "right-as-saved-lossily",
        Verdict::Right if d.within.is_some_and(|w| !w.exact()) => "right-within-picture",
        v => v.name(),
    }
}

impl Said {
    /// What `d` found.
    pub fn of(d: &Diagnosis) -> Said {
        let named = match d.verdict {
            Verdict::Right => Vec::new(),
            Verdict::Wrong => d.causes.clone(),
            Verdict::Unexplained if d.shape.is_some() => Vec::new(),
            // The closest mistake is named only when it explains more of the picture than the
            // right picture does: one that explains less is no nearer the picture than the
            // scene itself, and naming it sent students after it (a JPEG'd right picture
            // "closest to the local viewer swapped").
            Verdict::Unexplained => d
                .tried
                .first()
                .filter(|t| t.matched.is_some_and(|m| m.score > d.right.score))
                .copied()
                .into_iter()
                .collect(),
        };
        Said {
            verdict: d.verdict,
            right: d.right.score,
            named,
            same: d.same_picture.clone(),
            shape: d.shape,
            lossy: d.lossy,
            footprint: d.footprint.clone(),
            within: d.within,
            grid: d.grid,
            bias: d.bias,
            nearer: d.nearer,
        }
    }

    /// The diagnosis in words, in the language set now: the verdict with the closest cause
    /// and its score, what it rests on, the other causes.
    pub fn lines(&self) -> Vec<String> {
        let mut out = self.findings();
        if self.places() {
            out.push(tr_args("diagnose-where", &[]));
        }
        out
    }

    /// Whether a line names pixels by their coordinates (a footprint's groups, a region, an
    /// offset's square, marks): then [`Self::lines`] says once where (0, 0) is.
    pub fn places(&self) -> bool {
        let shown = matches!(self.shape, Some(Shape::Region(_) | Shape::Marks(_) | Shape::Offset(_)));
        shown || self.bias.is_some() || (self.verdict == Verdict::Wrong && self.footprint.is_some())
    }

    /// The findings, one a line: the verdict first.
    fn findings(&self) -> Vec<String> {
        let right = percent(self.right);
        match self.verdict {
            Verdict::Right => vec![self.right_words()],
            Verdict::Wrong => self.wrong_lines(&right),
            Verdict::Unexplained => match (self.shape, self.named.first()) {
                (Some(s), _) => vec![unexplained(shape_words(&s, self.right))],
                (None, Some(t)) => {
                    let (cause, id, score) = named(t);
                    let args = [("right", right), ("cause", cause), ("id", id), ("score", score)];
                    vec![tr_args("diagnose-verdict-unexplained", &args)]
                }
                (None, None) => vec![tr_args("diagnose-verdict-unexplained-none", &[("right", right)])],
            }
            .into_iter()
            .chain(self.evenly_off())
            .chain(self.looks_jpeg())
            .collect(),
        }
    }

    /// For a picture left unexplained only because it is evenly off the right picture
    /// beyond its losses ([`super::systematic`]): where, by how much, and that the losses
    /// may hide which value is off.
    fn evenly_off(&self) -> Option<String> {
        let b = self.bias?;
        let at = |name: &'static str, v: usize| (name, Arg::Text(v.to_string()));
        let number = |v: f64| Arg::Text(crate::locale::decimal(&format!("{v:.1}")));
        Some(tr_args(
            "diagnose-evenly-off",
            &[
                at("width", super::bias::TILE),
                at("x0", b.at.0),
                at("y0", b.at.1),
                ("channel", Arg::Count(b.channel as i64)),
                ("levels", number(b.levels)),
                ("errors", number(b.errors)),
            ],
        ))
    }

    /// For a picture left unexplained that looks saved as JPEG ([`super::JPEG_GRID_AT`]):
    /// that it does, and that the losses may hide the cause.
    fn looks_jpeg(&self) -> Option<String> {
        let ratio = Arg::Text(crate::locale::decimal(&format!("{:.1}", self.grid)));
        (self.grid >= super::JPEG_GRID_AT).then(|| tr_args("diagnose-looks-jpeg", &[("ratio", ratio)]))
    }

    /// "Right": as saved lossily, within what a picture can tell (how far it is inside the
    /// object), or the right picture to the rounding.
    fn right_words(&self) -> String {
        let text = |v: String| Arg::Text(v);
        if let Some(m) = self.lossy {
            return tr_args(
                "diagnose-verdict-right-lossy",
                &[
                    ("score", percent(m.score)),
                    ("levels", text(LOSSY.to_string())),
                    ("strict", percent(self.right)),
                    ("tolerance", text(TOLERANCE.to_string())),
                ],
            );
        }
        match self.within.filter(|w| !w.exact()) {
            Some(w) => tr_args(
                "diagnose-verdict-right-within",
                &[
                    ("score", percent(self.right)),
                    ("most", text(w.most.to_string())),
                    ("pixels", text(w.pixels.to_string())),
                    ("rounding", text(ROUNDING.to_string())),
                    ("tolerance", text(TOLERANCE.to_string())),
                ],
            ),
            None => tr_args(
                "diagnose-verdict-right",
                &[("score", percent(self.right)), ("rounding", text(ROUNDING.to_string()))],
            ),
        }
    }

    /// "Wrong": what a picture that several causes draw shows, the cause (or the causes
    /// the picture cannot rank, "X or Y"), the footprint it rests on, the others that draw
    /// it in one line, then the rest.
    fn wrong_lines(&self, right: &Arg) -> Vec<String> {
        let tie = most_common_first(&self.same);
        let mut out: Vec<String> = picture_shows(&tie).into_iter().collect();
        let tied = self.tied();
        let Some(first) = tied.first() else { return out };
        let (cause, id, score) = named(first);
        let mut args = vec![("cause", cause), ("id", id), ("score", score), ("right", right.clone())];
        let said = match tied.get(1) {
            None => &tied[..1],
            Some(other) => {
                let (other_cause, other_id, _) = named(other);
                // Run into the sentence after "or": "… or the material's specular …".
                let other_cause = match other_cause {
                    Arg::Text(t) => Arg::Text(run_in(&t)),
                    other => other,
                };
                let more = (tied.len() - 2) as i64;
                args.extend([("other", other_cause), ("other-id", other_id), ("more", Arg::Count(more))]);
                &tied[..2]
            }
        };
        let id = if said.len() == 1 { "diagnose-verdict-wrong" } else { "diagnose-verdict-wrong-or" };
        let tie = said.len() == 1 && shown_alike(first, self.right);
        match (nearer_said(first).filter(|_| tie), self.nearer.filter(|_| tie)) {
            (Some(nearer), _) => out.push(tr_args("diagnose-verdict-wrong-nearer", &[&args[..], &nearer[..]].concat())),
            (None, Some((cause, right))) => {
                let levels = |v: f64| Arg::Text(crate::locale::decimal(&format!("{v:.1}")));
                let far = [("fitted", levels(cause)), ("scene", levels(right))];
                out.push(tr_args("diagnose-verdict-wrong-nearer-inside", &[&args[..], &far[..]].concat()));
            }
            (None, None) => out.push(tr_args(id, &args)),
        }
        out.extend(self.footprint.as_ref().map(super::footprint_said));
        out.extend(same_picture_said(&self.same));
        for c in self.named.iter().filter(|c| !said.contains(c) && !self.same.contains(c)) {
            let (cause, id, score) = named(c);
            out.push(tr_args("diagnose-also", &[("cause", cause), ("id", id), ("score", score)]));
        }
        out
    }

    /// The causes "wrong" names as its cause, the most common first: those the picture
    /// cannot rank (they draw the same picture, or explain the same share of it as the
    /// report shows it, to 0.1 %, with no footprint to rank them); else the first alone.
    fn tied(&self) -> Vec<Tried> {
        if !self.same.is_empty() {
            return most_common_first(&self.same);
        }
        let Some(first) = self.named.first() else { return Vec::new() };
        if self.footprint.is_some() {
            return vec![*first];
        }
        let shown = |t: &Tried| (t.matched.map_or(0.0, |m| m.score) * 1000.0).round();
        let tied: Vec<Tried> = self.named.iter().filter(|t| shown(t) == shown(first)).copied().collect();
        most_common_first(&tied)
    }

    /// The places the findings name by their pixels, as boxes to draw on the difference
    /// image ([`crate::teach::picture_match::draw_boxes`]): the region, the marks or the
    /// offset's square; the square evenly off the right picture; the footprint's groups said
    /// one by one.
    pub fn boxes(&self) -> Vec<Boxed> {
        let mut out = Vec::new();
        match self.shape {
            Some(Shape::Region(r)) => out.push((r.from, r.to)),
            Some(Shape::Marks(m)) => out.push((m.from, m.to)),
            Some(Shape::Offset(o)) => out.push((o.from, o.to)),
            _ => {}
        }
        if let Some(b) = self.bias {
            let last = super::bias::TILE - 1;
            out.push((b.at, (b.at.0 + last, b.at.1 + last)));
        }
        if self.verdict == Verdict::Wrong
            && let Some(f) = &self.footprint
        {
            out.extend(f.groups.iter().take(GROUPS_SAID).map(|g| (g.from, g.to)));
        }
        out
    }
}

/// The difference image `d` in words, as drawn with `boxes` boxes on it: its gain, what
/// black and full strength mean, the level its largest difference is drawn at, and the
/// boxes. `phonglab diagnose --diff` and the window say it under the image.
pub fn difference_said(d: &Difference, boxes: usize) -> String {
    let text = |v: String| Arg::Text(v);
    tr_args(
        "diagnose-difference-said",
        &[
            ("gain", text(d.gain.to_string())),
            ("full", Arg::Count(i64::from(d.full_from()))),
            ("largest", Arg::Count(i64::from(d.largest))),
            ("drawn", text(d.largest_drawn().to_string())),
            ("boxes", Arg::Count(boxes as i64)),
        ],
    )
}

/// A finding that leaves the picture unexplained, after the verdict's word: the one place
/// that word is put before a finding ("Unexplained: a region of 64 pixels...").
fn unexplained(finding: String) -> String {
    tr_args("diagnose-unexplained-said", &[("finding", Arg::Text(finding))])
}

/// What the picture's shape `s` shows, in words, given the right picture's score: each
/// ends with what to check.
fn shape_words(s: &Shape, right: f64) -> String {
    let text = |v: String| Arg::Text(v);
    let at = |name: &'static str, v: usize| (name, Arg::Text(v.to_string()));
    let levels = |v: f64| Arg::Text(crate::locale::decimal(&format!("{:.1}", v.abs())));
    match *s {
        Shape::NothingDrawn => tr_args("diagnose-nothing-drawn", &[]),
        Shape::OtherOutline(share) => tr_args("diagnose-outline-differs", &[("share", percent(share))]),
        Shape::Region(r) => tr_args(
            "diagnose-region-differs",
            &[at("pixels", r.pixels), at("x", r.centre.0), at("y", r.centre.1), ("score", percent(right))],
        ),
        Shape::Marks(m) => tr_args(
            "diagnose-marks-differ",
            &[
                at("pixels", m.pixels),
                at("x0", m.from.0),
                at("y0", m.from.1),
                at("x1", m.to.0),
                at("y1", m.to.1),
                ("score", percent(right)),
            ],
        ),
        Shape::Levels(l) => tr_args(
            if l.shift < 0.0 { "diagnose-levels-darker" } else { "diagnose-levels-lighter" },
            &[("levels", levels(l.shift)), ("score", percent(l.matched.score))],
        ),
        Shape::Offset(o) => tr_args(
            if o.levels < 0.0 { "diagnose-offset-darker" } else { "diagnose-offset-lighter" },
            &[
                at("pixels", o.pixels),
                at("x0", o.from.0),
                at("y0", o.from.1),
                at("x1", o.to.0),
                at("y1", o.to.1),
                ("levels", levels(o.levels)),
                ("least", text(crate::locale::decimal(&format!("{:.1}", OFFSET_AT + o.shift.abs())))),
                ("score", percent(right)),
            ],
        ),
    }
}

/// A share of pixels as a percentage in the user's decimal mark.
fn percent(share: f64) -> Arg {
    Arg::Text(crate::locale::percent(share, 1))
}

/// `words`, a sentence of their own, run into another after "or": a first capital letter
/// followed by a small one or a space is made small ("A cor especular" → "a cor
/// especular"); a name in capitals (GL_LIGHT0, RGB) is kept.
fn run_in(words: &str) -> String {
    let mut chars = words.chars();
    match (chars.next(), chars.next()) {
        // A word ("The", "Cor") or a one-letter article ("A cor", "O brilho").
        (Some(first), Some(second)) if first.is_uppercase() && (second.is_lowercase() || second == ' ') => {
            first.to_lowercase().chain(words[first.len_utf8()..].chars()).collect()
        }
        _ => words.to_string(),
    }
}

/// A cause's words (which name its light), its id, and its score.
/// For a "wrong" whose cause is colours fitted from the picture ([`super::colours::Nearer`])
/// where its picture and the right one explain the same share of the student's, as the
/// report shows it (to 0.1 %): what the verdict rests on instead, where the two pictures
/// differ (the pixels, and how far the student's is from each there). "The picture with
/// that mistake explains 100.0 %, the right picture 100.0 %" gave the teacher no reason.
fn nearer_said(t: &Tried) -> Option<[(&'static str, Arg); 3]> {
    let n = t.at.colours?.shown.filter(|_| t.id() == "colours-differ")?;
    let levels = |v: f64| Arg::Text(crate::locale::decimal(&format!("{v:.1}")));
    Some([("pixels", Arg::Text(n.pixels.to_string())), ("fitted", levels(n.to_fitted)), ("scene", levels(n.to_scene))])
}

/// Do `t`'s picture and the right one explain the same share of the student's, as the
/// report shows it (to 0.1 %)? Then the shares are no reason, and the line says what is.
fn shown_alike(t: &Tried, right: f64) -> bool {
    let shown = |share: f64| (share * 1000.0).round();
    t.matched.is_some_and(|m| shown(m.score) == shown(right))
}

fn named(t: &Tried) -> (Arg, Arg, Arg) {
    (Arg::Text(t.words()), Arg::Text(t.id().to_owned()), percent(t.matched.map_or(0.0, |m| m.score)))
}

impl Diagnosis {
    /// In words, one finding a line, in the language set now ([`Said::lines`]).
    pub fn lines(&self) -> Vec<String> {
        Said::of(self).lines()
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn words_run_into_a_sentence_lose_their_first_capital_but_not_a_name() {
        assert_eq!(super::run_in("A cor especular do material"), "a cor especular do material");
        assert_eq!(super::run_in("O brilho (GL_SHININESS)"), "o brilho (GL_SHININESS)");
        assert_eq!(super::run_in("The material's specular"), "the material's specular");
        assert_eq!(super::run_in("GL_LIGHT0's position"), "GL_LIGHT0's position");
        assert_eq!(super::run_in("RGB swapped"), "RGB swapped");
    }

    use super::*;
    use crate::locale::{Lang, Locale, with_locale};
    use crate::teach::diagnose::{At, Levels, MISTAKES, Marks, Offset, Region};

    fn matched(score: f64) -> Match {
        Match { score, pixels: 1000, worst: (0, 0), worst_levels: 0, miss: 0.0 }
    }

    fn unexplained_with(shape: Shape) -> Said {
        Said {
            verdict: Verdict::Unexplained,
            right: 0.995,
            named: Vec::new(),
            same: Vec::new(),
            shape: Some(shape),
            lossy: None,
            footprint: None,
            within: None,
            grid: 1.0,
            bias: None,
            nearer: None,
        }
    }

    fn cause(id: &str, score: f64) -> Tried {
        let mistake = MISTAKES.iter().position(|m| m.id == id).expect(id);
        Tried { mistake, at: At::default(), matched: Some(matched(score)) }
    }

    const SHAPES: [Shape; 7] = [
        Shape::NothingDrawn,
        Shape::OtherOutline(0.2),
        Shape::Region(Region { pixels: 64, centre: (24, 24), from: (21, 21), to: (28, 28) }),
        Shape::Marks(Marks { pixels: 200, from: (160, 270), to: (359, 270) }),
        Shape::Levels(Levels {
            shift: -4.0,
            gamma: None,
            matched: Match { score: 0.99, pixels: 1000, worst: (0, 0), worst_levels: 0, miss: 0.0 },
            distance: 1.0,
        }),
        Shape::Offset(Offset { levels: -12.0, pixels: 256, from: (240, 240), to: (255, 255), shift: 0.0 }),
        Shape::Offset(Offset { levels: 12.0, pixels: 256, from: (240, 240), to: (255, 255), shift: 0.0 }),
    ];

    #[test]
    fn every_shape_s_finding_starts_with_the_verdict_s_word_and_ends_with_what_to_check() {
        let words = [(Lang::En, "Unexplained: ", "check"), (Lang::PtPt, "Não explicada: ", "verifique")];
        let words = [words[0], words[1], (Lang::PtBr, "Não explicada: ", "confira")];
        for (lang, word, check) in words {
            for shape in SHAPES {
                let line = with_locale(Locale::of(lang), || unexplained_with(shape).lines()[0].clone());
                assert!(line.starts_with(word), "{lang:?} {}: {line}", shape.id());
                assert_eq!(line.matches(word.trim_end()).count(), 1, "{lang:?}: the word once: {line}");
                let last = line.rsplit(". ").next().unwrap().to_lowercase();
                let to_do = last.contains(check) || last.contains("verifique") || last.contains("--png");
                assert!(to_do, "{lang:?} {}: no what to do last: {line}", shape.id());
            }
        }
    }

    #[test]
    fn an_unexplained_picture_that_looks_saved_as_jpeg_is_told_the_losses_may_hide_the_cause() {
        // The spotlight's honest JPEG of quality 75 was unexplained with no hint of it.
        let jpeg = Said { named: Vec::new(), shape: None, grid: 1.56, ..unexplained_with(Shape::NothingDrawn) };
        let lines = with_locale(Locale::of(Lang::En), || jpeg.lines());
        assert_eq!(lines.len(), 2, "{lines:?}");
        assert!(lines[1].starts_with("The picture looks saved as JPEG"), "{lines:?}");
        assert!(lines[1].contains("(1.6 times") && lines[1].contains("may hide the cause"), "{lines:?}");
        let lines = with_locale(Locale::of(Lang::PtPt), || jpeg.lines());
        assert!(lines[1].contains("guardada como JPEG") && lines[1].contains("(1,6 vezes"), "{lines:?}");
        // Nor for a picture with no grid, nor for one judged right or wrong.
        let plain = Said { grid: 1.05, ..jpeg.clone() };
        assert_eq!(with_locale(Locale::of(Lang::En), || plain.lines()).len(), 1);
        let right = Said { verdict: Verdict::Right, ..jpeg.clone() };
        assert!(!with_locale(Locale::of(Lang::En), || right.lines()).iter().any(|l| l.contains("JPEG:")));
    }

    #[test]
    fn an_unexplained_picture_evenly_off_beyond_its_losses_is_told_where_and_by_how_much() {
        // The three-lights' red light 5 levels low with noise of ±3 was "right as saved
        // lossily", "its differences are noise": now unexplained, and told why.
        let bias = crate::teach::diagnose::Bias { at: (224, 96), channel: 0, levels: -2.76, errors: 21.0 };
        let off = Said { named: Vec::new(), shape: None, bias: Some(bias), ..unexplained_with(Shape::NothingDrawn) };
        let lines = with_locale(Locale::of(Lang::En), || off.lines());
        assert_eq!(lines.len(), 3, "{lines:?}");
        assert!(lines[1].contains("32 x 32 pixels from (224, 96) its red is -2.8 levels"), "{lines:?}");
        assert!(lines[2].starts_with("Pixels are counted from (0, 0)"), "{lines:?}");
        // The square it names is boxed on the difference image, as the teacher could not find it.
        assert_eq!(off.boxes(), vec![((224, 96), (255, 127))]);
        assert!(lines[1].contains("21.0 standard errors") && lines[1].contains("may hide which"), "{lines:?}");
        let lines = with_locale(Locale::of(Lang::PtBr), || off.lines());
        assert!(lines[1].contains("o vermelho dela difere") && lines[1].contains("-2,8 níveis"), "{lines:?}");
        let lines = with_locale(Locale::of(Lang::PtPt), || {
            Said { bias: Some(crate::teach::diagnose::Bias { channel: 2, ..bias }), ..off.clone() }.lines()
        });
        assert!(lines[1].contains("o seu azul difere"), "{lines:?}");
    }

    #[test]
    fn causes_that_explain_the_picture_equally_are_said_as_one_or_the_other() {
        let tie = vec![cause("attenuation-left-out", 0.9951), cause("spot-left-out", 0.9949)];
        let wrong = |named: Vec<Tried>| Said {
            verdict: Verdict::Wrong,
            right: 0.9,
            named,
            same: Vec::new(),
            shape: None,
            lossy: None,
            footprint: None,
            within: None,
            grid: 1.0,
            bias: None,
            nearer: None,
        };
        let lines = with_locale(Locale::of(Lang::En), || wrong(tie.clone()).lines());
        let first = &lines[0];
        assert!(first.starts_with("Wrong. The cause: "), "{lines:?}");
        assert!(first.contains("(attenuation-left-out) or ") && first.contains("(spot-left-out)"), "{lines:?}");
        assert!(!lines.iter().any(|l| l.starts_with("It also explains")), "said once: {lines:?}");
        let pt = with_locale(Locale::of(Lang::PtBr), || wrong(tie.clone()).lines());
        assert!(pt[0].contains("(attenuation-left-out) ou ") && pt[0].contains("(spot-left-out)"), "{pt:?}");
        // Three alike: two named, the third counted and listed after.
        let three = vec![tie[0], tie[1], cause("specular-left-out", 0.995)];
        let lines = with_locale(Locale::of(Lang::En), || wrong(three).lines());
        assert!(lines[0].contains(", or one more listed below"), "{lines:?}");
        assert!(lines[1].starts_with("It also explains the picture: ") && lines[1].contains("(specular-left-out)"));
        // One clearly ahead (0.1 % shown apart) is the cause alone.
        let ahead = vec![cause("attenuation-left-out", 0.999), cause("spot-left-out", 0.995)];
        let lines = with_locale(Locale::of(Lang::En), || wrong(ahead).lines());
        assert!(!lines[0].contains(" or "), "{lines:?}");
        assert!(lines[1].starts_with("It also explains the picture: "), "{lines:?}");
    }

    #[test]
    fn the_places_named_are_the_boxes_and_the_difference_is_said_as_drawn() {
        assert_eq!(unexplained_with(SHAPES[2]).boxes(), vec![((21, 21), (28, 28))]);
        assert_eq!(unexplained_with(SHAPES[3]).boxes(), vec![((160, 270), (359, 270))]);
        assert!(unexplained_with(SHAPES[4]).boxes().is_empty(), "the whole picture: no box");
        // Two levels off at most: × 64, drawn at 128 (grey), white only from 4 levels.
        let d = crate::teach::picture_match::difference_image(&[100, 100, 100, 255], &[102, 100, 100, 255]);
        let said = with_locale(Locale::of(Lang::En), || difference_said(&d, 1));
        assert!(said.contains("× 64") && said.contains("2 levels, is drawn at 128/255"), "{said}");
        assert!(said.contains("from a difference of 4 levels on") && said.contains("A dashed magenta box"), "{said}");
        assert!(!said.contains("near white"), "{said}");
        let none = with_locale(Locale::of(Lang::PtPt), || difference_said(&d, 0));
        assert!(none.ends_with("128/255.") && !none.contains("caixa"), "{none}");
        // One level: "1 level", not "1 levels" (the teacher's caption, in all three).
        let one = crate::teach::picture_match::difference_image(&[100, 100, 100, 255], &[101, 100, 100, 255]);
        let said = |lang| with_locale(Locale::of(lang), || difference_said(&one, 0));
        assert!(said(Lang::En).contains("here, 1 level, is drawn"), "{}", said(Lang::En));
        assert!(said(Lang::PtPt).contains("aqui, 1 nível, está"), "{}", said(Lang::PtPt));
        assert!(said(Lang::PtBr).contains("aqui, 1 nível, é"), "{}", said(Lang::PtBr));
    }

    #[test]
    fn right_to_the_rounding_says_a_value_a_little_off_cannot_show() {
        // The teacher's light diffuse 0.78 for 0.8 moved pixels by 1 level at most and was a
        // bare "Right": it now says what a picture cannot tell.
        let within = crate::teach::diagnose::within::Within { most: 1, pixels: 0, inside: 5000 };
        let right = Said { verdict: Verdict::Right, shape: None, within: Some(within), ..unexplained_with(SHAPES[0]) };
        let en = with_locale(Locale::of(Lang::En), || right.lines());
        assert!(en[0].starts_with("Right: the right picture explains 99.5\u{a0}%"), "{en:?}");
        assert!(en[0].contains("to the rounding (1 level)") && en[0].contains("cannot show in a picture"), "{en:?}");
        let pt = with_locale(Locale::of(Lang::PtPt), || right.lines());
        assert!(pt[0].contains("até ao arredondamento (1 nível)") && pt[0].contains("não se vê numa imagem"), "{pt:?}");
    }

    #[test]
    fn a_colour_shown_though_both_pictures_explain_it_alike_is_wrong_for_its_distances() {
        // "the picture with that mistake explains 100.0 %, the right picture 100.0 %" gave no
        // reason: where the two pictures differ, how far the student's is from each.
        let nearer = crate::teach::diagnose::colours::Nearer { pixels: 4210, to_fitted: 0.62, to_scene: 1.94 };
        let colours = crate::teach::diagnose::colours::Colours {
            lights: 1,
            fitted: [[0.48; 3]; crate::teach::diagnose::colours::TERMS],
            scene: [[0.5; 3]; crate::teach::diagnose::colours::TERMS],
            shown: Some(nearer),
        };
        let mut fitted = cause("colours-differ", 0.99996);
        fitted.at.colours = Some(colours);
        let wrong = Said {
            verdict: Verdict::Wrong,
            right: 0.99993,
            named: vec![fitted],
            shape: None,
            ..unexplained_with(SHAPES[0])
        };
        let en = with_locale(Locale::of(Lang::En), || wrong.lines());
        assert!(en[0].starts_with("Wrong. The cause: "), "{en:?}");
        assert!(en[0].contains("both explain 100.0\u{a0}%"), "{en:?}");
        assert!(en[0].contains("where the two differ (4210 pixels) yours is 0.6 levels from the first"), "{en:?}");
        assert!(en[0].contains("and 1.9 from the right one"), "{en:?}");
        let br = with_locale(Locale::of(Lang::PtBr), || wrong.lines());
        assert!(br[0].contains("(4210 pixels) a sua fica, em média (quadrática), a 0,6 níveis"), "{br:?}");
        // Another fitted cause (a shininess) chosen on the same ground: how far the picture is
        // from its drawing and from the right one's, over the object's inside.
        let shininess =
            Said { named: vec![cause("shininess-differs", 0.99996)], nearer: Some((0.42, 2.31)), ..wrong.clone() };
        let en = with_locale(Locale::of(Lang::En), || shininess.lines());
        assert!(en[0].contains("both explain 100.0\u{a0}%") && en[0].contains("0.4 levels from the first"), "{en:?}");
        assert!(en[0].contains("and 2.3 from the right one"), "{en:?}");
        // Shown apart (99.9 % against 99.5 %): the scores are the reason, said as before.
        let apart = Said { right: 0.995, ..wrong.clone() };
        let en = with_locale(Locale::of(Lang::En), || apart.lines());
        assert!(en[0].contains(", the right picture 99.5\u{a0}%") && !en[0].contains("where the two differ"), "{en:?}");
    }
}
