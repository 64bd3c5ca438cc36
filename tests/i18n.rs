//! Every message in every language, and no English on screen in Portuguese: the source's
//! message ids are all in the three catalogues, and the window walked in pt-PT (with
//! egui_kittest) shows no label that is an English message.

use std::collections::BTreeSet;

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::{AppState, app_ui};
use phonglab_core::locale::{Lang, has_message, message_ids, tr_in};

mod common;

/// The text of every source file of the app and the core.
fn source_texts() -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![
        std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/src")),
        std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/crates/phonglab-core/src")),
    ];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(std::fs::read_to_string(&path).unwrap());
            }
        }
    }
    out
}

/// Every `t!("id"` and `tr("id"` in `sources`, and the help table's ids.
fn ids_in_sources(sources: &[String]) -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    for text in sources {
        for open in ["t!(", "tr("] {
            for (at, _) in text.match_indices(open) {
                let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
                if text[line_start..at].trim_start().starts_with("//") {
                    continue; // documentation
                }
                let Some(rest) = text[at + open.len()..].trim_start().strip_prefix('"') else { continue };
                let id: String = rest.chars().take_while(|c| *c != '"').collect();
                let is_id = id.starts_with(|c: char| c.is_ascii_lowercase())
                    && id.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-');
                if is_id {
                    ids.insert(id);
                }
            }
        }
    }
    for (.., id) in phonglab::app::panels::help::SHORTCUTS {
        ids.insert(id.to_string());
    }
    for id in phonglab::app::panels::help::DEMO_CHOICES {
        ids.insert(id.to_string());
    }
    // The vocabulary's labels, asked for through Quantity::label.
    for q in phonglab_core::vocabulary::Quantity::ALL {
        ids.extend(q.term().message.map(str::to_string));
    }
    ids
}

#[test]
fn every_message_the_code_asks_for_is_in_every_language() {
    let sources = source_texts();
    let ids = ids_in_sources(&sources);
    assert!(ids.len() > 300, "{} ids found", ids.len());
    for lang in Lang::ALL {
        let missing: Vec<&String> = ids.iter().filter(|id| !has_message(lang, id)).collect();
        assert!(missing.is_empty(), "{} lacks {missing:?}", lang.code());
    }
    // And every message of the catalogues is asked for somewhere: by t!/tr, named in a
    // table of ids, or built from a prefix (material-*/back-* by field name, preset-* by
    // scene file (src/scenes.rs tests them); the command line's help by command and
    // argument, checked in tests/cli_help.rs).
    let all_source = sources.concat();
    let root = <phonglab::cli::Cli as clap::CommandFactory>::command();
    let abouts: BTreeSet<String> = phonglab::cli::help::command_paths(&root)
        .iter()
        .map(|(path, _)| phonglab::cli::help::about_message_id(path))
        .collect();
    let unused: Vec<String> = message_ids(Lang::En)
        .into_iter()
        .filter(|id| !ids.contains(id) && !all_source.contains(&format!("\"{id}\"")))
        .filter(|id| !id.starts_with("material-") && !id.starts_with("back-") && !id.starts_with("preset-"))
        .filter(|id| !id.starts_with("cli-arg-") && !id.starts_with("cli-value-") && !abouts.contains(id))
        .collect();
    assert!(unused.is_empty(), "messages no code asks for: {unused:?}");
}

/// English messages without arguments whose Portuguese differs: none may be on screen in
/// Portuguese.
fn english_only_texts() -> BTreeSet<String> {
    message_ids(Lang::En)
        .into_iter()
        .map(|id| (tr_in(Lang::En, &id, &[]), tr_in(Lang::PtPt, &id, &[])))
        .filter(|(en, pt)| en != pt && !en.contains('{') && en.len() > 2)
        .map(|(en, _)| en)
        .collect()
}

fn labels(h: &Harness<'_, AppState>) -> Vec<String> {
    let mut out = Vec::new();
    let root = h.root();
    let mut stack = vec![root];
    while let Some(n) = stack.pop() {
        if let Some(l) = n.accesskit_node().label() {
            out.push(l.to_string());
        }
        if let Some(v) = n.accesskit_node().value() {
            out.push(v.to_string());
        }
        stack.extend(n.children());
    }
    out
}

