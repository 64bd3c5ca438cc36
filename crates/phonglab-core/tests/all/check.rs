//! The checker's key is the key: the worksheet's calculation worked by the plan's stages
//! (`study::check::worked`) gives every value `explain` gives under the same name, on the
//! shipped scenes and on generated exercises; and the worksheet's own printed output is
//! checked right.

use std::path::Path;

use phonglab_core::Document;
use phonglab_core::exercise::{Level, Spec, generate};
use phonglab_core::explain::{Side, explain};
use phonglab_core::study::check::printed::printed_text;
use phonglab_core::study::check::worked::work;
use phonglab_core::study::check::{Verdict, check};
use phonglab_core::{Engine, Rules};

fn scenes() -> Vec<(String, Document)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes");
    let mut files: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    let mut docs: Vec<(String, Document)> = files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "toml"))
        .map(|f| {
            (f.display().to_string(), Document::from_toml_in(&std::fs::read_to_string(f).unwrap(), f.parent()).unwrap())
        })
        .collect();
    for level in 1..=4u8 {
        for rules in [Rules::WORKSHEET, Rules::OPENGL] {
            let spec = Spec::level(Level::from_number(level).unwrap(), rules);
            for (k, ex) in generate(70 + level as u64, 5, &spec).unwrap().into_iter().enumerate() {
                docs.push((format!("exercise {level} {rules:?} #{k}"), ex.doc));
            }
        }
    }
    docs
}

#[test]
fn the_worked_key_gives_what_explain_gives() {
    let mut compared = 0;
    for (what, doc) in scenes() {
        let lit = Engine::<f64>::light_scene_vertex(&doc.scene).unwrap();
        let ex = explain(&doc.scene, &lit, Side::Front);
        let worked = work(&doc.scene, None, None);
        for (name, value) in &worked.values {
            let Some(want) = ex.value(name) else { continue };
            assert_eq!(value.len(), want.len(), "{what}: {name} {value:?} vs {want:?}");
            for (g, w) in value.iter().zip(want) {
                assert!((g - w).abs() <= 1e-9 * w.abs().max(1e-3), "{what}: {name} = {value:?}, explain {want:?}");
            }
            compared += 1;
        }
        for name in ["vertexNormal", "vlv", "cosTheta", "I"] {
            let name =
                if doc.scene.lights.len() > 1 && name == "vlv" { "vlv[0]".to_string() } else { name.to_string() };
            if doc.scene.lights.is_empty() && name != "vertexNormal" && name != "I" {
                continue;
            }
            assert!(
                worked.get(&name).is_some() || name == "cosTheta" && doc.scene.lights.len() > 1,
                "{what}: no {name}"
            );
        }
    }
    assert!(compared > 400, "{compared} values compared");
}

