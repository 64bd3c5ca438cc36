//! `--exam`: exercises a student works with a pencil. Checked here from the outside: the
//! worked calculation of each exercise's scene, lit again by the engine, not the
//! generator's own arithmetic.

use phonglab_core::exam::generate;
use phonglab_core::exercise::{Exercise, Level, Spec};
use phonglab_core::explain::{Side, StepKind, explain};
use phonglab_core::{Engine, Rules};

/// Exact roots an exam may hold beside rationals: the cosines of the spot cutoffs
/// 45° and 30° (a value compared with, never computed from).
const LISTED_ROOTS: [f64; 2] = [std::f64::consts::FRAC_1_SQRT_2, 0.866_025_403_784_438_6];

/// Is `x` `p / q` with `q` dividing 10^`decimals`, to f64's rounding (1e-12 of `x`: an
/// exact 0 computed as 0.8 · 3 − 0.6 · 4 is 2e-15)?
fn ends_within(x: f64, decimals: i32) -> bool {
    let unit = 10f64.powi(-decimals);
    (x - (x / unit).round() * unit).abs() <= 1e-12 * x.abs().max(1.0)
}

/// A rational with a small denominator (one dividing 10^8), or a listed root.
fn pencil_number(x: f64) -> bool {
    ends_within(x, 8) || LISTED_ROOTS.iter().any(|r| (x.abs() - r).abs() < 1e-12)
}

fn sides(ex: &Exercise) -> Vec<phonglab_core::explain::Explanation> {
    let s = &ex.doc.scene;
    let lit = Engine::<f64>::new(s).expect("the engine takes the scene").light(&s.vertex);
    let sides: &[Side] = if s.light_model.two_sided { &[Side::Front, Side::Back] } else { &[Side::Front] };
    sides.iter().map(|&side| explain(s, &lit, side)).collect()
}

/// Every intermediate of every exam exercise, over 1 000 seeds and the four levels, is a
/// rational with a denominator dividing 10^8 or a listed root; every cosine is exact in
/// four decimals; every distance an integer; every shininess 1, 2 or 4.
#[test]
fn a_thousand_seeds_give_numbers_for_a_pencil() {
    for seed in 0..1000u64 {
        let level = Level::from_number((seed % 4) as u8 + 1).unwrap();
        let rules = if seed % 8 < 4 { Rules::WORKSHEET } else { Rules::OPENGL };
        let ex = generate(seed, 1, &Spec::level(level, rules)).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        let ex = &ex[0];
        let s = &ex.doc.scene;
        assert!([1.0, 2.0, 4.0].contains(&s.material.shininess), "seed {seed}: shininess {}", s.material.shininess);
        let n = s.vertex.normal.length();
        assert_eq!(n, n.round(), "seed {seed}: the normal's length {n} is a whole number");
        for x in s.vertex.position.to_array().into_iter().chain(s.lights.iter().flat_map(|l| l.position.to_array())) {
            assert_eq!(x, x.round(), "seed {seed}: a given position is not whole: {x}");
        }
        for e in sides(ex) {
            for st in &e.steps {
                let Some(v) = &st.value else { continue };
                for &x in v {
                    assert!(pencil_number(x), "seed {seed}, level {level:?}: {} = {x} is no pencil number", st.name);
                    match st.kind {
                        StepKind::CosTheta | StepKind::CosBeta => {
                            assert!(ends_within(x, 4), "seed {seed}: {} = {x} is not exact in four decimals", st.name);
                        }
                        StepKind::Distance => assert!(ends_within(x, 0), "seed {seed}: d = {x}"),
                        _ => {}
                    }
                }
            }
        }
    }
}

#[test]
fn the_same_seed_gives_the_same_exam() {
    let spec = Spec::level(Level::Spotlight, Rules::WORKSHEET);
    let (a, b) = (generate(7, 3, &spec).unwrap(), generate(7, 3, &spec).unwrap());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.doc.scene, y.doc.scene);
    }
    assert_ne!(a[0].doc.scene, generate(8, 1, &spec).unwrap()[0].doc.scene);
}

#[test]
fn the_pencil_test_refuses_a_notebook_number() {
    assert!(pencil_number(0.84934656));
    assert!(pencil_number(-12.6));
    assert!(!pencil_number(0.79220526 / 3.0 + 1e-9));
    assert!(!pencil_number(1.0 / 3.0));
    assert!(!pencil_number(2f64.sqrt()));
    assert!(!ends_within(0.12345, 4));
}

