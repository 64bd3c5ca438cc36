//! Issue 57: work is right only when it is whole. Every step the worksheet asks for (its
//! `print` lines: the normal, `vlv`, `vov`, `Iamb`, `Idif`, `Ispec`, `I`, for each light)
//! that the work does not print makes it incomplete, never right, the first named; the
//! steps only some rule sets print are never asked; and a notebook's outputs that are not
//! one run's (after an error, out of order, a cell's error of any name) are said.

use std::path::Path;

use phonglab_core::Document;
use phonglab_core::scene::Scene;
use phonglab_core::study::check::printed::{Stale, notebook_outputs, printed_text};
use phonglab_core::study::check::worked::{Worked, work};
use phonglab_core::study::check::{ASKED, Overall, Verdict, asked, check};

fn scene_file(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes").join(name);
    Document::from_toml_in(&std::fs::read_to_string(&path).unwrap(), path.parent()).unwrap().scene
}

/// The `name = value` lines of `names` (every step of `worked` where `None`), in the key's
/// order, with Rust's round-trip digits.
fn printed_of(worked: &Worked, names: Option<&[String]>) -> String {
    let mut text = String::new();
    for (name, v) in &worked.values {
        if names.is_some_and(|n| !n.contains(name)) {
            continue;
        }
        let numbers: Vec<String> = v.iter().map(|x| format!("{x}")).collect();
        let value = if v.len() == 1 { numbers[0].clone() } else { format!("[{}]", numbers.join(" ")) };
        text.push_str(&format!("{name} =  {value}\n"));
    }
    text
}

/// A notebook of code cells, each `(execution_count, outputs)`.
fn notebook(cells: &[(Option<i64>, serde_json::Value)]) -> String {
    let cells: Vec<serde_json::Value> = cells
        .iter()
        .map(|(n, outputs)| {
            serde_json::json!({"cell_type": "code", "execution_count": n, "source": ["x = 1\n"], "outputs": outputs})
        })
        .collect();
    serde_json::json!({"cells": cells}).to_string()
}

fn stream(text: &str) -> serde_json::Value {
    serde_json::json!([{"output_type": "stream", "name": "stdout", "text": text}])
}

#[test]
fn a_step_the_worksheet_asks_for_not_printed_makes_the_work_incomplete_naming_the_first() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let whole = printed_of(&key, None);
    assert_eq!(check(&scene, &scene, &printed_text(&whole)).overall(), Overall::Right);
    // The outputs cleared from Ispec on (the first wrong step of a hostile notebook).
    let cut = whole.find("\nIspec =").unwrap_or_else(|| panic!("{whole}"));
    let c = check(&scene, &scene, &printed_text(&whole[..=cut]));
    assert!(!c.right());
    assert_eq!(c.overall(), Overall::Incomplete);
    assert!(c.first_wrong.is_none() && c.causes.is_empty());
    assert_eq!(c.not_printed, ["Ispec", "I"]);
    assert_eq!(c.unchecked().unwrap().id(), "missing-steps");
    let words = phonglab_core::study::check::said::words(&c);
    assert!(
        words
            .contains("incomplete: the worksheet asks for 2 steps this work does not print, the first Ispec: Ispec, I"),
        "{words}"
    );
    assert!(!words.contains("all right"), "{words}");
    // One right line: incomplete, every other step named in the worksheet's order.
    let one = check(&scene, &scene, &printed_text("vlv =  [ 0.79220526  0.55887606 -0.2450885   0.        ]\n"));
    assert_eq!(one.steps[0].verdict, Verdict::Right);
    assert_eq!(one.overall(), Overall::Incomplete);
    assert_eq!(one.not_printed, ["vertexNormal", "vov", "Iamb", "Idif", "Ispec", "I"]);
    // A wrong step is wrong, whole or not, and the steps not printed are still named.
    let wrong = check(&scene, &scene, &printed_text("vlv =  [ 0.5  0.55887606 -0.2450885   0.        ]\n"));
    assert_eq!(wrong.overall(), Overall::Wrong);
    assert_eq!(wrong.not_printed.len(), 6);
}

