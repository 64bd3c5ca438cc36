//! Every message in every language, each in the catalogue of the crate that uses it, and no
//! English on screen in Portuguese: the sources' message ids are all in the three languages
//! of their catalogues, the core's catalogue holds what the core uses and the app's what
//! only the app uses (`scripts/split-catalogue.py` sorts them by the same reading), and the
//! window walked in pt-PT (with egui_kittest) shows no label that is an English message.

use std::collections::{BTreeMap, BTreeSet};

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use phonglab::app::{AppState, app_ui};
use phonglab::locale::{APP_SOURCES, CORE_SOURCES, Lang, has_message, ids_of, tr_in};

use crate::common;

/// The text of every source file under `dir` (a crate's `src`), one string a file.
fn source_texts(dir: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(dir)];
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

fn app_sources() -> Vec<String> {
    source_texts("src")
}

/// The core's sources and the Python package's (its messages are the core's catalogue's).
fn core_sources() -> Vec<String> {
    let mut sources = source_texts("crates/phonglab-core/src");
    sources.extend(source_texts("crates/phonglab-py/src"));
    sources
}

/// Every `t!("id"` and `tr("id"` in `sources`.
fn ids_asked_in(sources: &[String]) -> BTreeSet<String> {
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
    ids
}

/// The ids the app's tables name (the help's), besides its `t!`s and `tr`s.
fn ids_in_app_tables() -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    for (.., id) in phonglab::app::panels::help::SHORTCUTS {
        ids.insert(id.to_string());
    }
    for id in phonglab::app::panels::help::DEMO_CHOICES {
        ids.insert(id.to_string());
    }
    ids
}

/// The ids the core's tables name: the vocabulary's labels, asked for through Quantity::label.
fn ids_in_core_tables() -> BTreeSet<String> {
    phonglab_core::vocabulary::Quantity::ALL.iter().filter_map(|q| q.term().message.map(str::to_string)).collect()
}

/// The messages each message of `source` names (`{ id }`), by id.
fn named_by(source: &str) -> BTreeMap<String, BTreeSet<String>> {
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut current = None;
    for line in source.lines() {
        if line.starts_with('#') {
            current = None;
            continue;
        }
        if line.starts_with(|c: char| c.is_ascii_alphabetic()) {
            current = line.split_once(" =").map(|(id, _)| id.trim().to_string());
        }
        let Some(id) = &current else { continue };
        let named = out.entry(id.clone()).or_default();
        for (at, _) in line.match_indices('{') {
            let inner = line[at + 1..].split('}').next().unwrap_or("").trim();
            if inner.starts_with(|c: char| c.is_ascii_alphabetic())
                && inner.chars().all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
            {
                named.insert(inner.to_string());
            }
        }
    }
    out
}

/// Does a crate whose sources are `text` use message `id`: by its string literal (a `t!`,
/// a `tr`, a table of ids, a `message_id()` arm), or built from one of `prefixes`?
fn uses(text: &str, prefixes: &[&str], id: &str) -> bool {
    text.contains(&format!("\"{id}\"")) || prefixes.iter().any(|p| id.starts_with(p))
}

/// The ids the core builds from parts: a classic material's name (materials::display_name).
const CORE_PREFIXES: [&str; 1] = ["material-name-"];
/// The ids the app builds from parts: a material field's label by field name
/// (`{side}-{field}`), a shipped scene's name by file (src/io/scenes.rs tests them), and
/// the command line's help by command, argument and value (tests/cli_help.rs).
const APP_PREFIXES: [&str; 5] = ["material-", "back-", "preset-", "cli-arg-", "cli-value-"];

