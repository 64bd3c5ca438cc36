//! The memory budget: a command that allocates in proportion to a size the user gives (a
//! picture's size, a mesh's triangles) estimates the bytes first, and refuses past the
//! budget, saying the estimate and the option that raises it, instead of failing half-way
//! or exhausting the machine.
//!
//! The budget is `--memory-budget SIZE` where given (`512M`, `8G`, `1.5GiB`, or bytes),
//! else the smaller of half the memory the system says is available at the start
//! ([`crate::platform::os::available_memory`]) and half the address space left under the
//! process's limit (`ulimit -v`: [`crate::platform::os::address_space_limit`]), else 4 GiB. The core's OBJ reader gets the
//! same budget ([`phonglab_core::mesh::obj::set_memory_budget`]).
//!
//! The estimates are upper bounds of what phonglab itself allocates, from its arrays'
//! sizes (each named below), not of the process's fixed part (the code, the fonts: tens of
//! megabytes).

use std::sync::atomic::{AtomicU64, Ordering};

use phonglab_core::mesh::obj::describe_bytes;

use crate::t;

/// The budget in bytes, once set (0: not set yet).
static BUDGET: AtomicU64 = AtomicU64::new(0);

/// Where the budget came from, for the message: 0 the memory available, 1
/// `--memory-budget`, 2 the address-space limit (`ulimit -v`), 3 `--memory-budget` given
/// as a number without a unit (bytes: `90` meant for 90 MiB is 90 bytes).
static FROM: AtomicU64 = AtomicU64::new(0);

/// The process's own part, besides what a command allocates for what it is asked: the
/// code, the catalogues, the fonts. `phonglab --version` peaks at 27 MB resident (debug
/// build, `/usr/bin/time -v`); a command that writes files, at up to 40 MB before its
/// first exercise. Every estimate that says "never below" what a run takes counts it.
/// 2026-11-29: `--version` 28.7 MB, three pictures with one mistake each (level 5) 61.5 MB
/// against the 60 MiB (62.9 MB) counted with 48 MiB here — the test that holds the estimate
/// to the peak failed once at 63.8 MB —, so 52 MiB.
pub const PROCESS: u64 = 52 << 20;

/// When the system does not say how much memory is available.
const FALLBACK: u64 = 4 << 30;

/// Sets the budget: `asked` (`--memory-budget`) or the default, for this process and for
/// the core's OBJ reader. Refuses, in words, a budget larger than the address space the
/// process's limit (`ulimit -v`) still leaves: past the limit an
/// allocation aborts the process, so such a budget would let a run start that cannot end.
pub fn set(asked: Option<Asked>) -> Result<(), String> {
    use crate::platform::os;
    if let Some(Asked { bytes: asked, .. }) = asked
        && let Some(room) = over_the_limit(asked, os::address_space_limit(), os::address_space_in_use())
    {
        return Err(t!("budget-over-limit", budget = describe_bytes(asked), room = describe_bytes(room)));
    }
    let (bytes, from) = asked.map_or_else(default_budget, |a| (a.bytes, if a.bare { 3 } else { 1 }));
    BUDGET.store(bytes, Ordering::Relaxed);
    FROM.store(from, Ordering::Relaxed);
    phonglab_core::mesh::obj::set_memory_budget(bytes);
    Ok(())
}

/// The address space left under the process's `limit` (`ulimit -v`) once what it takes
/// (`in_use`) is counted, when a budget of `asked` bytes is more than that; `None` when it
/// fits, or no limit is set.
fn over_the_limit(asked: u64, limit: Option<u64>, in_use: Option<u64>) -> Option<u64> {
    let room = limit?.saturating_sub(in_use.unwrap_or(0));
    (asked > room).then_some(room)
}

/// The default budget, and where it came from (1: `--memory-budget`, 0: the memory
/// available, 2: the address-space limit): [`budget_of`] the system's numbers now.
fn default_budget() -> (u64, u64) {
    use crate::platform::os;
    budget_of(os::available_memory(), os::address_space_limit(), os::address_space_in_use())
}

/// The smaller of half the memory `available` and half the address space left under the
/// process's `limit` (`ulimit -v`) once what it takes (`in_use`) is counted, or
/// [`FALLBACK`] where the system says neither, with where it came from (0: the memory, 2:
/// the limit). Half of each: an allocation that grows can hold its old block and its new
/// one at once, and the allocator reserves more address space than it fills.
fn budget_of(available: Option<u64>, limit: Option<u64>, in_use: Option<u64>) -> (u64, u64) {
    let memory = available.map(|a| a / 2);
    let room = limit.map(|l| l.saturating_sub(in_use.unwrap_or(0)) / 2);
    match (memory, room) {
        (Some(m), Some(r)) if r < m => (r, 2),
        (None, Some(r)) => (r, 2),
        (Some(m), _) => (m, 0),
        (None, None) => (FALLBACK, 0),
    }
}