/// The four-significant-digit roundings a student may write of `x`, a decimal of at most
/// eight decimals: the nearest, or both neighbours of a tie (0.14625: 0.1462 and 0.1463),
/// as decimal text, computed in integers (no float rounding decides a tie).
fn roundings(x: f64) -> Vec<String> {
    let units = (x * 1e8).round() as i128; // x in 1e-8
    let exponent = x.abs().log10().floor() as i32;
    let decimals = 3 - exponent; // of the fourth significant digit
    if decimals >= 8 {
        return vec![format!("{:.8}", units as f64 / 1e8)];
    }
    let step = 10i128.pow((8 - decimals) as u32);
    let (q, r) = (units.div_euclid(step), units.rem_euclid(step));
    let candidates = if 2 * r == step {
        vec![q, q + 1]
    } else if 2 * r < step {
        vec![q]
    } else {
        vec![q + 1]
    };
    let show = |k: i128| {
        if decimals <= 0 {
            format!("{}", k * 10i128.pow((-decimals) as u32))
        } else {
            format!("{:.*}", decimals as usize, k as f64 / 10f64.powi(decimals))
        }
    };
    candidates.into_iter().map(show).collect()
}

/// Moodle's numerical comparison (`qtype_numerical_answer::within_tolerance`, nominal):
/// `answer - tol <= x <= answer + tol` in floating point, with Moodle's own slack: the
/// tolerance grows by 1e-14 of the larger of itself and the answer.
fn moodle_accepts(answer: f64, tolerance: f64, typed: &str) -> bool {
    let x: f64 = typed.parse().unwrap();
    let tolerance = tolerance + 1e-14 * tolerance.abs().max(answer.abs()).max(1e-14);
    answer - tolerance <= x && x <= answer + tolerance
}

/// The honest roundings of `x` ([`roundings`], half-up and half-down of a tie) and the
/// double's own (Rust's exact formatting of the binary value), as decimal text.
fn honest_roundings(x: f64) -> Vec<String> {
    let mut all = roundings(x);
    let decimals = 3 - x.abs().log10().floor() as i32;
    if decimals > 0 && decimals < 8 {
        let binary = format!("{:.*}", decimals as usize, x);
        if !all.contains(&binary) {
            all.push(binary);
        }
    }
    all
}

/// The four-significant-digit numbers one unit of the fourth digit either side of each
/// honest rounding that are not themselves honest: what no exam field may take.
fn dishonest_neighbours(x: f64, honest: &[String]) -> Vec<String> {
    let decimals = 3 - x.abs().log10().floor() as i32;
    let unit = 10f64.powi(-decimals);
    let show = |v: f64| if decimals > 0 { format!("{:.*}", decimals as usize, v) } else { format!("{}", v.round()) };
    honest
        .iter()
        .flat_map(|r| {
            let r: f64 = r.parse().unwrap();
            [show(r - unit), show(r + unit)]
        })
        .filter(|n| !honest.iter().any(|h| h.parse::<f64>().unwrap() == n.parse::<f64>().unwrap()))
        .collect()
}

/// Every exam field of levels 1-4 takes every honest rounding a student may write of its
/// value (half-up, half-down of a tie, the double's) and no four-digit number one unit off
/// them, in Moodle's comparison with its slack: 0.7839 is wrong for 0.78384 (the quiz's
/// 0.01 %, 0.000078384, took it); every answer is written as its exact decimal.
#[test]
fn every_honest_rounding_of_an_exam_value_is_right_and_one_unit_off_is_not() {
    use phonglab_core::moodle::{Rounding, parts};
    use phonglab_core::question::number;
    let (mut ties, mut checked, mut neighbours) = (0, 0, 0);
    for level in 1..=4u8 {
        let spec = Spec::level(Level::from_number(level).unwrap(), Rules::WORKSHEET);
        for seed in 0..60u64 {
            for ex in &generate(seed, 20, &spec).unwrap() {
                for p in parts(ex, Rounding::Exam) {
                    let written = number(p.answer);
                    assert!(written.trim_start_matches('-').len() <= 14, "seed {seed}: {written} is no exact decimal");
                    if p.answer == 0.0 {
                        assert!(
                            moodle_accepts(p.answer, p.tolerance, "0")
                                && !moodle_accepts(p.answer, p.tolerance, "0.0001")
                        );
                        continue;
                    }
                    let honest = honest_roundings(p.answer);
                    ties += usize::from(honest.len() == 2);
                    checked += 1;
                    for r in &honest {
                        assert!(
                            moodle_accepts(p.answer, p.tolerance, r),
                            "level {level} seed {seed}: {r} refused for {written}"
                        );
                    }
                    for off in dishonest_neighbours(p.answer, &honest) {
                        neighbours += 1;
                        assert!(
                            !moodle_accepts(p.answer, p.tolerance, &off),
                            "level {level} seed {seed}: {off} taken for {written} (tolerance {})",
                            p.tolerance
                        );
                    }
                }
            }
        }
    }
    assert!(ties > 0, "the seeds hold ties, such as 0.14625");
    assert!(checked > 10_000 && neighbours >= 2 * checked, "{checked} fields, {neighbours} neighbours");
}