#[test]
fn the_worksheets_own_printed_output_is_right() {
    // What the exported worksheet notebook prints, run by NumPy (its default print options).
    let text = "vertexNormal =  [0.  0.6 0.8 0. ]\nvertexPos =  [-512.  -307.2 -729.6    1. ]\n\
                lightPos =  [   0.   54. -888.    1.]\nvlv =  [ 0.79220526  0.55887606 -0.2450885   0.        ]\n\
                vov =  [0. 0. 1. 0.]\nIamb =  [0.2125 0.1275 0.054  0.    ]\ncosTheta =  0.13925483139909867\n\
                Idif =  [0.09942795 0.05965677 0.0252664  0.        ]\nH =  [0.64472529 0.45483354 0.61437427 0.        ]\n\
                cosBeta =  0.764399545502715\nIspec =  [0.00040551 0.00028017 0.00017179 0.        ]\n\
                d =  646.2971452822611\nat =  5.241629714528227\nI =  [0.05958709 0.03575929 0.01515525 0.        ]\n";
    let scene = phonglab_core::presets::worksheet(5);
    let c = check(&scene, &scene, &printed_text(text));
    assert_eq!(c.steps.len(), 14);
    assert!(c.steps.iter().all(|s| s.verdict == Verdict::Right), "{:?}", c.steps);
    assert!(c.right());
    // One value rounded for display is judged at its own digits: right to them.
    let rounded =
        text.replace("0.79220526", "0.7922").replace("0.55887606", "0.5589").replace("-0.2450885 ", "-0.2451    ");
    let c = check(&scene, &scene, &printed_text(&rounded));
    assert_eq!(c.steps[3].verdict, Verdict::Right);
    // Changed in its last digits (single precision) is rounding; changed more, wrong, and
    // what follows from it is right given it.
    let float = text.replace("0.79220526", "0.79220530");
    let c = check(&scene, &scene, &printed_text(&float));
    assert_eq!(c.steps[3].verdict, Verdict::Rounding);
    assert!(c.first_wrong.is_none());
    // vlv reversed: cosTheta from it is right given it, though worked from its 8 printed decimals.
    let reversed = text
        .replace("[ 0.79220526  0.55887606 -0.2450885 ", "[-0.79220526 -0.55887606  0.2450885 ")
        .replace("cosTheta =  0.13925483139909867", "cosTheta =  -0.13925483139909867");
    let c = check(&scene, &scene, &printed_text(&reversed));
    assert_eq!(c.steps[c.first_wrong.unwrap()].name, "vlv");
    assert_eq!(c.steps[6].name, "cosTheta");
    assert_eq!(c.steps[6].verdict, Verdict::RightGiven("vlv".into()));
    let wrong = text
        .replace("cosTheta =  0.13925483139909867", "cosTheta =  0.2")
        .replace("[0.09942795 0.05965677 0.0252664  0.        ]", "[0.1428   0.08568  0.036288 0.      ]");
    let c = check(&scene, &scene, &printed_text(&wrong));
    let first = c.first_wrong.unwrap();
    assert_eq!(c.steps[first].name, "cosTheta");
    assert_eq!(c.steps[first].verdict, Verdict::Wrong);
    // Idif from their cosTheta is 0.2 Ldif matDif: right, given it.
    assert_eq!(c.steps[first + 1].name, "Idif");
    assert_eq!(c.steps[first + 1].verdict, Verdict::RightGiven("cosTheta".into()));
}

/// A position divided by its w early is the same point: `lightPos = [0. 27. -444. 0.5]`
/// for the key's `[0. 54. -888. 1.]` is right (a right notebook of the blind set was
/// marked wrong for it); a different point, or a direction's w of 0, is not.
#[test]
fn a_position_in_other_homogeneous_coordinates_is_the_same_point() {
    let text = "vertexNormal =  [0.  0.6 0.8 0. ]\nvertexPos =  [-512.  -307.2 -729.6    1. ]\n\
                lightPos =  [   0.   54. -888.    1.]\nvlv =  [ 0.79220526  0.55887606 -0.2450885   0.        ]\n";
    let scene = phonglab_core::presets::worksheet(5);
    let halved = text.replace("[   0.   54. -888.    1.]", "[   0.   27. -444.    0.5]");
    let c = check(&scene, &scene, &printed_text(&halved));
    assert_eq!(c.steps[2].name, "lightPos");
    assert_eq!(c.steps[2].verdict, Verdict::Right, "{:?}", c.steps);
    // Nothing wrong (the text prints only four steps: incomplete, issue 57).
    let nothing_wrong = |c: &phonglab_core::study::check::Check| c.first_wrong.is_none() && c.causes.is_empty();
    assert!(nothing_wrong(&c));
    let doubled = text.replace("[-512.  -307.2 -729.6    1. ]", "[-1024.  -614.4 -1459.2    2. ]");
    assert!(nothing_wrong(&check(&scene, &scene, &printed_text(&doubled))));
    for other in ["[   0.   27. -444.    1.]", "[   0.   54. -888.    0.]", "[   0.   54. -888.    1.1]"] {
        let c = check(&scene, &scene, &printed_text(&text.replace("[   0.   54. -888.    1.]", other)));
        assert_eq!(c.steps[2].verdict, Verdict::Wrong, "{other}");
    }
    // The normal is a direction: a multiple of it is not right.
    let c = check(&scene, &scene, &printed_text(&text.replace("[0.  0.6 0.8 0. ]", "[0.  1.2 1.6 0. ]")));
    assert_eq!(c.steps[0].verdict, Verdict::Wrong);
}

