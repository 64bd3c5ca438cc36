//! Exercise sets (what `phonglab exercise` and the window's Export write): exercise sheets in the worksheet's style, each with its scene file
//! and its answer key (the worked calculation `phonglab explain` prints for that file).
//!
//! For exercise k (numbered from 1; 0 is the worksheet itself, with `--worksheet`) it
//! writes `exercise-KK.md` (the sheet), `exercise-KK-key.md` (the answers) and
//! `exercise-KK.toml` (the scene, which the app and every command open), `index.md`
//! listing them, `sheets.pdf` (to hand out: each exercise starts a page and takes an even
//! number of them, two for levels 1 to 3, so printed on both sides it is one sheet of
//! paper; the lines for the class, the name and the date; each page's footer names its
//! exercise and counts its pages) and `keys.pdf` (for the teacher), typeset by [`super::sheet_pdf`]
//! in the chosen language. The same seed gives the same files, byte for byte.
//! The set is written as one: a folder holds one whole set, never parts of two.

use std::fmt::Write as _;

use anyhow::{Context as _, Result};
use phonglab_core::exercise::{Exercise, Numbering, Spec, generate, sheet_markdown_numbered};
use phonglab_core::explain::{Side, explain};
use phonglab_core::vocabulary::Quantity as Q;
use phonglab_core::{Document, Engine};

use super::file_set::FileSet;
use super::sheet_pdf::{Block, Pages, pdf};
use crate::t;

/// What a set is made of: the seed and the count, the effects and rules ([`Spec`]), the
/// rules' name as the index shows it, and whether exercise 0, the worksheet itself, comes
/// first.
#[derive(Clone, Debug)]
pub struct Request {
    /// The random seed: the same seed gives the same files, byte for byte.
    pub seed: u64,
    /// How many exercises.
    pub count: usize,
    /// The effects the exercises have and the rules their answers follow.
    pub spec: Spec,
    /// Exercise 0: the worksheet's five modelviews on one sheet.
    pub worksheet: bool,
    /// Exam exercises ([`phonglab_core::exam`]): numbers for a pencil, "no calculator" at
    /// the top of each sheet, and a key with each value exact and rounded to four
    /// significant digits.
    pub exam: bool,
}

/// The answer key: what `phonglab explain FILE` prints (and `--back` with two-sided
/// lighting), in a code block.
pub fn answer_key(doc: &Document, file: &str) -> Result<String> {
    let name = phonglab_core::escape::markdown::text(&doc.name);
    Ok(format!("# {}\n\n{}", t!("key-title", name = name), answer_key_body(doc, file)?))
}

/// The worked calculation of `doc`'s vertex in f64: the front side, and the back one too
/// with two-sided lighting. What every key, in Markdown or in the PDF, shows.
fn explained_sides(doc: &Document) -> Result<Vec<phonglab_core::explain::Explanation>> {
    let lit = Engine::<f64>::light_scene_vertex(&doc.scene)?;
    let sides: &[Side] = if doc.scene.light_model.two_sided { &[Side::Front, Side::Back] } else { &[Side::Front] };
    Ok(sides.iter().map(|&side| explain(&doc.scene, &lit, side)).collect())
}

/// The answer key without its title.
fn answer_key_body(doc: &Document, file: &str) -> Result<String> {
    let mut o = format!("{}\n\n", t!("key-intro", file = file));
    for ex in explained_sides(doc)? {
        // Inside a code block: one printable line.
        let name = phonglab_core::escape::terminal::text(&doc.name);
        let _ = writeln!(o, "```\n{}\n{}```\n", t!("worked-calculation-of", name = name), ex.to_handout_text(8));
    }
    Ok(o)
}

/// The files for Moodle's question bank ([`super::moodle_set`]): Moodle XML and GIFT.
pub const MOODLE_FILES: [&str; 2] = ["questions.xml", "questions.gift.txt"];

/// Is `name` a file of an exercise set or of a set of mistakes (`--level 5`), so that a
/// new set in the same folder replaces it? A Moodle file ([`MOODLE_FILES`]) is not: sheets
/// leave the questions alone, and a Moodle file replaces only itself.
pub fn belongs_to_a_set(name: &str) -> bool {
    if is_mistake_file(name) {
        return true;
    }
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
        // exercises.pdf: what a set held before the sheets and keys were apart.
        None => ["sheets.pdf", "keys.pdf", "exercises.pdf"].contains(&name),
    }
}

