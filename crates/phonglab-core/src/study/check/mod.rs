//! A student's own work, checked: the values their notebook or script printed
//! ([`printed`]), each against the key worked by the stages of the plan ([`worked`]),
//! with a verdict (right; right given an earlier value of theirs; rounding; wrong), the
//! first wrong step, and the causes from the catalogue ([`mistakes`]) that reproduce
//! everything they printed, to the printed digits. Nothing the student wrote is run.

pub mod mistakes;
pub mod printed;
pub mod said;
pub mod worked;

use crate::model::rules::Rules;
use crate::model::scene::{Scene, Side};
use mistakes::{ACOS_PAST_ONE, CATALOGUE, ColourSwap, Made, MistakeInfo};
use printed::{Printed, PrintedValue, Stale};
use worked::{Worked, work, work_made};

/// How a printed step compares with the key.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The key's value, to the printed digits.
    Right,
    /// Not the key's, but right computed from the student's own earlier wrong value(s)
    /// that it depends on (named, the most recent first; several: joined by `, `).
    RightGiven(String),
    /// The key's to about three digits, not to the printed ones: rounded on the way.
    Rounding,
    /// The key's to the printed digits, but so are a catalogue mistake's value there, or
    /// zero where the key is not: too few digits to tell (the decimal places printed).
    /// Never right: a verdict is proven on the printed digits.
    TooFewDigits(u32),
    /// None of these.
    Wrong,
}

impl Verdict {
    /// The verdict's id in JSON and CSV: `right`, `right-given`, `rounding`,
    /// `too-few-digits`, `wrong`.
    pub fn id(&self) -> &'static str {
        match self {
            Verdict::Right => "right",
            Verdict::RightGiven(_) => "right-given",
            Verdict::Rounding => "rounding",
            Verdict::TooFewDigits(_) => "too-few-digits",
            Verdict::Wrong => "wrong",
        }
    }

    /// The verdict in the user's language.
    pub fn words(&self) -> String {
        match self {
            Verdict::Right => crate::t!("check-verdict-right"),
            Verdict::RightGiven(x) => crate::t!("check-verdict-right-given", step = x.clone()),
            Verdict::Rounding => crate::t!("check-verdict-rounding"),
            Verdict::TooFewDigits(decimals) => crate::t!("check-verdict-too-few-digits", decimals = *decimals),
            Verdict::Wrong => crate::t!("check-verdict-wrong"),
        }
    }
}

/// One printed step checked.
#[derive(Clone, Debug, PartialEq)]
pub struct StepCheck {
    /// The worksheet's name (`vlv`, `vlv[1]`).
    pub name: String,
    /// What the student printed.
    pub student: Vec<f64>,
    /// The key's value.
    pub key: Vec<f64>,
    /// How they compare.
    pub verdict: Verdict,
}

/// A cause named, with its evidence: the step where the student's value is the mistaken
/// calculation's and not the key's.
#[derive(Clone, Debug)]
pub struct Cause {
    /// The catalogue's entry.
    pub info: &'static MistakeInfo,
    /// The step shown as evidence.
    pub step: String,
    /// The key worked with the mistake, at that step.
    pub value: Vec<f64>,
    /// The one light the mistake was made for, of several (`None`: all of them).
    pub light: Option<usize>,
    /// The colours mixed up, for `colours-mixed-up`.
    pub swap: Option<ColourSwap>,
}

impl Cause {
    /// What the mistake means, in the user's language, with the light it was made for.
    pub fn words(&self) -> String {
        let words = (self.info.words)();
        match self.light {
            Some(i) => crate::t!("check-cause-for-light", cause = words, light = i),
            None => words,
        }
    }

    /// What the student wrote, as code: the catalogue's formula, or the colours mixed up.
    pub fn formula(&self) -> String {
        match self.swap {
            Some(swap) => {
                let value = swap.term.value_name();
                let i = self.light.map(|i| format!("[{i}]")).unwrap_or_default();
                let right = format!("{}{i}*{}", swap.term.light_name(), swap.term.material_name());
                format!("{value}{i} = ({})*...  # != {right}", swap.product(&i))
            }
            None => self.info.formula.to_string(),
        }
    }
}

