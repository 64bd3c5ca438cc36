//! An exam exercise's key ([`phonglab_core::exam`]): each step the sheet asks, its value
//! exact (it ends in at most eight decimals) and rounded as the sheet asks, to four
//! significant digits, in Markdown and as the key PDF's blocks.

use std::fmt::Write as _;

use phonglab_core::exercise::Exercise;
use phonglab_core::moodle::EXAM_DIGITS;

use super::sheet_pdf::Block;
use crate::t;

/// Each asked step: (label, name, exact, rounded), numbered 1, 2, 3 … as the exam's sheet
/// numbers them ([`phonglab_core::exercise::Numbering::Own`]).
fn rows(ex: &Exercise) -> Vec<(String, String, String, String)> {
    let key = &ex.key;
    let printed = |v: &[f64], digits: Option<usize>| {
        let parts: Vec<String> = phonglab_core::explain::printed_components(v, 12)
            .iter()
            .map(|x| match digits {
                Some(d) => phonglab_core::locale::decimal(&significant(*x, d)),
                None => crate::locale::num(*x, 12),
            })
            .collect();
        if parts.len() == 1 { parts.concat() } else { format!("[{}]", parts.join(" ")) }
    };
    (0..key.steps.len())
        .filter(|&k| phonglab_core::quiz::asked(&ex.doc.scene, key, k))
        .enumerate()
        .filter_map(|(row, k)| {
            let st = &key.steps[k];
            let v = st.value.as_ref()?;
            let label = format!("{}. {}", row + 1, st.title);
            Some((label, st.name.clone(), printed(v, None), printed(v, Some(EXAM_DIGITS))))
        })
        .collect()
}

/// `x` to `digits` significant digits as the student writes it, its trailing zeros kept
/// (0.1360, 38.20; 0 as `0`), with a point: a tie rounded half away from zero on the
/// decimal the key shows, as students are taught (1.5875 is 1.588;
/// [`phonglab_core::moodle::round_by_hand`]).
pub fn significant(x: f64, digits: usize) -> String {
    phonglab_core::moodle::round_by_hand(x, digits)
}

/// The rows as a Markdown section of the key.
pub fn markdown(ex: &Exercise) -> String {
    let mut o = format!("\n## {}\n\n", t!("exam-key-heading"));
    let (exact, rounded) = (t!("exam-key-exact"), t!("exam-key-rounded"));
    for (label, name, x, r) in rows(ex) {
        let _ = writeln!(o, "- {label}: `{name}` = {x} ({exact}) ≈ {r} ({rounded})");
    }
    o
}

/// The rows as the key PDF's blocks.
pub fn blocks(ex: &Exercise) -> Vec<Block> {
    let (exact, rounded) = (t!("exam-key-exact"), t!("exam-key-rounded"));
    let mut b = vec![Block::Heading(t!("exam-key-heading"))];
    for (label, name, x, r) in rows(ex) {
        b.push(Block::KeyStep {
            label,
            formula: format!("{name} = {x} ({exact})"),
            line: format!("{name} ≈ {r} ({rounded})"),
        });
    }
    b
}

#[cfg(test)]
mod tests {
    use super::significant;

    #[test]
    fn a_rounded_value_keeps_its_trailing_zeros() {
        assert_eq!(significant(0.1360384, 4), "0.1360");
        assert_eq!(significant(0.212992, 4), "0.2130");
        assert_eq!(significant(38.2, 4), "38.20");
        assert_eq!(significant(9.99996, 4), "10.00");
        assert_eq!(significant(-0.6, 4), "-0.6000");
        assert_eq!(significant(12345.0, 4), "12345");
        assert_eq!(significant(0.0, 4), "0");
        // A tie, as a student rounds it: half up, not by the double's binary digits.
        assert_eq!(significant(1.5875, 4), "1.588");
    }
}