/// Is `name` a file of a set of mistakes ([`super::misconception_set`]: `wrong-KK.md`, `wrong-KK-key.md`, `wrong-KK.png`,
/// `wrong-KK-right.png`)?
fn is_mistake_file(name: &str) -> bool {
    let Some(rest) = name.strip_prefix("wrong-") else { return false };
    let stem = rest.strip_suffix(".md").or_else(|| rest.strip_suffix(".png"));
    let Some(stem) = stem else { return false };
    let number = stem.strip_suffix("-key").or_else(|| stem.strip_suffix("-right")).unwrap_or(stem);
    number.len() == 2 && number.bytes().all(|b| b.is_ascii_digit())
}

/// The worksheet as exercise 0: its five modelviews, one sheet, with the values it prints.
fn worksheet_sheet(set: &mut FileSet, sheets: &mut Vec<Block>, keys: &mut Vec<Block>) -> Result<String> {
    let mut sheet = format!("# {}\n\n{}\n\n", t!("exercise-zero-title"), t!("exercise-zero-intro"));
    let mut key = format!("# {}\n\n", t!("key-title", name = t!("exercise-zero-name")));
    sheets.extend([
        Block::Section(t!("exercise-zero-title")),
        Block::Title(t!("exercise-zero-title")),
        Block::WriteOn(vec![t!("sheet-class"), t!("sheet-name"), t!("sheet-date")]),
        Block::Text(t!("exercise-zero-intro").replace('`', "")),
    ]);
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
        for r in matrix_components(&rows) {
            let _ = writeln!(sheet, "[{}]", r.join(" "));
        }
        let _ = writeln!(sheet, "```\n");
        sheets.push(Block::Heading(format!("mview{k} ({file})")));
        sheets.push(Block::Matrix { name: format!("mview{k}"), rows: matrix_components(&rows) });
        let _ = write!(key, "## mview{k}\n\n{}", answer_key_body(&doc, &file)?);
        keys.extend(key_blocks(&doc, &file)?.into_iter().skip(1));
    }
    set.add("exercise-00.md", sheet);
    set.add("exercise-00-key.md", key);
    Ok(format!("- [{}](exercise-00.md) ([{}](exercise-00-key.md))\n", t!("exercise-zero-title"), t!("answers")))
}

/// Several quantities given on one line: `[atC atLin atQuad]`.
fn names<const N: usize>(qs: [Q; N]) -> String {
    format!("[{}]", qs.map(Q::name).join(" "))
}

/// A vector's components for people (8 significant digits, the locale's decimal mark), as
/// printed on a handout (`explain::printed_components`: no 6.123234e-17 where 0 belongs).
fn components(v: &[f64]) -> Vec<String> {
    phonglab_core::explain::printed_components(v, 8).iter().map(|x| crate::locale::num(*x, 8)).collect()
}

/// A matrix's rows for people, as printed on a handout: an entry below the whole matrix's
/// last printed digit is 0.
fn matrix_components(rows: &[[f64; 4]; 4]) -> Vec<Vec<String>> {
    let printed = phonglab_core::explain::printed_components(rows.as_flattened(), 8);
    printed.chunks(4).map(|r| r.iter().map(|x| crate::locale::num(*x, 8)).collect()).collect()
}

/// A colour as the worksheet writes it, `[r g b 0]`.
fn colour(c: glam::DVec4) -> Vec<String> {
    components(&[c.x, c.y, c.z, 0.0])
}