/// A piece of work checked.
#[derive(Clone, Debug)]
pub struct Check {
    /// The rule set the key was worked under.
    pub rules: Rules,
    /// Typed inputs that differ from the assignment's (the first finding when any).
    pub inputs_differ: Vec<String>,
    /// Every printed step the key has, in the order printed.
    pub steps: Vec<StepCheck>,
    /// The first wrong step's index in `steps`.
    pub first_wrong: Option<usize>,
    /// The causes that reproduce everything printed (none: not explained by the catalogue).
    pub causes: Vec<Cause>,
    /// The errors the run stopped with (`ModuleNotFoundError: No module named 'numpy'`).
    pub errors: Vec<String>,
    /// Steps of the key printed with a value that could not be read (`cosTheta = 0.9 rad`).
    pub unreadable: Vec<String>,
    /// Steps of the key the work holds no value for (a notebook's cell not run), from the
    /// notebook's self-check ([`Printed::missing`]).
    pub missing: Vec<String>,
    /// Steps the worksheet asks for ([`asked`]) that the work does not print, in the
    /// key's order: a cell not run, or its output cleared. Never right.
    pub not_printed: Vec<String>,
    /// A notebook's outputs not from one run in order: two execution counts, the earlier
    /// cell's and the later cell's, or a count no run gives ([`Printed::stale`]).
    pub stale: Option<Stale>,
    /// The values printed after a cell's error output, from an earlier run: not checked
    /// ([`Printed::after_error`]).
    pub after_error: Vec<String>,
}

/// The steps the worksheet's notebook prints under every rule set (its `print` lines,
/// the modelview aside): the normal, `vlv`, `vov`, `Iamb`, `Idif`, `Ispec` and `I`. Each
/// is asked of a student's work, for each light; the steps only some rule sets or scenes
/// print (`H` or `R`, `d`, `spot`, `Iscene`, the back side, `glColor`) and those phonglab's
/// own notebook adds (`cosTheta`, `Ilight`) are checked where printed, never asked.
pub const ASKED: [&str; 7] = ["vertexNormal", "vlv", "vov", "Iamb", "Idif", "Ispec", "I"];

/// The steps of `key` the worksheet asks the work to print ([`ASKED`]), in the
/// worksheet's order (`vlv[0]`, `vlv[1]` for a light of several, then `vov`).
pub fn asked(key: &Worked) -> Vec<String> {
    let rank = |n: &str| ASKED.iter().position(|a| *a == n.split('[').next().unwrap_or(n));
    let mut out: Vec<(usize, String)> =
        key.values.iter().filter_map(|(n, _)| rank(n).map(|r| (r, n.clone()))).collect();
    out.sort_by_key(|(r, _)| *r);
    out.into_iter().map(|(_, n)| n).collect()
}

/// A piece of work as a whole: right, wrong (a wrong step, a typed input that differs, or
/// a cause named), or incomplete (nothing wrong, but not checked whole: a step the
/// worksheet asks for not printed, a run that stopped, outputs out of order, a step that
/// could not be read, nothing compared).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Overall {
    /// Every step printed is the key's, and the work is whole.
    Right,
    /// Something is wrong.
    Wrong,
    /// Nothing is wrong, but the work is not whole.
    Incomplete,
}

impl Overall {
    /// The verdict's id in JSON and CSV: `right`, `wrong`, `incomplete`.
    pub fn id(self) -> &'static str {
        match self {
            Overall::Right => "right",
            Overall::Wrong => "wrong",
            Overall::Incomplete => "incomplete",
        }
    }
}

/// Why a piece of work with no wrong step is still not right: nothing was compared.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Unchecked {
    /// The run stopped with this error (its last line).
    Stopped(String),
    /// Nothing it printed is a step of the worksheet.
    NothingCompared,
    /// Steps printed with values that could not be read (named).
    Unreadable(String),
    /// Steps of the key the work holds no value for (named): a cell skipped or stopped.
    Missing(String),
    /// A notebook's outputs not from one run in order (two execution counts, the earlier
    /// cell's and the later's; or a count no run gives).
    Stale(Stale),
    /// Steps the worksheet asks for not printed: how many, the first, all (named).
    NotPrinted(usize, String, String),
    /// Steps printed with too few digits to tell the key from a mistake's value or from
    /// zero (named), and the fewest decimal places seen among them.
    TooFewDigits(String, u32),
}