/// The budget in bytes (the default until [`set`] is called).
pub fn bytes() -> u64 {
    from_and_bytes().1
}

/// Where the budget came from (see [`FROM`]) and its bytes.
fn from_and_bytes() -> (u64, u64) {
    match BUDGET.load(Ordering::Relaxed) {
        0 => {
            let (bytes, from) = default_budget();
            (from, bytes)
        }
        b => (FROM.load(Ordering::Relaxed), b),
    }
}

/// Refuses `what` (in words, in the user's language) when its estimate `needed` is over
/// the budget; the message gives both and how to raise the budget.
pub fn check(what: &str, needed: u64) -> Result<(), String> {
    let (from, budget) = from_and_bytes();
    if needed <= budget {
        return Ok(());
    }
    let from = match from {
        1 => t!("budget-from-option"),
        3 => t!("budget-from-option-bare", number = budget.to_string()),
        2 => t!("budget-from-limit"),
        _ => t!("budget-from-system"),
    };
    Err(t!(
        "budget-over",
        what = what,
        needed = describe_bytes(needed),
        budget = describe_bytes(budget),
        from = from,
        suggest = suggested_budget(needed)
    ))
}

/// A `--memory-budget` that lets a run needing `needed` bytes go, as people write it, just
/// above the need and never below it: whole KiB under 1 MiB (`5K`), whole MiB under 1 GiB
/// (`5M` for 4.8 MiB), tenths of a GiB under 10 GiB (`1.1G`), whole GiB above (`68G`). (It
/// was 256 MiB at the least: "needs 4.8 MiB ... --memory-budget 256M".)
pub fn suggested_budget(needed: u64) -> String {
    const K: u64 = 1 << 10;
    const M: u64 = 1 << 20;
    const G: u64 = 1 << 30;
    let (unit, letter) = if needed < M {
        (K, 'K')
    } else if needed < G {
        (M, 'M')
    } else {
        (G, 'G')
    };
    let tenths = (u128::from(needed) * 10).div_ceil(u128::from(unit));
    if letter == 'G' && tenths < 100 && tenths % 10 != 0 {
        return format!("{}.{}G", tenths / 10, tenths % 10);
    }
    format!("{}{letter}", needed.div_ceil(unit).max(1))
}

/// `--memory-budget` as typed: its bytes, and whether it was a number without a unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Asked {
    /// The bytes it stands for.
    pub bytes: u64,
    /// Typed without a unit (`90`): bytes, perhaps meant as MiB.
    pub bare: bool,
}

/// Reads `--memory-budget` ([`parse_size`]), noting whether it had a unit.
pub fn parse_asked(text: &str) -> Result<Asked, String> {
    let bare = !text.contains(|c: char| c.is_ascii_alphabetic());
    Ok(Asked { bytes: parse_size(text)?, bare })
}

/// Reads a size: a number of bytes with an optional unit, K, M, G or T (powers of 1024;
/// `KiB`, `MB` and `GB` are read the same way), a decimal point or comma allowed.
pub fn parse_size(text: &str) -> Result<u64, String> {
    let refused = || t!("budget-size-refused", value = format!("{text:?}"));
    let t = text.trim();
    let split = t.find(|c: char| c.is_ascii_alphabetic()).unwrap_or(t.len());
    let (number, unit) = t.split_at(split);
    let number: f64 = number.trim().replace(',', ".").parse().map_err(|_| refused())?;
    let unit = unit.trim().to_ascii_uppercase();
    let shift = match unit.trim_end_matches('B').trim_end_matches('I') {
        "" => 0,
        "K" => 10,
        "M" => 20,
        "G" => 30,
        "T" => 40,
        _ => return Err(refused()),
    };
    let bytes = number * (1u64 << shift) as f64;
    if bytes < 0.0 {
        return Err(t!("budget-size-negative", value = format!("{text:?}")));
    }
    if !(bytes.is_finite() && bytes >= 1.0 && bytes < u64::MAX as f64) {
        return Err(refused());
    }
    Ok(bytes as u64)
}