/// What a calculation worked by `work` prints, one `name = value` line each (Rust's
/// shortest round-trip digits: the checker reads them as NumPy's).
fn printed_of(worked: &phonglab_core::study::check::worked::Worked) -> String {
    let mut text = String::new();
    for (name, v) in &worked.values {
        let numbers: Vec<String> = v.iter().map(|x| format!("{x}")).collect();
        let value = if v.len() == 1 { numbers[0].clone() } else { format!("[{}]", numbers.join(" ")) };
        text.push_str(&format!("{name} =  {value}\n"));
    }
    text
}

/// A notebook that checked nothing is not right: a run stopped by an error before it
/// printed (`ModuleNotFoundError`), or text with no step of the worksheet in it. Each
/// says why, and has no first wrong step.
#[test]
fn work_with_nothing_compared_or_a_run_stopped_is_not_right() {
    use phonglab_core::study::check::Unchecked;
    let scene = phonglab_core::presets::worksheet(5);
    let c = check(&scene, &scene, &printed_text("hello\n"));
    assert!(c.steps.is_empty());
    assert!(!c.right());
    assert_eq!(c.unchecked(), Some(Unchecked::NothingCompared));
    assert!(c.first_wrong.is_none());
    let stopped =
        "Traceback (most recent call last):\n  File \"x\", line 1\nModuleNotFoundError: No module named 'numpy'\n";
    let c = check(&scene, &scene, &printed_text(stopped));
    assert!(!c.right());
    assert_eq!(c.unchecked(), Some(Unchecked::Stopped("ModuleNotFoundError: No module named 'numpy'".into())));
    assert_eq!(c.unchecked().unwrap().id(), "run-stopped");
    // The whole key printed, then an error: still stopped, not right.
    let key = printed_of(&work(&scene, None, None));
    assert!(check(&scene, &scene, &printed_text(&key)).right());
    let c = check(&scene, &scene, &printed_text(&format!("{key}NameError: name 'x' is not defined\n")));
    assert!(!c.right() && c.first_wrong.is_none());
}

/// "Right, given your X" names the wrong step the value depends on, not the latest wrong
/// one: with vlv reversed, H (from vlv and vov) is right given vlv though cosTheta and
/// Idif, printed before it, are not the key's; with a wrong cosTheta, Idif is right given
/// cosTheta.
#[test]
fn right_given_names_the_step_the_value_depends_on() {
    use phonglab_core::study::check::mistakes::Mistake;
    let scene = phonglab_core::presets::worksheet(5);
    let reversed = printed_of(&work(&scene, Some(Mistake::VlvReversed), None));
    let c = check(&scene, &scene, &printed_text(&reversed));
    let verdict = |name: &str| c.steps.iter().find(|s| s.name == name).unwrap().verdict.clone();
    assert_eq!(verdict("vlv"), Verdict::Wrong);
    assert_eq!(verdict("cosTheta"), Verdict::RightGiven("vlv".into()));
    assert_eq!(verdict("H"), Verdict::RightGiven("vlv".into()), "{:?}", c.steps);
    assert_eq!(verdict("cosBeta"), Verdict::RightGiven("H".into()));
    // cosTheta printed 0.2, and what follows worked from it.
    let mut wrong_cos = work(&scene, None, Some(&printed_text("cosTheta =  0.2\n")));
    let k = wrong_cos.values.iter().position(|(n, _)| n == "cosTheta").unwrap();
    wrong_cos.values[k].1 = vec![0.2];
    let c = check(&scene, &scene, &printed_text(&printed_of(&wrong_cos)));
    let verdict = |name: &str| c.steps.iter().find(|s| s.name == name).unwrap().verdict.clone();
    assert_eq!(verdict("cosTheta"), Verdict::Wrong);
    assert_eq!(verdict("Idif"), Verdict::RightGiven("cosTheta".into()));
    assert_eq!(verdict("H"), Verdict::Right);
}

