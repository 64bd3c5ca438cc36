//! What `phonglab exercise --format moodle-xml | gift` checks before anything is written:
//! the category's name, as Moodle reads and keeps it ([`check_category`]), and the file's
//! size and the memory it takes, against the memory budget ([`check_budget`]).

use anyhow::{Result, bail};

use phonglab_core::question::{Bank, Category};

use super::moodle_set::{Bundle, Format, exercise_bank};
use crate::t;

/// The most characters Moodle keeps in a category's name (`question_categories.name`, a
/// column of 255 characters).
pub const CATEGORY_MAX: usize = 255;

/// Refuses a category Moodle would not read back as one name: empty or only spaces (the
/// path would get an empty level, `top//exercise 1`), starting or ending with `/` (its
/// doubled `/` would run into the path's separators: `top////exercise 1`), or longer than
/// [`CATEGORY_MAX`] characters, or with a control character (a line break, a tab, an
/// escape).
pub fn check_category(name: &str) -> Result<()> {
    if name.trim().is_empty() {
        bail!(t!("err-category-blank"));
    }
    // A line break or another control character would be written into the category's
    // path as it is (`$course$/top/a\u{A}b`): Moodle's names are one line of text.
    if let Some(c) = name.chars().find(|c| c.is_control()) {
        bail!(t!("err-category-control", character = phonglab_core::escape::printable(&c.to_string())));
    }
    if name.starts_with('/') || name.ends_with('/') {
        bail!(t!("err-category-slash"));
    }
    let length = phonglab_core::escape::printable(name).chars().count();
    if length > CATEGORY_MAX {
        bail!(t!("err-category-long", length = length as i64, max = CATEGORY_MAX as i64));
    }
    Ok(())
}

/// How many exercises the estimate writes to measure one: the bank's first ones (fewer
/// where the bank has fewer), which the whole bank starts with.
pub const SAMPLE: usize = 32;

/// What phonglab holds while it writes, besides the file's text: the exercises and the
/// bank's questions, 2.2 to 2.5 times the bank written as Moodle XML (measured with
/// `/usr/bin/time -v` over levels 1 to 4, both formats, 100 to 10 000 exercises:
/// docs/performance.md, "A file for Moodle"), counted as 2.6 times the sample's mean, and
/// 5 % more for a sample's mean below the bank's (at level 4 an exercise's size varies by
/// 15 %, so the mean of 32 by under 3 %).
pub const HELD_PER_XML_BYTE: f64 = 2.6 * 1.05;

/// The process's fixed part: the code, the catalogues (40 MB measured, a debug build;
/// [`super::budget::PROCESS`]).
pub const FIXED: u64 = super::budget::PROCESS;

/// The estimated size of the file `b` asks for in `format`, and the memory writing it
/// takes, from a sample of its exercises each written alone ([`SAMPLE`]). The file: the
/// largest of them times the exercises asked for (`count × variants`), so never below
/// the file (an exercise written alone carries the file's header and a category; the
/// largest is at most 1.2 times the mean at level 4, 1.03 at levels 1 to 3). The memory:
/// the file, what the bank holds ([`HELD_PER_XML_BYTE`] times the sample's mean in
/// Moodle XML, times the exercises) and [`FIXED`].
pub fn estimate(b: &Bundle, format: Format) -> Result<(u64, u64)> {
    let total = (b.request.count * b.variants.max(1)) as u64;
    let mut sample = b.clone();
    sample.request.count = 1;
    sample.variants = (total as usize).min(SAMPLE);
    let bank = exercise_bank(&sample)?;
    let (mut largest, mut xml, mut written) = (0u64, 0u64, 0u64);
    for category in &bank.categories {
        for q in &category.questions {
            let alone = Bank { categories: vec![Category { path: category.path.clone(), questions: vec![q.clone()] }] };
            largest = largest.max(format.write(&alone).len() as u64);
            xml += Format::MoodleXml.write(&alone).len() as u64;
            written += 1;
        }
    }
    let file = largest.saturating_mul(total);
    let held = xml as f64 / written.max(1) as f64 * HELD_PER_XML_BYTE * total as f64;
    Ok((file, file.saturating_add(held as u64).saturating_add(FIXED)))
}

/// Refuses the file `b` asks for when writing it would take more than the memory budget
/// ([`super::budget`]), before any exercise but the sample is made; the message names the
/// exercises, the file's size and the memory it needs.
pub fn check_budget(b: &Bundle, format: Format) -> Result<()> {
    let (file, memory) = estimate(b, format)?;
    let what = t!(
        "budget-what-moodle",
        count = phonglab_core::locale::grouped((b.request.count * b.variants.max(1)) as u64),
        size = phonglab_core::mesh::obj::describe_bytes(file)
    );
    super::budget::check(&what, memory).map_err(anyhow::Error::msg)
}
