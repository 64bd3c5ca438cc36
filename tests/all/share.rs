//! A scene in a link (`phonglab share`, the fragment of the browser build's address): every
//! shipped scene goes there and back unchanged in at most 1 500 characters; damaged, old,
//! oversized or hostile fragments are refused with a message that says why, never a panic,
//! and never inflated past the bound; the command line prints the link and writes its QR
//! code.

use crate::common;

use std::path::Path;

use common::phonglab;
use phonglab_core::Document;
use phonglab_core::export::share::{self, MAX_FRAGMENT, ShareError, Shared, decode, encode};

fn shared(doc: Document) -> Shared {
    Shared { lang: Some("pt-BR".into()), present: true, channel: Some("specular".into()), ..Shared::of(doc) }
}

#[test]
fn every_shipped_scene_goes_there_and_back_in_at_most_1500_characters() {
    let mut longest = 0;
    for f in common::scene_files() {
        let doc = Document::from_toml(&std::fs::read_to_string(&f).unwrap()).unwrap();
        let s = shared(doc);
        let link = share::link("https://example.org/phonglab/", &s).unwrap();
        longest = longest.max(link.len());
        assert!(link.len() <= 1500, "{}: {} characters", f.display(), link.len());
        let back = decode(link.split_once('#').unwrap().1).unwrap();
        assert_eq!(back, s, "{}", f.display());
    }
    eprintln!("the longest link: {longest} characters");
    // Without the choices, too; the default scene.
    let plain = Shared::of(Document::default());
    assert_eq!(decode(&format!("#{}", encode(&plain).unwrap())).unwrap(), plain);
}

/// A fragment with this payload, deflated and encoded as a link's.
fn fragment_of(payload: &[u8]) -> String {
    use base64::Engine as _;
    let deflated = miniz_oxide::deflate::compress_to_vec(payload, 6);
    format!("v1.{}", base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(deflated))
}

#[test]
fn damaged_old_oversized_and_hostile_fragments_are_refused_with_a_reason() {
    let good = encode(&shared(Document::default())).unwrap();
    let cases: Vec<(String, &str)> = vec![
        (good.replacen("v1.", "v2.", 1), "version"),
        ("no-dot-at-all".into(), "version"),
        ("v1.!!!not base64!!!".into(), "damaged"),
        ("v1.AAAAAAAA".into(), "damaged"),
        (good[..good.len() / 2].to_string(), "damaged"),
        ("v1.".to_string() + &"A".repeat(MAX_FRAGMENT), "characters"),
        // A bomb: a megabyte of zeros deflates to about a kilobyte (said as too big).
        (fragment_of(&vec![b'0'; 1 << 20]), "inflates past 262144 bytes"),
        // Bytes after the deflated scene: the link was changed.
        (good.clone() + "AAAA", "damaged"),
        (fragment_of(b"phonglab-share 1\ncolour = red\n\nname = \"x\"\n"), "does not know"),
        (fragment_of(b"phonglab-share 1\nlang = klingon\n\nname = \"x\"\n"), "does not know"),
        (fragment_of(b"phonglab-share 1\n\n[material]\nshininess = 500\n"), "shininess"),
        (fragment_of(b"phonglab-share 1\n\nnot toml at all [[["), ""),
        (fragment_of(b"something else\n\nname = \"x\"\n"), "damaged"),
    ];
    for (fragment, says) in cases {
        let e = decode(&fragment).expect_err(&fragment[..fragment.len().min(40)]);
        let text = e.to_string();
        assert!(text.contains(says), "{says:?} not in {text:?}");
        if says == "characters" {
            assert!(matches!(e, ShareError::TooLong(_)));
        }
    }
}

/// Random damage never panics: bytes flipped in a good link, and random text after `v1.`.
#[test]
fn random_damage_never_panics() {
    let good = encode(&shared(Document::default())).unwrap();
    let mut s = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s
    };
    let alphabet: Vec<char> = ('A'..='Z').chain('a'..='z').chain('0'..='9').chain(['-', '_', '.', '%']).collect();
    let mut opened = 0;
    for _ in 0..3000 {
        let mut chars: Vec<char> = good.chars().collect();
        for _ in 0..1 + next() % 4 {
            let at = 3 + (next() as usize) % (chars.len() - 3);
            chars[at] = alphabet[(next() as usize) % alphabet.len()];
        }
        let damaged: String = chars.into_iter().collect();
        opened += decode(&damaged).is_ok() as usize;
        let len = (next() % 300) as usize;
        let random: String = (0..len).map(|_| alphabet[(next() as usize) % alphabet.len()]).collect();
        let _ = decode(&format!("v1.{random}"));
    }
    // A flipped character in deflate's data almost always breaks it (its checksum).
    assert!(opened < 300, "{opened}");
}