/// A cause is a mistake under the rules assumed: the worksheet's rules have no N·L gate
/// (their specular is gated by its own cosine), so work that printed OpenGL's calculation
/// with the gate left out, checked against a worksheet assignment, is not told it left
/// out a gate those rules do not have.
#[test]
fn a_cause_is_only_named_under_rules_where_it_is_a_mistake() {
    use phonglab_core::study::check::mistakes::Mistake;
    assert!(!Mistake::SpecularWithoutGate.applies(Rules::WORKSHEET));
    assert!(Mistake::SpecularWithoutGate.applies(Rules::OPENGL));
    assert!(!Mistake::NormalByModelview.applies(Rules::WORKSHEET));
    assert!(Mistake::NormalByModelview.applies(Rules::OPENGL));
    assert!(Mistake::VlvReversed.applies(Rules::WORKSHEET));
    let assignment = phonglab_core::presets::worksheet(5);
    let mut own = assignment.clone();
    own.rules = Rules::OPENGL;
    // The light just behind the surface, far to one side, where N.H is still positive:
    // the gate left out prints a specular the key has not.
    let n = own.vertex.normal;
    let side = [glam::DVec3::X, glam::DVec3::Y, glam::DVec3::Z, -glam::DVec3::X, -glam::DVec3::Y, -glam::DVec3::Z]
        .into_iter()
        .map(|t| (t - n * t.dot(n)).normalize())
        .find(|t| {
            let mut s = own.clone();
            s.lights[0].position = s.vertex.position + (1000.0 * *t - 10.0 * n).extend(0.0);
            work(&s, Some(Mistake::SpecularWithoutGate), None).get("Ispec") != work(&s, None, None).get("Ispec")
        })
        .unwrap();
    own.lights[0].position = own.vertex.position + (1000.0 * side - 10.0 * n).extend(0.0);
    let made = work(&own, Some(Mistake::SpecularWithoutGate), None);
    assert!(made.get("cosTheta").unwrap()[0] < 0.0, "the light must be behind: {made:?}");
    let c = check(&assignment, &own, &printed_text(&printed_of(&made)));
    assert!(!c.right());
    assert!(c.inputs_differ.contains(&"rules".to_string()));
    let ids: Vec<&str> = c.causes.iter().map(|k| k.info.id).collect();
    assert!(!ids.contains(&"specular-without-gate"), "{ids:?}");
    // Under OpenGL's rules, the same work is named.
    let c = check(&own, &own, &printed_text(&printed_of(&made)));
    assert!(c.causes.iter().any(|k| k.info.id == "specular-without-gate"), "{:?}", c.causes);
}

/// Work typed for another scene than the one given (a wrong `--scene`: most typed inputs
/// differ) is asked "is this the right scene?" once, and no cause is named under its first
/// step (one was, found on a scene the work was not typed for).
#[test]
fn work_typed_for_another_scene_is_asked_whether_the_scene_is_right_and_given_no_cause() {
    use phonglab_core::locale::{Lang, Locale, with_locale};
    let assignment = phonglab_core::presets::worksheet(5);
    let mut own = assignment.clone();
    own.vertex.position += glam::DVec4::new(0.5, -0.25, 0.125, 0.0);
    own.lights[0].position += glam::DVec4::new(1.0, 2.0, -1.0, 0.0);
    own.material.diffuse = glam::DVec4::new(0.3, 0.6, 0.2, 1.0);
    own.material.shininess += 7.0;
    let printed = printed_text(&printed_of(&work(&own, None, None)));
    let c = check(&assignment, &own, &printed);
    assert!(c.inputs_differ.len() >= 4, "{:?}", c.inputs_differ);
    assert!(c.other_scene() && c.causes.is_empty(), "{:?}", c.causes);
    let words = with_locale(Locale::of(Lang::En), || phonglab_core::study::check::said::words(&c));
    assert_eq!(words.matches("is this the right scene (--scene)?").count(), 1, "{words}");
    assert!(!words.contains("no mistake in the catalogue"), "{words}");
    let words = with_locale(Locale::of(Lang::PtBr), || phonglab_core::study::check::said::words(&c));
    assert!(words.contains("esta é a cena certa (--scene)?"), "{words}");
    // One input typed wrong is a slip, not another scene.
    let mut slip = assignment.clone();
    slip.material.shininess += 7.0;
    let c = check(&assignment, &slip, &printed_text(&printed_of(&work(&slip, None, None))));
    assert!(!c.other_scene(), "{:?}", c.inputs_differ);
}

/// The catalogue's formulas are code only: their words are in the user's language
/// elsewhere, so no English comment is left in what a Portuguese student reads.
#[test]
fn the_catalogues_formulas_hold_no_english_words() {
    use phonglab_core::study::check::mistakes::CATALOGUE;
    for info in &CATALOGUE {
        let comment = info.formula.split_once("  #").map_or("", |c| c.1);
        for word in ["not", "instead", "also", "where", "with", "outside", "too", "normalised"] {
            assert!(!comment.split_whitespace().any(|w| w == word), "{}: {}", info.id, info.formula);
        }
    }
}

