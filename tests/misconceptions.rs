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
