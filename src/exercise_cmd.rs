//! `phonglab exercise`: exercise sheets in the worksheet's style, each with its scene file
//! and its answer key (the worked calculation `phonglab explain` prints for that file).
//!
//! For exercise k (numbered from 1; 0 is the worksheet itself, with `--worksheet`) it
//! writes `exercise-KK.md` (the sheet), `exercise-KK-key.md` (the answers) and
//! `exercise-KK.toml` (the scene, which the app and every command open), `index.md`
//! listing them, and `exercises.pdf`, every sheet and key ready to print. The same seed gives the same files, byte for byte.
//! The set is written as one: a folder holds one whole set, never parts of two.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;
use phonglab_core::exercise::{Effect, Exercise, Level, Spec, generate, sheet_markdown};
use phonglab_core::explain::{Side, explain};
use phonglab_core::{Document, Engine, Rules};

use crate::atomic_write::FileSet;
use phonglab_core::t;

/// `phonglab exercise`.
#[derive(Args, Debug)]
pub struct ExerciseArgs {
    /// The random seed: the same seed gives the same sheets.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// How many exercises.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub count: u32,
    /// Difficulty: 1 directional only, 2 positional with attenuation, 3 spotlights, 4
    /// two-sided with several lights.
    #[arg(long, value_parser = clap::value_parser!(u8).range(1..=4), conflicts_with = "effects")]
    pub level: Option<u8>,
    /// Exactly these effects instead of a level (comma-separated): positional,
    /// attenuation, spot, local-viewer, two-sided, several-lights.
    #[arg(long, value_delimiter = ',')]
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
}

/// The answer key: what `phonglab explain FILE` prints (and `--back` with two-sided
/// lighting), in a code block.
pub fn answer_key(doc: &Document, file: &str) -> Result<String> {
    Ok(format!("# {}\n\n{}", t!("key-title", name = &doc.name), answer_key_body(doc, file)?))
}

/// The answer key without its title.
fn answer_key_body(doc: &Document, file: &str) -> Result<String> {
    let lit = Engine::<f64>::light_scene_vertex(&doc.scene)?;
    let mut o = format!("{}\n\n", t!("key-intro", file = file));
    let sides: &[Side] = if doc.scene.light_model.two_sided { &[Side::Front, Side::Back] } else { &[Side::Front] };
    for &side in sides {
        let ex = explain(&doc.scene, &lit, side);
        let _ = writeln!(o, "```\n{}\n{}```\n", t!("worked-calculation-of", name = &doc.name), ex.to_text(8));
    }
    Ok(o)
}