/// An exercise's sheet, to hand out: the class, name and date lines, the givens set as
/// vectors and a matrix, and a box for each step, sized for its value; then the scene
/// file's name, which an exam's sheet (`toml` = `None`) leaves off, and whose steps it
/// numbers 1, 2, 3 … ([`Numbering::Own`]), as its key does.
fn sheet_blocks(ex: &Exercise, toml: Option<&str>) -> Vec<Block> {
    use Block::{Answer, Heading, Matrix, Text, Title, Vector, WriteOn};
    let s = &ex.doc.scene;
    let vector = |name: &str, values: Vec<String>| Vector { name: name.into(), values, note: String::new() };
    let rules = phonglab_core::exercise::rules_in_words(s.rules.set);
    let mut b = vec![
        Title(ex.doc.name.clone()),
        WriteOn(vec![t!("sheet-class"), t!("sheet-name"), t!("sheet-date")]),
        Text(format!("{} {}", t!("sheet-compute", rules = rules), t!("sheet-colours"))),
    ];
    if s.light_model.two_sided {
        // Which side to compute, as the Markdown sheet and the Moodle question say.
        b.push(Text(t!("moodle-front-side")));
    }
    b.extend([
        Heading(t!("sheet-vertex")),
        vector(Q::VertexPos.name(), components(&s.vertex.position.to_array())),
        vector(Q::VertexNormal.name(), components(&s.vertex.normal.extend(0.0).to_array())),
        Heading(t!("sheet-modelview")),
        Text(ex.modelview.clone()),
        Matrix {
            name: "mview".into(),
            rows: matrix_components(&phonglab_core::transform::mat4_rows(&s.eye_from_world)),
        },
    ]);
    for (i, l) in s.lights.iter().enumerate() {
        b.push(Heading(t!("light-tab", index = i.to_string())));
        let what = if l.position.w == 0.0 { t!("sheet-direction") } else { t!("sheet-position") };
        b.push(Vector {
            name: Q::LightPos.name().into(),
            values: components(&l.position.to_array()),
            note: t!("sheet-light-world", what = what),
        });
        b.push(vector(Q::LightAmbient.name(), colour(l.ambient)));
        b.push(vector(Q::LightDiffuse.name(), colour(l.diffuse)));
        b.push(vector(Q::LightSpecular.name(), colour(l.specular)));
        if l.position.w != 0.0 {
            b.push(vector(&names([Q::AttConstant, Q::AttLinear, Q::AttQuadratic]), components(&l.attenuation)));
        }
        if l.is_spot() {
            b.push(Vector {
                name: Q::SpotDirection.name().into(),
                values: components(&l.spot_direction.extend(0.0).to_array()),
                note: t!("sheet-light-world", what = t!("sheet-direction")),
            });
            b.push(vector(&names([Q::SpotCutoff, Q::SpotExponent]), components(&[l.spot_cutoff, l.spot_exponent])));
        }
    }
    let m = &s.material;
    b.push(Heading(t!("sheet-material", name = phonglab_core::materials::display_name(&ex.material))));
    b.push(vector(Q::MatAmbient.name(), colour(m.ambient)));
    b.push(vector(Q::MatDiffuse.name(), colour(m.diffuse)));
    b.push(vector(Q::MatSpecular.name(), colour(m.specular)));
    b.push(vector(Q::Shininess.name(), components(&[m.shininess])));
    let lm = &s.light_model;
    let yes_no = |on: bool| if on { t!("yes") } else { t!("no") };
    b.push(Heading(t!("sheet-light-model")));
    b.push(Text(format!(
        "{}: {}. {}: {}.",
        t!("local-viewer"),
        yes_no(lm.local_viewer),
        t!("two-sided"),
        yes_no(lm.two_sided)
    )));
    if s.rules.scene_ambient() {
        b.push(vector(&t!("scene-ambient"), colour(lm.ambient)));
    }
    b.push(Heading(t!("sheet-compute-heading")));
    let asked = (0..ex.key.steps.len()).filter(|k| phonglab_core::quiz::asked(s, &ex.key, *k));
    // Numbered as the key numbers them: the calculation's own step numbers; an exam's 1, 2, 3 ….
    for (row, k) in asked.enumerate() {
        let st = &ex.key.steps[k];
        let cells = st.value.as_ref().map_or(1, Vec::len);
        let number = if toml.is_some() { k + 1 } else { row + 1 };
        b.push(Answer { label: format!("{number}. {}", st.title), name: st.name.clone(), cells });
    }
    if let Some(toml) = toml {
        b.push(Text(t!("sheet-scene-file", file = toml).replace('`', "")));
    }
    b
}

/// An exercise's key, for the teacher: every step's formula and value, as explain prints
/// them (both sides with two-sided lighting).
fn key_blocks(doc: &Document, file: &str) -> Result<Vec<Block>> {
    use Block::{Heading, KeyStep, Text, Title};
    let mut b = vec![Title(t!("key-title", name = &doc.name)), Text(t!("key-intro", file = file).replace('`', ""))];
    for ex in explained_sides(doc)? {
        b.push(Heading(ex.heading.clone()));
        for (k, st) in ex.steps.iter().enumerate() {
            let value = match &st.value {
                Some(v) => crate::locale::decimal(&phonglab_core::explain::fmt_printed(v, 8)),
                None => t!("not-applicable"),
            };
            b.push(KeyStep {
                label: format!("{}. {}", k + 1, st.title),
                formula: st.formula.clone(),
                line: format!("{} = {value}", st.name),
            });
        }
    }
    Ok(b)
}