/// The worksheet's own `print` lines are all a work must print, under every rule set and
/// scene: `H`, `d`, `spot`, `Iscene`, `glColor` or the back side are checked where printed,
/// never asked; a light of several is asked for each light.
#[test]
fn only_the_worksheets_printed_steps_are_asked_under_every_rule_set() {
    let mut scenes = vec![phonglab_core::presets::worksheet(5)];
    for name in ["spotlight.toml", "three-lights.toml", "phong-demo.toml", "worksheet-mview1.toml", "of-set-color.toml"]
    {
        scenes.push(scene_file(name));
    }
    let mut two_sided = scene_file("spotlight.toml");
    two_sided.light_model.two_sided = true;
    scenes.push(two_sided);
    for scene in &scenes {
        let key = work(scene, None, None);
        let names = asked(&key);
        for n in &names {
            assert!(ASKED.contains(&n.split('[').next().unwrap()), "{n}");
        }
        for base in ["vertexNormal", "I"] {
            assert!(names.iter().any(|n| n == base), "{base} asked: {names:?}");
        }
        let per_light = names.iter().filter(|n| n.starts_with("vlv")).count();
        assert_eq!(per_light, scene.lights.len(), "{names:?}");
        // Printing just those is whole and right; the key's every step too.
        let c = check(scene, scene, &printed_text(&printed_of(&key, Some(&names))));
        assert!(c.right(), "{names:?}: {:?} {:?}", c.unchecked(), c.steps);
        assert!(check(scene, scene, &printed_text(&printed_of(&key, None))).right());
        // Without the last asked step: incomplete, that step named.
        let fewer = &names[..names.len() - 1];
        let c = check(scene, scene, &printed_text(&printed_of(&key, Some(fewer))));
        assert_eq!(c.overall(), Overall::Incomplete, "{names:?}");
        assert_eq!(c.not_printed, [names.last().unwrap().clone()]);
    }
}

/// A step printed with the wrong number of components is wrong, never right or rounding.
#[test]
fn a_step_printed_with_the_wrong_length_is_wrong() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = printed_of(&work(&scene, None, None), None);
    for short in
        ["vlv =  [0.79220526 0.55887606]", "vlv =  0.79220526", "vlv =  [0.79220526 0.55887606 -0.2450885 0. 0.]"]
    {
        let line = key.lines().find(|l| l.starts_with("vlv =")).unwrap();
        let c = check(&scene, &scene, &printed_text(&key.replace(line, short)));
        assert_eq!(c.overall(), Overall::Wrong, "{short}");
        assert_eq!(c.steps[c.first_wrong.unwrap()].name, "vlv", "{short}");
    }
}

/// A cell's error output stops the run whatever its name (`KeyboardInterrupt`,
/// `Exception`), and what the cells after it printed is from an earlier run: named, and
/// never checked, so the steps it held are not printed.
#[test]
fn outputs_after_a_cells_error_are_not_checked_and_any_error_stops_the_run() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let asked = asked(&key);
    let before: Vec<String> = asked.iter().take(3).cloned().collect();
    let after: Vec<String> = asked.iter().skip(3).cloned().collect();
    for ename in ["KeyboardInterrupt", "Exception", "NameError"] {
        let error =
            serde_json::json!([{"output_type": "error", "ename": ename, "evalue": "stop\nmore", "traceback": []}]);
        let nb = notebook(&[
            (Some(1), stream(&printed_of(&key, Some(&before)))),
            (Some(2), error),
            (Some(3), stream(&printed_of(&key, Some(&after)))),
        ]);
        let p = notebook_outputs(&nb).unwrap();
        assert_eq!(p.errors, [format!("{ename}: stop")]);
        assert_eq!(p.after_error, after, "{ename}");
        assert!(p.values.iter().all(|v| before.contains(&v.name)), "{ename}: {:?}", p.values);
        let c = check(&scene, &scene, &p);
        assert_eq!(c.overall(), Overall::Incomplete, "{ename}");
        assert_eq!(c.unchecked().unwrap().id(), "run-stopped");
        assert_eq!(c.not_printed, after);
        let words = phonglab_core::study::check::said::words(&c);
        assert!(words.contains("printed after the error, so by an earlier run"), "{words}");
        assert!(words.contains(&format!("the first {}", after[0])), "{words}");
        // One verdict: "not checked" (the run stopped), the steps not printed said beside it.
        let verdicts = words.lines().filter(|l| l.starts_with("not checked") || l.starts_with("incomplete")).count();
        assert_eq!(verdicts, 1, "{words}");
    }
}

