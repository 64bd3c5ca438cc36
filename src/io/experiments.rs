//! The experiments of the "Things to try" window, as data: one TOML file each, shipped under
//! `assets/experiments/` (embedded at build time, `build.rs`) and, on the desktop, a
//! teacher's own in the `experiments` folder beside the session
//! ([`crate::platform::storage::experiments_dir`]).
//!
//! A file names a scene and the changes that set the experiment up, the step of the worked
//! calculation that answers its question, and its words in each language:
//!
//! ```toml
//! scene = "worksheet-mview1"   # a shipped scene (assets/scenes/, no .toml), or a scene file
//!                              # beside this one ("my-scene.toml": a name, no folder)
//! answer = "cosTheta"          # the step's name in the worksheet (vlv, d, Idif, at, spot, I…)
//! light = 0                    # whose step, with several lights (0 when left out)
//! control = "light-z"          # the control the words tell the class to move, by its label's
//!                              # catalogue id (light-x/y/z, material-shininess, spot-cutoff…):
//!                              # the click opens the controls on it, and the window keeps clear
//!
//! [changes]                    # laid over the scene file: a table key by key, a list of
//! lights = [{ position = [0, 0, -40, 1] }]   # tables item by item, anything else replaced
//!
//! [text.en]                    # and "pt-PT", "pt-BR": the class's language, else English
//! title = "The light behind the surface"
//! look = "What one click set up, and what to look for"
//! question = "A question the step named by `answer` answers"
//! ```

use std::collections::BTreeMap;
use std::path::Path;

use phonglab_core::escape::printable;

use phonglab_core::Document;
use serde::Deserialize;

use crate::locale::Lang;
use crate::t;

include!(concat!(env!("OUT_DIR"), "/experiment_files.rs"));

/// An experiment's words in one language.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Words {
    /// Its title in the list.
    pub title: String,
    /// What the click set up, and what to look for.
    pub look: String,
    /// The question the calculation answers.
    pub question: String,
}

/// The file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    scene: String,
    answer: String,
    #[serde(default)]
    light: Option<usize>,
    #[serde(default)]
    control: Option<String>,
    #[serde(default)]
    changes: Option<toml::Table>,
    text: BTreeMap<String, Words>,
}

/// One experiment, ready: the scene set up, the step that answers, the words.
#[derive(Clone, Debug, PartialEq)]
pub struct Experiment {
    /// Where it came from: `assets/experiments/01-light-behind.toml`, or the teacher's file.
    pub source: String,
    /// The scene the click loads (validated as any scene file is).
    pub doc: Document,
    /// The worked calculation's step that answers the question (its worksheet name).
    pub answer: String,
    /// Whose step that is, with several lights.
    pub light: Option<usize>,
    /// The control its words tell the class to move: its label's catalogue id.
    pub control: Option<String>,
    /// The words, by language code ("en", "pt-PT", "pt-BR").
    pub text: BTreeMap<String, Words>,
}

/// The most experiment files read from a teacher's folder.
pub const MAX_EXPERIMENTS: usize = 64;

/// The largest experiment file read: a shipped one is about 1.5 KB.
pub const MAX_EXPERIMENT_BYTES: u64 = 64 << 10;

/// The most bytes a teacher's folder is read for, its experiments and the scenes they name
/// together (each scene file at most [`crate::io::input_file::MAX_SCENE_BYTES`]).
pub const MAX_FOLDER_BYTES: u64 = 4 << 20;

/// Where an experiment's scene comes from (see [`Experiment::parse`]).
pub enum SceneText {
    /// A scene's text, and the name it is said by in a message.
    Found(String, String),
    /// Nothing of that name.
    Missing,
    /// Refused, and why (not a shipped name nor a plain name in the folder, too large...).
    Refused(String),
}