/// The exercises and the files of their set: the sheets, keys and scene files, `index.md`
/// and the two PDFs, `sheets.pdf` and `keys.pdf` (nothing is written).
pub fn exercise_set(a: &Request) -> Result<(Vec<Exercise>, FileSet)> {
    let spec = &a.spec;
    let exercises =
        if a.exam { phonglab_core::exam::generate(a.seed, a.count, spec) } else { generate(a.seed, a.count, spec) };
    let exercises = exercises.map_err(|e| anyhow::anyhow!(e))?;
    let mut set = FileSet::default();
    // In the reader's words: the effects' and the rules' names, not the command line's.
    let names: Vec<String> = spec.effects.iter().map(|e| e.label()).collect();
    let effects = if names.is_empty() { t!("index-directional-only") } else { names.join(", ") };
    let rules = phonglab_core::exercise::rules_in_words(spec.rules.set);
    let mut index = format!(
        "# {}\n\n{}\n\n",
        t!("index-title", seed = a.seed.to_string()),
        t!("index-intro", effects = effects, rules = rules)
    );
    // To hand out, each exercise on its own paper; and the keys, for the teacher.
    let (mut sheets, mut keys) = (Vec::new(), Vec::new());
    if a.worksheet {
        let title = t!("key-title", name = t!("exercise-zero-name"));
        keys.extend([Block::Section(title.clone()), Block::Title(title)]);
        index.push_str(&worksheet_sheet(&mut set, &mut sheets, &mut keys)?);
    }
    for (i, ex) in exercises.iter().enumerate() {
        let stem = format!("exercise-{}", padded(i + 1, exercises.len()));
        let toml = format!("{stem}.toml");
        set.add(toml.clone(), ex.doc.to_toml()?);
        let banner = if a.exam {
            format!("**{}** {}\n\n", t!("exam-no-calculator"), exam_instructions())
        } else {
            String::new()
        };
        let handed_out = handed_out(ex, i + 1, a.exam);
        // An exam's sheet numbers its steps 1, 2, 3 … (as its key does) and leaves the scene
        // file, which holds the seed, off.
        let sheet = if a.exam {
            format!("{banner}{}", sheet_markdown_numbered(&handed_out, Numbering::Own))
        } else {
            let file = t!("sheet-scene-file", file = &toml);
            format!("{}\n{file}\n", sheet_markdown_numbered(&handed_out, Numbering::Key))
        };
        set.add(format!("{stem}.md"), sheet.clone());
        let mut key = answer_key(&ex.doc, &toml)?;
        sheets.push(Block::Section(handed_out.doc.name.clone()));
        if a.exam {
            // At the top of the page, before the title.
            sheets.push(Block::Heading(t!("exam-no-calculator")));
            sheets.push(Block::Text(exam_instructions()));
            key.push_str(&super::exam_key::markdown(ex));
        }
        set.add(format!("{stem}-key.md"), key);
        sheets.extend(sheet_blocks(&handed_out, (!a.exam).then_some(toml.as_str())));
        keys.push(Block::Section(t!("key-title", name = &ex.doc.name)));
        let mut key_pages = key_blocks(&ex.doc, &toml)?;
        if a.exam {
            // After the title and the key's introduction, before the worked calculation.
            let at = key_pages.len().min(2);
            key_pages.splice(at..at, super::exam_key::blocks(ex));
        }
        keys.extend(key_pages);
        let name = phonglab_core::escape::markdown::text(&ex.doc.name);
        let _ = writeln!(index, "- [{name}]({stem}.md) ([{}]({stem}-key.md))", t!("answers"));
    }
    let _ = writeln!(index, "\n{}", t!("index-printable"));
    set.add("index.md", index);
    // Sheets are printed on both sides and handed out: each exercise its own paper.
    set.add("sheets.pdf", pdf(&sheets, Pages::Duplex)?);
    set.add("keys.pdf", pdf(&keys, Pages::Plain)?);
    Ok((exercises, set))
}

/// `number` as the set's file names write it, padded with zeros to the width of `largest`,
/// the set's last number, and to two digits at least (`07` of 9 or 99, `007` of 300), so
/// that a file browser lists `exercise-099` before `exercise-100`.
pub fn padded(number: usize, largest: usize) -> String {
    let width = largest.max(number).to_string().len().max(2);
    format!("{number:0width$}")
}

/// Exercise `number` as its sheet shows it to students: an exam's without its seed, which
/// reproduces the key ("exam exercise 3"); the key, the scene file and the index keep it.
fn handed_out(ex: &Exercise, number: usize, exam: bool) -> std::borrow::Cow<'_, Exercise> {
    if !exam {
        return std::borrow::Cow::Borrowed(ex);
    }
    let mut sheet = ex.clone();
    sheet.doc.name = t!("exam-sheet-name", number = number as i64);
    std::borrow::Cow::Owned(sheet)
}