impl Unchecked {
    /// The reason's id in JSON: `run-stopped`, `stale-outputs`, `missing-steps`,
    /// `unreadable-step`, `too-few-digits`, `nothing-compared`.
    pub fn id(&self) -> &'static str {
        match self {
            Unchecked::Stopped(_) => "run-stopped",
            Unchecked::NothingCompared => "nothing-compared",
            Unchecked::Unreadable(_) => "unreadable-step",
            Unchecked::Missing(_) | Unchecked::NotPrinted(..) => "missing-steps",
            Unchecked::Stale(..) => "stale-outputs",
            Unchecked::TooFewDigits(..) => "too-few-digits",
        }
    }

    /// The reason in the user's language.
    pub fn words(&self) -> String {
        match self {
            Unchecked::Stopped(e) => crate::t!("check-run-stopped", error = e.clone()),
            Unchecked::NothingCompared => crate::t!("check-nothing-compared"),
            Unchecked::Unreadable(names) => crate::t!("check-unreadable-steps", names = names.clone()),
            Unchecked::Missing(names) => crate::t!("check-missing-steps", names = names.clone()),
            Unchecked::Stale(Stale::Back(earlier, later)) => {
                crate::t!("check-stale-outputs", earlier = *earlier, later = *later)
            }
            Unchecked::Stale(Stale::NotACount(count)) => crate::t!("check-stale-count", count = count.clone()),
            Unchecked::Stale(Stale::NotRun(above, below)) => {
                crate::t!("check-stale-not-run", above = *above, below = *below)
            }
            Unchecked::NotPrinted(..) => crate::t!("check-incomplete", steps = self.steps_words().unwrap_or_default()),
            Unchecked::TooFewDigits(names, decimals) => {
                crate::t!("check-too-few-digits", names = names.clone(), decimals = *decimals)
            }
        }
    }

    /// The steps not printed in words, without the verdict's word ("incomplete"): what is
    /// said of them beside another reason, which gives the verdict (one verdict a check).
    pub fn steps_words(&self) -> Option<String> {
        let Unchecked::NotPrinted(count, first, names) = self else { return None };
        Some(crate::t!("check-not-printed", count = *count, first = first.clone(), names = names.clone()))
    }
}

/// How many typed inputs must differ from the assignment's for the work to look typed for
/// another scene (a wrong `--scene`): a student's slip changes one or two (a colour, a
/// light's position); the worksheet's scenes differ from each other in most of their 13.
/// No cause is named then: the mistakes are sought on the assignment, and one found on a
/// scene the work was not typed for would be a guess.
pub const OTHER_SCENE_AT: usize = 4;

impl Check {
    /// Whether so many typed inputs differ from the assignment's ([`OTHER_SCENE_AT`]) that
    /// the work looks typed for another scene: "is this the right scene?".
    pub fn other_scene(&self) -> bool {
        self.inputs_differ.len() >= OTHER_SCENE_AT
    }

    /// Is the work right: its inputs the assignment's, some step compared, none wrong, and
    /// the run not stopped by an error?
    pub fn right(&self) -> bool {
        self.inputs_differ.is_empty()
            && self.first_wrong.is_none()
            && self.causes.is_empty()
            && self.unchecked().is_none()
    }

    /// The work as a whole: right, wrong, or incomplete ([`Overall`]).
    pub fn overall(&self) -> Overall {
        if self.right() {
            Overall::Right
        } else if !self.inputs_differ.is_empty() || self.first_wrong.is_some() || !self.causes.is_empty() {
            Overall::Wrong
        } else {
            Overall::Incomplete
        }
    }

    /// Every step of the key the work holds no value for, in the key's order: those the
    /// self-check found missing, and those the worksheet asks for not printed.
    pub fn all_missing(&self) -> Vec<String> {
        let mut out = self.missing.clone();
        out.extend(self.not_printed.iter().filter(|n| !self.missing.contains(n)).cloned());
        out
    }

