//! The cost-of-accuracy study's error figures. They are deterministic (the same pixels
//! come out of every run), so they are checked; the timings are not.

use std::sync::OnceLock;

use phonglab_core::cost::{self, Question, Setup, Study, Timing};
use phonglab_core::view::ObjectKind;
use phonglab_core::{Document, Shading};

const SIZE: usize = 160;

/// The worksheet's lighting on `object`, turned 30 degrees so the cylinder shows its side.
fn study_of(object: ObjectKind) -> Study {
    let mut doc = Document::default();
    doc.view.object = object;
    doc.view.spin_degrees = 30.0;
    let shaded = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let setup = Setup::new(&shaded, SIZE, [0.1; 3]);
    cost::run(&setup, Timing::ONCE, &mut |_| true).unwrap().expect("not cancelled")
}

fn study(object: ObjectKind) -> &'static Study {
    static S: [OnceLock<Study>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];
    let i = ObjectKind::ALL.iter().position(|o| *o == object).unwrap();
    S[i].get_or_init(|| study_of(object))
}

fn point<'a>(s: &'a Study, label: &str) -> &'a cost::CostPoint {
    s.points.iter().find(|p| p.variant.label == label).unwrap_or_else(|| panic!("no {label}"))
}

#[test]
fn finer_meshes_come_closer_to_the_reference() {
    for object in ObjectKind::ALL {
        let s = study(object);
        for shading in Shading::ALL {
            let errors: Vec<f64> =
                cost::levels(object).iter().map(|l| point(s, &format!("{} {l}", shading.label())).error.mean).collect();
            for w in errors.windows(2) {
                assert!(w[1] <= w[0] * 1.02, "{object:?} {shading:?}: {errors:?}");
            }
            assert!(errors[4] < errors[0] / 3.0, "{object:?} {shading:?}: {errors:?}");
        }
    }
}

#[test]
fn phong_beats_gouraud_beats_flat() {
    for object in [ObjectKind::Sphere, ObjectKind::Teapot] {
        let s = study(object);
        for (i, l) in cost::levels(object).into_iter().enumerate() {
            let e = |sh: Shading| point(s, &format!("{} {l}", sh.label())).error;
            let (f, g, p) = (e(Shading::Flat), e(Shading::Gouraud), e(Shading::Phong));
            assert!(p.mean <= g.mean && p.share_over_one <= g.share_over_one, "{object:?} {l}: {g:?} {p:?}");
            // On the coarsest teapot (64 triangles) interpolating its few colours is no
            // better than flat faces; from the middle level on it is.
            if i >= 2 {
                assert!(g.mean <= f.mean, "{object:?} {l}: {f:?} {g:?}");
            }
        }
    }
    // On the finest level studied Phong is within a display step nearly everywhere; Flat
    // still shows its facets.
    let s = study(ObjectKind::Sphere);
    assert!(point(s, "Phong 128").error.share_over_one < 0.01, "{:?}", point(s, "Phong 128").error);
    assert!(point(s, "Flat 128").error.share_over_one > 0.2, "{:?}", point(s, "Flat 128").error);
}

#[test]
fn f64_changes_nothing_a_display_shows() {
    for object in ObjectKind::ALL {
        let s = study(object);
        let p = s.points.iter().find(|p| p.variant.question == Question::Precision).unwrap();
        // Phong in f32 on the reference's own mesh: only the 8-bit rounding is left.
        assert!(p.error.max <= 0.5 + 1e-3, "{object:?}: {:?}", p.error);
        assert_eq!(p.error.share_over_one, 0.0);
        assert!(s.precision.max_error < 1e-5, "{:?}", s.precision);
        assert!(s.precision.max_error_shown_255 < 0.01, "{:?}", s.precision);
    }
}

