//! `phonglab exercise`: an exercise set ([`crate::io::exercise_set`]) written into a
//! folder, from the command line's seed, count, level or effects and rules.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;
use phonglab_core::Rules;
use phonglab_core::exercise::{Effect, Level, Spec};

use crate::io::exercise_set::{Request, write};
use crate::io::moodle_set::{Bundle, Format, exercise_bank, misconception_bank};
use crate::t;
use phonglab_core::misconception::Misconception;

/// `phonglab exercise`.
#[derive(Args, Debug)]
pub struct ExerciseArgs {
    /// The random seed: the same seed gives the same sheets.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true, value_parser = super::arg_errors::whole(0, u64::MAX))]
    pub seed: u64,
    /// How many exercises.
    #[arg(long, default_value_t = 10, allow_negative_numbers = true, value_parser = super::arg_errors::whole(1, 1000))]
    pub count: u64,
    /// Whether `--count` was given (not its default): level 5 says it wrote fewer
    /// questions only to a teacher who asked for more.
    #[arg(skip)]
    pub count_given: bool,
    /// Difficulty: 1 directional only, 2 positional with attenuation, 3 spotlights, 4
    /// two-sided with several lights; 5 "what is wrong with this picture?" (a picture drawn
    /// with one mistake, its cause to pick; at most seven).
    #[arg(long, value_parser = clap::value_parser!(u8).range(1..=5), conflicts_with = "effects")]
    pub level: Option<u8>,
    /// Exactly these effects instead of a level (comma-separated): positional,
    /// attenuation, spot, local-viewer, two-sided, several-lights.
    #[arg(long, value_delimiter = ',', action = clap::ArgAction::Set, num_args = 1)]
    pub effects: Vec<String>,
    /// The rules the answers follow: worksheet or opengl.
    #[arg(long, default_value = "worksheet")]
    pub rules: String,
    /// Also write exercise 0: the worksheet itself, its five modelviews on one sheet.
    #[arg(long)]
    pub worksheet: bool,
    /// The folder to write to (created if missing).
    #[arg(long, default_value = "sheets")]
    pub out: PathBuf,
    /// What to write: the sheets, keys and PDFs; or a file for Moodle's question bank,
    /// `questions.xml` (Moodle XML: one Cloze question per exercise) or
    /// `questions.gift.txt` (GIFT: one numerical question per value).
    #[arg(long, value_enum, default_value_t = OutputFormat::Sheets)]
    pub format: OutputFormat,
    /// With a Moodle format: this many seeded variants of each exercise, in one category
    /// per exercise, for a quiz's "random question" from it.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true, value_parser = super::arg_errors::whole(1, 100))]
    pub variants: u64,
    /// With a Moodle format: the name of the top category (default "phonglab").
    #[arg(long)]
    pub category: Option<String>,
    /// Exam exercises, to be worked without a calculator: rational unit vectors, whole
    /// distances, shininess 1, 2 or 4, every value four significant digits by hand.
    #[arg(long, conflicts_with = "worksheet")]
    pub exam: bool,
}

/// What `phonglab exercise` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum OutputFormat {
    /// Sheets, keys, scene files and the two PDFs.
    Sheets,
    /// Moodle XML (`questions.xml`).
    MoodleXml,
    /// GIFT (`questions.gift.txt`).
    Gift,
}

/// The set the arguments ask for.
fn request_of(a: &ExerciseArgs) -> Result<Request> {
    let spec = spec_of(a)?;
    Ok(Request { seed: a.seed, count: a.count as usize, spec, worksheet: a.worksheet, exam: a.exam })
}

fn spec_of(a: &ExerciseArgs) -> Result<Spec> {
    let rules = match a.rules.as_str() {
        "worksheet" => Rules::WORKSHEET,
        "opengl" => Rules::OPENGL,
        other => bail!(crate::t!("err-rules", value = format!("{other:?}"))),
    };
    if !a.effects.is_empty() {
        let mut effects = Vec::new();
        let names: Vec<&str> = Effect::ALL.iter().map(|e| e.name()).collect();
        for e in &a.effects {
            // `--effects spot,`: a comma with no name after it (or before it).
            if e.trim().is_empty() {
                bail!(crate::t!("err-effects-empty", names = names.join(", ")));
            }
            let Some(x) = Effect::parse(e) else {
                bail!(crate::t!("err-effects", value = format!("{e:?}"), names = names.join(", ")));
            };
            effects.push(x);
        }
        // Attenuation and spotlights exist only on positional lights.
        if effects.iter().any(|e| matches!(e, Effect::Attenuation | Effect::Spot))
            && !effects.contains(&Effect::Positional)
        {
            effects.push(Effect::Positional);
        }
        effects.sort();
        effects.dedup();
        return Ok(Spec { effects, rules });
    }
    let level = Level::from_number(a.level.unwrap_or(2)).context(crate::t!("err-level"))?;
    Ok(Spec::level(level, rules))
}