    /// Why the work could not be found right though no step is wrong: the run stopped
    /// with an error, its outputs are out of order, a step is missing or unreadable, or
    /// nothing was compared. `None` where the work is whole.
    pub fn unchecked(&self) -> Option<Unchecked> {
        if let Some(e) = self.errors.last() {
            return Some(Unchecked::Stopped(e.clone()));
        }
        if let Some(stale) = &self.stale {
            return Some(Unchecked::Stale(stale.clone()));
        }
        if !self.missing.is_empty() {
            return Some(Unchecked::Missing(self.missing.join(", ")));
        }
        if !self.unreadable.is_empty() {
            return Some(Unchecked::Unreadable(self.unreadable.join(", ")));
        }
        if let Some(few) = self.too_few_digits() {
            return Some(few);
        }
        if self.steps.is_empty() {
            return Some(Unchecked::NothingCompared);
        }
        self.not_printed_reason()
    }

    /// The steps printed with too few digits to tell, as a reason: named once each, with
    /// the fewest decimal places seen among them.
    pub fn too_few_digits(&self) -> Option<Unchecked> {
        let mut names: Vec<&str> = Vec::new();
        let mut fewest = u32::MAX;
        for s in &self.steps {
            if let Verdict::TooFewDigits(decimals) = s.verdict {
                fewest = fewest.min(decimals);
                if !names.contains(&s.name.as_str()) {
                    names.push(&s.name);
                }
            }
        }
        (!names.is_empty()).then(|| Unchecked::TooFewDigits(names.join(", "), fewest))
    }

    /// The steps the worksheet asks for that the work does not print, as a reason.
    pub fn not_printed_reason(&self) -> Option<Unchecked> {
        let first = self.not_printed.first()?;
        Some(Unchecked::NotPrinted(self.not_printed.len(), first.clone(), self.not_printed.join(", ")))
    }
}

/// A little over a rounding of f64 arithmetic done in another order (NumPy's norm, dot).
const SLACK: f64 = 1e-12;

/// The part of the key's `want` that `got` prints: all of it, or a point's or a
/// direction's x, y, z where the student works in three components (`vlv[:3]`) and the key
/// in four with a w of 0 or 1. `None` where the sizes do not match.
fn aligned<'a>(got: &PrintedValue, want: &'a [f64]) -> Option<&'a [f64]> {
    match (got.numbers.len(), want.len()) {
        (g, w) if g == w => Some(want),
        (3, 4) if want[3] == 0.0 || want[3] == 1.0 => Some(&want[..3]),
        _ => None,
    }
}

/// Does `got`, as printed, equal `want` to the printed digits?
fn same(got: &PrintedValue, want: &[f64]) -> bool {
    let Some(want) = aligned(got, want) else { return false };
    got.numbers
        .iter()
        .zip(&got.half_units)
        .zip(want)
        .all(|((g, h), w)| (g.is_nan() && w.is_nan()) || (g - w).abs() <= h * (1.0 + 1e-9) + SLACK * w.abs().max(1.0))
}

/// Is `got` the point `want` in other homogeneous coordinates? A position (`lightPos`,
/// `vertexPos`) divided by its w early prints `[1 2 -1 1]` for the key's `[2 4 -2 2]`:
/// the same point, and what follows from it is the same. To the printed digits, carried
/// through the divide; a direction (w = 0) has no other form.
fn same_point(got: &PrintedValue, want: &[f64]) -> bool {
    let homogeneous = ["lightPos", "vertexPos"].iter().any(|n| got.name.split('[').next() == Some(n));
    let (Some(&gw), Some(&ww)) = (got.numbers.last(), want.last()) else { return false };
    if !homogeneous || got.numbers.len() != 4 || want.len() != 4 || gw == 0.0 || ww == 0.0 {
        return false;
    }
    got.numbers.iter().zip(&got.half_units).zip(want).all(|((g, h), w)| {
        let (g, w) = (g / gw, w / ww);
        (g - w).abs()
            <= (h / gw.abs()) * (1.0 + 1e-9) + (got.half_units[3] / gw.abs()) * g.abs() + SLACK * w.abs().max(1.0)
    })
}

