//! "What is wrong with this picture?": each mistake's switch changes the picture the way
//! its key says (`misconception::check`), its pictures differ, its key names the cause and
//! gives the probe's numbers in the reader's language, and the exercise set's new level
//! prints both pictures in its PDF.

mod common;

use phonglab_core::misconception::{self, Misconception};

const SIZE: usize = 96;

#[test]
fn every_mistake_changes_the_picture_as_its_key_says() {
    for kind in Misconception::ALL {
        let case = misconception::case(kind);
        let drawn = case.draw(SIZE).unwrap();
        misconception::check(&case, &drawn).unwrap_or_else(|e| panic!("{kind:?}: {e}"));
        assert_ne!(drawn.correct, drawn.bugged, "{kind:?}");
        let key = misconception::key_lines(&case, &drawn);
        let text = key.join("\n");
        assert!(text.contains(&kind.cause()), "{kind:?}: {text}");
        let bytes = drawn.correct_probe.rgba8;
        assert!(text.contains(&format!("({}, {}, {})", bytes[0], bytes[1], bytes[2])), "{kind:?}: {text}");
        // The probe's bytes are the pictures' at the pixel.
        let (x, y) = drawn.pixel;
        let i = (y * SIZE + x) * 4;
        assert_eq!(&drawn.correct[i..i + 4], &drawn.correct_probe.rgba8[..]);
        assert_eq!(&drawn.bugged[i..i + 4], &drawn.bugged_probe.rgba8[..]);
        eprintln!("{kind:?}: {} pixels differ; {}", drawn.pixels_differing, key[3]);
    }
}

/// `exercise --level 5` writes the seven sheets and keys with both pictures in each PDF
/// (14 images in each), the pictures as PNG files, and keys that name the cause.
#[test]
fn level_five_prints_the_pictures() {
    let out = std::env::temp_dir().join(format!("phonglab-wrong-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = common::phonglab(&["exercise", "--level", "5", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for k in 1..=7 {
        for f in [format!("wrong-{k:02}.md"), format!("wrong-{k:02}-key.md"), format!("wrong-{k:02}.png")] {
            assert!(out.join(&f).is_file(), "{f}");
        }
        let key = std::fs::read_to_string(out.join(format!("wrong-{k:02}-key.md"))).unwrap();
        assert!(key.contains("Cause: ") && key.contains("drawn right: bytes ("), "{key}");
    }
    for pdf in ["sheets.pdf", "keys.pdf"] {
        let list = std::process::Command::new("pdfimages").arg("-list").arg(out.join(pdf)).output().unwrap();
        let images = String::from_utf8_lossy(&list.stdout).lines().skip(2).count();
        assert_eq!(images, 14, "{pdf}");
    }
    let text = std::process::Command::new("pdftotext").arg(out.join("sheets.pdf")).arg("-").output().unwrap();
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(text.contains("What is wrong with this picture? (7)") && text.contains("Drawn with one mistake"));
    // The same seed, the same files.
    let again = std::env::temp_dir().join(format!("phonglab-wrong-again-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&again);
    assert!(common::phonglab(&["exercise", "--level", "5", "--out", again.to_str().unwrap()]).status.success());
    assert_eq!(std::fs::read(out.join("keys.pdf")).unwrap(), std::fs::read(again.join("keys.pdf")).unwrap());
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_dir_all(&again);
}