#[test]
fn the_window_in_portuguese_shows_no_english_message() {
    let mut state = AppState::worksheet();
    state.ui.layout.language = Some("pt-PT".into());
    let mut h =
        Harness::builder().with_size([1600.0, 1200.0]).build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), state);
    h.run_steps(3);
    let english = english_only_texts();
    assert!(english.len() > 150, "{}", english.len());
    let mut seen = Vec::new();
    // The main window, the File and View menus, the Scene menu and its teapots, View
    // options, the help overlay, then the quiz.
    seen.extend(labels(&h));
    for menu in ["Ficheiro", "Ver"] {
        common::open_menu(&mut h, &[menu]);
        seen.extend(labels(&h));
        h.key_press(egui::Key::Escape);
        h.run_steps(2);
    }
    common::open_menu(&mut h, &["Cena"]);
    h.run_steps(3);
    h.get_by_label("Bules do Red Book").hover();
    h.run_steps(3);
    let presets = labels(&h);
    for pt in ["A ficha", "Ficha, mview3", "Demo de Phong", "Mais cenas", "Três luzes", "Borracha amarela"] {
        assert!(presets.iter().any(|l| l == pt), "{pt} in the Presets menu: {presets:?}");
    }
    seen.extend(presets);
    h.key_press(egui::Key::Escape);
    h.run_steps(3);
    h.get_by_label("Opções da vista").click();
    h.run_steps(3);
    seen.extend(labels(&h));
    h.key_press(egui::Key::F1);
    h.run_steps(3);
    seen.extend(labels(&h));
    h.key_press(egui::Key::F1);
    common::menu_item(&mut h, &["Ver"], "Teste");
    h.run_steps(3);
    seen.extend(labels(&h));
    h.state_mut().quiz.open = false;
    // Compare, pinned and then changed (the material), and the Shader window.
    common::menu_item(&mut h, &["Ver"], "Comparar");
    h.run_steps(3);
    h.key_press(egui::Key::M);
    h.run_steps(3);
    seen.extend(labels(&h));
    h.get_by_label("Fechar a comparação").click();
    common::menu_item(&mut h, &["Ver"], "Programa de sombreamento (shader)");
    h.run_steps(3);
    seen.extend(labels(&h));
    let leaks: BTreeSet<&String> = seen.iter().filter(|l| english.contains(*l)).collect();
    assert!(leaks.is_empty(), "English on screen in pt-PT: {leaks:?}");
    // Nor English typed into the code rather than the catalogue: words no Portuguese label has.
    let words =
        [" the ", "The ", " of ", " and ", "Light ", "Vertex ", "Reset", "Open ", "Save", "Undo", "Show ", "Drag "];
    // The generated program's comments included (the Shader window's): they are in the
    // class's language too.
    let typed: BTreeSet<&String> = seen.iter().filter(|l| words.iter().any(|w| l.contains(w))).collect();
    assert!(typed.is_empty(), "English words on screen in pt-PT: {typed:?}");
    assert!(seen.iter().any(|l| l.contains("// passo 1")), "the shader's comments were read");
    // The Portuguese is there: the calculation's, the quiz's and the controls'.
    for pt in ["Luzes", "Cor do vértice", "Pontuação: 0 de 14 (0 respondidos)", "Material: brilho (ns)"] {
        assert!(seen.iter().any(|l| l.contains(pt)), "{pt} on screen");
    }
    // The plot's legend names H as the sheets do (it said "halfway"); the Shader window's title.
    assert!(seen.iter().any(|l| l.ends_with("Hvetor médio")), "H's name in the legend");
    assert!(!seen.iter().any(|l| l == "Shader" || l.ends_with("Hhalfway")), "Shader or H halfway on screen");
    // Numbers in Portuguese use the decimal comma: the shininess field shows 25,6.
    assert!(seen.iter().any(|l| l == "25,6"), "the shininess as 25,6");
}

#[test]
fn switching_the_language_in_the_app_takes_effect_at_once() {
    let mut h = Harness::builder()
        .with_size([1500.0, 1000.0])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(2);
    h.get_by_label("File");
    h.get_by_label("en").click();
    h.run_steps(2);
    h.get_by_label("Português (Brasil)").click();
    h.run_steps(2);
    assert_eq!(h.state().ui.layout.language.as_deref(), Some("pt-BR"));
    h.get_by_label("Cena");
    assert!(h.query_by_label("File").is_none());
    // Brazilian where usage differs: the File menu, and the Scene file field in it, are an
    // "Arquivo".
    common::open_menu(&mut h, &["Arquivo"]);
    h.get_by_label("Arquivo de cena:");
    // Kept across restarts with the layout.
    let back = phonglab::app::shell::layout::Layout::from_ron(Some(&h.state().ui.layout.to_ron()));
    assert_eq!(back.language.as_deref(), Some("pt-BR"));
}

/// "Loaded" a title that starts with a capital and ends with a full stop read "Loaded The
/// local viewer, on and off.." in English: the title is quoted, in each language's quotes.
#[test]
fn the_loaded_message_quotes_the_title() {
    use phonglab_core::locale::Arg;
    let what = "The local viewer, on and off.";
    for (lang, want) in [
        (Lang::En, "Opened “The local viewer, on and off.”"),
        (Lang::PtPt, "Aberto: «The local viewer, on and off.»"),
        (Lang::PtBr, "Aberto: “The local viewer, on and off.”"),
    ] {
        let got = tr_in(lang, "loaded", &[("what", Arg::from(what))]);
        assert_eq!(got.replace(['\u{2068}', '\u{2069}'], ""), want, "{lang:?}");
    }
}