/// What rendering a mesh into a `width` x `height` picture allocates: the image (RGBA, the
/// PNG's rows and compressed copy, and the renderer's kept visibility: 16 bytes a pixel),
/// each vertex's eye and clip positions, window coordinates, normal and two colours (96
/// bytes), each triangle's raster setup, bin entry, face colours and the renderer's copy
/// of its corners (188 bytes), and the mesh itself (24 bytes a vertex, 12 a triangle).
pub fn render_bytes(width: u64, height: u64, vertices: u64, triangles: u64) -> u64 {
    width * height * 16 + vertices * (96 + 24) + triangles * (188 + 12)
}

/// What `phonglab diagnose` holds at its peak for a `size` x `size` picture of a mesh of
/// `vertices` and `triangles`: the process's own part ([`PROCESS`]: the budget counts the
/// memory the process really takes), the right drawing's renderer, kept for the probe, and
/// one mistake's renderer at a time ([`render_bytes`] each), and per pixel the right
/// picture, the student's picture decoded, a mistake's picture, the coverage masks, the
/// pictures of the mistakes that may be named (kept to tell which draw the same) and the
/// difference image, with the PNG reader's and writer's rows: 128 bytes a pixel more.
/// Measured (`/usr/bin/time -v`, debug build): three-lights, the shipped scene that takes
/// most, peaks at 49 MiB at 256, 76 MiB at 512 and 187 MiB at 1024 pixels (39 MiB and 148
/// bytes a pixel); spotlight at 72 MiB, phong-demo at 58 MiB, worksheet-mview1 at 55 MiB
/// at 512. This counts 48 MiB and 160 bytes a pixel: 88 MiB at 512. (It counted 96 bytes a
/// pixel and not the process: a run given the 26M it asked for peaked at 52 MB.)
pub fn diagnose_bytes(size: u64, vertices: u64, triangles: u64) -> u64 {
    PROCESS + 2 * render_bytes(size, size, vertices, triangles) + size * size * 128
}

/// What `eval` holds while it lights a case file whose largest case is `largest_case`
/// bytes of JSON: that case as serde_json's values (at most 32 bytes a byte of JSON: a
/// list of one-digit numbers, "0,", takes a 32-byte value for 2 bytes, and a list's room
/// can double), the ids, and 16 MiB for the rest (the reading buffers, one result).
pub fn eval_bytes(largest_case: u64) -> u64 {
    largest_case.saturating_mul(32) + (16 << 20)
}

/// What `phonglab check` holds at its peak for `count` submissions, the largest `largest`
/// bytes: the process's own part ([`PROCESS`]), that notebook as serde_json's values (at
/// most 32 bytes a byte of JSON, as [`eval_bytes`] counts), 16 MiB for the rest (the key
/// worked, the reading buffers) and 192 KiB a submission (its check kept for the report,
/// the marks and the chart). Measured (`/usr/bin/time -v`): a script's printed text peaks
/// at 31 MB resident (debug build; 64 MiB counted); a class of 200 notebooks with its
/// report, chart and marks at 86 MB (release build, docs/guide.md; 102 MiB counted).
pub fn check_bytes(count: u64, largest: u64) -> u64 {
    PROCESS + largest.saturating_mul(32) + (16 << 20) + count.saturating_mul(192 << 10)
}

/// What `phonglab cost` holds at its peak for a `size` x `size` study of each of the
/// `views` (each a view of one object, as the study draws it): for the object whose study
/// takes most, its reference (the finest mesh lit per vertex by the general engine in f64,
/// a full breakdown of each vertex, and per pixel its colour, depth and the kept f64 colour:
/// 97 bytes a pixel) and a frame of that mesh drawn by the renderer ([`render_bytes`]);
/// for every object, each variant's error map (4 bytes a pixel) and its reference image,
/// kept to the end; and the chart painted at the end (60 bytes a pixel of 1440 x 645 an
/// object).
pub fn cost_bytes(views: &[phonglab_core::View], size: u64) -> u64 {
    use phonglab_core::cost;
    let pixels = size * size;
    let breakdown = std::mem::size_of::<phonglab_core::VertexLighting<f64>>() as u64;
    let mut peak = 0u64;
    let mut kept = 0u64;
    for view in views {
        let mesh = cost::reference_view(view).mesh();
        let (v, t) = (mesh.positions.len() as u64, mesh.triangle_count() as u64);
        let reference = v * (breakdown + 64) + pixels * 97;
        peak = peak.max(reference + render_bytes(size, size, v, t));
        kept += pixels * (4 * cost::variants(view.object).len() as u64 + 25);
    }
    peak + kept + 1440 * 645 * 60 * views.len() as u64
}