impl Experiment {
    /// Reads an experiment's `text`; `scene_text` finds a scene file's text by the name the
    /// experiment gives. `Err` says what is wrong, in the reader's words, quoting only the
    /// file it names (the experiment's lines, or the scene's under the scene's name). Its
    /// words are one line of printable text each: control characters written `\u{1B}`.
    pub fn parse(text: &str, scene_text: impl Fn(&str) -> SceneText) -> Result<Experiment, String> {
        use phonglab_core::document::toml_error_text;
        let file: File = toml::from_str(text).map_err(|e| toml_error_text(text, &e))?;
        if file.text.is_empty() {
            return Err(t!("experiment-no-text"));
        }
        if let Some(id) = &file.control
            && !crate::locale::has_message(Lang::En, id)
        {
            return Err(t!(
                "experiment-no-control",
                control = phonglab_core::numerics::strict::quoted_line(&printable(id))
            ));
        }
        let shown = phonglab_core::numerics::strict::quoted_line(&printable(&file.scene));
        let (base, name) = match scene_text(&file.scene) {
            SceneText::Found(text, name) => (text, name),
            SceneText::Missing => return Err(t!("experiment-no-scene", scene = shown)),
            SceneText::Refused(why) => return Err(t!("experiment-scene-refused", scene = shown, why = why)),
        };
        let in_scene = |e: String| t!("experiment-scene-error", scene = name.clone(), error = e);
        let table = toml::from_str::<toml::Table>(&base).map_err(|e| in_scene(toml_error_text(&base, &e)))?;
        Document::from_toml(&base).map_err(|e| in_scene(e.to_string()))?;
        let mut scene: toml::Value = table.into();
        if let Some(changes) = &file.changes {
            merge(&mut scene, &toml::Value::Table(changes.clone()));
        }
        let merged = toml::to_string(&scene).map_err(|e| e.to_string())?;
        // The changes' error: what is wrong, never a line of the merged text (it is neither
        // file's).
        let doc = Document::from_toml(&merged).map_err(|e| {
            t!("experiment-changes-refused", scene = name.clone(), error = without_place(&e.to_string()))
        })?;
        let text = file.text.into_iter().map(|(lang, w)| (lang, w.printable())).collect();
        Ok(Experiment {
            source: String::new(),
            doc,
            answer: file.answer,
            light: file.light,
            control: file.control,
            text,
        })
    }

    /// The label of the control its words tell the class to move, in the reader's language.
    pub fn control_label(&self) -> Option<String> {
        self.control.as_deref().map(crate::locale::tr)
    }

    /// The words in `lang`, else in English, else the first language the file has.
    pub fn words(&self, lang: Lang) -> &Words {
        self.text
            .get(lang.code())
            .or_else(|| self.text.get("en"))
            .or_else(|| self.text.values().next())
            .expect("parse refuses a file without words")
    }
}

impl Words {
    /// The words with every control character written visibly (`\u{1B}`): a title, what to
    /// look for and the question are each one line of printable text.
    fn printable(self) -> Words {
        Words { title: printable(&self.title), look: printable(&self.look), question: printable(&self.question) }
    }
}

/// A document error's message without its place and excerpt (the first line, after
/// "line L, column C: "), for an error whose place is in a text no file holds.
fn without_place(message: &str) -> String {
    let first = message.lines().next().unwrap_or_default();
    // "line \0, column \0" in the reader's language: the words around the numbers.
    let pattern = t!("toml-place", line = "\u{0}", column = "\u{0}");
    let words: Vec<&str> = pattern.split('\u{0}').collect();
    match (first.split_once(": "), words.as_slice()) {
        (Some((place, what)), [line, column, ..]) if place.starts_with(line) && place.contains(column) => {
            what.to_string()
        }
        _ => first.to_string(),
    }
}

/// Lays `over` on `base`: tables key by key, a list of tables item by item (a longer list
/// adds items), anything else replaced.
pub fn merge(base: &mut toml::Value, over: &toml::Value) {
    use toml::Value as V;
    match (base, over) {
        (V::Table(b), V::Table(o)) => {
            for (k, v) in o {
                match b.get_mut(k) {
                    Some(slot) => merge(slot, v),
                    None => {
                        b.insert(k.clone(), v.clone());
                    }
                }
            }
        }
        (V::Array(b), V::Array(o)) if o.iter().all(toml::Value::is_table) && b.iter().all(toml::Value::is_table) => {
            for (i, v) in o.iter().enumerate() {
                match b.get_mut(i) {
                    Some(slot) => merge(slot, v),
                    None => b.push(v.clone()),
                }
            }
        }
        (slot, v) => *slot = v.clone(),
    }
}

/// A shipped scene's text by its stem ("worksheet-mview1", "redbook-teapots/11-gold").
fn shipped_scene(name: &str) -> Option<String> {
    let file = format!("{}.toml", name.trim_end_matches(".toml"));
    crate::io::scenes::SCENE_FILES.iter().find(|(path, _)| *path == file).map(|(_, text)| text.to_string())
}