/// Outputs whose execution counts go back are not one run's (a cell run again after the
/// cells below it): said, never right; counts left null (a notebook written by a program)
/// say nothing.
#[test]
fn outputs_out_of_order_are_not_right() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let names = asked(&key);
    let (a, b) = names.split_at(3);
    let cells = |first: Option<i64>, second: Option<i64>| {
        notebook(&[(first, stream(&printed_of(&key, Some(a)))), (second, stream(&printed_of(&key, Some(b))))])
    };
    let p = notebook_outputs(&cells(Some(5), Some(3))).unwrap();
    assert_eq!(p.stale, Some(Stale::Back(5, 3)));
    let c = check(&scene, &scene, &p);
    assert_eq!(c.overall(), Overall::Incomplete);
    assert_eq!(c.unchecked().unwrap().id(), "stale-outputs");
    assert!(phonglab_core::study::check::said::words(&c).contains("a cell numbered [3] below one numbered [5]"));
    for (x, y) in [(Some(1), Some(2)), (None, None), (Some(4), None)] {
        let p = notebook_outputs(&cells(x, y)).unwrap();
        assert_eq!(p.stale, None, "{x:?} {y:?}");
        assert!(check(&scene, &scene, &p).right(), "{x:?} {y:?}");
    }
    assert_eq!(notebook_outputs(&cells(Some(2), Some(2))).unwrap().stale, Some(Stale::Back(2, 2)));
}

/// The notebook's self-check names the steps it holds no value for; they are said once
/// (not again as not printed), and the work is incomplete.
#[test]
fn steps_the_self_check_found_missing_are_said_once() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let names: Vec<String> = asked(&key).into_iter().filter(|n| n != "Iamb" && n != "I").collect();
    let mut p = printed_text(&printed_of(&key, Some(&names)));
    p.missing = vec!["Iamb".into(), "I".into()];
    let c = check(&scene, &scene, &p);
    assert_eq!(c.overall(), Overall::Incomplete);
    assert!(c.not_printed.is_empty(), "{:?}", c.not_printed);
    assert_eq!(c.all_missing(), ["Iamb", "I"]);
    let words = phonglab_core::study::check::said::words(&c);
    assert!(words.contains("holds no value for Iamb, I") && !words.contains("incomplete:"), "{words}");
}

/// Issue 57: an execution count no run gives (a string, a fraction, a negative, a number
/// past 2^64, past the largest count taken) says nothing of the order: the outputs are
/// stale, never right; said with the count as the notebook wrote it.
#[test]
fn execution_counts_that_are_not_small_integers_are_stale() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let names = asked(&key);
    let (a, b) = names.split_at(3);
    let with_counts = |first: serde_json::Value, second: serde_json::Value| {
        let cells = vec![
            serde_json::json!({"cell_type": "code", "execution_count": first, "source": ["x = 1\n"],
                "outputs": stream(&printed_of(&key, Some(a)))}),
            serde_json::json!({"cell_type": "code", "execution_count": second, "source": ["x = 1\n"],
                "outputs": stream(&printed_of(&key, Some(b)))}),
        ];
        serde_json::json!({"cells": cells}).to_string()
    };
    let huge: serde_json::Value = serde_json::from_str("18446744073709551617").unwrap();
    for (first, second, shown) in [
        (serde_json::json!("100"), serde_json::json!("99"), "\"100\""),
        (serde_json::json!(1), serde_json::json!(2.5), "2.5"),
        (serde_json::json!(1.0), serde_json::json!(2), "1.0"),
        (serde_json::json!(1), huge, "1.8446744073709552e+19"),
        (serde_json::json!(-1), serde_json::json!(2), "-1"),
        (serde_json::json!(1), serde_json::json!(u64::MAX), "18446744073709551615"),
        (serde_json::json!(true), serde_json::json!(2), "true"),
    ] {
        let p = notebook_outputs(&with_counts(first.clone(), second.clone())).unwrap();
        assert_eq!(p.stale, Some(Stale::NotACount(shown.to_string())), "{first} {second}");
        let c = check(&scene, &scene, &p);
        assert_eq!(c.overall(), Overall::Incomplete, "{first} {second}");
        assert_eq!(c.unchecked().unwrap().id(), "stale-outputs", "{first} {second}");
        let words = phonglab_core::study::check::said::words(&c);
        assert!(words.contains(&format!("[{shown}]")) && words.contains("not a run's"), "{words}");
    }
    // Small non-negative integers in order (and none at all) are one run's.
    let p = notebook_outputs(&with_counts(serde_json::json!(0), serde_json::json!(7))).unwrap();
    assert_eq!(p.stale, None);
    assert!(check(&scene, &scene, &p).right());
}

