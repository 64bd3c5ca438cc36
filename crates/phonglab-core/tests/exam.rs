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