/// "Rounding" is single precision, not three digits: a share printed 8 parts in 10^4 off
/// the key (the spot left off the ambient, in a blind set) is wrong, and the work is not
/// right; one off by what `float` arithmetic gives (a part in 10^6) is rounding.
#[test]
fn a_small_real_difference_is_wrong_and_single_precision_is_rounding() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let with_i = |scale: f64| {
        let mut w = key.clone();
        let k = w.values.iter().position(|(n, _)| n == "I").unwrap();
        w.values[k].1.iter_mut().for_each(|x| *x *= scale);
        w.values.retain(|(n, _)| n != "glColor");
        check(&scene, &scene, &printed_text(&printed_of(&w)))
    };
    let off = with_i(1.0008);
    assert_eq!(off.steps.iter().find(|s| s.name == "I").unwrap().verdict, Verdict::Wrong);
    assert!(!off.right());
    let float = with_i(1.000_001);
    assert_eq!(float.steps.iter().find(|s| s.name == "I").unwrap().verdict, Verdict::Rounding);
    assert!(float.right());
}

/// What a hostile classmate printed to pass wrong work as right: a whole number is
/// Python's exact int (`cosTheta = 0` is not 0.139 rounded); a step printed with a value
/// that is not a number (`0.9 rad`, a value wrapped past the cap) leaves the work not
/// checked whole, never right.
#[test]
fn a_whole_number_is_exact_and_an_unreadable_step_is_never_right() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = printed_of(&work(&scene, None, None));
    assert!(check(&scene, &scene, &printed_text(&key)).right());
    let cos = key.lines().find(|l| l.starts_with("cosTheta")).unwrap().to_string();
    for whole in ["cosTheta =  0", "cosTheta =  1"] {
        let c = check(&scene, &scene, &printed_text(&key.replace(&cos, whole)));
        assert!(!c.right(), "{whole}");
        assert_eq!(c.steps[c.first_wrong.unwrap()].name, "cosTheta");
    }
    // A whole number that is the key's is right: `spot = 1`, `[0 0 0 0]`.
    let spot = check(&scene, &scene, &printed_text("vov =  [0 0 1 0]\nIdif =  [0 0 0 0]\n"));
    assert_eq!(spot.steps[0].verdict, Verdict::Right);
    for junk in ["cosTheta =  0.9 rad", "cosTheta =  0.139j", "cosTheta =  0x1.1d3p-3"] {
        let c = check(&scene, &scene, &printed_text(&key.replace(&cos, junk)));
        assert!(!c.right(), "{junk}");
        assert_eq!(c.unchecked().map(|u| u.id()), Some("unreadable-step"), "{junk}");
    }
    // A wrong vlv wrapped past the cap, then the right one: not right.
    let wrapped = format!("vlv =  [-0.79220526\n{}-0.13925483 0.]\n{key}", " -0.59415395\n".repeat(1030));
    assert!(!check(&scene, &scene, &printed_text(&wrapped)).right());
}