/// Issue 57: a cell that calls the self-check has its printed table skipped, but an error
/// it stopped with is the run's, as any cell's: the run stopped, and the values printed
/// below it are from an earlier run (never checked).
#[test]
fn an_error_in_the_self_checks_cell_stops_the_run_as_any_cells() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let names = asked(&key);
    let (a, b) = names.split_at(3);
    let cells = serde_json::json!({"cells": [
        {"cell_type": "code", "execution_count": 1, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(a)))},
        {"cell_type": "code", "execution_count": 5, "source": ["y = z\n", "_ = 'check(globals()'\n"],
         "outputs": [{"output_type": "stream", "name": "stdout", "text": "vlv = [9 9 9 0]\n"},
                     {"output_type": "error", "ename": "NameError", "evalue": "name 'z' is not defined", "traceback": []}]},
        // From an earlier run (numbered before the error's cell): Run All stopped at [5].
        {"cell_type": "code", "execution_count": 3, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(b)))},
    ]});
    let p = notebook_outputs(&cells.to_string()).unwrap();
    assert_eq!(p.errors, ["NameError: name 'z' is not defined"]);
    assert_eq!(p.after_error, b);
    assert!(p.get("vlv").is_none_or(|v| v.numbers != [9.0, 9.0, 9.0, 0.0]), "the self-check's table is not read");
    let c = check(&scene, &scene, &p);
    assert_eq!(c.overall(), Overall::Incomplete);
    assert_eq!(c.unchecked().unwrap().id(), "run-stopped");
}

/// The exported notebook's last cell calls phonglab's self-check: a student without
/// phonglab installed gets `ModuleNotFoundError` there, after every step was printed. Nothing
/// below it ran stale, so the work is judged as printed (right here), not "run stopped".
#[test]
fn an_error_in_a_last_self_check_cell_leaves_the_work_above_it_judged() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let cells = serde_json::json!({"cells": [
        {"cell_type": "code", "execution_count": 1, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, None))},
        {"cell_type": "code", "execution_count": 2, "source": ["import phonglab\n", "phonglab.check(globals())\n"],
         "outputs": [{"output_type": "error", "ename": "ModuleNotFoundError", "evalue": "No module named 'phonglab'", "traceback": []}]},
    ]});
    let p = notebook_outputs(&cells.to_string()).unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    let c = check(&scene, &scene, &p);
    assert_eq!(c.overall(), Overall::Right, "{:?}", c.unchecked().map(|u| u.id()));
}

