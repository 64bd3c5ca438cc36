//! Any text as a scene file: it parses or is refused, never panics. A document it accepts
//! is valid, saves and loads back to itself, lights its vertex with no NaN and finite f64
//! colours (the editing rules keep every number a float; llvmpipe's pow is f32 arithmetic), gives the same colour in the
//! specialised evaluator as in the general engine (bit for bit, f32), explains itself, and
//! renders. A refusal's message is short, whatever the input (an excerpt of the line at
//! fault, never the line).
#![no_main]

use libfuzzer_sys::fuzz_target;
use phonglab_core::explain::{Side, explain};
use phonglab_core::mesh::sphere;
use phonglab_core::render::{Job, Renderer};
use phonglab_core::specialised::Lighter;
use phonglab_core::{Document, Engine, EvalOptions, PowFn};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let doc = match Document::from_toml(text) {
        Ok(doc) => doc,
        Err(e) => {
            assert!(e.to_string().chars().count() < 1000, "a long message: {e}");
            return;
        }
    };
    assert!(doc.validate().is_ok());
    let again = Document::from_toml(&doc.to_toml().expect("a valid document saves")).expect("and loads back");
    assert_eq!(again, doc);

    let scene = &doc.scene;
    for pow in PowFn::ALL {
        let options = EvalOptions::with_pow(pow);
        let lit64 = Engine::<f64>::with_options(scene, options).unwrap().light(&scene.vertex);
        for c in [lit64.front.primary, lit64.front.secondary, lit64.back.primary, lit64.back.secondary] {
            // llvmpipe's pow is f32 arithmetic even in the f64 engine (it emulates Mesa), so
            // 5^100 from an unnormalised normal is infinity there, as in Mesa.
            if pow == PowFn::Llvmpipe {
                assert!(!c.iter().any(|x| x.is_nan()), "f64 {c:?}");
            } else {
                assert!(c.iter().all(|x| x.is_finite()), "f64 {pow:?} {c:?}");
            }
        }
        let lit32 = Engine::<f32>::with_options(scene, options).unwrap().light(&scene.vertex);
        for c in [lit32.front.primary, lit32.front.secondary, lit32.back.primary, lit32.back.secondary] {
            assert!(!c.iter().any(|x| x.is_nan()), "f32 {c:?}");
        }
        let fast = Lighter::new(scene, options).unwrap().light_vertex(&scene.vertex);
        let bits = |c: [f32; 4]| c.map(f32::to_bits);
        assert_eq!(bits(fast[0].primary), bits(lit32.front.primary));
        assert_eq!(bits(fast[0].secondary), bits(lit32.front.secondary));
        let _ = explain(scene, &lit64, Side::Front);
        let _ = explain(scene, &lit32, Side::Back);
    }

    let setup = doc.shaded_setup(phonglab_core::PowFn::Exact);
    let mesh = sphere::glu_sphere(0.5, 8, 6);
    let job = setup.job(&mesh);
    let mut r = Renderer::new();
    let (image, _) = r.render(&job, 24, 24).expect("a valid scene renders");
    assert_eq!(image.rgba.len(), 24 * 24 * 4);
});