#[test]
fn the_approximations_cost_what_they_should() {
    for object in [ObjectKind::Sphere, ObjectKind::Teapot] {
        let s = study(object);
        let mid = cost::levels(object)[2];
        let exact = point(s, &format!("Phong {mid}")).error;
        let with = |name: &str| point(s, &format!("Phong {mid}, {name}")).error;
        // llvmpipe's exp2/log2 pow is within an 8-bit step of the exact one.
        let llvm = with("llvmpipe pow");
        assert!((llvm.mean - exact.mean).abs() < 0.02, "{object:?}: {llvm:?} vs {exact:?}");
        // Schlick's rational pow changes the highlight's shape.
        assert!(with("Schlick pow").mean > exact.mean * 1.5, "{object:?}: {:?}", with("Schlick pow"));
        // The fast rsqrt (0.175 %) and skipping the renormalisation both cost accuracy.
        assert!(with("fast rsqrt").mean > exact.mean, "{object:?}");
        assert!(with("no renormalisation").mean > with("fast rsqrt").mean, "{object:?}");
    }
}

#[test]
fn the_figures_are_deterministic_and_the_maps_agree_with_them() {
    let s = study(ObjectKind::Teapot);
    let again = study_of(ObjectKind::Teapot);
    for (a, b) in s.points.iter().zip(&again.points) {
        assert_eq!(a.error, b.error, "{}", a.variant.label);
    }
    for (p, map) in s.points.iter().zip(&s.error_maps) {
        assert_eq!(map.len(), SIZE * SIZE);
        let max = map.iter().copied().fold(0.0f32, f32::max) as f64;
        assert!((max - p.error.max).abs() < 1e-3, "{}: {max} vs {}", p.variant.label, p.error.max);
        let over = map.iter().filter(|e| **e > 1.0).count();
        assert!((over as f64 / p.error.pixels as f64 - p.error.share_over_one).abs() < 1e-12);
    }
    let heat = cost::heat_map_rgba(&s.error_maps[0], &s.reference, 16.0);
    assert_eq!(heat.len(), SIZE * SIZE * 4);
    let csv = cost::to_csv(s);
    assert_eq!(csv.lines().count(), 1 + cost::variants(ObjectKind::Teapot).len());
    assert!(csv.lines().nth(1).unwrap().starts_with("teapot,Flat 1,Shading,Flat,1,64,"), "{csv}");
    // Labels with a comma are quoted, so every row has the header's ten fields.
    assert!(csv.contains("\nteapot,\"Phong 4, fast rsqrt\",Approximation,Phong,4,1024,"), "{csv}");
    for line in csv.lines() {
        let unquoted: String = line.split('"').step_by(2).collect();
        assert_eq!(unquoted.matches(',').count(), 9, "{line}");
    }
}

#[test]
fn a_study_can_be_cancelled() {
    let doc = Document::default();
    let shaded = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let setup = Setup::new(&shaded, 32, [0.0; 3]);
    let mut seen = 0;
    let r = cost::run(&setup, Timing::ONCE, &mut |p| {
        seen += 1;
        p.done < 3
    })
    .unwrap();
    assert!(r.is_none());
    assert_eq!(seen, 4);
}

#[test]
fn timing_rounds_visit_every_variant_again_and_keep_the_errors() {
    let doc = Document::default();
    let shaded = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let setup = Setup::new(&shaded, 32, [0.0; 3]);
    let n = cost::variants(doc.view.object).len();
    let once = cost::run(&setup, Timing::ONCE, &mut |_| true).unwrap().unwrap();
    let mut steps = Vec::new();
    let timing = Timing { rounds: 3, ..Timing::ONCE };
    let three = cost::run(&setup, timing, &mut |p| {
        steps.push((p.done, p.total, p.what.clone()));
        true
    })
    .unwrap()
    .unwrap();
    // The reference, each variant in three rounds, the precision figures, done.
    assert_eq!(steps.len(), 3 * n + 3);
    assert!(steps.iter().all(|s| s.1 == 3 * n + 2));
    assert!(steps.windows(2).all(|w| w[1].0 == w[0].0 + 1), "{steps:?}");
    assert_eq!(steps[3 * n].2, format!("{} (timing round 3)", cost::variants(doc.view.object)[n - 1].label));
    for (a, b) in once.points.iter().zip(&three.points) {
        assert_eq!(a.error, b.error, "{}", a.variant.label);
        assert!(b.ms.is_finite() && b.ms > 0.0);
    }
}
