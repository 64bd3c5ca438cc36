//! What `phonglab exercise --format moodle-xml | gift` checks before anything is written:
//! the category's name, as Moodle reads and keeps it ([`check_category`]), and the file's
//! size and the memory it takes, against the memory budget ([`check_budget`]).

use anyhow::{Result, bail};

use super::moodle_set::{Bundle, Format, exercise_bank};
use crate::t;

/// The most characters Moodle keeps in a category's name (`question_categories.name`, a
/// column of 255 characters).
pub const CATEGORY_MAX: usize = 255;

/// Refuses a category Moodle would not read back as one name: empty or only spaces (the
/// path would get an empty level, `top//exercise 1`), starting or ending with `/` (its
/// doubled `/` would run into the path's separators: `top////exercise 1`), or longer than
/// [`CATEGORY_MAX`] characters as written (a control character is written visibly, as
/// `\u{1B}`).
pub fn check_category(name: &str) -> Result<()> {
    if name.trim().is_empty() {
        bail!(t!("err-category-blank"));
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

/// How many exercises the estimate writes to measure one: the first exercise's first
/// variants (fewer where the bank has fewer).
const SAMPLE: usize = 8;

/// How much larger than the sample's mean the whole file's exercises may be, on average:
/// measured at level 4, `--count 20 --variants 20`, the sample's mean times the exercises
/// came within 4 % of the file (Moodle XML 10 436 765 bytes, GIFT 82 246 236); 1.5 leaves
/// room for the exercises with more lights.
const MARGIN: f64 = 1.5;

/// While it writes, phonglab holds the exercises, the bank's questions and the file's
/// text: measured (`/usr/bin/time -f %M`, the same two files), a peak of 64 MB for the
/// Moodle XML and 136 MB for the GIFT, the process's fixed part included: under twice the
/// file's size, with 4 KiB an exercise counted besides.
const HELD_PER_FILE_BYTE: u64 = 2;
const HELD_PER_EXERCISE: u64 = 4 << 10;

/// The estimated size of the file `b` asks for in `format`, and the memory writing it
/// takes: the mean of a sample of its exercises, written, times the exercises asked for
/// (`count × variants`), with a margin.
pub fn estimate(b: &Bundle, format: Format) -> Result<(u64, u64)> {
    let total = b.request.count * b.variants.max(1);
    let mut sample = b.clone();
    sample.request.count = 1;
    sample.variants = total.min(SAMPLE);
    let bytes = format.write(&exercise_bank(&sample)?).len() as f64;
    let file = (bytes / sample.variants as f64 * MARGIN * total as f64) as u64;
    Ok((file, file.saturating_mul(HELD_PER_FILE_BYTE) + total as u64 * HELD_PER_EXERCISE))
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
