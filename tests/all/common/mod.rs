//! Helpers shared by the UI tests. (Each test file uses some of them.)
#![allow(dead_code)]

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use phonglab::app::AppState;

/// Brings the number field named `label` into view and clicks it, as a student does.
pub fn click_field(h: &mut Harness<'static, AppState>, label: &str) {
    h.get_by_role_and_label(Role::SpinButton, label).scroll_to_me();
    // Scrolling is animated: wait for it to settle before clicking.
    h.run_steps(30);
    h.get_by_role_and_label(Role::SpinButton, label).click();
    h.run_steps(1);
}

/// The texts the last frame put on the clipboard.
pub fn copied_text(h: &Harness<'_, AppState>) -> Vec<String> {
    h.output()
        .platform_output
        .commands
        .iter()
        .filter_map(|c| match c {
            egui::OutputCommand::CopyText(t) => Some(t.clone()),
            _ => None,
        })
        .collect()
}

/// Runs the binary in English whatever the machine's locale (tests of the other languages
/// use [`phonglab_in`]).
pub fn phonglab(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
        .env_remove("LC_MESSAGES")
        .env_remove("LANG")
        .env("LC_ALL", "C.UTF-8")
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Runs the binary with the system's language `lang` (`LANG`, the others unset), as a
/// user whose machine speaks it.
pub fn phonglab_in(lang: &str, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", lang)
        .args(args)
        .output()
        .expect("the binary runs")
}

/// A file dropped on the window, as eframe hands it to egui.
#[derive(Debug)]
pub struct Dropped(pub std::path::PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &std::path::Path {
        &self.0
    }
    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// The widgets a user clicks named `label` (not a text or a window's title that reads the
/// same).
fn clickable<'h>(h: &'h Harness<'static, AppState>, label: &'h str) -> Option<egui_kittest::Node<'h>> {
    use egui_kittest::kittest::NodeT;
    h.query_all_by_label(label)
        .rfind(|n| !matches!(n.accesskit_node().role(), Role::Label | Role::Window | Role::TitleBar))
}

/// Opens the menus named in `path` one inside the next (`["File", "Export"]`), as a user
/// clicks through them, and leaves the last one open.
pub fn open_menu(h: &mut Harness<'static, AppState>, path: &[&str]) {
    for m in path {
        h.get_all_by_label(m).last().unwrap_or_else(|| panic!("no menu {m:?}")).click();
        h.run_steps(2);
    }
}

/// Clicks `item` in the menu reached through `path` (opened unless `item` is already on
/// screen, see [`open_menu`]), then closes whatever menu is still open (Escape), as a user
/// does after a switch in the View menu.
pub fn menu_item(h: &mut Harness<'static, AppState>, path: &[&str], item: &str) {
    if clickable(h, item).is_none() {
        open_menu(h, path);
    }
    clickable(h, item).unwrap_or_else(|| panic!("no {item:?} in {path:?}")).click();
    h.run_steps(2);
    h.key_press(egui::Key::Escape);
    h.run_steps(2);
}

/// Every shipped scene file (`assets/scenes/`, its folders too), sorted.
pub fn scene_files() -> Vec<std::path::PathBuf> {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "toml") {
                out.push(p);
            }
        }
    }
    let mut v = Vec::new();
    walk(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes"), &mut v);
    v.sort();
    v
}

/// The primary button pressed (`true`) or let go at `at`, as one event.
pub fn button(h: &mut Harness<'static, AppState>, at: egui::Pos2, pressed: bool) {
    h.input_mut().events.push(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    });
}

/// A drag as a hand makes it: pressed at `from`, moved to `to` in six steps, a frame each,
/// the button still down (let it go with [`button`]).
pub fn press_and_move(h: &mut Harness<'static, AppState>, from: egui::Pos2, to: egui::Pos2) {
    h.input_mut().events.push(egui::Event::PointerMoved(from));
    button(h, from, true);
    h.step();
    for k in 1..=6 {
        h.input_mut().events.push(egui::Event::PointerMoved(from + (to - from) * (k as f32 / 6.0)));
        h.step();
    }
}

/// Makes `link` a symbolic link to `target`. The tests that plant one are not run on
/// Windows (`ignore`d there): making a link takes a privilege (an administrator, or
/// Developer Mode) that a lab PC's student account and a test runner lack, and Wine 8 makes
/// none (`CreateSymbolicLinkW` answers yes and leaves nothing). phonglab's refusal of links
/// on Windows is `open_no_follow`'s (`FILE_FLAG_OPEN_REPARSE_POINT`, the link itself
/// refused through its handle). On Windows a folder link where `target` is a folder.
pub fn symlink(target: impl AsRef<std::path::Path>, link: impl AsRef<std::path::Path>) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(target, link)
    }
    #[cfg(windows)]
    {
        let resolved = link.as_ref().parent().map(|p| p.join(target.as_ref())).unwrap_or_default();
        if resolved.is_dir() {
            std::os::windows::fs::symlink_dir(target, link)
        } else {
            std::os::windows::fs::symlink_file(target, link)
        }
    }
}

/// A folder of a test's own in the system's temporary folder (`phonglab-NAME-PID`), made
/// empty, removed with everything in it when dropped.
pub struct TempDir(pub std::path::PathBuf);

impl TempDir {
    pub fn new(name: &str) -> TempDir {
        let p = std::env::temp_dir().join(format!("phonglab-{name}-{}", std::process::id()));
        std::fs::remove_dir_all(&p).ok();
        std::fs::create_dir_all(&p).unwrap();
        TempDir(p)
    }

    pub fn path(&self) -> &std::path::Path {
        &self.0
    }

    pub fn join(&self, name: &str) -> std::path::PathBuf {
        self.0.join(name)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}