/// Does `got` equal `want`, a value worked from the student's printed (so rounded) earlier
/// values? To the printed digits, or to a millionth of the value's size: an input printed
/// with 8 decimals carries its rounding into what follows.
fn given_from_printed(got: &PrintedValue, want: &[f64]) -> bool {
    let size = want.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    let Some(want) = aligned(got, want) else { return false };
    same(got, want)
        || got.numbers.iter().zip(&got.half_units).zip(want).all(|((g, h), w)| (g - w).abs() <= 1e-6 * size + h)
}

/// Is `got` the key's rounded, each number: to the digits the student's number itself
/// shows (`0.7922` for 0.79220526; at least three significant digits), or to single
/// precision (two parts in 10^5: a program computing in `float`, C++, GLSL or
/// `np.float32`)? (A key of 0 is rounded only to 0: a tiny value where there should be
/// none is a term computed that should not be.) Anything else is a mistake: the spot left
/// off the ambient changes a share printed to 8 decimals by 8 parts in 10^4, and was once
/// passed as "rounding" by a three-digit rule.
fn close(got: &PrintedValue, want: &[f64]) -> bool {
    let Some(want) = aligned(got, want) else { return false };
    got.numbers.iter().zip(&got.half_units).zip(&got.own_half_units).zip(want).all(|(((g, h), own), w)| {
        let float = (g - w).abs() <= 2e-5 * w.abs() + h;
        let rounded = *own <= 5e-4 * w.abs() && (g - w).abs() <= own * (1.0 + 1e-9) + SLACK * w.abs().max(1.0);
        float || rounded
    })
}

/// How far a value must be from the key's, in some number, to be another value: a
/// millionth (of the number's size, past 1). Printed at NumPy's default precision (8
/// decimals) the key and such a value never print alike.
const TOLD_APART: f64 = 1e-6;

/// Is `other` another value than the key's `want`, by [`TOLD_APART`]?
fn apart(other: &[f64], want: &[f64]) -> bool {
    other.len() != want.len() || other.iter().zip(want).any(|(o, w)| (o - w).abs() > TOLD_APART * w.abs().max(1.0))
}

/// The key worked with each of the catalogue's mistakes (under the assignment's rules),
/// worked once, and only where a step's printed digits are coarse enough to need them.
struct Mistaken<'a> {
    scene: &'a Scene,
    worked: Option<Vec<Worked>>,
}

impl<'a> Mistaken<'a> {
    fn new(scene: &'a Scene) -> Self {
        Mistaken { scene, worked: None }
    }

    /// Every mistake's worked values.
    fn all(&mut self) -> &[Worked] {
        let scene = self.scene;
        self.worked.get_or_insert_with(|| {
            let mut out = Vec::new();
            for info in &CATALOGUE {
                let Some(m) = info.mistake.filter(|m| m.applies(scene.rules)) else { continue };
                for made in Made::instances(m, scene.lights.len()) {
                    out.push(work_made(scene, Some(made), None));
                }
            }
            out
        })
    }
}

/// Where `got` is the key's `want` to its printed digits: can those digits tell the key
/// from zero (in a number where the key is not zero) and from every catalogue mistake's
/// value there? `None` where they can; else the decimal places printed (the coarsest
/// number's). A verdict is proven on the printed digits: `[0. 0. 0. 0.]` at two decimals
/// is the key's 0.0004 and a specular left out alike.
fn untold(got: &PrintedValue, want: &[f64], mistaken: &mut Mistaken) -> Option<u32> {
    let want = aligned(got, want)?;
    // A number printed alone is Python's shortest round trip (NumPy's print options do
    // not shorten it): `-1.0` where the key is -1 exactly is the key, not -1 to a decimal.
    if let ([g], [w]) = (got.numbers.as_slice(), want)
        && (g - w).abs() <= SLACK * w.abs().max(1.0)
    {
        return None;
    }
    let coarsest = got.half_units.iter().copied().fold(0.0f64, f64::max);
    // Two values a millionth apart never both lie within half a unit finer than this.
    if coarsest < 0.25 * TOLD_APART {
        return None;
    }
    let decimals = (-(2.0 * coarsest).log10()).round().max(0.0) as u32;
    let zero_too = (0..want.len()).any(|i| {
        let mut zeroed = want.to_vec();
        zeroed[i] = 0.0;
        apart(&zeroed, want) && same(got, &zeroed)
    });
    if zero_too {
        return Some(decimals);
    }
    let mistake_too = mistaken.all().iter().any(|m| {
        m.get(&got.name)
            .and_then(|v| aligned(got, v).map(<[f64]>::to_vec))
            .is_some_and(|v| apart(&v, want) && same(got, &v))
    });
    mistake_too.then_some(decimals)
}