/// [`shipped_scene`] as an experiment's scene.
fn shipped_as_scene(name: &str) -> SceneText {
    shipped_scene(name).map_or(SceneText::Missing, |text| SceneText::Found(text, printable(name)))
}

/// The shipped experiments, in file order, parsed once (every one parses: a test checks).
pub fn shipped() -> &'static [Experiment] {
    static ALL: std::sync::OnceLock<Vec<Experiment>> = std::sync::OnceLock::new();
    ALL.get_or_init(|| {
        EXPERIMENT_FILES
            .iter()
            .filter_map(|(path, text)| {
                let mut e = Experiment::parse(text, shipped_as_scene).ok()?;
                e.source = format!("assets/experiments/{path}");
                Some(e)
            })
            .collect()
    })
}

/// A teacher's own experiments in `dir` (each `.toml` in it, by name), and for each file
/// that does not load, its name and why: regular files, never read through a link. A scene
/// named in one is a shipped scene or a regular file in `dir`, named without a folder
/// (never `..`, an absolute path or a link).
/// At most [`MAX_EXPERIMENTS`] files are read, each at most [`MAX_EXPERIMENT_BYTES`], and
/// [`MAX_FOLDER_BYTES`] in all with their scenes; past that a file is refused unread.
pub fn in_folder(dir: &Path) -> (Vec<Experiment>, Vec<String>) {
    let mut found = Vec::new();
    let mut refused = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else { return (found, refused) };
    let mut paths: Vec<_> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .filter(|p| std::fs::symlink_metadata(p).is_ok_and(|m| m.is_file()))
        .collect();
    paths.sort();
    let read = std::cell::Cell::new(0u64);
    // Reads a file of the folder under its own cap and what is left of the folder's.
    let take = |path: &Path, cap: u64, kind: &str| -> Result<String, String> {
        let left = MAX_FOLDER_BYTES.saturating_sub(read.get());
        let size = std::fs::metadata(path).map_or(0, |m| m.len());
        if size > left {
            return Err(t!(
                "experiment-folder-full",
                most = phonglab_core::mesh::obj::describe_bytes(MAX_FOLDER_BYTES)
            ));
        }
        let text = crate::io::input_file::read_text_capped(path, cap, kind)?;
        read.set(read.get() + text.len() as u64);
        Ok(text)
    };
    let beside = |name: &str| match shipped_as_scene(name) {
        SceneText::Missing => beside_scene(dir, name, &take),
        found => found,
    };
    for (k, p) in paths.iter().enumerate() {
        let name = printable(&p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default());
        if k >= MAX_EXPERIMENTS {
            refused.push(format!("{name}: {}", t!("experiment-too-many", most = MAX_EXPERIMENTS)));
            continue;
        }
        let parsed = take(p, MAX_EXPERIMENT_BYTES, &t!("file-kind-experiments"))
            .and_then(|text| Experiment::parse(&text, beside));
        match parsed {
            Ok(mut e) => {
                e.source = crate::io::reasons::shown(p);
                found.push(e);
            }
            Err(why) => refused.push(format!("{name}: {why}")),
        }
    }
    (found, refused)
}