/// What painting the whole window into a picture of `width` x `height` points at `scale`
/// pixels a point allocates: the canvas (four f32 a pixel), its RGBA copy and the PNG's
/// rows (24 bytes a pixel).
pub fn window_picture_bytes(width: u64, height: u64, scale: f64) -> u64 {
    let pixels = (width as f64 * scale).round() * (height as f64 * scale).round();
    (pixels * 24.0) as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_as_people_write_them() {
        assert_eq!(parse_size("512M"), Ok(512 << 20));
        assert_eq!(parse_size("8G"), Ok(8 << 30));
        assert_eq!(parse_size("1.5GiB"), Ok(3 << 29));
        assert_eq!(parse_size("1,5 GB"), Ok(3 << 29));
        assert_eq!(parse_size("4096"), Ok(4096));
        for bad in ["", "G", "-1G", "0", "12X", "1e30T", "nan"] {
            assert!(parse_size(bad).is_err(), "{bad:?}");
        }
    }

    /// Under `ulimit -v` the budget is half the address space left, where that is less
    /// than half the memory available (a run that went past it aborted on an allocation).
    #[test]
    fn the_default_budget_is_the_smaller_of_the_memory_and_the_address_space_limit() {
        let g = 1u64 << 30;
        assert_eq!(budget_of(Some(16 * g), None, Some(g)), (8 * g, 0));
        assert_eq!(budget_of(Some(16 * g), Some(4 * g), Some(g)), (3 * g / 2, 2));
        assert_eq!(budget_of(Some(2 * g), Some(40 * g), Some(g)), (g, 0));
        assert_eq!(budget_of(None, Some(4 * g), None), (2 * g, 2));
        assert_eq!(budget_of(None, None, None), (FALLBACK, 0));
        assert_eq!(budget_of(Some(16 * g), Some(g), Some(2 * g)), (0, 2), "a limit already reached");
    }

    /// A `--memory-budget` past what `ulimit -v` leaves is refused (a run under it
    /// aborted on an allocation); one within it, or without a limit, is taken.
    #[test]
    fn a_budget_past_the_address_space_limit_is_refused() {
        let g = 1u64 << 30;
        assert_eq!(over_the_limit(16 * g, Some(3 * g), Some(g)), Some(2 * g));
        assert_eq!(over_the_limit(g, Some(3 * g), Some(g)), None);
        assert_eq!(over_the_limit(16 * g, None, Some(g)), None);
        assert_eq!(over_the_limit(g, Some(g / 2), Some(g)), Some(0), "a limit already reached");
    }

    /// The suggested budget is never below what the run needs (it said "16G" for a run
    /// needing 68 GiB).
    #[test]
    fn the_suggested_budget_covers_the_need() {
        let g = 1u64 << 30;
        let m = 1u64 << 20;
        assert_eq!(suggested_budget(1), "1K");
        assert_eq!(suggested_budget(4900), "5K");
        // Issue 57: a run needing 4.8 MiB was told to use 256M.
        assert_eq!(suggested_budget(48 * m / 10), "5M");
        assert_eq!(suggested_budget(256 * m), "256M");
        assert_eq!(suggested_budget(256 * m + 1), "257M");
        assert_eq!(suggested_budget(g - 1), "1024M");
        assert_eq!(suggested_budget(g), "1G");
        assert_eq!(suggested_budget(g + 1), "1.1G");
        assert_eq!(suggested_budget(5 * g / 2), "2.5G");
        assert_eq!(suggested_budget(10 * g - 1), "10G");
        assert_eq!(suggested_budget(72_021_287_500), "68G");
        let mut needs = vec![1, 1023, 1025, m - 1, m + 1, 300 * m, g - 1, 5 * g / 2, 67 * g + 12345, 1 << 45];
        needs.extend((1..200u64).map(|k| k * 48_271_813 + 7));
        for needed in needs {
            let said = parse_size(&suggested_budget(needed)).unwrap();
            // Never below the need, and just above it (within a tenth, or a MiB).
            assert!(said >= needed, "{needed}: {}", suggested_budget(needed));
            assert!(said <= needed + (needed / 10).max(1 << 20), "{needed}: {}", suggested_budget(needed));
        }
    }

    #[test]
    fn over_the_budget_says_the_estimate_and_the_option() {
        set(Some(Asked { bytes: 1 << 30, bare: false })).unwrap();
        assert!(check("a picture", 1 << 29).is_ok());
        let e = check("a picture of 32768 x 32768 pixels", 24 << 30).unwrap_err();
        assert!(e.contains("a picture of 32768 x 32768 pixels needs about 25 769 803 776 bytes"), "{e}");
        assert!(e.contains("the memory budget of 1 073 741 824 bytes") && e.contains("--memory-budget"), "{e}");
        assert!(e.contains("--memory-budget 24G"), "the suggestion covers the need: {e}");
    }
}