/// Writes the exercises as one set into the folder `dir` ([`super::file_set::write_set`]):
/// the folder ends with the new set whole, or as it was; returns them, and what was left
/// as it is in the folder (see [`super::file_set::recover`]). A file of the set that
/// phonglab did not write there as it is now (a key edited since) refuses the set
/// ([`refuse_foreign`]). The folder's lock is taken before the set is made and held
/// through the check and the write: a second run into the folder waits for this one, then
/// sees the folder as this one left it.
pub fn write(dir: &std::path::Path, a: &Request) -> Result<(Vec<Exercise>, Vec<String>)> {
    check_budget(a)?;
    super::atomic_write::check_folder_destination(dir)?;
    let held = super::file_set::hold_folder(dir)?;
    let (exercises, set) = exercise_set(a)?;
    refuse_foreign(dir, &set)?;
    let notices = super::file_set::write_set_held(&held, &set, belongs_to_a_set)?;
    Ok((exercises, notices))
}

/// How many exercises the estimate of a set's size makes (the request's first ones).
const SAMPLE: usize = 4;

/// While it makes a set, phonglab holds all its files (sheets, keys, scene files, the two
/// PDFs) and what made them. Measured (`VmPeak` in `/proc`, the address space `ulimit -v`
/// limits; debug build, level 4): 95 MB for one exercise, 100 MB for 40, so about 125 KB
/// an exercise for 34 KB of files: under 4 times the files' bytes.
const HELD_PER_FILE_BYTE: u64 = 4;

/// What a set of at most [`SAMPLE`] exercises is counted a sheet, besides the process's
/// own part, without making a sample: the PDFs' fonts and pages (one exercise's files are
/// 0.3 to 0.5 MB, a set of four 1.5 MB at level 4).
const SMALL_SET_PER_EXERCISE: u64 = 2 << 20;

/// Refuses, in words and before anything is written, a set whose making would take more
/// than the memory budget ([`super::budget`]; under `ulimit -v`, what the limit leaves):
/// the files of a sample of four exercises are made, and their bytes (the PDFs' fonts
/// counted in each, a margin) scaled to the count asked for, times
/// `HELD_PER_FILE_BYTE`, and the process's own part ([`super::budget::PROCESS`]). A set
/// no larger than the sample is not sampled (making it is as cheap as the estimate): it
/// is counted `SMALL_SET_PER_EXERCISE` (2 MiB) an exercise.
pub fn check_budget(a: &Request) -> Result<()> {
    let (files, held) = if a.count <= SAMPLE {
        let held = (a.count + a.worksheet as usize) as u64 * SMALL_SET_PER_EXERCISE;
        (held / HELD_PER_FILE_BYTE, held)
    } else {
        let sample = Request { count: SAMPLE, worksheet: false, ..a.clone() };
        let (_, set) = exercise_set(&sample)?;
        let bytes: u64 = set.files.iter().map(|(_, b)| b.len() as u64).sum();
        let files = bytes / SAMPLE as u64 * a.count as u64;
        (files, files.saturating_mul(HELD_PER_FILE_BYTE))
    };
    let what = t!(
        "budget-what-sheets",
        count = a.count,
        shown = phonglab_core::locale::grouped(a.count as u64),
        size = phonglab_core::mesh::obj::describe_bytes(files)
    );
    super::budget::check(&what, held.saturating_add(super::budget::PROCESS)).map_err(anyhow::Error::msg)
}

/// Refuses to write `set` into `dir` over a file phonglab did not write there as it is now
/// ([`super::file_set::foreign_file`]: a key the teacher edited since), which it keeps.
pub fn refuse_foreign(dir: &std::path::Path, set: &FileSet) -> Result<()> {
    super::set_journal::check_records(dir)?;
    use super::file_set::Foreign;
    match super::file_set::foreign_file(dir, set) {
        Some(Foreign::NotOurs(path)) => anyhow::bail!(t!("set-not-ours", path = super::reasons::shown(&path))),
        Some(Foreign::Unreadable(path, e)) => anyhow::bail!(t!(
            "read-cannot",
            path = super::reasons::shown(&path),
            reason = phonglab_core::files::reasons::io_reason(&e)
        )),
        None => Ok(()),
    }
}

/// What an exam sheet says under "No calculator": work exactly, round what is written
/// down to four significant digits (a paragraph, wrapped on the PDF's page).
fn exam_instructions() -> String {
    let digits = phonglab_core::moodle::EXAM_DIGITS.to_string();
    format!("{} {}", t!("exam-by-hand"), t!("moodle-digits-exam", digits = digits))
}