#[test]
fn every_message_the_code_asks_for_is_in_every_language_of_its_catalogue() {
    let core_asks = ids_asked_in(&core_sources()).into_iter().chain(ids_in_core_tables()).collect::<BTreeSet<_>>();
    let app_asks = ids_asked_in(&app_sources()).into_iter().chain(ids_in_app_tables()).collect::<BTreeSet<_>>();
    assert!(core_asks.len() > 200 && app_asks.len() > 300, "{} and {} ids found", core_asks.len(), app_asks.len());
    for lang in Lang::ALL {
        // The core finds only its own catalogue's messages; the app, its own and the core's.
        let missing: Vec<&String> =
            core_asks.iter().filter(|id| !phonglab_core::locale::has_message(lang, id)).collect();
        assert!(missing.is_empty(), "the core's {} catalogue lacks {missing:?}", lang.code());
        let missing: Vec<&String> = app_asks.iter().filter(|id| !has_message(lang, id)).collect();
        assert!(missing.is_empty(), "the {} catalogues lack {missing:?}", lang.code());
    }
    for (name, sources) in [("core", CORE_SOURCES), ("app", APP_SOURCES)] {
        let [en, pt_pt, pt_br] = sources.map(ids_of);
        assert!(en.len() > 200, "the {name}'s catalogue has {} messages", en.len());
        assert_eq!(en, pt_pt, "the {name}'s English and pt-PT catalogues have the same ids in the same order");
        assert_eq!(en, pt_br, "the {name}'s English and pt-BR catalogues have the same ids in the same order");
    }
}

#[test]
fn each_catalogue_holds_the_messages_its_crate_uses_and_no_id_is_in_both() {
    let core_text = core_sources().concat();
    let app_text = app_sources().concat();
    let core_ids = ids_of(CORE_SOURCES[0]);
    let app_ids = ids_of(APP_SOURCES[0]);
    let both: Vec<&String> = core_ids.iter().filter(|id| app_ids.contains(id)).collect();
    assert!(both.is_empty(), "in both catalogues: {both:?}");
    let core_named: BTreeSet<String> = named_by(CORE_SOURCES[0]).into_values().flatten().collect();
    let app_named: BTreeSet<String> = named_by(APP_SOURCES[0]).into_values().flatten().collect();
    // The command line's help by command (its about), as tests/cli_help.rs reads it.
    let root = <phonglab::cli::Cli as clap::CommandFactory>::command();
    let abouts: BTreeSet<String> = phonglab::cli::help::command_paths(&root)
        .iter()
        .map(|(path, _)| phonglab::cli::help::about_message_id(path))
        .collect();
    let core_uses = |id: &str| uses(&core_text, &CORE_PREFIXES, id) || core_named.contains(id);
    let app_uses = |id: &str| uses(&app_text, &APP_PREFIXES, id) || app_named.contains(id) || abouts.contains(id);
    // The core's: each used by the core (the app may use it too: it reads both).
    let unused: Vec<&String> = core_ids.iter().filter(|id| !core_uses(id)).collect();
    assert!(unused.is_empty(), "in the core's catalogue, but the core does not use: {unused:?}");
    // The app's: each used by the app, and not by the core, whose lookup would not find it.
    let unused: Vec<&String> = app_ids.iter().filter(|id| !app_uses(id)).collect();
    assert!(unused.is_empty(), "in the app's catalogue, but the app does not use: {unused:?}");
    let cores: Vec<&String> = app_ids.iter().filter(|id| core_uses(id)).collect();
    assert!(cores.is_empty(), "in the app's catalogue, but the core uses (run scripts/split-catalogue.py): {cores:?}");
}