/// Checks what `student` printed against the key of `assignment`; `own` is the scene the
/// work typed (read from its code: the same as `assignment` unless the class was given
/// one).
pub fn check(assignment: &Scene, own: &Scene, student: &Printed) -> Check {
    let inputs_differ = differing_inputs(assignment, own);
    let key = work(assignment, None, None);
    let given = work(assignment, None, Some(student));
    let mut steps = Vec::new();
    let mut first_wrong = None;
    // The steps that are not the key's, in order: what a later value may be right given.
    let mut wrong_so_far: Vec<&PrintedValue> = Vec::new();
    let mut mistaken = Mistaken::new(assignment);
    for p in &student.values {
        let Some(k) = key.get(&p.name) else { continue };
        // Read as NumPy's options pad it (the work's finest digits), then at its own.
        let padded = PrintedValue { half_units: p.padded_half_units.clone(), ..p.clone() };
        let verdict = if same(&padded, k) && untold(&padded, k, &mut mistaken).is_none() {
            Verdict::Right
        } else if same(p, k) {
            match untold(p, k, &mut mistaken) {
                Some(decimals) => Verdict::TooFewDigits(decimals),
                None => Verdict::Right,
            }
        } else if same_point(p, k) {
            Verdict::Right
        } else if let Some(w) = right_given(assignment, &key, &given, &wrong_so_far, p) {
            Verdict::RightGiven(w)
        } else if close(p, k) {
            Verdict::Rounding
        } else {
            Verdict::Wrong
        };
        // A rounded value is carried too: what follows from it is right given it. A name
        // printed again is carried as last printed (what the cells after it use): each
        // name once, so the check stays linear in the printings.
        if !matches!(verdict, Verdict::Right | Verdict::TooFewDigits(_)) {
            wrong_so_far.retain(|w| w.name != p.name);
            wrong_so_far.push(p);
        }
        if verdict == Verdict::Wrong && first_wrong.is_none() {
            first_wrong = Some(steps.len());
        }
        steps.push(StepCheck { name: p.name.clone(), student: p.numbers.clone(), key: k.to_vec(), verdict });
    }
    // Work typed for another scene (a wrong --scene) is no mistake of this one's.
    let causes = if inputs_differ.len() >= OTHER_SCENE_AT {
        Vec::new()
    } else if first_wrong.is_some() || !student.errors.is_empty() {
        // On the assignment (a mistake in a typed input, `ns = 0.2`), then on what they typed.
        // Only mistakes under the rules assumed (the assignment's) are offered.
        let mut found = causes(assignment, &key, student, assignment.rules);
        if found.is_empty() && !inputs_differ.is_empty() {
            found = causes(own, &work(own, None, None), student, assignment.rules);
        }
        found
    } else {
        Vec::new()
    };
    let unreadable = student.unread.iter().filter(|n| key.get(n).is_some()).cloned().collect();
    let missing = student.missing.iter().filter(|n| key.get(n).is_some()).cloned().collect();
    // Asked and not printed; what the self-check already found missing is said once, there.
    let not_printed = asked(&key)
        .into_iter()
        .filter(|n| student.get(n).is_none() && !student.unread.contains(n) && !student.missing.contains(n))
        .collect();
    Check {
        rules: assignment.rules,
        inputs_differ,
        steps,
        first_wrong,
        causes,
        errors: student.errors.clone(),
        unreadable,
        missing,
        not_printed,
        stale: student.stale.clone(),
        after_error: student.after_error.clone(),
    }
}

