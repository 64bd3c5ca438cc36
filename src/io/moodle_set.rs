//! Exercises as a file for Moodle's question bank (`phonglab exercise --format
//! moodle-xml` or `gift`): `questions.xml` (Moodle XML) or `questions.gift.txt` (GIFT),
//! written by the core's writers ([`phonglab_core::moodle_xml`], [`phonglab_core::gift`])
//! from its questions ([`phonglab_core::moodle`]). Each exercise of the request is one
//! category holding its `variants` seeded variants, so that a quiz's "random question"
//! from the category gives each student their own; level 5 is one category of
//! multiple-choice questions with both pictures embedded. The file is written as a set of
//! one, as the sheets are ([`super::file_set`]); the same seed gives the same bytes.

use anyhow::Result;
use phonglab_core::exercise::{Exercise, generate};
use phonglab_core::misconception::{self, Misconception};
use phonglab_core::moodle::{Rounding, exercise_question, misconception_question};
use phonglab_core::question::{Bank, Category};

use super::exercise_set::{MOODLE_FILES, Request};
use super::file_set::FileSet;
use crate::t;

/// Which of Moodle's import formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// "Moodle XML format": Cloze questions, pictures as files.
    MoodleXml,
    /// "GIFT format": one numerical question per value, pictures as `data:` URIs.
    Gift,
}

impl Format {
    /// The file it writes.
    pub fn file_name(self) -> &'static str {
        match self {
            Format::MoodleXml => MOODLE_FILES[0],
            Format::Gift => MOODLE_FILES[1],
        }
    }

    /// The bank in this format.
    pub fn write(self, bank: &Bank) -> String {
        match self {
            Format::MoodleXml => phonglab_core::moodle_xml::write(bank),
            Format::Gift => phonglab_core::gift::write(bank),
        }
    }
}

/// What to put in the bank beside the exercises' request.
#[derive(Clone, Debug)]
pub struct Bundle {
    /// The exercises (their seed, count, effects, rules).
    pub request: Request,
    /// How many variants of each exercise.
    pub variants: usize,
    /// The category's name, the top of every category written.
    pub category: String,
    /// Exam exercises, to be worked without a calculator.
    pub exam: bool,
}

/// The exercises of `b`: `count × variants` of them, exercise k's variants together.
fn exercises(b: &Bundle) -> Result<Vec<Exercise>> {
    let (r, n) = (&b.request, b.request.count * b.variants);
    let all = if b.exam { phonglab_core::exam::generate(r.seed, n, &r.spec) } else { generate(r.seed, n, &r.spec) };
    all.map_err(anyhow::Error::msg)
}

/// The bank of exercises (levels 1 to 4, or chosen effects).
pub fn exercise_bank(b: &Bundle) -> Result<Bank> {
    let all = exercises(b)?;
    let rounding = if b.exam { Rounding::Exam } else { Rounding::Quiz };
    let mut bank = Bank::default();
    let total = all.len();
    for (k, group) in all.chunks(b.variants.max(1)).enumerate() {
        let exercise = t!("moodle-category-exercise", number = (k + 1) as i64);
        let questions = group
            .iter()
            .enumerate()
            .map(|(v, ex)| {
                // The statement's heading, which students see: no seed, which would let
                // them write the key.
                let mut ex = ex.clone();
                ex.doc.name.clone_from(&exercise);
                let mut q = exercise_question(&ex, rounding);
                q.name = teacher_name(b, &exercise, v + 1, k * b.variants.max(1) + v + 1, total);
                q
            })
            .collect();
        bank.categories.push(Category { path: vec![b.category.clone(), exercise], questions });
    }
    Ok(bank)
}

/// A question's name in the bank, which Moodle shows to teachers only: the exercise, the
/// variant, and where its worked key is: sheet `sheet` of the same request written as
/// sheets, `--count total` (exercise k's variants are sheets (k − 1) × variants + 1 on),
/// by the command that writes it ([`sheets_command`]).
fn teacher_name(b: &Bundle, exercise: &str, variant: usize, sheet: usize, total: usize) -> String {
    t!(
        "moodle-question-name",
        exercise = exercise.to_string(),
        variant = variant as i64,
        sheet = format!("{sheet:02}"),
        command = sheets_command(b, total)
    )
}

