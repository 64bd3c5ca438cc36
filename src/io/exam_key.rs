//! An exam exercise's key ([`phonglab_core::exam`]): each step the sheet asks, its value
//! exact (it ends in at most eight decimals) and rounded as the sheet asks, to four
//! significant digits, in Markdown and as the key PDF's blocks.

use std::fmt::Write as _;

use phonglab_core::exercise::Exercise;
use phonglab_core::moodle::EXAM_DIGITS;

use super::sheet_pdf::Block;
use crate::t;

/// Each asked step: (label, name, exact, rounded).
fn rows(ex: &Exercise) -> Vec<(String, String, String, String)> {
    let key = &ex.key;
    let printed = |v: &[f64], digits: usize| {
        let parts: Vec<String> =
            phonglab_core::explain::printed_components(v, 12).iter().map(|x| crate::locale::num(*x, digits)).collect();
        if parts.len() == 1 { parts.concat() } else { format!("[{}]", parts.join(" ")) }
    };
    (0..key.steps.len())
        .filter(|&k| phonglab_core::quiz::asked(&ex.doc.scene, key, k))
        .filter_map(|k| {
            let st = &key.steps[k];
            let v = st.value.as_ref()?;
            Some((format!("{}. {}", k + 1, st.title), st.name.clone(), printed(v, 12), printed(v, EXAM_DIGITS)))
        })
        .collect()
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