/// The earlier wrong step(s) `p` is right given: the key worked with only one of the
/// student's wrong values carried, the most recent first, that reproduces `p`; else all
/// of them together, naming only those `p` depends on. A step `p` does not depend on
/// (carrying it leaves `p` the key's: `H` and `Idif`) is never named. `None` where none does.
fn right_given(
    scene: &Scene,
    key: &Worked,
    given: &Worked,
    wrong: &[&PrintedValue],
    p: &PrintedValue,
) -> Option<String> {
    let want = key.get(&p.name)?;
    let mut depends = Vec::new();
    for w in wrong.iter().rev() {
        let one = Printed { values: vec![(*w).clone()], ..Printed::default() };
        let carried = work(scene, None, Some(&one));
        let Some(g) = carried.get(&p.name).filter(|g| apart(g, want)) else { continue };
        if given_from_printed(p, g) {
            return Some(w.name.clone());
        }
        depends.push(w.name.as_str());
    }
    if depends.is_empty() || !given.get(&p.name).is_some_and(|g| given_from_printed(p, g)) {
        return None;
    }
    Some(depends.join(", "))
}

/// The catalogue's mistakes under the `assumed` rules that reproduce every value the
/// student printed (worked on the scene they typed), and the error a run stopped with. A
/// mistake made for all lights is named before (and instead of) the same made for one.
fn causes(own: &Scene, key: &Worked, student: &Printed, assumed: Rules) -> Vec<Cause> {
    let mut out: Vec<Cause> = Vec::new();
    for info in &CATALOGUE {
        let Some(m) = info.mistake.filter(|m| m.applies(assumed)) else { continue };
        for made in Made::instances(m, own.lights.len()) {
            if out.iter().any(|c| c.info.id == info.id && (c.light.is_none() || c.swap != made.swap)) {
                continue;
            }
            if let Some((step, value)) = reproduces(&work_made(own, Some(made), None), key, student) {
                out.push(Cause { info, step, value, light: made.light, swap: made.swap });
            }
        }
    }
    if let Some(c) = acos_past_one(student) {
        out.push(c);
    }
    // Causes the printed values cannot tell apart (a spot of 0) in the order the student's
    // code makes likely: one whose formula is in it first (the catalogue's order kept
    // otherwise). What is named is never chosen by the code, only its order.
    out.sort_by_key(|c| !written(&c.formula(), &student.code));
    out
}

/// Is `formula`'s statement (before its comment) in `code`? Spaces, a light's index
/// (`[i]`, `[2]`) and `;` are ignored on both sides.
fn written(formula: &str, code: &str) -> bool {
    fn plain(s: &str) -> String {
        let mut out = String::with_capacity(s.len());
        let mut rest = s;
        while let Some(c) = rest.chars().next() {
            if c == '['
                && let Some(end) = rest.find(']')
            {
                let inner = &rest[1..end];
                if inner == "i" || !inner.is_empty() && inner.chars().all(|d| d.is_ascii_digit()) {
                    rest = &rest[end + 1..];
                    continue;
                }
            }
            if !c.is_whitespace() && c != ';' {
                out.push(c);
            }
            rest = &rest[c.len_utf8()..];
        }
        out
    }
    let statement = plain(formula.split("  #").next().unwrap_or(formula));
    !statement.is_empty() && !code.is_empty() && plain(code).contains(&statement)
}

/// Does `made` (the key worked with a mistake) give every value the student printed, one
/// of them not the key's? The first such step and the mistaken value there.
fn reproduces(made: &Worked, key: &Worked, student: &Printed) -> Option<(String, Vec<f64>)> {
    let mut compared = 0;
    let mut evidence = None;
    for p in &student.values {
        let Some(v) = made.get(&p.name) else { continue };
        if !same(p, v) {
            return None;
        }
        compared += 1;
        if evidence.is_none() && key.get(&p.name).is_some_and(|k| !same(p, k)) {
            evidence = Some((p.name.clone(), v.to_vec()));
        }
    }
    evidence.filter(|_| compared > 0)
}

