//! `phonglab diagnose`: a student's picture of a scene, compared with the right picture and
//! with each picture mistake's ([`phonglab_core::teach::diagnose`]): the verdict, the
//! closest mistake with its score, a difference image (the places the findings name boxed
//! on it) and the probe's numbers at the pixel that differs most.

use std::path::{Path, PathBuf};

use crate::t;
use anyhow::Result;
use clap::Args;
use phonglab_core::teach::diagnose::{
    Diagnosis, Drawing, Shape, Tried, Verdict, diagnose, drawings_at_most, listed, said, said::Said,
};
use phonglab_core::teach::picture_match::{difference_image, draw_boxes};
use phonglab_core::{PowFn, probe, probe_report};

use super::render::ShadedInput;
use crate::io::work_output::Kind;

/// `phonglab diagnose`.
#[derive(Args, Debug)]
pub struct DiagnoseArgs {
    /// The scene the picture was made for (TOML).
    #[arg(long)]
    pub scene: PathBuf,
    /// The student's picture (PNG), made with the export's camera and size.
    #[arg(long)]
    pub image: PathBuf,
    /// The picture's width and height in pixels: the export's window is 512.
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(8..=4096))]
    pub size: u32,
    /// Write the difference image (the picture against the right one) to this PNG.
    #[arg(long, value_name = "FILE.png")]
    pub diff: Option<PathBuf>,
    /// Print JSON (for scripts and tests) instead of the report.
    #[arg(long)]
    pub json: bool,
}

/// The scene drawn as the export draws it: its shaded view at `size` pixels square.
fn right_drawing(a: &DiagnoseArgs, outputs: &[&Path]) -> Result<Drawing> {
    let input = ShadedInput {
        object: None,
        obj: None,
        shading: None,
        size: a.size,
        scene: Some(a.scene.clone()),
        preset: None,
        bench_frame: None,
        pow: PowFn::Exact,
        cull: false,
        frame: None,
        correct: Vec::new(),
    };
    // Its whole need is checked below, once: the render's share alone would be refused
    // first with a budget too small for the rest ("1M: needs 5M", then "5M: needs 26M").
    let loaded = input.load_unbudgeted(outputs)?;
    let job = loaded.job();
    let (vertices, triangles) = (job.mesh.positions.len() as u64, job.mesh.triangle_count() as u64);
    let mut drawing = Drawing::of(&job);
    drawing.inside.clone_from(&loaded.inside);
    let what = t!("budget-what-diagnose", size = a.size, count = drawings_at_most(&drawing));
    let needed = crate::io::budget::diagnose_bytes(u64::from(a.size), vertices, triangles);
    crate::io::budget::check(&what, needed).map_err(anyhow::Error::msg)?;
    Ok(drawing)
}

/// Whether `path`'s name ends in `.png` (any case): a difference image under another name
/// (`.ipynb`, `.py`, `.txt`) in a class's folder would be read by `check` as a submission.
fn named_png(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"))
}

fn score_of(t: &Tried) -> f64 {
    t.matched.map_or(0.0, |m| m.score)
}

/// The mistakes this scene cannot show, for JSON: each its id, and `light` for one made per
/// light (separate fields, so that a script reads the id as the table's).
fn invisible(d: &Diagnosis) -> Vec<serde_json::Value> {
    let entry = |t: &Tried| match t.light() {
        Some(light) => serde_json::json!({ "id": t.id(), "light": light }),
        None => serde_json::json!({ "id": t.id() }),
    };
    d.tried.iter().filter(|t| t.matched.is_none()).map(entry).collect()
}

/// The pixel's bytes as "(r, g, b)".
fn bytes_at(rgba: &[u8], size: usize, (x, y): (usize, usize)) -> [u8; 3] {
    let i = (y * size + x) * 4;
    [rgba[i], rgba[i + 1], rgba[i + 2]]
}