#[test]
fn one_lookup_finds_the_apps_messages_and_the_cores_in_every_language() {
    // An app message ("loaded", the window's) and a core message (the local viewer's name,
    // the exercises'), each in its own catalogue; the app's lookup finds both.
    assert!(ids_of(APP_SOURCES[0]).contains(&"loaded".to_string()));
    assert!(!phonglab_core::locale::has_message(Lang::En, "loaded"));
    assert!(ids_of(CORE_SOURCES[0]).contains(&"local-viewer".to_string()));
    for (lang, loaded, viewer) in [
        (Lang::En, "Opened “x”", "Local viewer"),
        (Lang::PtPt, "Aberto: «x»", "Observador local"),
        (Lang::PtBr, "Aberto: “x”", "Observador local"),
    ] {
        assert_eq!(tr_in(lang, "loaded", &[("what", "x".into())]), loaded, "{lang:?}");
        assert_eq!(tr_in(lang, "local-viewer", &[]), viewer, "{lang:?}");
        assert_eq!(phonglab_core::locale::tr_in(lang, "local-viewer", &[]), viewer, "{lang:?}");
        // An app message naming a core one: the undo history's name of a changed field.
        let field = [("field", "light_model-local_viewer".into())];
        assert_eq!(tr_in(lang, "history-field", &field), viewer, "{lang:?}");
    }
    // An id no catalogue has is said as itself.
    assert_eq!(tr_in(Lang::PtBr, "no-such-message", &[]), "no-such-message");
}

/// English messages without arguments whose Portuguese differs, of both catalogues: none
/// may be on screen in Portuguese.
fn english_only_texts() -> BTreeSet<String> {
    ids_of(APP_SOURCES[0])
        .into_iter()
        .chain(ids_of(CORE_SOURCES[0]))
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
            out.push(l.clone());
        }
        if let Some(v) = n.accesskit_node().value() {
            out.push(v.clone());
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
    use phonglab::locale::Arg;
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

/// A count takes the noun's number its language gives it: one thing is singular, none is
/// plural in both Portuguese ("0 luzes"), though CLDR's rule for pt (Brazil) puts 0 in
/// "one" (so pt-BR's selectors name [0] first).
#[test]
fn counts_take_the_number_their_language_gives_them() {
    use phonglab::locale::Arg;
    let said = |lang, id, args: &[(&str, usize)]| {
        let args: Vec<(&str, Arg)> = args.iter().map(|&(k, n)| (k, Arg::from(n))).collect();
        tr_in(lang, id, &args).replace(['\u{2068}', '\u{2069}'], "")
    };
    let plan = [("computed", 1), ("skipped", 0)];
    assert_eq!(said(Lang::En, "plan-heading", &plan), "Specialised plan: 1 effect computed, 0 skipped");
    assert_eq!(said(Lang::PtPt, "plan-heading", &plan), "Plano especializado: 1 efeito calculado, 0 saltados");
    assert_eq!(said(Lang::PtBr, "plan-heading", &plan), "Plano especializado: 1 efeito calculado, 0 pulados");
    let plan = [("computed", 0), ("skipped", 1)];
    assert_eq!(said(Lang::PtBr, "plan-heading", &plan), "Plano especializado: 0 efeitos calculados, 1 pulado");
    for lang in [Lang::PtPt, Lang::PtBr] {
        assert_eq!(said(lang, "lights-count", &[("count", 0)]), "0 luzes", "{lang:?}");
        assert_eq!(said(lang, "lights-count", &[("count", 1)]), "1 luz", "{lang:?}");
        assert_eq!(said(lang, "lights-count", &[("count", 2)]), "2 luzes", "{lang:?}");
    }
    assert_eq!(said(Lang::PtBr, "mesh-triangles", &[("count", 1)]).split(':').next(), Some("1 triângulo"));
    assert_eq!(said(Lang::PtBr, "mesh-triangles", &[("count", 0)]).split(':').next(), Some("0 triângulos"));
    assert!(
        said(Lang::PtPt, "shader-last-change", &[("added", 1), ("removed", 2)]).contains("juntou 1 linha (destacada)")
    );
    assert!(
        said(Lang::PtBr, "quiz-score", &[("right", 0), ("all", 5), ("answered", 0), ("shown", 0)])
            .contains("0 respondidos")
    );
}

/// Every pt-BR selector with a [one] variant names [0] right before it: CLDR's pt rule
/// (i = 0..1) would otherwise print "0 luz" or "1 respondido" for none.
#[test]
fn every_brazilian_one_has_its_zero() {
    for path in ["i18n/pt-BR.ftl", "crates/phonglab-core/i18n/pt-BR.ftl"] {
        let text = std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).expect(path);
        let lines: Vec<&str> = text.lines().collect();
        let lacking: Vec<&str> = lines
            .windows(2)
            .filter(|w| w[1].trim_start().starts_with("[one]") && !w[0].trim_start().starts_with("[0]"))
            .map(|w| w[1].trim())
            .collect();
        assert!(lacking.is_empty(), "{path}: [one] without [0] before it: {lacking:?}");
    }
}