fn spec_of(a: &ExerciseArgs) -> Result<Spec> {
    let rules = match a.rules.as_str() {
        "worksheet" => Rules::WORKSHEET,
        "opengl" => Rules::OPENGL,
        other => bail!("--rules {other:?}: try worksheet or opengl"),
    };
    if !a.effects.is_empty() {
        let mut effects = Vec::new();
        for e in &a.effects {
            let Some(x) = Effect::parse(e) else {
                let names: Vec<&str> = Effect::ALL.iter().map(|e| e.name()).collect();
                bail!("--effects: {e:?} is not one of {}", names.join(", "));
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
    let level = Level::from_number(a.level.unwrap_or(2)).context("--level is 1 to 4")?;
    Ok(Spec::level(level, rules))
}

/// Is `name` a file of an exercise set (so a new set in the same folder replaces it)?
pub fn belongs_to_a_set(name: &str) -> bool {
    let stem = name.strip_suffix(".md").or_else(|| name.strip_suffix(".toml"));
    match stem {
        Some("index") => name == "index.md",
        Some(stem) => stem.strip_prefix("exercise-").is_some_and(|rest| {
            let rest = rest.strip_suffix("-key").unwrap_or(rest);
            let (number, mview) = rest.split_once("-mview").unwrap_or((rest, "1"));
            !number.is_empty()
                && number.bytes().all(|b| b.is_ascii_digit())
                && mview.len() == 1
                && mview.bytes().all(|b| b.is_ascii_digit())
        }),
        None => name == "exercises.pdf",
    }
}

/// The worksheet as exercise 0: its five modelviews, one sheet, with the values it prints.
fn worksheet_sheet(set: &mut FileSet) -> Result<String> {
    let mut sheet = format!("# {}\n\n{}\n\n", t!("exercise-zero-title"), t!("exercise-zero-intro"));
    let mut key = format!("# {}\n\n", t!("key-title", name = t!("exercise-zero-name")));
    for k in 1..=5u8 {
        let doc = phonglab_core::library::documents()
            .into_iter()
            .map(|(_, d)| d)
            .find(|d| d.camera == phonglab_core::CameraSpec::Worksheet(k))
            .context("the worksheet's documents")?;
        let file = format!("exercise-00-mview{k}.toml");
        set.add(file.clone(), doc.to_toml()?);
        let rows = phonglab_core::transform::mat4_rows(&doc.scene.eye_from_world);
        let _ = writeln!(sheet, "## mview{k} ({file})\n\n```");
        for r in rows {
            let _ = writeln!(sheet, "[{}]", r.map(|x| phonglab_core::locale::num(x, 8)).join(" "));
        }
        let _ = writeln!(sheet, "```\n");
        let _ = write!(key, "## mview{k}\n\n{}", answer_key_body(&doc, &file)?);
    }
    set.add("exercise-00.md", sheet);
    set.add("exercise-00-key.md", key);
    Ok(format!("- [{}](exercise-00.md) ([{}](exercise-00-key.md))\n", t!("exercise-zero-title"), t!("answers")))
}

/// Lines of at most `width` characters (longer ones wrapped at spaces where possible).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut out = Vec::new();
    for line in text.lines() {
        let mut rest = line.trim_end().to_string();
        loop {
            if rest.chars().count() <= width {
                out.push(rest);
                break;
            }
            let cut: String = rest.chars().take(width).collect();
            let at = cut.rfind(' ').filter(|i| *i > width / 3).unwrap_or(cut.len());
            out.push(rest[..at].to_string());
            rest = format!("      {}", rest[at..].trim_start());
        }
    }
    out
}

/// A printable PDF of `documents` (each starts on a new page): A4, 9-point Hack (the
/// monospaced font egui ships, embedded and subset), so the numbers line up as in the
/// worksheet. No dates or random ids: the same input gives the same bytes.
pub fn pdf(documents: &[String]) -> Result<Vec<u8>> {
    use krilla::geom::Point;
    use krilla::page::PageSettings;
    use krilla::text::{Font, TextDirection};
    let font = Font::new(epaint_default_fonts::HACK_REGULAR.to_vec().into(), 0).context("the embedded font")?;
    let (w, h, margin, size, lead) = (595.0f32, 842.0f32, 48.0f32, 9.0f32, 12.0f32);
    let per_page = ((h - 2.0 * margin) / lead) as usize;
    let mut doc = krilla::Document::new();
    for text in documents {
        let lines = wrap(text, 88);
        for chunk in lines.chunks(per_page) {
            let settings = PageSettings::from_wh(w, h).context("A4")?;
            let mut page = doc.start_page_with(settings);
            let mut surface = page.surface();
            for (i, line) in chunk.iter().enumerate() {
                if !line.is_empty() {
                    let y = margin + size + i as f32 * lead;
                    surface.draw_text(Point::from_xy(margin, y), font.clone(), size, line, false, TextDirection::Auto);
                }
            }
            surface.finish();
            page.finish();
        }
    }
    doc.finish().map_err(|e| anyhow::anyhow!("cannot write the PDF: {e:?}"))
}

/// The exercises and the files of their set: the sheets, keys and scene files, `index.md`
/// and `exercises.pdf` (nothing is written).
pub fn exercise_set(a: &ExerciseArgs) -> Result<(Vec<Exercise>, FileSet)> {
    let spec = spec_of(a)?;
    let exercises = generate(a.seed, a.count as usize, &spec).map_err(|e| anyhow::anyhow!(e))?;
    let mut set = FileSet::default();
    let names: Vec<&str> = spec.effects.iter().map(|e| e.name()).collect();
    let effects = if names.is_empty() { t!("index-directional-only") } else { names.join(", ") };
    let mut index = format!(
        "# {}\n\n{}\n\n",
        t!("index-title", seed = a.seed.to_string()),
        t!("index-intro", effects = effects, rules = &a.rules)
    );
    let mut printable = Vec::new();
    if a.worksheet {
        index.push_str(&worksheet_sheet(&mut set)?);
        for f in ["exercise-00.md", "exercise-00-key.md"] {
            let text = set.get(f).map(|b| String::from_utf8_lossy(b).into_owned()).unwrap_or_default();
            printable.push(text);
        }
    }
    for (i, ex) in exercises.iter().enumerate() {
        let stem = format!("exercise-{:02}", i + 1);
        let toml = format!("{stem}.toml");
        set.add(toml.clone(), ex.doc.to_toml()?);
        let sheet = format!("{}\n{}\n", sheet_markdown(ex), t!("sheet-scene-file", file = &toml));
        set.add(format!("{stem}.md"), sheet.clone());
        let key = answer_key(&ex.doc, &toml)?;
        set.add(format!("{stem}-key.md"), key.clone());
        printable.push(sheet);
        printable.push(key);
        let _ = writeln!(index, "- [{}]({stem}.md) ([{}]({stem}-key.md))", ex.doc.name, t!("answers"));
    }
    let _ = writeln!(index, "\n{}", t!("index-printable"));
    set.add("index.md", index);
    set.add("exercises.pdf", pdf(&printable)?);
    Ok((exercises, set))
}

/// Writes the exercises as one set ([`crate::atomic_write::write_set`]): the folder ends
/// with the new set whole, or as it was; returns them.
pub fn write_exercises(a: &ExerciseArgs) -> Result<Vec<Exercise>> {
    crate::atomic_write::check_folder_destination(&a.out)?;
    let (exercises, set) = exercise_set(a)?;
    crate::atomic_write::write_set(&a.out, &set, belongs_to_a_set)?;
    Ok(exercises)
}

/// Runs `phonglab exercise`.
pub fn run(a: &ExerciseArgs) -> Result<()> {
    let ex = write_exercises(a)?;
    let redraws: usize = ex.iter().map(|e| e.redraws).sum();
    eprintln!(
        "{}",
        t!(
            "exercises-written",
            count = ex.len() + a.worksheet as usize,
            out = a.out.display().to_string(),
            redraws = redraws
        )
    );
    Ok(())
}
