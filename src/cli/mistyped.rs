//! A word on the command line that is no command and no file: `phonglab exercicios` (a
//! command mistyped) was taken for the scene file to open the window on, and the window
//! said it could not read it, where the terminal said nothing. It is refused on the
//! terminal instead, exit 2, with the nearest command's name; and `phonglab help NAME` for
//! no command of that name says so, exit 2 (it printed the general help and exited 0).

use std::path::Path;

use crate::t;

/// Why `file`, the one word given where the window's scene file goes, is refused: a plain
/// word (no folder, no extension, not a link) that names nothing here. `None` for anything
/// that may be a file to open (the window says why it cannot read one).
pub fn refuse_word(file: &Path, root: &clap::Command) -> Option<String> {
    let word = file.to_str()?;
    let plain = !word.is_empty() && !word.contains(['/', '\\', '.', ':']);
    if !plain || std::fs::symlink_metadata(file).is_ok() {
        return None;
    }
    let shown = phonglab_core::escape::terminal::text(word);
    let names: Vec<&str> = root.get_subcommands().map(clap::Command::get_name).collect();
    Some(match nearest(word, &names) {
        Some(near) => t!("cmdline-not-a-command-near", word = shown, command = near),
        None => t!("cmdline-not-a-command", word = shown),
    })
}

/// Why `phonglab help NAMES…` names no command, if it does not: the first name that is no
/// command (of the one named before it).
pub fn refuse_help_of<'a>(root: &clap::Command, names: impl Iterator<Item = &'a String>) -> Option<String> {
    let mut cmd = root;
    for name in names {
        match cmd.find_subcommand(name) {
            Some(sub) => cmd = sub,
            None => {
                let shown = phonglab_core::escape::terminal::text(name);
                return Some(t!("cmdline-help-no-command", name = shown));
            }
        }
    }
    None
}

/// The name among `names` nearest to `word` (at most two letters added, removed or changed,
/// without case; or one that begins the same way for four letters), if one is.
fn nearest<'a>(word: &str, names: &[&'a str]) -> Option<&'a str> {
    let word = word.to_lowercase();
    let prefix = |n: &str| word.chars().count() >= 4 && n.starts_with(&word.chars().take(4).collect::<String>());
    names
        .iter()
        .map(|&n| (distance(&word, n), n))
        .filter(|&(d, n)| d <= 2 || prefix(n))
        .min_by_key(|&(d, _)| d)
        .map(|(_, n)| n)
}

/// The edit distance (Levenshtein) between `a` and `b`, by characters.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut last = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let here = row[j + 1];
            row[j + 1] = (last + usize::from(ca != cb)).min(row[j] + 1).min(here + 1);
            last = here;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_nearest_command_is_a_few_letters_away() {
        let names = ["exercise", "export", "explain", "render", "check"];
        assert_eq!(super::nearest("exercicios", &names), Some("exercise"));
        assert_eq!(super::nearest("rendr", &names), Some("render"));
        assert_eq!(super::nearest("Chek", &names), Some("check"));
        assert_eq!(super::nearest("scene", &names), None);
        assert_eq!(super::distance("kitten", "sitting"), 3);
    }
}
