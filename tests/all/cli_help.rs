//! The command line's help in every language: every command, argument and value has its
//! message in every catalogue, the catalogue describes no argument that is gone, clap
//! accepts the localised command tree, and `--help` in Portuguese prints no English
//! sentence of ours nor clap's own words.

use std::collections::BTreeSet;

use clap::CommandFactory;
use phonglab::cli::Cli;
use phonglab::cli::help::{about_message_id, command_paths, described_arguments, described_values, value_message_id};
use phonglab::locale::{Lang, Locale, has_message, message_ids, tr_in, with_locale};

/// Every message id the help asks for: commands' abouts, arguments and values.
fn ids_the_help_asks_for() -> BTreeSet<String> {
    let root = Cli::command();
    let mut ids = BTreeSet::new();
    for (path, cmd) in command_paths(&root) {
        ids.insert(about_message_id(&path));
        for (arg, id) in described_arguments(cmd, &path) {
            ids.insert(id);
            let arg = cmd.get_arguments().find(|a| a.get_id() == arg.as_str()).unwrap();
            for v in described_values(arg) {
                ids.insert(value_message_id(v.get_name()));
            }
        }
    }
    ids
}

#[test]
fn every_command_argument_and_value_has_its_message_in_every_language() {
    let ids = ids_the_help_asks_for();
    assert!(ids.len() > 80, "{} ids", ids.len());
    for lang in Lang::ALL {
        let missing: Vec<&String> = ids.iter().filter(|id| !has_message(lang, id)).collect();
        assert!(missing.is_empty(), "{} lacks {missing:?}", lang.code());
    }
    // And no description of an argument or value that the command line no longer has.
    let stale: Vec<String> = message_ids(Lang::En)
        .into_iter()
        .filter(|id| id.starts_with("cli-arg-") || id.starts_with("cli-value-"))
        .filter(|id| !ids.contains(id))
        .collect();
    assert!(stale.is_empty(), "described but not on the command line: {stale:?}");
}

#[test]
fn the_localised_command_tree_is_one_clap_accepts_in_every_language() {
    // This thread's language, not the process's: the other tests of this binary run beside it.
    for lang in Lang::ALL {
        with_locale(Locale::of(lang), || phonglab::cli::help::localised(Cli::command()).debug_assert());
    }
}

use crate::common;

fn help(lang: &str, args: &[&str]) -> String {
    let o = common::phonglab_in(lang, args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn help_in_portuguese_has_no_english_sentence() {
    // The English of every message the help prints, long enough to be a sentence.
    let english: Vec<String> = ids_the_help_asks_for()
        .iter()
        .map(|id| tr_in(Lang::En, id, &[]))
        .filter(|s| s.contains(' ') && s.len() > 12)
        .collect();
    let root = Cli::command();
    for (path, _) in command_paths(&root) {
        let mut args: Vec<&str> = if path == "app" { vec![] } else { path.split('-').collect() };
        args.push("--help");
        for lang in ["pt_PT.UTF-8", "pt_BR.UTF-8"] {
            let text = help(lang, &args);
            for words in ["Usage:", "Options:", "Arguments:", "Commands:", "Print help", "[default:", "Possible values"]
            {
                assert!(!text.contains(words), "{lang} {args:?} prints clap's {words:?}:\n{text}");
            }
            for sentence in &english {
                assert!(!text.contains(sentence.as_str()), "{lang} {args:?} prints {sentence:?}:\n{text}");
            }
        }
    }
    let text = help("pt_PT.UTF-8", &["explain", "--help"]);
    let exe = std::env::consts::EXE_SUFFIX;
    assert!(text.contains(&format!("Utilização: phonglab{exe} explain")), "{text}");
    assert!(text.contains("- f32: precisão simples, como o OpenGL calcula"), "{text}");
    assert!(text.contains("[por omissão: f64]"), "{text}");
    let text = help("pt_BR.UTF-8", &["help", "bench", "render"]);
    assert!(text.starts_with("ms por imagem do desenho na CPU"), "{text}");
    assert!(text.contains(&format!("Uso: phonglab{exe} bench render")) && text.contains("[padrão: 200]"), "{text}");
    // English keeps the source's words.
    let text = help("C.UTF-8", &["render", "-h"]);
    assert!(
        text.contains(&format!("Usage: phonglab{exe} render")) && text.contains("[values: sphere, teapot, cylinder]"),
        "{text}"
    );
}

/// `--lang`'s help says where the default comes from on each system, in every language:
/// the variables where one is set, else Windows' display language or macOS's preferred one
/// (`platform::language`), not the variables alone.
#[test]
fn lang_help_says_where_the_default_comes_from_on_each_system() {
    for (lang, words) in [
        ("C.UTF-8", ["LC_ALL", "Windows", "display", "macOS", "preferred"]),
        ("pt_PT.UTF-8", ["LC_ALL", "Windows", "apresentação", "macOS", "preferida"]),
        ("pt_BR.UTF-8", ["LC_ALL", "Windows", "exibição", "macOS", "preferido"]),
    ] {
        let text = help(lang, &["help", "export"]);
        for word in words {
            assert!(text.contains(word), "{lang}: no {word:?} in:\n{text}");
        }
    }
}

/// `phonglab --version` prints the crate's version and the commit the binary was built from:
/// the repository's HEAD where git is there (as here, when the tests run from a clone), else
/// "unknown".
#[test]
fn version_names_the_version_and_the_commit() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
        .env("LC_ALL", "C.UTF-8")
        .arg("--version")
        .output()
        .expect("the binary runs");
    assert!(out.status.success(), "{out:?}");
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    let head = std::process::Command::new("git")
        .args(["-C", env!("CARGO_MANIFEST_DIR"), "rev-parse", "--short", "HEAD"])
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    // Where this test cannot run git (Windows under Wine) the build still could.
    let commit = head.unwrap_or_else(|| {
        if cfg!(windows) {
            phonglab::cli::VERSION.split(['(', ')']).nth(1).unwrap_or("").to_string()
        } else {
            "unknown".to_string()
        }
    });
    assert_eq!(text, format!("phonglab {} ({commit})\n", env!("CARGO_PKG_VERSION")));
    assert_eq!(phonglab::cli::VERSION, format!("{} ({commit})", env!("CARGO_PKG_VERSION")));
}