/// Issue 57: a verdict is proven on the printed digits. The specular left out and printed
/// with `np.set_printoptions(precision=2)` prints `Ispec = [0. 0. 0. 0.]`, which is the
/// key's 0.0004 to two decimals, and zero alike: too few digits to tell, never right; so
/// is `I` at one decimal, whose 0.036 prints 0. NumPy's default precision stays right.
#[test]
fn too_few_digits_to_tell_the_key_from_a_mistake_or_from_zero_are_never_right() {
    use phonglab_core::study::check::Overall;
    let scene = phonglab_core::presets::worksheet(5);
    let at_two = "vertexNormal =  [0.  0.6 0.8 0. ]\nvertexPos =  [-512.  -307.2 -729.6    1. ]\n\
                  lightPos =  [   0.   54. -888.    1.]\nvlv =  [ 0.79  0.56 -0.25  0.  ]\nvov =  [0. 0. 1. 0.]\n\
                  Iamb =  [0.21 0.13 0.05 0.  ]\ncosTheta =  0.13925483139909867\nIdif =  [0.1  0.06 0.03 0.  ]\n\
                  H =  [0.64 0.45 0.61 0.  ]\ncosBeta =  0.764399545502715\nIspec =  [0. 0. 0. 0.]\n\
                  d =  646.2971452822611\nat =  5.241629714528227\nI =  [0.06 0.04 0.02 0.  ]\n";
    let c = check(&scene, &scene, &printed_text(at_two));
    let verdict = |c: &phonglab_core::study::check::Check, name: &str| {
        c.steps.iter().find(|s| s.name == name).unwrap_or_else(|| panic!("no {name}")).verdict.clone()
    };
    // `[0. 0. 0. 0.]` shows no decimal of its own: the print options' two, which the
    // other arrays show.
    assert_eq!(verdict(&c, "Ispec"), Verdict::TooFewDigits(2));
    // The specular left out changes I by 0.0001: two decimals cannot tell.
    assert_eq!(verdict(&c, "I"), Verdict::TooFewDigits(2));
    assert!(c.first_wrong.is_none() && !c.right(), "{:?}", c.steps);
    assert_eq!(c.overall(), Overall::Incomplete);
    let why = c.unchecked().unwrap();
    assert_eq!(why.id(), "too-few-digits");
    let words = phonglab_core::study::check::said::words(&c);
    assert!(!words.contains("all right"), "{words}");
    assert!(words.contains("Ispec") && words.contains("2 decimal places"), "{words}");
    assert!(words.contains("np.set_printoptions(precision=8)"), "{words}");
    assert!(words.contains("too few digits to tell (printed to 2 decimal places"), "{words}");
    // One decimal (every array printed so): I's 0.036 and 0.015 print 0, as zero would.
    let at_one = "Ispec =  [0. 0. 0. 0.]\nI =  [0.1 0.  0.  0. ]\n";
    assert_eq!(verdict(&check(&scene, &scene, &printed_text(at_one)), "I"), Verdict::TooFewDigits(1));
    // Precision 0: `[0. 0. 0. 0.]` for 0.0596.
    let at_none = "I =  [0. 0. 0. 0.]\n";
    assert_eq!(verdict(&check(&scene, &scene, &printed_text(at_none)), "I"), Verdict::TooFewDigits(0));
    // Enough digits to tell: right, and a key of 0 printed 0 is right at any precision.
    let enough = at_two.replace("Ispec =  [0. 0. 0. 0.]", "Ispec =  [4.0551e-04 2.8017e-04 1.7179e-04 0.0000e+00]");
    let c = check(&scene, &scene, &printed_text(&enough));
    assert_eq!(verdict(&c, "Ispec"), Verdict::Right);
    assert_eq!(verdict(&c, "vov"), Verdict::Right);
}

/// Issue 57: the check is linear in the printings (4000 printings of a wrong `vlv` took
/// 15 s, each compared again with every earlier one), and its cap counts numbers, not
/// printings: seventeen arrays of a thousand numbers are refused, saying so.
#[test]
fn many_printings_are_checked_in_linear_time_and_the_cap_counts_numbers() {
    use phonglab_core::study::check::printed::{MAX_VALUES, OutputsError, read_printed_text};
    let scene = phonglab_core::presets::worksheet(5);
    let text: String = (0..4000).map(|k| format!("vlv =  [0.1 0.2 0.{} 0]\n", k % 2 + 3)).collect();
    let start = std::time::Instant::now();
    let c = check(&scene, &scene, &printed_text(&text));
    let words = phonglab_core::study::check::said::words(&c);
    let took = start.elapsed();
    assert_eq!(c.steps.len(), 4000);
    assert!(c.steps.iter().all(|s| s.verdict == Verdict::Wrong), "{:?}", &c.steps[..2]);
    assert_eq!(phonglab_core::study::check::said::printed_again(&c), vec!["vlv".to_string()]);
    assert!(words.contains("vlv"), "{words}");
    assert!(took < std::time::Duration::from_secs(4), "{took:?} for 4000 printings");
    let thousand = vec!["1."; 1000].join(" ");
    let big: String = (0..17).map(|k| format!("a{k} = [{thousand}]\n")).collect();
    let Err(OutputsError::TooMany(why)) = read_printed_text(&big) else { panic!("17000 numbers read") };
    assert!(why.contains(&format!("more than {MAX_VALUES} numbers")), "{why}");
    let sixteen: String = (0..16).map(|k| format!("a{k} = [{thousand}]\n")).collect();
    assert_eq!(read_printed_text(&sixteen).unwrap().values.len(), 16);
}