/// Writes the file for Moodle that `a` asks for, and says where and how to import it.
fn run_moodle(a: &ExerciseArgs, format: Format) -> Result<()> {
    if a.worksheet {
        bail!(t!("err-worksheet-moodle"));
    }
    let category = a.category.clone().unwrap_or_else(|| t!("moodle-category-default"));
    crate::io::moodle_checks::check_category(&category)?;
    let level_5 = a.level == Some(5);
    let bundle = if level_5 {
        if a.exam {
            bail!(t!("err-exam-level-5"));
        }
        // Seven pictures, one per mistake: no variants to draw from a category.
        if a.variants > 1 {
            bail!(t!("err-level-5-variants"));
        }
        crate::io::misconception_set::check_budget(a.count as usize)?;
        None
    } else {
        let bundle =
            Bundle { request: request_of(a)?, variants: a.variants as usize, category: category.clone(), exam: a.exam };
        crate::io::moodle_checks::check_budget(&bundle, format)?;
        Some(bundle)
    };
    let make_bank = || match &bundle {
        Some(bundle) => exercise_bank(bundle),
        None => misconception_bank(a.seed, a.count as usize, &category),
    };
    let (file, bank, notices) = crate::io::moodle_set::write(&a.out, format, make_bank)?;
    for n in &notices {
        super::say(n);
    }
    // GIFT writes each part of a statement as a question of its own.
    let questions: usize = bank
        .categories
        .iter()
        .flat_map(|c| &c.questions)
        .map(|q| match (&q.body, format) {
            (phonglab_core::question::Body::Numbers { parts, .. }, Format::Gift) => parts.len(),
            _ => 1,
        })
        .sum();
    let format_name = match format {
        Format::MoodleXml => t!("moodle-format-xml"),
        Format::Gift => t!("moodle-format-gift"),
    };
    say_level_5_count(a);
    super::say(&t!(
        "moodle-written",
        file = file,
        out = crate::io::reasons::shown(&a.out),
        questions = questions,
        categories = bank.categories.len(),
        format = format_name
    ));
    Ok(())
}

/// Says, to a teacher who asked level 5 for more questions than its seven mistakes, that
/// it wrote seven ("7, not 9"), for the sheets as for Moodle.
fn say_level_5_count(a: &ExerciseArgs) {
    if a.level == Some(5) && a.count_given && a.count as usize > Misconception::ALL.len() {
        let all = Misconception::ALL.len() as i64;
        super::say(&t!("level-5-count", count = a.count as i64, all = all));
    }
}

/// Runs `phonglab exercise`.
pub fn run(a: &ExerciseArgs) -> Result<()> {
    // Said in one sentence (the writer's own error chains its step and reason: "cannot
    // write afile: create the folder: it is a file…").
    if std::fs::metadata(&a.out).is_ok_and(|m| !m.is_dir()) {
        bail!(t!("err-out-is-a-file", out = crate::io::reasons::shown(&a.out)));
    }
    match a.format {
        OutputFormat::Sheets if a.variants > 1 || a.category.is_some() => bail!(t!("err-moodle-only")),
        OutputFormat::Sheets => {}
        OutputFormat::MoodleXml => return run_moodle(a, Format::MoodleXml),
        OutputFormat::Gift => return run_moodle(a, Format::Gift),
    }
    if a.level == Some(5) {
        if a.exam {
            bail!(t!("err-exam-level-5"));
        }
        let (count, notices) = crate::io::misconception_set::write(&a.out, a.seed, a.count as usize)?;
        for n in &notices {
            super::say(n);
        }
        say_level_5_count(a);
        super::say(&t!("wrong-written", count = count, out = crate::io::reasons::shown(&a.out)));
        return Ok(());
    }
    let (ex, notices) = write(&a.out, &request_of(a)?)?;
    for n in &notices {
        super::say(n);
    }
    let redraws: usize = ex.iter().map(|e| e.redraws).sum();
    super::say(&t!(
        "exercises-written",
        count = ex.len() + a.worksheet as usize,
        out = crate::io::reasons::shown(&a.out),
        redraws = redraws
    ));
    Ok(())
}