#[test]
fn the_command_prints_the_link_and_writes_its_qr_code() {
    let dir = std::env::temp_dir().join(format!("phonglab-share-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let (png, svg) = (dir.join("qr.png"), dir.join("qr.svg"));
    let out = phonglab(&[
        "share",
        scene.to_str().unwrap(),
        "--base",
        "http://localhost:8080/phonglab/",
        "--open-in",
        "pt-PT",
        "--present",
        "--qr",
        png.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let link = String::from_utf8(out.stdout).unwrap().trim().to_string();
    assert!(link.starts_with("http://localhost:8080/phonglab/#v1."), "{link}");
    let back = decode(link.split_once('#').unwrap().1).unwrap();
    let doc = Document::from_toml(&std::fs::read_to_string(&scene).unwrap()).unwrap();
    assert_eq!(back, Shared { lang: Some("pt-PT".into()), present: true, ..Shared::of(doc) });
    let (w, h, rgba) = phonglab::io::image::read_png(&png).unwrap();
    assert_eq!(w, h);
    assert!(w >= 8 * (21 + 8), "{w}: a module is 8 pixels, with the quiet zone");
    let dark = rgba.chunks(4).filter(|p| p[0] == 0).count();
    assert!(dark * 5 > w * h && dark * 5 < 4 * w * h, "{dark} dark of {}", w * h);
    assert!(phonglab(&["share", "--qr", svg.to_str().unwrap()]).status.success());
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    // The code may not be written over the scene; an unknown language is refused.
    let onto = phonglab(&["share", scene.to_str().unwrap(), "--qr", scene.to_str().unwrap()]);
    assert_eq!(onto.status.code(), Some(2));
    assert_eq!(phonglab(&["share", "--open-in", "xx"]).status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The window opens a link's fragment: the scene, the language, presenting and the term
/// shown; a damaged one leaves the scene as it was and says why.
#[test]
fn the_window_opens_a_link_and_refuses_a_damaged_one() {
    use phonglab::app::AppState;
    use phonglab::app::editing::message::Message;
    use phonglab::app::shell::shared_link::open_fragment;
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/three-lights.toml");
    let doc = Document::from_toml(&std::fs::read_to_string(scene).unwrap()).unwrap();
    let fragment = encode(&shared(doc.clone())).unwrap();
    let mut state = AppState::worksheet();
    open_fragment(&mut state, &fragment);
    assert_eq!(state.doc, doc);
    assert_eq!(state.ui.layout.language.as_deref(), Some("pt-BR"));
    // Said in the link's language, not the language the window had.
    assert!(
        matches!(&state.message, Some(Message::Info(m)) if m.contains("link compartilhado")),
        "{:?}",
        state.message
    );
    assert!(state.ui.layout.presenting);
    assert_eq!(state.view_options.channel, Some(phonglab_core::channels::Channel::Specular));
    let before = state.doc.clone();
    open_fragment(&mut state, &fragment[..fragment.len() - 9]);
    assert_eq!(state.doc, before, "a damaged link changes nothing");
    assert!(matches!(&state.message, Some(Message::Refused(m)) if m.contains("damaged")), "{:?}", state.message);
}

/// The payload a fragment carries, inflated.
fn payload_of(fragment: &str) -> String {
    use base64::Engine as _;
    let body = fragment.split_once('.').unwrap().1;
    let deflated = base64::engine::general_purpose::URL_SAFE_NO_PAD.decode(body).unwrap();
    String::from_utf8(miniz_oxide::inflate::decompress_to_vec(&deflated).unwrap()).unwrap()
}

#[test]
fn a_scene_with_a_mesh_names_the_file_alone_and_asks_for_it_until_it_is_opened() {
    use phonglab::app::AppState;
    use phonglab::app::editing::message::Message;
    use phonglab::app::shell::files::open_bytes;
    use phonglab::app::shell::shared_link::open_fragment;
    use phonglab_core::ObjectKind;
    // A mesh in a folder of the sharer's: the link names the file, never the folder.
    let dir = std::env::temp_dir().join(format!("phonglab-share-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let name = format!("tetra-{}.obj", std::process::id());
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    std::fs::write(dir.join(&name), obj).unwrap();
    let mut doc = Document::default();
    doc.view.object = ObjectKind::Obj;
    doc.view.obj = Some(dir.join(&name).display().to_string());
    doc.validate().unwrap();
    let fragment = encode(&Shared { lang: Some("en".into()), ..Shared::of(doc.clone()) }).unwrap();
    let payload = payload_of(&fragment);
    assert!(payload.contains(&format!("obj = \"{name}\"")), "{payload}");
    assert!(!payload.contains(dir.to_str().unwrap()), "the sharer's folder is not in the link: {payload}");

    // Opened where the mesh is not: the scene on the sphere, and the file asked for by name.
    let back = decode(&fragment).unwrap();
    assert_eq!(back.missing_mesh.as_deref(), Some(name.as_str()));
    assert_eq!(back.doc.view.object, ObjectKind::Sphere);
    assert_eq!(back.doc.scene, doc.scene, "the rest of the scene is the link's");
    let mut state = AppState::worksheet();
    open_fragment(&mut state, &fragment);
    assert_eq!(state.doc.scene, doc.scene);
    assert_eq!(state.doc.view.object, ObjectKind::Sphere);
    assert!(
        matches!(&state.message, Some(Message::Info(m)) if m.contains(&name) && m.contains("open or drop")),
        "{:?}",
        state.message
    );

    // The file given as bytes (as the browser gives it: a name, no path) is shown.
    open_bytes(&mut state, obj.as_bytes(), Path::new(&name));
    assert_eq!(state.doc.view.object, ObjectKind::Obj);
    assert_eq!(state.doc.view.obj.as_deref(), Some(name.as_str()));
    assert_eq!(state.doc.view.mesh().triangle_count(), 4);
    assert!(
        matches!(&state.message, Some(Message::Info(m)) if m.contains(&name) && m.contains("4 triangles")),
        "{:?}",
        state.message
    );
    // And a link naming it now opens with the mesh.
    let mut again = AppState::worksheet();
    open_fragment(&mut again, &fragment);
    assert_eq!(again.doc.view.object, ObjectKind::Obj);
    assert_eq!(again.doc.view.mesh().triangle_count(), 4);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_mesh_given_as_bytes_meets_the_desktops_limits_and_messages() {
    use phonglab_core::mesh::obj::{load_obj, load_obj_bytes};
    let dir = std::env::temp_dir().join(format!("phonglab-bytes-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (text, says) in [
        ("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "out of range"),
        ("v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n", "line 2"),
        ("v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3"),
    ] {
        let path = dir.join("broken.obj");
        std::fs::write(&path, text).unwrap();
        let from_file = load_obj(&path).unwrap_err();
        let from_bytes = load_obj_bytes("broken.obj", text.as_bytes()).unwrap_err();
        assert!(from_bytes.contains(says), "{from_bytes}");
        assert_eq!(from_file.replace(&path.display().to_string(), "broken.obj"), from_bytes);
    }
    let e =
        phonglab_core::mesh::obj::refuse_too_large("big.obj", phonglab_core::mesh::obj::MAX_OBJ_BYTES + 1).unwrap_err();
    assert!(e.contains("big.obj") && e.contains("536 870 913 bytes"), "{e}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_file_packed_for_the_pages_storage_comes_back_whole_or_is_refused() {
    let bytes: Vec<u8> = (0..200_000u32).map(|i| (i % 251) as u8 ^ (i / 997) as u8).collect();
    let packed = share::pack_bytes(&bytes);
    assert!(packed.len() < bytes.len(), "{} of {}", packed.len(), bytes.len());
    assert_eq!(share::unpack_bytes(&packed, bytes.len()).unwrap(), bytes);
    let e = share::unpack_bytes(&packed, bytes.len() - 1).unwrap_err();
    assert_eq!(e, ShareError::TooBig(bytes.len() - 1));
    assert!(e.to_string().contains("inflates past 199999 bytes"), "{e}");
    assert!(matches!(share::unpack_bytes(&packed[..packed.len() / 2], 1 << 20), Err(ShareError::Damaged(_))));
    assert!(matches!(share::unpack_bytes("not base64!", 1 << 20), Err(ShareError::Damaged(_))));
}

/// File → Share link… at a window size: the window shows the link the command line would
/// make (the choices as ticked), copies it, and draws its QR code large, square and on
/// screen, beside the link rather than over it.
fn share_window_at(w: f32, ht: f32) {
    use egui::accesskit::Role;
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;
    use phonglab::app::editing::message::Message;
    use phonglab::app::{AppState, app_ui};
    let mut h = Harness::builder()
        .with_size([w, ht])
        .build_ui_state(|ui, s: &mut AppState| app_ui(ui, s), AppState::worksheet());
    h.run_steps(3);
    common::menu_item(&mut h, &["File"], "Share link…");
    h.run_steps(3);
    assert!(h.state().share.open);
    let doc = h.state().doc.clone();
    let expected =
        share::link(share::DEFAULT_BASE, &Shared { lang: Some("en".into()), ..Shared::of(doc.clone()) }).unwrap();
    let link = h.get_by_label(&expected).rect();
    let qr = h.get_by_role_and_label(Role::Image, "QR code of the link").rect();
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(w, ht));
    assert!((qr.width() - qr.height()).abs() < 0.5, "{qr:?}");
    assert!(qr.width() >= 0.55 * w.min(ht), "{qr:?} at {w}x{ht}: large enough for a room");
    assert!(screen.contains_rect(qr) && screen.contains_rect(link), "{qr:?} {link:?}");
    assert!(!qr.intersects(link), "{qr:?} {link:?}");
    // Copied as shown; and what is copied opens this scene.
    h.get_by_label("Copy link").click();
    h.run_steps(1);
    assert_eq!(common::copied_text(&h), vec![expected.clone()]);
    assert!(
        matches!(&h.state().message, Some(Message::Info(m)) if m.starts_with("Link copied")),
        "{:?}",
        h.state().message
    );
    let back = decode(expected.split_once('#').unwrap().1).unwrap();
    assert_eq!(back.doc, doc);
    assert!(!back.present);
    // Ticking "presenting" makes another link, which asks for it.
    h.get_by_role_and_label(Role::CheckBox, "Open presenting to a class").click();
    h.run_steps(2);
    let presenting =
        share::link(share::DEFAULT_BASE, &Shared { lang: Some("en".into()), present: true, ..Shared::of(doc) })
            .unwrap();
    assert_ne!(presenting, expected);
    assert!(h.query_by_label(&presenting).is_some(), "the link follows the choices");
    assert!(h.query_by_label(&expected).is_none());
}

#[test]
fn the_share_window_shows_copies_and_draws_the_link_at_1280x720() {
    share_window_at(1280.0, 720.0);
}

#[test]
fn the_share_window_shows_copies_and_draws_the_link_at_1024x600() {
    share_window_at(1024.0, 600.0);
}

/// `zbarimg`'s reading of the QR code in the PNG at `path` (zbar-tools, installed by
/// scripts/test): the text, without its `QR-Code:` prefix.
fn scanned(path: &Path) -> String {
    let out = std::process::Command::new("zbarimg")
        .args(["--quiet", "--raw", "-Sbinary"])
        .arg(path)
        .output()
        .expect("zbarimg (Debian's zbar-tools; scripts/test installs it)");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap().trim_end_matches('\n').to_string()
}

#[test]
fn a_scanner_reads_the_link_back_from_the_windows_code_and_the_commands() {
    let dir = std::env::temp_dir().join(format!("phonglab-qr-scan-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // The longest shipped scene's link, as the window draws it (one pixel a module, scaled
    // here as the window scales it, error correction L) and as `share --qr` writes it (M).
    let longest = common::scene_files()
        .into_iter()
        .map(|f| {
            let doc = Document::from_toml(&std::fs::read_to_string(&f).unwrap()).unwrap();
            share::link(share::DEFAULT_BASE, &shared(doc)).unwrap()
        })
        .max_by_key(String::len)
        .unwrap();
    let (n, rgba) = phonglab::io::qr::qr_rgba_at(&longest, 3, qrcode::EcLevel::L).unwrap();
    let window = dir.join("window.png");
    phonglab::io::image::write_png(&window, n, n, &rgba).unwrap();
    assert_eq!(scanned(&window), longest);
    let png = dir.join("cli.png");
    let out = phonglab(&["share", "--open-in", "pt-BR", "--qr", png.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let printed = String::from_utf8(out.stdout).unwrap().trim().to_string();
    assert_eq!(scanned(&png), printed);
    std::fs::remove_dir_all(&dir).ok();
}

/// A link where a scene file is taken: the command line reads the scene it carries with
/// the browser build's decoder (so `phonglab explain LINK` is the scene's calculation), and
/// says why a cut link or one with no scene is not read; a page that is not an http(s)
/// address is refused before a link is made.
#[test]
fn a_link_is_a_scene_wherever_a_scene_file_is_taken_and_its_page_is_http() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let out = phonglab(&["share", scene.to_str().unwrap()]);
    let link = String::from_utf8(out.stdout).unwrap().trim().to_string();
    let from_link = phonglab(&["explain", &link]);
    assert!(from_link.status.success(), "{}", String::from_utf8_lossy(&from_link.stderr));
    let from_file = phonglab(&["explain", scene.to_str().unwrap()]);
    assert_eq!(String::from_utf8_lossy(&from_link.stdout), String::from_utf8_lossy(&from_file.stdout));
    let cut = phonglab(&["explain", &link[..link.len() - 12]]);
    let said = String::from_utf8_lossy(&cut.stderr);
    assert!(!cut.status.success() && said.contains("…: the link is damaged"), "{said}");
    assert!(!said.contains("does not exist"), "{said}");
    let bare = phonglab(&["explain", "https://phonglab.github.io/phonglab/"]);
    assert!(String::from_utf8_lossy(&bare.stderr).contains("holds no scene"));
    for base in ["not a url", "javascript:alert(1)//", "https://e.org/\u{1b}[31m", "https:///", "http://#x"] {
        let o = phonglab(&["share", "--base", base]);
        let said = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && said.contains("http:// or https://") && o.stdout.is_empty(), "{said}");
    }
}

/// A damaged link is said in the user's words, one word for "link" a language, never the
/// decoder's own text (`Invalid last symbol`, `FailedCannotMakeProgress`).
#[test]
fn a_damaged_link_is_said_in_the_users_language_without_decoder_words() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let out = phonglab(&["share", scene.to_str().unwrap()]);
    let link = String::from_utf8(out.stdout).unwrap().trim().to_string();
    let garbage = "https://phonglab.github.io/phonglab/#v1.garbage".to_string();
    for (lang, damaged) in [
        ("en_GB.UTF-8", "the link is damaged: it was cut or changed"),
        ("pt_PT.UTF-8", "a ligação está danificada: foi cortada ou alterada"),
        ("pt_BR.UTF-8", "o link está danificado: foi cortado ou alterado"),
    ] {
        for bad in [garbage.clone(), link[..200].to_string()] {
            let o = common::phonglab_in(lang, &["explain", &bad]);
            let said = String::from_utf8_lossy(&o.stderr);
            assert!(!o.status.success() && said.contains(damaged), "{lang}: {said}");
            for jargon in ["Invalid", "symbol", "offset", "Failed", "Progress", "UTF-8", "("] {
                assert!(!said.contains(jargon), "{lang}: {jargon} in {said}");
            }
        }
    }
}

/// `phonglab screenshot --scene LINK` draws the window as started on the link: its
/// language and presenting taken, not only its scene (N11).
#[test]
fn a_screenshot_of_a_link_takes_its_language_and_presenting() {
    use phonglab::app::shell::screenshot::{Shot, state_of};
    let doc = Document { name: "ruby".into(), ..Default::default() };
    let shared = Shared { lang: Some("pt-PT".into()), present: true, ..Shared::of(doc) };
    let url = share::link("https://example.org/phonglab/", &shared).unwrap();
    let shot = |scene: &str| Shot {
        size: (1024, 600),
        scale: 1.0,
        present: false,
        light: false,
        scene: Some(scene.into()),
        open: None,
        output: "unused.png".into(),
    };
    let state = state_of(&shot(&url)).unwrap();
    assert_eq!(state.doc.name, "ruby");
    assert_eq!(state.ui.layout.language.as_deref(), Some("pt-PT"));
    assert!(state.ui.layout.presenting);
    let plain = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let state = state_of(&shot(plain.to_str().unwrap())).unwrap();
    assert!(!state.ui.layout.presenting && state.ui.layout.language.is_none());
}

/// The desktop app started on a link (`phonglab LINK`) opens the scene and the choices it
/// carries; a cut link opens the worksheet and says why.
#[test]
fn the_app_started_on_a_link_opens_its_scene_or_says_why_not() {
    use phonglab::app::AppState;
    use phonglab::app::shell::state::Message;
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let doc = Document::from_toml(&std::fs::read_to_string(&scene).unwrap()).unwrap();
    let link =
        share::link("https://example.org/phonglab/", &Shared { present: true, ..Shared::of(doc.clone()) }).unwrap();
    let mut s = AppState::worksheet();
    phonglab::app::shell::files::open_at_start(&mut s, Path::new(&link));
    assert_eq!(s.doc.scene, doc.scene);
    assert!(s.ui.layout.presenting);
    let mut s = AppState::worksheet();
    phonglab::app::shell::files::open_at_start(&mut s, Path::new(&link[..link.len() - 12]));
    assert_eq!(s.doc, Document::default());
    assert!(
        matches!(&s.message, Some(Message::Refused(m)) if m.contains("…: the link is damaged") && m.contains("Showing the worksheet")),
        "{:?}",
        s.message
    );
}

/// The scene file's text with its object the mesh file.
fn as_obj(text: &str) -> String {
    text.lines()
        .map(|l| if l.starts_with("object = ") { "object = \"obj\"\n".to_string() } else { format!("{l}\n") })
        .collect()
}

/// A link's scene showing a mesh named with folders (absolute, `..`): phonglab never reads
/// that path (the file is there, readable); the file name alone is kept and asked for, and
/// the command line says so, as it says which mesh is missing where a bare name is not here.
#[test]
fn a_link_never_makes_phonglab_read_a_path_it_names_and_says_which_mesh_is_missing() {
    use phonglab_core::ObjectKind;
    let dir = std::env::temp_dir().join(format!("phonglab-share-far-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("far")).unwrap();
    std::fs::create_dir_all(dir.join("here")).unwrap();
    let far = dir.join("far/x9.obj");
    std::fs::write(&far, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let toml = Document::default().to_toml().unwrap();
    for (obj, shown) in [
        (far.display().to_string(), far.display().to_string()),
        ("../far/x9.obj".into(), "../far/x9.obj".into()),
        ("..\\far\\x9.obj".into(), "..\\far\\x9.obj".into()),
    ] {
        let text =
            format!("{toml}\n").replace("[view]\n", &format!("[view]\nobj = \"{}\"\n", obj.replace('\\', "\\\\")));
        let text = as_obj(&text);
        assert!(text.contains("object = \"obj\""), "{text}");
        let fragment = fragment_of(format!("phonglab-share 1\n\n{text}").as_bytes());
        let back = decode(&fragment).unwrap();
        assert_eq!(back.doc.view.object, ObjectKind::Sphere, "{obj}");
        assert_eq!(back.doc.view.obj.as_deref(), Some("x9.obj"), "{obj}");
        assert_eq!(back.missing_mesh.as_deref(), Some("x9.obj"), "{obj}");
        let note = back.mesh_note.unwrap();
        assert!(note.contains(&shown) && note.contains("never reads a path"), "{note}");
        // The command line, run beside the far folder: the sphere, and the words said.
        let link = format!("https://example.org/#{fragment}");
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_phonglab"))
            .current_dir(dir.join("here"))
            .env("LC_ALL", "C.UTF-8")
            .args(["explain", &link])
            .output()
            .unwrap();
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success() && said.contains("never reads a path") && said.contains("x9.obj"), "{said}");
    }
    // A bare name that is not here (or not a regular file): the sphere, and which mesh, said.
    let text = as_obj(&toml.replacen("[view]\n", "[view]\nobj = \"nonexistent.obj\"\n", 1));
    let link = format!("https://example.org/#{}", fragment_of(format!("phonglab-share 1\n\n{text}").as_bytes()));
    let out = phonglab(&["explain", &link]);
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && said.contains("The mesh nonexistent.obj is missing"), "{said}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A link longer than phonglab opens is not made: the package's, the command's.
#[test]
fn a_link_phonglab_would_not_open_is_not_made() {
    // Letters that do not repeat (a repeated one deflates to nothing).
    let mut x = 1u64;
    let mut letter = || {
        x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        char::from(b'a' + ((x >> 33) % 26) as u8)
    };
    let name: String = (0..30_000).map(|_| letter()).collect();
    let doc = Document { name, ..Default::default() };
    let e = encode(&Shared::of(doc.clone())).unwrap_err();
    assert!(matches!(e, ShareError::MakeTooLong(n) if n > MAX_FRAGMENT), "{e:?}");
    assert!(e.to_string().contains(&format!("at most {MAX_FRAGMENT}")), "{e}");
    let dir = std::env::temp_dir().join(format!("phonglab-share-long-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("long.toml");
    std::fs::write(&f, doc.to_toml().unwrap()).unwrap();
    let out = phonglab(&["share", f.to_str().unwrap()]);
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && out.stdout.is_empty() && said.contains("shorten the scene's name"), "{said}");
    std::fs::remove_dir_all(&dir).ok();
}