/// Runs `phonglab diagnose`: whether the picture is right (the exit code, for scripts: 0
/// right, 1 wrong or unexplained; [`super::judged`]).
pub fn run(a: &DiagnoseArgs) -> Result<bool> {
    use crate::io::same_file::Input;
    if let Some(diff) = a.diff.as_deref().filter(|d| !named_png(d)) {
        anyhow::bail!(t!("diagnose-diff-not-png", path = crate::io::reasons::shown(diff)));
    }
    let outputs: Vec<&Path> = a.diff.iter().map(PathBuf::as_path).collect();
    let inputs = [(a.scene.as_path(), Input::Scene), (a.image.as_path(), Input::Any)];
    // Never through a link, nor over a file phonglab did not write (`io::work_output`); a
    // link said first, as a link.
    let kinds: Vec<(&Path, Kind)> = outputs.iter().map(|&o| (o, Kind::Difference)).collect();
    crate::io::work_output::refuse_links(&kinds).map_err(anyhow::Error::msg)?;
    crate::io::same_file::refuse_onto(&outputs, &inputs).map_err(anyhow::Error::msg)?;
    crate::io::work_output::refuse(&kinds, None).map_err(anyhow::Error::msg)?;
    let right = right_drawing(a, &outputs)?;
    let size = a.size as usize;
    let image = crate::io::student_png::read(&a.image, size).map_err(anyhow::Error::msg)?;
    let d = diagnose(&right, &image, size)?;
    let is_right = matches!(d.verdict, Verdict::Right);
    // The places the findings name, boxed on it.
    let boxes = Said::of(&d).boxes();
    let mut difference = difference_image(&d.picture, &image);
    draw_boxes(&mut difference.rgba, size, &boxes);
    if let Some(diff) = &a.diff {
        let signed = Kind::Difference.png_text();
        let png = crate::io::image::encode_png_signed(size, size, &difference.rgba, signed)?;
        crate::io::work_output::write(diff, Kind::Difference, None, &png).map_err(anyhow::Error::msg)?;
    }
    let worst = (d.right.worst_levels > 0).then_some(d.right.worst);
    let probed = match worst {
        Some((x, y)) => probe::probe(&d.renderer, &right.job(), x, y)?,
        None => None,
    };
    if a.json {
        println!(
            "{}",
            phonglab_core::escape::json::text(&serde_json::to_string_pretty(&json(&d, &image, size, probed.as_ref()))?)
        );
        return Ok(is_right);
    }
    let mut out = d.lines();
    // Each once, its light in brackets; never a fitted one (its picture is the scene's
    // only because the picture showed the scene's values).
    let hidden: Vec<Tried> = d.tried.iter().filter(|t| t.matched.is_none() && !t.fitted()).copied().collect();
    if !hidden.is_empty() {
        out.push(t!("diagnose-invisible", ids = listed(&hidden)));
    }
    if let Some(diff) = &a.diff {
        let said = said::difference_said(&difference, boxes.len());
        out.push(t!("diagnose-diff-written", path = crate::io::reasons::shown(diff), said = said));
    }
    if let Some(p) = worst {
        // Where (0, 0) is, once: the findings say it when they name pixels already.
        if !Said::of(&d).places() {
            out.push(t!("diagnose-where"));
        }
        let show = |b: [u8; 3]| format!("({}, {}, {})", b[0], b[1], b[2]);
        out.push(t!(
            "diagnose-worst",
            x = p.0 as i64,
            y = p.1 as i64,
            image = show(bytes_at(&image, size, p)),
            right = show(bytes_at(&d.picture, size, p))
        ));
        match &probed {
            Some(pr) => out.push(probe_report::text(&probe_report::report(pr))),
            None => out.push(t!("probe-uncovered", x = p.0 as i64, y = p.1 as i64)),
        }
    }
    println!("{}", phonglab_core::escape::terminal::lines(&out.join("\n")));
    Ok(is_right)
}

/// The JSON: the verdict, the causes with their scores (best first; `light` for a mistake
/// made per light, `emission` the fitted colour for `emission-added`), the first causes
/// when they draw the same picture (`same_picture`, else empty), every mistake tried,
/// the right picture's score and the pixel that differs most with the probe there.
fn json(d: &Diagnosis, image: &[u8], size: usize, probed: Option<&probe::Probe>) -> serde_json::Value {
    use serde_json::json;
    let cause = |t: &Tried| {
        let mut c = json!({ "id": t.id(), "score": score_of(t) });
        if let Some(light) = t.light() {
            c["light"] = json!(light);
        }
        if t.id() == "emission-added" {
            c["emission"] = json!(t.at.emission);
        }
        c
    };
    let worst = (d.right.worst_levels > 0).then(|| {
        let p = d.right.worst;
        json!({
            "x": p.0, "y": p.1, "levels": d.right.worst_levels,
            "image": bytes_at(image, size, p), "right": bytes_at(&d.picture, size, p),
            "probe": probed.and_then(|pr| serde_json::to_value(pr).ok()),
        })
    });
    let shape = d.shape.map(|s| {
        let mut j = json!({ "id": s.id() });
        match s {
            Shape::OtherOutline(share) => j["share"] = json!(share),
            Shape::Region(r) => {
                j["region"] = json!({
                    "pixels": r.pixels, "x": r.centre.0, "y": r.centre.1,
                    "from": [r.from.0, r.from.1], "to": [r.to.0, r.to.1],
                });
            }
            Shape::Marks(m) => {
                j["marks"] = json!({ "pixels": m.pixels, "from": [m.from.0, m.from.1], "to": [m.to.0, m.to.1] });
            }
            Shape::Levels(l) => {
                j["levels"] = json!({ "shift": l.shift, "gamma": l.gamma, "score": l.matched.score });
            }
            Shape::Offset(o) => {
                j["offset"] = json!({ "levels": o.levels, "pixels": o.pixels, "from": [o.from.0, o.from.1], "to": [o.to.0, o.to.1] });
            }
            Shape::NothingDrawn => {}
        }
        j
    });
    json!({
        "verdict": d.verdict.name(),
        "finding": said::finding(&Said::of(d)),
        "within": d.within.map(|w| json!({ "most": w.most, "pixels": w.pixels, "inside": w.inside })),
        "shape": shape,
        "causes": d.causes.iter().map(cause).collect::<Vec<_>>(),
        "same_picture": d.same_picture.iter().map(cause).collect::<Vec<_>>(),
        "right_score": d.right.score,
        "lossy_score": d.lossy.map(|m| m.score),
        "evenly_off": d.bias.map(|b| {
            let channel = ["red", "green", "blue"][b.channel.min(2)];
            json!({
                "from": [b.at.0, b.at.1], "width": phonglab_core::teach::diagnose::BIAS_SQUARE,
                "channel": channel, "levels": b.levels, "errors": b.errors,
            })
        }),
        "footprint": d.footprint.as_ref().map(|f| json!({
            "pixels": f.pixels, "x": f.centre.0, "y": f.centre.1, "right": f.right, "mistake": f.mistake,
            "most": f.most,
            "groups": f.groups.iter().map(|g| json!({
                "pixels": g.pixels, "from": [g.from.0, g.from.1], "to": [g.to.0, g.to.1],
            })).collect::<Vec<_>>(),
        })),
        "pixels": d.right.pixels,
        "size": size,
        "tried": d.tried.iter().filter(|t| t.matched.is_some()).map(cause).collect::<Vec<_>>(),
        "not_visible": invisible(d),
        "worst": worst,
    })
}
