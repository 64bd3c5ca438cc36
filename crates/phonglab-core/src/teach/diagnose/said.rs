//! A diagnosis in words, one finding a line: the same lines for `phonglab diagnose` and the
//! window's Compare, kept as numbers so that the window says them in the language shown
//! when it draws them.

use crate::locale::{Arg, tr_args};
use crate::teach::picture_match::{Match, TOLERANCE};

use super::footprint::Footprint;
use super::within::{ROUNDING, Within};
use super::{Diagnosis, LOSSY, Shape, Tried, Verdict, most_common_first, picture_shows, same_picture_said};

/// What a diagnosis found, kept as numbers: the verdict, the right picture's score, the
/// mistakes named (the closest first; for an unexplained picture the closest tried, if
/// any matched) and what each verdict rests on.
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
            Verdict::Unexplained => d.tried.first().filter(|t| t.matched.is_some()).copied().into_iter().collect(),
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
        shown || (self.verdict == Verdict::Wrong && self.footprint.is_some())
    }

    /// The findings, one a line: the verdict first.
    fn findings(&self) -> Vec<String> {
        let right = percent(self.right);
        match self.verdict {
            Verdict::Right => vec![self.right_words()],
            Verdict::Wrong => self.wrong_lines(&right),
            Verdict::Unexplained => match (self.shape, self.named.first()) {
                (Some(s), _) => vec![s.words(self.right)],
                (None, Some(t)) => {
                    let (cause, id, score) = named(t);
                    let args = [("right", right), ("cause", cause), ("id", id), ("score", score)];
                    vec![tr_args("diagnose-verdict-unexplained", &args)]
                }
                (None, None) => vec![tr_args("diagnose-verdict-unexplained-none", &[("right", right)])],
            },
        }
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
            None => tr_args("diagnose-verdict-right", &[("score", percent(self.right))]),
        }
    }

    /// "Wrong": what a picture that several causes draw shows, the most common named, the
    /// footprint it rests on, the others that draw it in one line, then the rest.
    fn wrong_lines(&self, right: &Arg) -> Vec<String> {
        let tie = most_common_first(&self.same);
        let mut out: Vec<String> = picture_shows(&tie).into_iter().collect();
        let Some(first) = tie.first().or(self.named.first()) else { return out };
        let (cause, id, score) = named(first);
        out.push(tr_args(
            "diagnose-verdict-wrong",
            &[("cause", cause), ("id", id), ("score", score), ("right", right.clone())],
        ));
        out.extend(self.footprint.as_ref().map(super::footprint_said));
        out.extend(same_picture_said(&self.same));
        for c in self.named.iter().filter(|c| *c != first && !tie.contains(c)) {
            let (cause, id, score) = named(c);
            out.push(tr_args("diagnose-also", &[("cause", cause), ("id", id), ("score", score)]));
        }
        out
    }
}

/// A share of pixels as a percentage in the user's decimal mark.
fn percent(share: f64) -> Arg {
    Arg::Text(crate::locale::percent(share, 1))
}

/// A cause's words (which name its light), its id, and its score.
fn named(t: &Tried) -> (Arg, Arg, Arg) {
    (Arg::Text(t.words()), Arg::Text(t.id().to_owned()), percent(t.matched.map_or(0.0, |m| m.score)))
}

impl Diagnosis {
    /// In words, one finding a line, in the language set now ([`Said::lines`]).
    pub fn lines(&self) -> Vec<String> {
        Said::of(self).lines()
    }
}