/// A cell of comments only, not run, between run cells (the exported self-check left
/// commented out, a `# try later`) changes nothing: the work is right, not "stale"; and a
/// self-check cell's `ModuleNotFoundError` followed by a cell numbered after it (run after
/// it, one cell at a time) stops nothing (hostile, round 4: both were "incomplete").
#[test]
fn a_comment_cell_not_run_and_a_self_check_error_run_past_leave_right_work_right() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let names = asked(&key);
    let (a, b) = names.split_at(3);
    let comment = serde_json::json!({"cells": [
        {"cell_type": "code", "execution_count": 1, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(a)))},
        {"cell_type": "code", "execution_count": null, "source": ["# import phonglab\n", "# phonglab.check(globals())\n"], "outputs": []},
        {"cell_type": "code", "execution_count": 2, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(b)))},
    ]});
    let p = notebook_outputs(&comment.to_string()).unwrap();
    assert_eq!(p.stale, None);
    assert_eq!(check(&scene, &scene, &p).overall(), Overall::Right);
    let run_past = serde_json::json!({"cells": [
        {"cell_type": "code", "execution_count": 1, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(a)))},
        {"cell_type": "code", "execution_count": 2, "source": ["import phonglab\n", "phonglab.check(globals())\n"],
         "outputs": [{"output_type": "error", "ename": "ModuleNotFoundError", "evalue": "No module named 'phonglab'", "traceback": []}]},
        {"cell_type": "code", "execution_count": 3, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(b)))},
    ]});
    let p = notebook_outputs(&run_past.to_string()).unwrap();
    assert!(p.errors.is_empty(), "{:?}", p.errors);
    assert_eq!(check(&scene, &scene, &p).overall(), Overall::Right);
}

/// Issue 57: a code cell with no execution count between two numbered ones was not run
/// in that run (or its outputs were cleared): the outputs below it are stale, as counts
/// that go back are. An empty cell (Jupyter never runs one), and cells not run above or
/// below every numbered one, say nothing.
#[test]
fn a_cell_not_run_between_numbered_cells_makes_the_outputs_stale() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let names = asked(&key);
    let (a, b) = names.split_at(3);
    let with = |middle: serde_json::Value, source: &str, last: Option<i64>| {
        serde_json::json!({"cells": [
            {"cell_type": "code", "execution_count": 1, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(a)))},
            {"cell_type": "code", "execution_count": middle, "source": [source], "outputs": []},
            {"cell_type": "code", "execution_count": last, "source": ["x = 1\n"], "outputs": stream(&printed_of(&key, Some(b)))},
        ]})
        .to_string()
    };
    let p = notebook_outputs(&with(serde_json::Value::Null, "cosTheta = 1\n", Some(3))).unwrap();
    assert_eq!(p.stale, Some(Stale::NotRun(1, 3)));
    let c = check(&scene, &scene, &p);
    assert_eq!(c.overall(), Overall::Incomplete);
    assert_eq!(c.unchecked().unwrap().id(), "stale-outputs");
    let words = phonglab_core::study::check::said::words(&c);
    assert!(words.contains("between those numbered [1] and [3] has no execution count"), "{words}");
    for (middle, source, last) in [
        (serde_json::Value::Null, "  \n", Some(3)),
        (serde_json::Value::Null, "cosTheta = 1\n", None),
        (serde_json::json!(2), "cosTheta = 1\n", Some(3)),
    ] {
        let p = notebook_outputs(&with(middle.clone(), source, last)).unwrap();
        assert_eq!(p.stale, None, "{middle} {source:?} {last:?}");
        assert!(check(&scene, &scene, &p).right(), "{middle} {source:?} {last:?}");
    }
}

/// Issue 57: right work computed in float32 and printed with `repr()` (what a notebook
/// shows for an array as a cell's last value: `array([...], dtype=float32)`) is read and
/// found right (to single precision), never an unreadable step.
#[test]
fn right_float32_work_printed_as_its_repr_is_not_unreadable() {
    let scene = phonglab_core::presets::worksheet(5);
    let key = work(&scene, None, None);
    let mut text = String::new();
    for (name, v) in &key.values {
        let numbers: Vec<String> = v.iter().map(|x| format!("{}", *x as f32)).collect();
        let value =
            if v.len() == 1 { numbers[0].clone() } else { format!("array([{}], dtype=float32)", numbers.join(", ")) };
        text.push_str(&format!("{name} = {value}\n"));
    }
    let c = check(&scene, &scene, &printed_text(&text));
    assert!(c.unreadable.is_empty(), "{:?}\n{text}", c.unreadable);
    assert_eq!(c.first_wrong, None, "{text}");
    assert_ne!(c.unchecked().map(|u| u.id()), Some("unreadable-step"), "{text}");
}