/// `acos` of a cosine past 1: the run stopped with Python's math domain error, and the
/// last cosine printed before it lies past 1.
fn acos_past_one(student: &Printed) -> Option<Cause> {
    student.errors.iter().find(|e| e.contains("math domain error"))?;
    let cos = student.values.iter().rev().find(|v| v.name.starts_with("cos"))?;
    let past = cos.numbers.first().is_some_and(|c| c.abs() > 1.0);
    let info = mistakes::info(ACOS_PAST_ONE)?;
    past.then(|| Cause { info, step: cos.name.clone(), value: cos.numbers.clone(), light: None, swap: None })
}

/// The givens a scene's notebook types, by the worksheet's names.
fn givens(scene: &Scene) -> Vec<(String, Vec<f64>)> {
    let mut out = vec![
        ("vertexPos".to_string(), scene.vertex.position.to_array().to_vec()),
        ("vertexNormal".to_string(), scene.vertex.normal.to_array().to_vec()),
        ("mview".to_string(), scene.eye_from_object().to_cols_array().to_vec()),
    ];
    let m = scene.lit_material(Side::Front);
    for (name, c) in [("matAmb", m.ambient), ("matDif", m.diffuse), ("matSpec", m.specular)] {
        out.push((name.to_string(), c.truncate().to_array().to_vec()));
    }
    out.push(("ns".to_string(), vec![m.shininess]));
    for (i, l) in scene.lights.iter().enumerate() {
        let name = |base: &str| if scene.lights.len() == 1 { base.to_string() } else { format!("{base}[{i}]") };
        out.push((name("lightPos"), l.position.to_array().to_vec()));
        for (base, c) in [("Lamb", l.ambient), ("Ldif", l.diffuse), ("Lspec", l.specular)] {
            out.push((name(base), c.truncate().to_array().to_vec()));
        }
        // Named as the worksheet types them (`atLin`, not the `at` worked from them).
        for (base, k) in [("atC", 0), ("atLin", 1), ("atQuad", 2)] {
            out.push((name(base), vec![l.attenuation[k]]));
        }
        out.push((name("spotCutoff"), vec![l.spot_cutoff]));
        out.push((name("spotCoef"), vec![l.spot_exponent]));
    }
    out
}

/// The givens of `own` that are not the assignment's.
fn differing_inputs(assignment: &Scene, own: &Scene) -> Vec<String> {
    let (a, b) = (givens(assignment), givens(own));
    let mut out: Vec<String> = a
        .iter()
        .filter(|(name, v)| b.iter().find(|(n, _)| n == name).is_none_or(|(_, w)| w != v))
        .map(|(name, _)| name.clone())
        .collect();
    if assignment.lights.len() != own.lights.len() {
        out.push("lightPos".to_string());
    }
    if assignment.rules != own.rules {
        out.push("rules".to_string());
    }
    // The viewer is the notebook's `obs` switch (`#localViewer`), not a rule set.
    if assignment.light_model.local_viewer != own.light_model.local_viewer {
        out.push("localViewer".to_string());
    }
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::Unchecked;
    use crate::locale::{Lang, Locale, with_locale};

    #[test]
    fn one_step_not_printed_is_named_once() {
        let one = Unchecked::NotPrinted(1, "Ispec".into(), "Ispec".into());
        for (lang, said) in [
            (Lang::En, "a step this work does not print: Ispec."),
            (Lang::PtPt, "um passo que este trabalho não imprime: Ispec."),
            (Lang::PtBr, "um passo que este trabalho não imprime: Ispec."),
        ] {
            let words = with_locale(Locale::of(lang), || one.words());
            assert!(words.contains(said), "{lang:?}: {words}");
            assert_eq!(words.matches("Ispec").count(), 1, "{lang:?}: {words}");
        }
        let two = Unchecked::NotPrinted(2, "Ispec".into(), "Ispec, I".into());
        let words = with_locale(Locale::of(Lang::PtPt), || two.words());
        assert!(words.contains("2 passos que este trabalho não imprime, o primeiro Ispec: Ispec, I."), "{words}");
    }
}