/// The key printed as NumPy does by default (8 decimals), `I` as `print_i` prints it.
fn printed_with_i(print_i: impl Fn(&[f64]) -> String) -> String {
    let scene = phonglab_core::presets::worksheet(5);
    let mut text = String::new();
    for (name, v) in &work(&scene, None, None).values {
        let value = if name == "I" {
            print_i(v)
        } else if v.len() == 1 {
            format!("{}", v[0])
        } else {
            format!("[{}]", v.iter().map(|x| format!("{x:.8}")).collect::<Vec<_>>().join(" "))
        };
        text.push_str(&format!("{name} =  {value}\n"));
    }
    text
}

/// Each printing is judged at the digits it was printed with: `I` rounded for display
/// (`np.round(I, 4)`, a `"%.2f"` join, `np.printoptions(precision=3)` around one print)
/// beside steps printed to 8 decimals is right to its digits or too few to tell, never
/// wrong; `I.tolist()` or NumPy 2's `list(I)` (17 digits) makes no other step "rounding".
#[test]
fn one_step_printed_with_other_digits_is_judged_at_its_own() {
    let scene = phonglab_core::presets::worksheet(5);
    for decimals in [2usize, 3, 4] {
        let text = printed_with_i(|v| {
            format!("[{}]", v.iter().map(|x| format!("{x:.decimals$}")).collect::<Vec<_>>().join(" "))
        });
        let c = check(&scene, &scene, &printed_text(&text));
        assert!(c.first_wrong.is_none(), "{decimals}: {:?}", c.steps);
        for s in &c.steps {
            let ok = s.verdict == Verdict::Right || s.name == "I" && matches!(s.verdict, Verdict::TooFewDigits(_));
            assert!(ok, "{decimals}: {} {:?}", s.name, s.verdict);
        }
    }
    let listed = |wrap: &'static str| {
        move |v: &[f64]| {
            let items: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
            let items: Vec<String> =
                items.iter().map(|x| if wrap.is_empty() { x.clone() } else { format!("{wrap}({x})") }).collect();
            format!("[{}]", items.join(", "))
        }
    };
    for wrap in ["", "np.float64"] {
        let c = check(&scene, &scene, &printed_text(&printed_with_i(listed(wrap))));
        assert!(c.unreadable.is_empty(), "{wrap}: {:?}", c.unreadable);
        for s in &c.steps {
            assert_eq!(s.verdict, Verdict::Right, "{wrap}: {} {:?}", s.name, c.steps);
        }
        assert!(c.right(), "{wrap}");
    }
}

/// "Right, given your X" names only a step the value depends on: `H` (from `vlv` and
/// `vov`) a few parts in 10^7 off, after a wrong `at`, is not "right, given your at".
#[test]
fn right_given_never_names_a_step_the_value_does_not_depend_on() {
    let scene = phonglab_core::presets::worksheet(5);
    let text = printed_with_i(|v| format!("[{}]", v.iter().map(|x| format!("{x:.8}")).collect::<Vec<_>>().join(" ")));
    assert!(text.contains("0.64472529") && text.contains("at =  5.24"), "{text}");
    let off = text.replace("at =  5.24", "at =  6.24").replace("0.64472529", "0.64472579");
    let c = check(&scene, &scene, &printed_text(&off));
    let verdict = |name: &str| c.steps.iter().find(|s| s.name == name).unwrap().verdict.clone();
    assert_eq!(verdict("at"), Verdict::Wrong);
    assert_eq!(verdict("H"), Verdict::Rounding, "{:?}", c.steps);
}

/// The typed inputs that differ are named as typed: a changed linear attenuation is
/// `atLin`, not the `at` worked from it.
#[test]
fn typed_inputs_that_differ_are_named_as_typed() {
    let assignment = phonglab_core::presets::worksheet(5);
    let mut own = assignment.clone();
    own.lights[0].attenuation[1] += 0.001;
    let c = check(&assignment, &own, &printed_text(&printed_of(&work(&own, None, None))));
    assert_eq!(c.inputs_differ, vec!["atLin".to_string()]);
}