/// The command that writes `b`'s exercises as sheets, `total` of them, with their keys:
/// everything that changes a key (the seed, the count, the level or effects, the rules,
/// an exam; the language and decimal mark its words and numbers are written in), so that
/// following it gives the very key the question was made from.
pub fn sheets_command(b: &Bundle, total: usize) -> String {
    use phonglab_core::exercise::Level;
    let spec = &b.request.spec;
    let mut effects = spec.effects.clone();
    effects.sort();
    let level = (1..=4u8).find(|&n| {
        Level::from_number(n).is_some_and(|l| {
            let mut e = l.effects();
            e.sort();
            e == effects
        })
    });
    let what = match level {
        Some(n) => format!("--level {n}"),
        None => {
            let names: Vec<&str> = effects.iter().map(|e| e.name()).collect();
            format!("--effects {}", names.join(","))
        }
    };
    let rules = match spec.rules.set {
        phonglab_core::rules::RuleSet::OpenGl => "opengl",
        _ => "worksheet",
    };
    let locale = crate::locale::current();
    let mut command = format!(
        "phonglab exercise --seed {} --count {total} {what} --rules {rules}{} --lang {}",
        b.request.seed,
        if b.exam { " --exam" } else { "" },
        locale.lang.code()
    );
    if locale.decimal != locale.lang.decimal_mark() {
        let mark = match locale.decimal {
            crate::locale::DecimalMark::Point => "point",
            crate::locale::DecimalMark::Comma => "comma",
        };
        command.push_str(&format!(" --decimal {mark}"));
    }
    command
}

/// The bank of "What is wrong with this picture?": the mistakes in the seed's order, one
/// category, each question with its two pictures.
pub fn misconception_bank(seed: u64, count: usize, category: &str) -> Result<Bank> {
    let mut questions = Vec::new();
    for (k, kind) in super::misconception_set::chosen(seed, count).into_iter().enumerate() {
        questions.push(picture_question(kind, k + 1)?);
    }
    Ok(Bank { categories: vec![Category { path: vec![category.to_string()], questions }] })
}

fn picture_question(kind: Misconception, number: usize) -> Result<phonglab_core::question::Question> {
    let px = super::misconception_set::PX;
    let drawn = misconception::case(kind).draw(px).map_err(anyhow::Error::msg)?;
    let right = super::image::encode_png(px, px, &drawn.correct)?;
    let wrong = super::image::encode_png(px, px, &drawn.bugged)?;
    let name = t!("wrong-sheet-title", number = number as i64);
    Ok(misconception_question(kind, &name, right, wrong))
}

/// Writes the bank `make_bank` makes as `format` into the folder `dir`, whole or not at all: the file's name, the bank,
/// and what was left as it is in the folder (see [`super::file_set::recover`]). The file
/// replaces only its own earlier self as phonglab wrote it (named, unchanged, in the
/// folder's list of what phonglab wrote); every other file in the folder (the sheets and
/// keys, the other format's file) is left alone.
///
/// The folder is held ([`super::file_set::hold_folder`]) from before the bank is made
/// (`make_bank`) to the end of the write, so that a second run into it waits for this one
/// and then checks the folder as this one left it.
pub fn write(
    dir: &std::path::Path,
    format: Format,
    make_bank: impl FnOnce() -> Result<Bank>,
) -> Result<(String, Bank, Vec<String>)> {
    super::atomic_write::check_folder_destination(dir)?;
    let held = super::file_set::hold_folder(dir)?;
    let bank = make_bank()?;
    refuse_foreign(dir, format.file_name())?;
    let mut set = FileSet::default();
    set.add(format.file_name(), format.write(&bank));
    let name = format.file_name();
    let notices = super::file_set::write_set_held(&held, &set, |n| n == name)?;
    Ok((format.file_name().to_string(), bank, notices))
}

/// Refuses to write `name` into `dir` over a regular file of that name that phonglab did
/// not write there, or that was changed since (a teacher's own questions, an edited
/// export): the folder's list of what phonglab wrote ([`super::set_journal::WRITTEN`])
/// must name it with its bytes as they are (a copied folder's file, with the same bytes,
/// is still phonglab's: [`super::set_journal::written_as_is`]). A list that is a link or
/// not a regular file refuses the folder ([`super::set_journal::check_records`]). A link or anything else at the name is refused by the writer.
fn refuse_foreign(dir: &std::path::Path, name: &str) -> Result<()> {
    super::set_journal::check_records(dir)?;
    let path = dir.join(name);
    if !std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
        return Ok(());
    }
    let written = super::set_journal::written_list(dir);
    let now = super::set_journal::entry_of(dir, name);
    if now.is_ok_and(|now| super::set_journal::written_as_is(&written, &now)) {
        return Ok(());
    }
    anyhow::bail!(t!("moodle-not-ours", path = super::reasons::shown(&path)))
}