/// The scene file `name` beside the experiments in `dir`, read with `take`: only a plain
/// file name (no folder, not `..`, not absolute) of a regular file (not a link).
fn beside_scene(dir: &Path, name: &str, take: &dyn Fn(&Path, u64, &str) -> Result<String, String>) -> SceneText {
    let plain = !name.is_empty() && name != "." && name != ".." && !name.contains(['/', '\\', ':']);
    if !plain {
        return SceneText::Refused(t!("experiment-scene-not-beside"));
    }
    let path = dir.join(name);
    match std::fs::symlink_metadata(&path) {
        Err(_) => SceneText::Missing,
        Ok(m) if !m.is_file() => SceneText::Refused(t!("experiment-scene-not-beside")),
        Ok(_) => match take(&path, crate::io::input_file::MAX_SCENE_BYTES, &t!("file-kind-scenes")) {
            Ok(text) => SceneText::Found(text, printable(name)),
            Err(why) => SceneText::Refused(why),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shipped_experiment_loads_with_its_words_in_the_three_languages() {
        assert_eq!(shipped().len(), EXPERIMENT_FILES.len(), "every shipped experiment parses");
        assert!((8..=10).contains(&shipped().len()), "{}", shipped().len());
        for e in shipped() {
            for lang in ["en", "pt-PT", "pt-BR"] {
                let w = e.text.get(lang).unwrap_or_else(|| panic!("{}: no {lang}", e.source));
                assert!(!w.title.is_empty() && !w.look.is_empty() && w.question.ends_with('?'), "{}", e.source);
            }
        }
    }

    #[test]
    fn changes_lie_over_the_scene_table_by_table_and_light_by_light() {
        let mut base: toml::Value = toml::from_str::<toml::Table>(
            "name = \"a\"\n[material]\nshininess = 5\npreset = \"gold\"\n[[lights]]\nposition = [0, 0, 1, 1]\n\
             diffuse = [1, 1, 1]\n[[lights]]\nposition = [1, 0, 0, 0]\n",
        )
        .unwrap()
        .into();
        let over: toml::Value = toml::from_str::<toml::Table>(
            "name = \"b\"\n[material]\nshininess = 90\nlights = 3\n[[lights]]\nposition = [0, 0, -40, 1]\n",
        )
        .unwrap()
        .into();
        merge(&mut base, &over);
        let t = base.as_table().unwrap();
        assert_eq!(t["name"].as_str(), Some("b"));
        assert_eq!(t["material"]["shininess"].as_integer(), Some(90));
        assert_eq!(t["material"]["preset"].as_str(), Some("gold"), "kept");
        let lights = t["lights"].as_array().unwrap();
        assert_eq!(lights.len(), 2, "the second light kept");
        assert_eq!(lights[0]["position"].as_array().unwrap()[2].as_integer(), Some(-40));
        assert_eq!(lights[0]["diffuse"].as_array().unwrap().len(), 3, "the first light's other keys kept");
    }

    #[test]
    fn a_teachers_folder_gives_its_experiments_and_says_why_a_file_does_not_load() {
        let dir = std::env::temp_dir().join(format!("phonglab-experiments-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("mine.toml"), "name = \"mine\"\n[material]\nshininess = 7\n").unwrap();
        let good = "scene = \"mine.toml\"\nanswer = \"Ispec\"\n[changes.material]\nshininess = 60\n\
                    [text.pt-PT]\ntitle = \"O meu\"\nlook = \"Olhem.\"\nquestion = \"Porquê?\"\n";
        std::fs::write(dir.join("a-good.toml"), good).unwrap();
        std::fs::write(
            dir.join("b-bad.toml"),
            "scene = \"nowhere\"\nanswer = \"d\"\n[text.en]\ntitle = \"x\"\nlook = \"y\"\nquestion = \"z?\"\n",
        )
        .unwrap();
        std::fs::write(dir.join("c-range.toml"), "scene = \"worksheet-mview1\"\nanswer = \"d\"\n[changes.material]\nshininess = 900\n[text.en]\ntitle = \"x\"\nlook = \"y\"\nquestion = \"z?\"\n").unwrap();
        let (found, refused) = in_folder(&dir);
        // mine.toml is a scene, not an experiment: refused too, with why.
        assert_eq!(found.len(), 1, "{refused:?}");
        assert_eq!(found[0].doc.scene.material.shininess, 60.0);
        assert_eq!(found[0].words(Lang::En).title, "O meu", "the only language it has");
        assert_eq!(refused.len(), 3, "{refused:?}");
        assert!(refused.iter().any(|r| r.starts_with("b-bad.toml") && r.contains("nowhere")), "{refused:?}");
        assert!(refused.iter().any(|r| r.starts_with("c-range.toml") && r.contains("shininess")), "{refused:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// An experiment names the control its words tell the class to move by its label's
    /// catalogue id: the label in the reader's language; an id the catalogue lacks is
    /// refused with why.
    #[test]
    fn an_experiment_names_its_control_by_its_labels_id() {
        let text = |control: &str| {
            format!(
                "scene = \"worksheet-mview1\"\nanswer = \"d\"\ncontrol = \"{control}\"\n\
                 [text.en]\ntitle = \"x\"\nlook = \"y\"\nquestion = \"z?\"\n"
            )
        };
        let e = Experiment::parse(&text("light-z"), shipped_as_scene).unwrap();
        assert_eq!(e.control_label().as_deref(), Some("Light z"));
        let why = Experiment::parse(&text("light-w"), shipped_as_scene).unwrap_err();
        assert!(why.contains("light-w"), "{why}");
        assert_eq!(by_stem("01-light-behind").control.as_deref(), Some("light-z"));
    }

    fn by_stem(stem: &str) -> &'static Experiment {
        shipped().iter().find(|e| e.source.contains(stem)).unwrap()
    }

    /// An experiment in `dir` named `name` whose scene is `scene` (and whose title is
    /// `title`).
    fn experiment(dir: &Path, name: &str, scene: &str, title: &str) {
        let text = format!(
            "scene = {}\nanswer = \"d\"\n[text.en]\ntitle = {}\nlook = \"y\"\nquestion = \"z?\"\n",
            phonglab_core::escape::toml::string(scene),
            phonglab_core::escape::toml::string(title)
        );
        std::fs::write(dir.join(name), text).unwrap();
    }

    fn folder(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("phonglab-experiments-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Issue 54, 3: an experiment names only a scene beside it or a shipped one; nothing
    /// else is read, and no refusal quotes a line of another file.
    #[test]
    #[cfg(unix)]
    fn an_experiment_reads_only_a_scene_beside_it_or_a_shipped_one() {
        let dir = folder("outside");
        let secret = dir.join("../phonglab-secret.txt");
        std::fs::write(&secret, "root:x:0:0:the first line of someone's file\n").unwrap();
        std::os::unix::fs::symlink(&secret, dir.join("link.toml")).unwrap();
        let hostile = ["../../../../etc/passwd", "/etc/passwd", "../phonglab-secret.txt", "link.toml"];
        for (k, scene) in hostile.iter().enumerate() {
            experiment(&dir, &format!("e{k}.toml"), scene, "x");
        }
        let (found, refused) = in_folder(&dir);
        assert!(found.is_empty(), "{found:?}");
        let said = refused.join("\n");
        assert!(!said.contains("root:") && !said.contains("first line"), "{said}");
        for k in 0..4 {
            let line = refused.iter().find(|r| r.starts_with(&format!("e{k}.toml"))).unwrap();
            assert!(line.contains("by its name alone"), "{line}");
        }
        let _ = std::fs::remove_file(&secret);
    }

    /// An error quotes only the file it names: a broken scene beside the experiment is
    /// quoted under the scene's name, and only a short piece of its line.
    #[test]
    fn a_broken_scene_is_quoted_under_its_own_name_and_briefly() {
        let dir = folder("broken-scene");
        std::fs::write(dir.join("s.toml"), format!("name = {}\n", "A".repeat(100_000))).unwrap();
        experiment(&dir, "e.toml", "s.toml", "x");
        std::fs::write(dir.join("f.toml"), format!("scene = \"s.toml\"\nbroken = {}\n", "B".repeat(50_000))).unwrap();
        let (_, refused) = in_folder(&dir);
        let e = refused.iter().find(|r| r.starts_with("e.toml")).unwrap();
        assert!(e.contains("the scene s.toml does not load") && e.contains("AAAA"), "{e}");
        let f = refused.iter().find(|r| r.starts_with("f.toml")).unwrap();
        assert!(f.contains("BBBB") && !f.contains("AAAA"), "{f}");
        assert!(refused.iter().all(|r| r.len() < 600), "no whole line quoted: {refused:?}");
    }

    /// Issue 54, 4: the folder is read for a bounded number of bounded files.
    #[test]
    fn a_folder_of_many_or_large_experiments_is_read_only_up_to_its_caps() {
        let dir = folder("caps");
        std::fs::write(dir.join("big.toml"), vec![b'#'; 1 << 20]).unwrap();
        for k in 0..MAX_EXPERIMENTS + 5 {
            experiment(&dir, &format!("e{k:03}.toml"), "worksheet-mview1", &format!("number {k}"));
        }
        let (found, refused) = in_folder(&dir);
        assert_eq!(found.len(), MAX_EXPERIMENTS - 1, "the big file takes one place, refused unread");
        let big = refused.iter().find(|r| r.starts_with("big.toml")).unwrap();
        assert!(big.contains("at most 65 536 bytes"), "{big}");
        assert_eq!(refused.iter().filter(|r| r.contains("at most 64 experiments")).count(), 6, "{refused:?}");
    }

    /// A title (and what to look for, and the question) keeps no control character.
    #[test]
    fn an_experiments_words_keep_no_control_character() {
        let dir = folder("title");
        experiment(&dir, "e.toml", "worksheet-mview1", "Look\u{1b}[2J here\u{202e}\n");
        let (found, _) = in_folder(&dir);
        let title = &found[0].words(Lang::En).title;
        assert_eq!(title, "Look\\u{1B}[2J here\\u{202E}\\u{A}");
    }
}
