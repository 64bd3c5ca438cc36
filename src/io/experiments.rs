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
//!                              # beside this one ("my-scene.toml")
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

use phonglab_core::Document;
use phonglab_core::locale::Lang;
use phonglab_core::t;
use serde::Deserialize;

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

impl Experiment {
    /// Reads an experiment's `text`; `scene_text` finds a scene file's text by the name the
    /// experiment gives. `Err` says what is wrong, in the reader's words.
    pub fn parse(text: &str, scene_text: impl Fn(&str) -> Option<String>) -> Result<Experiment, String> {
        let file: File = toml::from_str(text).map_err(|e| e.to_string())?;
        if file.text.is_empty() {
            return Err(t!("experiment-no-text"));
        }
        if let Some(id) = &file.control
            && !phonglab_core::locale::has_message(Lang::En, id)
        {
            return Err(t!("experiment-no-control", control = id.clone()));
        }
        let base = scene_text(&file.scene).ok_or_else(|| t!("experiment-no-scene", scene = file.scene.clone()))?;
        let mut scene: toml::Value = toml::from_str::<toml::Table>(&base).map_err(|e| e.to_string())?.into();
        if let Some(changes) = &file.changes {
            merge(&mut scene, &toml::Value::Table(changes.clone()));
        }
        let merged = toml::to_string(&scene).map_err(|e| e.to_string())?;
        let doc = Document::from_toml(&merged).map_err(|e| e.to_string())?;
        let (answer, light, control, text) = (file.answer, file.light, file.control, file.text);
        Ok(Experiment { source: String::new(), doc, answer, light, control, text })
    }

    /// The label of the control its words tell the class to move, in the reader's language.
    pub fn control_label(&self) -> Option<String> {
        self.control.as_deref().map(phonglab_core::locale::tr)
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

/// The shipped experiments, in file order, parsed once (every one parses: a test checks).
pub fn shipped() -> &'static [Experiment] {
    static ALL: std::sync::OnceLock<Vec<Experiment>> = std::sync::OnceLock::new();
    ALL.get_or_init(|| {
        EXPERIMENT_FILES
            .iter()
            .filter_map(|(path, text)| {
                let mut e = Experiment::parse(text, shipped_scene).ok()?;
                e.source = format!("assets/experiments/{path}");
                Some(e)
            })
            .collect()
    })
}

/// A teacher's own experiments in `dir` (each `.toml` in it, by name), and for each file
/// that does not load, its name and why. A scene named in one is a shipped scene or a file
/// in `dir`.
pub fn in_folder(dir: &Path) -> (Vec<Experiment>, Vec<String>) {
    let mut found = Vec::new();
    let mut refused = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else { return (found, refused) };
    let mut paths: Vec<_> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml") && p.is_file())
        .collect();
    paths.sort();
    let cap = crate::io::input_file::MAX_SCENE_BYTES;
    let beside = |name: &str| {
        shipped_scene(name).or_else(|| crate::io::input_file::read_text_capped(&dir.join(name), cap, "scene").ok())
    };
    for p in paths {
        let name = p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let parsed = crate::io::input_file::read_text_capped(&p, cap, "experiment")
            .and_then(|text| Experiment::parse(&text, beside));
        match parsed {
            Ok(mut e) => {
                e.source = p.display().to_string();
                found.push(e);
            }
            Err(why) => refused.push(format!("{name}: {why}")),
        }
    }
    (found, refused)
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
        let e = Experiment::parse(&text("light-z"), shipped_scene).unwrap();
        assert_eq!(e.control_label().as_deref(), Some("Light z"));
        let why = Experiment::parse(&text("light-w"), shipped_scene).unwrap_err();
        assert!(why.contains("light-w"), "{why}");
        assert_eq!(by_stem("01-light-behind").control.as_deref(), Some("light-z"));
    }

    fn by_stem(stem: &str) -> &'static Experiment {
        shipped().iter().find(|e| e.source.contains(stem)).unwrap()
    }
}
