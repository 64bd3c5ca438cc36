//! A scene in a link (`phonglab share`, the fragment of the browser build's address): every
//! shipped scene goes there and back unchanged in at most 1 500 characters; damaged, old,
//! oversized or hostile fragments are refused with a message that says why, never a panic,
//! and never inflated past the bound; the command line prints the link and writes its QR
//! code.

mod common;

use std::path::Path;

use common::phonglab;
use phonglab_core::Document;
use phonglab_core::export::share::{self, MAX_FRAGMENT, ShareError, Shared, decode, encode};

fn shared(doc: Document) -> Shared {
    Shared { doc, lang: Some("pt-BR".into()), present: true, channel: Some("specular".into()) }
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
    let plain = Shared { doc: Document::default(), lang: None, present: false, channel: None };
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
        // A bomb: a megabyte of zeros deflates to about a kilobyte.
        (fragment_of(&vec![b'0'; 1 << 20]), "damaged"),
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
    assert_eq!(back, Shared { doc, lang: Some("pt-PT".into()), present: true, channel: None });
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
    use phonglab::app::model::message::Message;
    use phonglab::app::shell::shared_link::open_fragment;
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/three-lights.toml");
    let doc = Document::from_toml(&std::fs::read_to_string(scene).unwrap()).unwrap();
    let fragment = encode(&shared(doc.clone())).unwrap();
    let mut state = AppState::worksheet();
    open_fragment(&mut state, &fragment);
    assert_eq!(state.doc, doc);
    assert_eq!(state.ui.layout.language.as_deref(), Some("pt-BR"));
    assert!(state.ui.layout.presenting);
    assert_eq!(state.view_options.channel, Some(phonglab_core::channels::Channel::Specular));
    let before = state.doc.clone();
    open_fragment(&mut state, &fragment[..fragment.len() - 9]);
    assert_eq!(state.doc, before, "a damaged link changes nothing");
    assert!(matches!(&state.message, Some(Message::Refused(m)) if m.contains("damaged")), "{:?}", state.message);
}