/// European Portuguese speaks to the reader as "você" (or impersonally), as most of its
/// messages do ("Escolha", "Indique", "Execute"): no clause starts with a "tu" imperative
/// ("Calcula todos os passos", "Escreve primeiro", "2. Muda qualquer coisa", "escreve-os").
/// The verbs listed are those whose "tu" imperative was found; a message that describes
/// (a button's "Copia todos os passos", "Põe a ligação…") is third person, not listed, and
/// so are the two whose described subject says the same verb ("…; escreve cost.csv", the
/// program's "Dá aos shaders…").
#[test]
fn european_portuguese_never_says_tu_where_it_says_voce() {
    const TU: [&str; 20] = [
        "calcula",
        "escolhe",
        "abre",
        "guarda",
        "usa",
        "escreve",
        "corre",
        "vê",
        "tenta",
        "experimenta",
        "larga",
        "fixa",
        "muda",
        "remove",
        "limita",
        "define",
        "dá",
        "clica",
        "carrega",
        "arrasta",
    ];
    const DESCRIBING: [&str; 2] = ["cli-cost = ", "py-reader-doc = "];
    for path in ["i18n/pt-PT.ftl", "crates/phonglab-core/i18n/pt-PT.ftl"] {
        let text = std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).expect(path);
        let mut found = Vec::new();
        for line in text.lines().filter(|l| !l.starts_with('#') && !DESCRIBING.iter().any(|d| l.starts_with(d))) {
            let value = line.split_once(" = ").map_or(line, |(_, v)| v);
            let clauses = value.split(". ").flat_map(|s| s.split(": ")).flat_map(|s| s.split("; "));
            for clause in clauses {
                let clause =
                    clause.trim_start().trim_start_matches(|c: char| c.is_ascii_digit() || c == '.').trim_start();
                let word = clause.split([' ', ',']).next().unwrap_or("").to_lowercase();
                // "usa-se" is impersonal; "escreve-os" is "tu".
                let verb = word.split_once('-').map_or(word.as_str(), |(v, p)| if p == "se" { "" } else { v });
                if TU.contains(&verb) {
                    found.push(line.chars().take(100).collect::<String>());
                }
            }
        }
        assert!(found.is_empty(), "{path}: \"tu\" where the catalogue says \"você\":\n{}", found.join("\n"));
    }
}

#[test]
fn a_percent_sign_is_never_left_alone_at_the_start_of_a_line() {
    // A share wrapped at a projector's 1024x600 left "%." alone on a line: every `%` after a
    // number or a placeable is bound to it by a no-break space, in the catalogues and in
    // the code's own formats, and the one helper writes it so.
    let loose = |text: &str| {
        text.lines()
            .filter(|l| !l.trim_start().starts_with('#') && !l.trim_start().starts_with("//"))
            .filter(|l| l.contains(" %") || l.contains("} %") || l.contains("}%"))
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    for source in APP_SOURCES.iter().chain(CORE_SOURCES.iter()) {
        assert_eq!(loose(source), Vec::<String>::new());
    }
    let formats: Vec<String> = app_sources()
        .iter()
        .chain(core_sources().iter())
        .flat_map(|s| {
            s.lines().filter(|l| l.contains("} %\"") || l.contains("} %\\n")).map(str::to_string).collect::<Vec<_>>()
        })
        .collect();
    assert_eq!(formats, Vec::<String>::new());
    phonglab::locale::with_locale(phonglab::locale::Locale::of(Lang::PtPt), || {
        assert_eq!(phonglab::locale::percent(0.9937, 1), "99,4\u{a0}%");
    });
}
