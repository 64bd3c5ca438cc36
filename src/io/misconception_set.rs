//! "What is wrong with this picture?" as an exercise set (`phonglab exercise --level 5`):
//! for each mistake ([`phonglab_core::misconception`]), `wrong-KK.md` (the sheet: the
//! picture drawn right and the one with the mistake, and the seven causes with their
//! formulas to pick from), `wrong-KK-key.md` (the cause, why, and the probe's numbers at the
//! pixel where the pictures differ most), the two pictures as `wrong-KK-right.png` and
//! `wrong-KK.png`, `index.md`, and `sheets.pdf` and `keys.pdf` with the pictures printed.
//! The seed orders the mistakes; the same seed gives the same files.

use std::fmt::Write as _;
use std::sync::Arc;

use anyhow::Result;
use phonglab_core::misconception::{self, Misconception};

use super::file_set::FileSet;
use super::sheet_pdf::{Block, Figure, Pages, pdf};
use crate::t;

/// The pictures' side in pixels.
pub(crate) const PX: usize = 192;

/// The mistakes in the seed's order, `count` of them (at most seven).
pub(crate) fn chosen(seed: u64, count: usize) -> Vec<Misconception> {
    let mut all = Misconception::ALL.to_vec();
    let mut s = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    for i in (1..all.len()).rev() {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        all.swap(i, (s % (i as u64 + 1)) as usize);
    }
    all.truncate(count.clamp(1, all.len()));
    all
}

/// The seven causes with their mistaken formulas, to pick from.
fn choices() -> Vec<String> {
    Misconception::ALL
        .iter()
        .enumerate()
        .map(|(i, m)| format!("{}. {}", (b'A' + i as u8) as char, m.choice()))
        .collect()
}

/// What making `count` pictures with one mistake each (the set, or its questions for
/// Moodle) holds at its peak, besides the process's own part ([`super::budget::PROCESS`]):
/// per picture its two drawings, their PNGs and the PDFs' copies. Measured
/// (`/usr/bin/time -v`, debug build): the sheets 43 MB for one picture, 63 MB for seven
/// (3.3 MB a picture more); GIFT 35 and 54 MB. Counted: 4 MiB a picture.
pub const PICTURE_BYTES: u64 = 4 << 20;

/// Refuses, in words and before anything is made, `count` pictures with one mistake
/// (at most the seven mistakes) past the memory budget ([`super::budget`]).
pub fn check_budget(count: usize) -> Result<()> {
    let pictures = count.clamp(1, Misconception::ALL.len()) as u64;
    let what = t!("budget-what-wrong", count = pictures as i64);
    let needed = super::budget::PROCESS + pictures * PICTURE_BYTES;
    super::budget::check(&what, needed).map_err(anyhow::Error::msg)
}

/// The set's files (nothing is written).
pub fn misconception_set(seed: u64, count: usize) -> Result<FileSet> {
    let mut set = FileSet::default();
    let mut index = format!("# {}\n\n{}\n\n", t!("wrong-title"), t!("wrong-intro"));
    let (mut sheets, mut keys) = (Vec::new(), Vec::new());
    for (k, kind) in chosen(seed, count).into_iter().enumerate() {
        let stem = format!("wrong-{:02}", k + 1);
        let case = misconception::case(kind);
        let drawn = case.draw(PX).map_err(anyhow::Error::msg)?;
        set.add(format!("{stem}-right.png"), super::image::encode_png(PX, PX, &drawn.correct)?);
        set.add(format!("{stem}.png"), super::image::encode_png(PX, PX, &drawn.bugged)?);
        let title = t!("wrong-sheet-title", number = (k + 1) as i64);
        let pictures = vec![
            Figure { caption: t!("wrong-drawn-right"), px: PX, rgba: Arc::new(drawn.correct.clone()) },
            Figure { caption: t!("wrong-drawn-wrong"), px: PX, rgba: Arc::new(drawn.bugged.clone()) },
        ];
        // The sheet.
        let mut sheet = format!(
            "# {title}\n\n![{}]({stem}-right.png) ![{}]({stem}.png)\n\n{}\n\n",
            t!("wrong-drawn-right"),
            t!("wrong-drawn-wrong"),
            t!("wrong-question")
        );
        for c in choices() {
            let _ = writeln!(sheet, "- [ ] {c}");
        }
        set.add(format!("{stem}.md"), sheet);
        sheets.extend([Block::Section(title.clone()), Block::Title(title.clone()), Block::Figures(pictures.clone())]);
        sheets.push(Block::Text(t!("wrong-question")));
        sheets.extend(choices().into_iter().map(Block::Tick));
        // Room to say what in the picture shows it.
        sheets.push(Block::Ruled(4));
        sheets.push(Block::WriteOn(vec![t!("sheet-class"), t!("sheet-name"), t!("sheet-date")]));
        // The key.
        let lines = misconception::key_lines(&case, &drawn);
        let key_title = t!("key-title", name = &title);
        let mut key = format!("# {key_title}\n\n");
        for l in &lines {
            let _ = writeln!(key, "{}\n", phonglab_core::escape::markdown::text(l));
        }
        set.add(format!("{stem}-key.md"), key);
        keys.extend([Block::Section(key_title.clone()), Block::Title(key_title), Block::Figures(pictures)]);
        keys.extend(lines.into_iter().map(Block::Text));
        let _ = writeln!(index, "- [{title}]({stem}.md) ([{}]({stem}-key.md))", t!("answers"));
    }
    // Each sheet is one page and is not padded (every other page was blank): printed on
    // one side, each exercise is its own paper.
    let _ = writeln!(index, "\n{}", t!("index-printable-one-sided"));
    set.add("index.md", index);
    set.add("sheets.pdf", pdf(&sheets, Pages::Plain)?);
    set.add("keys.pdf", pdf(&keys, Pages::Plain)?);
    Ok(set)
}

/// Writes the set into the folder `dir`, whole or not at all (as the other sets are): how
/// many, and what was left as it is in the folder (see [`super::file_set::recover`]).
pub fn write(dir: &std::path::Path, seed: u64, count: usize) -> Result<(usize, Vec<String>)> {
    check_budget(count)?;
    super::atomic_write::check_folder_destination(dir)?;
    // Held from before the set is made to its end: see `exercise_set::write`.
    let held = super::file_set::hold_folder(dir)?;
    let set = misconception_set(seed, count)?;
    super::exercise_set::refuse_foreign(dir, &set)?;
    let notices = super::file_set::write_set_held(&held, &set, super::exercise_set::belongs_to_a_set)?;
    Ok((count.clamp(1, Misconception::ALL.len()), notices))
}
