//! Prints every hard_* public case: Mesa's front colour, ours in f32 and f64, and the limits taken.
use phonglab_core::glref::{evaluate, parse_cases};
use phonglab_core::{Engine, EvalOptions};

fn main() {
    let text = std::fs::read_to_string("tests/data/cases_public.json").unwrap();
    for (id, c) in parse_cases(&text).unwrap() {
        let c = c.unwrap();
        if !id.starts_with("hard_") {
            continue;
        }
        let mesa = c.expected.unwrap();
        let o32 = evaluate::<f32>(&c.scene, EvalOptions::default(), false);
        let o64 = evaluate::<f64>(&c.scene, EvalOptions::default(), false);
        let lim = Engine::<f64>::light_scene_vertex(&c.scene)
            .map(|l| l.all_limits().iter().map(|(_, l)| l.code()).collect::<Vec<_>>().join(","))
            .unwrap_or_default();
        let f = |r: &Result<phonglab_core::glref::CaseColors, _>| match r {
            Ok(c) => format!("{:.7?}", c.front),
            Err(e) => format!("ERR {e}"),
        };
        let same = match (&o32, &o64) {
            (Ok(a), Ok(b)) => {
                let d = (0..4)
                    .map(|k| (a.front[k] - mesa.front[k]).abs() / (1e-6 + 1e-5 * mesa.front[k].abs()))
                    .fold(0.0f64, f64::max);
                let d2 = (0..4)
                    .map(|k| (b.front[k] - mesa.front[k]).abs() / (1e-6 + 1e-5 * mesa.front[k].abs()))
                    .fold(0.0f64, f64::max);
                format!("{:.2}/{:.2}", d, d2)
            }
            _ => "-".into(),
        };
        println!(
            "{id:45} r={same:>12} mesa={:.7?}\n{:58} f32={}\n{:58} f64={}  [{lim}]",
            mesa.front,
            "",
            f(&o32),
            "",
            f(&o64)
        );
    }
}
