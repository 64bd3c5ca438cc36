//! Every ordinary public case (not `hard_*`) against Mesa llvmpipe's own result:
//! primary and secondary colours, front and back, in f32 and in f64, to rtol 1e-5, atol 1e-6.
//!
//! Two cases are exceptions, because there Mesa itself is 1.2-1.3e-5 away from the
//! exact value: each has a spotlight with exponent 87-121 aimed almost at the vertex and
//! a near-highlight specular with shininess 76.8. `cos^e` has condition number `e`, so
//! Mesa's f32 rounding of the cosine (1 ulp = 6e-8) and llvmpipe's `pow` (an
//! `exp2(e log2 x)` approximation whose log2 has ~6e-8 absolute error near 1; see
//! `phonglab_core::pow`, bit-exact with Mesa's on 540 probes) are amplified to ~1e-5.
//! glref's own float64 formula (`ref_spec.py`) misses the same cases. For them the
//! test asserts what is true instead: Mesa is within rtol 1.5e-5 of our f64 value (its
//! measured error is 1.2-1.3e-5), and our f32 value is within rtol 1e-5 of our f64 value
//! (measured 5e-8 and 6e-6): closer to the exact answer than Mesa is. The test fails if one
//! of them stops needing the exception in both precisions.

use crate::common;

use phonglab_core::glref::evaluate;
use phonglab_core::{EvalOptions, PowFn, Real};

/// Cases where Mesa's own error exceeds rtol 1e-5 (see the module comment).
const ILL_CONDITIONED: [&str; 2] = ["rand0054", "rand0076"];

/// Checks every case; returns the exceptions that matched the strict tolerance anyway.
fn check<S: Real>(pow: PowFn) -> Vec<String> {
    let mut strict_ok = Vec::new();
    let cases = common::public_cases();
    let ordinary: Vec<_> = cases.iter().filter(|c| !c.id.starts_with("hard_")).collect();
    assert_eq!(ordinary.len(), 200, "the public set has 200 random cases");
    let mut failures = Vec::new();
    let mut worst = (0.0f64, String::new());
    for c in &ordinary {
        let mesa = c.expected.expect("generated cases embed Mesa's result");
        let ours =
            evaluate::<S>(&c.scene, EvalOptions::with_pow(pow), false).unwrap_or_else(|e| panic!("{}: {e}", c.id));
        let strict = common::worst_ratio(&ours, &mesa, 1e-5, 1e-6);
        if ILL_CONDITIONED.contains(&c.id.as_str()) {
            let exact = evaluate::<f64>(&c.scene, EvalOptions::with_pow(pow), false).unwrap();
            let mesa_err = common::worst_ratio(&mesa, &exact, 1.5e-5, 1e-6);
            let ours_err = common::worst_ratio(&ours, &exact, 1e-5, 1e-6);
            if mesa_err > 1.0 || ours_err > 1.0 {
                failures.push(format!(
                    "{}: Mesa {mesa_err:.3} x rtol 1.5e-5 from the f64 value, ours {ours_err:.3} x rtol 1e-5\n  ours {ours:?}\n  mesa {mesa:?}",
                    c.id
                ));
            }
            if strict <= 1.0 {
                strict_ok.push(c.id.clone());
            }
            continue;
        }
        if strict > worst.0 {
            worst = (strict, c.id.clone());
        }
        if strict > 1.0 {
            failures.push(format!("{}: {strict:.3} x tolerance\n  ours {ours:?}\n  mesa {mesa:?}", c.id));
        }
    }
    eprintln!("{} {:?}: worst |diff| / (atol + rtol |mesa|) = {:.3} ({})", S::NAME, pow, worst.0, worst.1);
    assert!(
        failures.is_empty(),
        "{} of {} cases differ from Mesa:\n{}",
        failures.len(),
        ordinary.len(),
        failures.join("\n")
    );
    strict_ok
}

#[test]
fn ordinary_cases_match_mesa_in_f32() {
    check::<f32>(PowFn::Exact);
}

#[test]
fn ordinary_cases_match_mesa_in_f64() {
    check::<f64>(PowFn::Exact);
}

#[test]
fn every_exception_is_still_needed() {
    let ok32 = check::<f32>(PowFn::Exact);
    let ok64 = check::<f64>(PowFn::Exact);
    let stale: Vec<_> = ok32.iter().filter(|id| ok64.contains(id)).collect();
    assert!(stale.is_empty(), "{stale:?} now match to rtol 1e-5 in f32 and f64: remove them from ILL_CONDITIONED");
}
