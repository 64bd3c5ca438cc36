//! The pixel probe and the term channels, against the pictures the renderer draws.
//!
//! - The probe's stored value is the rendered pixel, byte for byte, at random pixels of
//!   every shipped scene x object x shading (Flat both ways), and "no surface" exactly
//!   where the picture shows the background.
//! - Its colour before the clamp rounds to those bytes; its terms add up to that colour
//!   (Phong and Flat: the fragment's; Gouraud: the vertices' unclamped colours, weighted);
//!   Gouraud's weighted sum of the vertex colours is that colour.
//! - The colour channels (emission, scene ambient, ambient, diffuse, specular) add up to
//!   the colour before the clamp at every pixel, and every channel at a probed pixel is
//!   the probe's value there.

use crate::common;

use std::path::{Path, PathBuf};

use common::phonglab;
use phonglab_core::channels::{self, Channel};
use phonglab_core::probe::{self, Probe, ProbeShading};
use phonglab_core::render::{Job, Renderer};
use phonglab_core::{Document, FlatNormal, ObjectKind, PowFn, Shading};

const SIZE: usize = 72;

/// A fresh directory of this test run's own.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("phonglab-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn xorshift(mut s: u64) -> impl FnMut() -> u64 {
    move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s
    }
}

/// Every shading the renderer has: Gouraud, Phong, Flat per face and the demo's Flat.
const SHADINGS: [(Shading, FlatNormal); 4] = [
    (Shading::Gouraud, FlatNormal::Face),
    (Shading::Phong, FlatNormal::Face),
    (Shading::Flat, FlatNormal::Face),
    (Shading::Flat, FlatNormal::ScreenDerivatives),
];

/// Each shipped scene with each object and shading, as documents.
fn every_setup() -> Vec<(String, Document)> {
    let mut out = Vec::new();
    for file in common::scene_files() {
        let doc = Document::from_toml(&std::fs::read_to_string(&file).unwrap()).unwrap();
        for object in [ObjectKind::Sphere, ObjectKind::Teapot, ObjectKind::Cylinder] {
            for (shading, flat) in SHADINGS {
                let mut d = doc.clone();
                d.view.object = object;
                d.view.shading = shading;
                d.view.flat_normal = flat;
                let name = format!("{} {object:?} {shading:?}/{flat:?}", file.file_name().unwrap().to_string_lossy());
                out.push((name, d));
            }
        }
    }
    out
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
}

/// What the probe says at one covered pixel, checked against the picture and itself.
fn check_probe(name: &str, p: &Probe, pixel: &[u8]) {
    assert_eq!(&p.rgba8[..], pixel, "{name}: probe at ({}, {})", p.x, p.y);
    let to_byte = |c: f64| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    assert_eq!(p.unclamped.map(to_byte), p.rgba8, "{name}: the colour before the clamp rounds to the bytes");
    let sum = p.terms.sum();
    match &p.shading {
        ProbeShading::Gouraud(g) => {
            for c in 0..3 {
                // The renderer steps f32 planes: within a few f32 roundings of the f64 sum.
                assert!(close(g.weighted_sum[c], p.unclamped[c], 2e-5), "{name}: {g:?} against {:?}", p.unclamped);
                let unclamped: f64 = (0..3).map(|k| p.weights[k] * g.vertex_unclamped[k][c]).sum();
                assert!(close(sum[c], unclamped, 1e-9), "{name}: terms {sum:?} against {unclamped}");
            }
        }
        ProbeShading::Phong(f) => {
            assert!((f.normal_length - 1.0).abs() < 0.2 || f.normal_length == 0.0, "{name}: {f:?}");
            for c in 0..3 {
                // f32 lighting against the f64 terms at the same point.
                assert!(close(sum[c], p.unclamped[c], 1e-4), "{name}: terms {sum:?} against {:?}", p.unclamped);
            }
        }
        ProbeShading::Flat(f) => {
            for c in 0..3 {
                assert!(close(sum[c], p.unclamped[c], 1e-4), "{name}: terms {sum:?} against {:?} ({f:?})", p.unclamped);
            }
        }
    }
}

/// The probe's bytes are the picture's at random pixels of every shipped scene x object x
/// shading (408 pictures), and it finds no surface exactly where the picture is background.
#[test]
fn the_probe_is_the_rendered_pixel_everywhere() {
    let mut next = xorshift(0x9e3779b97f4a7c15);
    let (mut probed, mut uncovered) = (0, 0);
    let setups = every_setup();
    assert_eq!(setups.len(), 34 * 3 * 4);
    for (name, doc) in &setups {
        let setup = doc.shaded_setup(PowFn::Exact);
        let mesh = doc.view.mesh();
        let job = setup.job(&mesh);
        let mut r = Renderer::new();
        // Half the pictures keep their visibility, half draw the pixel's band again.
        r.keep_visibility(next().is_multiple_of(2));
        let image = r.render(&job, SIZE, SIZE).unwrap().0.clone();
        let mut keep = Renderer::new();
        keep.keep_visibility(true);
        keep.render(&job, SIZE, SIZE).unwrap();
        let covered: Vec<usize> = (0..SIZE * SIZE).filter(|i| keep.surface_at(*i).is_some()).collect();
        assert!(!covered.is_empty(), "{name}: nothing covered");
        // 12 covered pixels and 12 anywhere.
        let pick = |k: u64, n: u64| (k % n) as usize;
        let pixels: Vec<usize> =
            (0..24)
                .map(|j| {
                    if j < 12 {
                        covered[pick(next(), covered.len() as u64)]
                    } else {
                        pick(next(), (SIZE * SIZE) as u64)
                    }
                })
                .collect();
        for i in pixels {
            let (x, y) = (i % SIZE, i / SIZE);
            let pixel = &image.rgba[i * 4..][..4];
            match probe::probe(&r, &job, x, y).unwrap() {
                Some(p) => {
                    check_probe(name, &p, pixel);
                    probed += 1;
                }
                None => {
                    assert!(keep.surface_at(i).is_none(), "{name}: ({x}, {y}) covered but not probed");
                    let bg = job.background.map(|c| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8);
                    assert_eq!(&pixel[..3], &bg[..], "{name}: ({x}, {y}) uncovered but not background");
                    uncovered += 1;
                }
            }
        }
    }
    eprintln!("{probed} pixels probed, {uncovered} uncovered");
    assert!(probed > 5_000, "{probed}");
}

/// A picture drawn with its visibility kept, and a probe at every `step`-th covered pixel.
fn probed(job: &Job<'_>, r: &mut Renderer, step: usize) -> Vec<Probe> {
    r.keep_visibility(true);
    let image = r.render(job, SIZE, SIZE).unwrap().0.clone();
    (0..SIZE * SIZE)
        .filter(|i| image.covered(i % SIZE, i / SIZE) == Some(true))
        .step_by(step)
        .map(|i| probe::probe(r, job, i % SIZE, i / SIZE).unwrap().expect("covered"))
        .collect()
}

/// The five colour channels add up to the colour before any clamp at every covered pixel
/// (the probe's terms' sum there), and each of the eleven channels at a probed pixel is the
/// probe's value, for a scene with three lights, a spotlight, the worksheet's mview3 and
/// the Phong demo, in every shading.
#[test]
fn the_channels_sum_to_the_image_and_match_the_probe() {
    let names = ["three-lights.toml", "spotlight.toml", "worksheet-mview3.toml", "phong-demo.toml"];
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut checked = 0;
    for file in names {
        let doc = Document::from_toml(&std::fs::read_to_string(dir.join(file)).unwrap()).unwrap();
        for (shading, flat) in SHADINGS {
            let mut d = doc.clone();
            (d.view.shading, d.view.flat_normal) = (shading, flat);
            let setup = d.shaded_setup(PowFn::Exact);
            let mesh = d.view.mesh();
            let job = setup.job(&mesh);
            let mut r = Renderer::new();
            let probes = probed(&job, &mut r, 37);
            assert!(probes.len() > 10, "{file}: {}", probes.len());
            let images: Vec<_> =
                Channel::ALL.iter().map(|&c| channels::channel_image(&r, &job, c, None).unwrap()).collect();
            let colour =
                [Channel::Emission, Channel::SceneAmbient, Channel::Ambient, Channel::Diffuse, Channel::Specular];
            let of = |c: Channel| &images[Channel::ALL.iter().position(|&k| k == c).unwrap()];
            for p in &probes {
                let i = p.y * SIZE + p.x;
                let sum: [f64; 3] =
                    std::array::from_fn(|k| colour.iter().map(|&c| of(c).values[i].unwrap()[k]).sum::<f64>());
                let want = p.terms.sum();
                for k in 0..3 {
                    assert!(close(sum[k], want[k], 1e-12), "{file} {shading:?}: {sum:?} against {want:?}");
                    if shading != Shading::Gouraud {
                        assert!(
                            close(sum[k], p.unclamped[k], 1e-4),
                            "{file} {shading:?}: {sum:?} vs {:?}",
                            p.unclamped
                        );
                    }
                }
                for (c, image) in Channel::ALL.iter().zip(&images) {
                    let v = image.values[i].unwrap();
                    let normal = v; // the normal channel is checked against itself below
                    let want = c.value(&p.terms, if *c == Channel::Normal { normal } else { [0.0; 3] }, None);
                    assert_eq!(v, want, "{file} {shading:?} {c:?} at ({}, {})", p.x, p.y);
                }
                let n = of(Channel::Normal).values[i].unwrap();
                let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                // The Phong demo's shader does not renormalise its interpolated normal.
                let unit = !(file == "phong-demo.toml" && shading == Shading::Phong);
                assert!(!unit || (len - 1.0).abs() < 1e-9, "{file} {shading:?}: normal {n:?}");
                checked += 1;
            }
            // Uncovered pixels have no value in any channel.
            for image in &images {
                for (i, v) in image.values.iter().enumerate() {
                    let covered = r.surface_at(i).is_some();
                    assert_eq!(v.is_some(), covered, "{file} {:?} pixel {i}", image.channel);
                }
            }
        }
    }
    assert!(checked > 300, "{checked}");
}

/// The three-lights scene (four lights on): three or more reach some pixel, the count's
/// scale runs to four, each light's diffuse channel differs and they add up to the
/// diffuse channel of all.
#[test]
fn per_light_channels_pick_their_light() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let doc = Document::from_toml(&std::fs::read_to_string(dir.join("three-lights.toml")).unwrap()).unwrap();
    let mut d = doc.clone();
    d.view.shading = Shading::Phong;
    let setup = d.shaded_setup(PowFn::Exact);
    let mesh = d.view.mesh();
    let job = setup.job(&mesh);
    let mut r = Renderer::new();
    r.keep_visibility(true);
    r.render(&job, SIZE, SIZE).unwrap();
    let count = channels::channel_image(&r, &job, Channel::LightCount, None).unwrap();
    let most = count.values.iter().flatten().map(|v| v[0] as usize).max().unwrap();
    let lights = job.scene.lights.len();
    assert!(most >= 3 && most <= lights, "at most {most} of {lights} lights reach a pixel");
    assert_eq!(count.range(), (0.0, lights as f64));
    let per: Vec<_> =
        (0..lights).map(|l| channels::channel_image(&r, &job, Channel::Diffuse, Some(l)).unwrap().values).collect();
    assert_ne!(per[0], per[1]);
    assert_ne!(per[1], per[2]);
    let all = channels::channel_image(&r, &job, Channel::Diffuse, None).unwrap();
    for (i, v) in all.values.iter().enumerate() {
        if let Some(v) = v {
            let s: f64 = per.iter().map(|p| p[i].unwrap()[0]).sum();
            assert!(close(v[0], s, 1e-12));
        }
    }
}

/// A PFM holds the channel's values bottom row first, as f32, NaN where uncovered.
#[test]
fn the_raw_channel_is_a_portable_float_map() {
    let doc = Document::default();
    let setup = doc.shaded_setup(PowFn::Exact);
    let mesh = doc.view.mesh();
    let job = setup.job(&mesh);
    let mut r = Renderer::new();
    r.keep_visibility(true);
    r.render(&job, SIZE, SIZE).unwrap();
    for channel in [Channel::Diffuse, Channel::NDotL] {
        let image = channels::channel_image(&r, &job, channel, None).unwrap();
        let bytes = channels::pfm(&image);
        let n = channel.components();
        let header = format!("{}\n{SIZE} {SIZE}\n-1.0\n", if n == 3 { "PF" } else { "Pf" });
        assert!(bytes.starts_with(header.as_bytes()));
        let data = &bytes[header.len()..];
        assert_eq!(data.len(), SIZE * SIZE * n * 4);
        let at = |x: usize, y_from_bottom: usize, c: usize| {
            let k = ((y_from_bottom * SIZE + x) * n + c) * 4;
            f32::from_le_bytes(data[k..k + 4].try_into().unwrap())
        };
        let mut covered = 0;
        for (i, v) in image.values.iter().enumerate() {
            let (x, y) = (i % SIZE, i / SIZE);
            match v {
                Some(v) => {
                    assert_eq!(at(x, SIZE - 1 - y, 0), v[0] as f32);
                    covered += 1;
                }
                None => assert!(at(x, SIZE - 1 - y, 0).is_nan()),
            }
        }
        assert!(covered > 500, "{covered}");
    }
}

/// `phonglab probe --json` at a pixel of a spotlight teapot gives the bytes `phonglab
/// render` wrote there, with the fields scripts read; the report speaks the student's
/// language; outside the picture, a clear refusal.
#[test]
fn the_probe_command_agrees_with_the_render_command() {
    let dir = scratch("probe");
    let png = dir.join("spot.png");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml");
    let scene = scene.to_str().unwrap();
    let common = ["--scene", scene, "--object", "teapot", "--size", "96"];
    for shading in ["gouraud", "phong", "flat"] {
        let args: Vec<&str> =
            ["render", "-o", png.to_str().unwrap(), "--shading", shading].into_iter().chain(common).collect();
        let out = phonglab(&args);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let (w, _, rgba) = phonglab::io::image::read_png(&png).unwrap();
        let mut covered = 0;
        for (x, y) in [(48, 48), (40, 60), (20, 30), (70, 52), (0, 0)] {
            let at = format!("{x},{y}");
            let args: Vec<&str> =
                ["probe", "--json", "--at", &at, "--shading", shading].into_iter().chain(common).collect();
            let out = phonglab(&args);
            assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
            let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
            if v["covered"] == false {
                continue;
            }
            covered += 1;
            let bytes: Vec<u8> = v["rgba8"].as_array().unwrap().iter().map(|b| b.as_u64().unwrap() as u8).collect();
            assert_eq!(&bytes[..], &rgba[(y * w + x) * 4..][..4], "{shading} at {at}");
            assert_eq!(v["unclamped"].as_array().unwrap().len(), 4);
            assert!(v["terms"]["lights"].as_array().is_some_and(|l| !l.is_empty()));
            for key in ["emission", "scene_ambient"] {
                assert_eq!(v["terms"][key].as_array().unwrap().len(), 3, "{key}");
            }
            let want: &[&str] = match shading {
                "gouraud" => &["weights", "vertices", "vertex_colours", "weighted_sum"],
                "phong" => &["normal", "position", "normal_interpolated"],
                _ => &["centroid", "provoking_vertex"],
            };
            for key in want {
                assert!(!v[key].is_null(), "{shading}: {key} missing in {v}");
            }
        }
        assert!(covered >= 3, "{shading}: {covered}");
    }
    let pt = common::phonglab_in("pt_PT.UTF-8", &["probe", "--at", "48,48", "--scene", scene, "--size", "96"]);
    let text = String::from_utf8_lossy(&pt.stdout);
    assert!(text.contains("Píxel (48, 48)") && text.contains("Pesos corrigidos pela perspetiva"), "{text}");
    let br = common::phonglab_in("pt_BR.UTF-8", &["probe", "--at", "48,48", "--scene", scene, "--size", "96"]);
    assert!(String::from_utf8_lossy(&br.stdout).contains("Pesos corrigidos pela perspectiva"));
    let out = phonglab(&["probe", "--at", "96,3", "--size", "96"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("outside the 96x96 picture"));
    let out = phonglab(&["probe", "--at", "3;4"]);
    assert_eq!(out.status.code(), Some(2));
}

/// `render --channel` writes the false colour and `--raw` its values; the raw file may not
/// be the picture, nor a scene.
#[test]
fn render_writes_a_channel_and_its_raw_values() {
    let dir = scratch("channel");
    let (png, pfm) = (dir.join("n.png"), dir.join("n.pfm"));
    let (png_s, pfm_s) = (png.to_str().unwrap(), pfm.to_str().unwrap());
    let out = phonglab(&["render", "-o", png_s, "--channel", "n-dot-l", "--raw", pfm_s, "--size", "64"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("channel N·L in viridis: from -1 to 1"), "{err}");
    let (w, h, rgba) = phonglab::io::image::read_png(&png).unwrap();
    assert_eq!((w, h), (64, 64));
    let raw = std::fs::read(&pfm).unwrap();
    assert!(raw.starts_with(b"Pf\n64 64\n-1.0\n"));
    assert_eq!(raw.len(), b"Pf\n64 64\n-1.0\n".len() + 64 * 64 * 4);
    // The centre faces the light: a value near the top of the scale, viridis' yellow end.
    let centre = &rgba[(32 * 64 + 32) * 4..][..3];
    assert!(centre[0] > 150 && centre[1] > 150 && centre[2] < 120, "{centre:?}");
    let out = phonglab(&["render", "-o", png_s, "--channel", "diffuse", "--raw", png_s]);
    assert_eq!(out.status.code(), Some(2), "the raw file onto the picture");
    let out = phonglab(&["render", "-o", png_s, "--raw", pfm_s]);
    assert_eq!(out.status.code(), Some(2), "--raw needs --channel");
}

/// `at` is one quantity in the probe: the worksheet's k0 + k1 d + k2 d², which divides,
/// and the factor OpenGL multiplies by is shown as 1/at (it was labelled "Attenuation"
/// with 0.9182 beside a calculation whose at was 1.089, and the terms "at spot Iamb").
#[test]
fn the_probe_shows_at_and_its_inverse_under_their_own_names() {
    use phonglab_core::locale::num;
    use phonglab_core::probe_report::report;
    let doc = Document::from_toml(
        &std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/spotlight.toml")).unwrap(),
    )
    .unwrap();
    let setup = doc.shaded_setup(PowFn::Exact);
    let mesh = doc.view.mesh();
    let job = setup.job(&mesh);
    let mut r = Renderer::new();
    r.keep_visibility(true);
    r.render(&job, SIZE, SIZE).unwrap();
    let p = probe::probe(&r, &job, SIZE / 2, SIZE / 2).unwrap().expect("the object at the centre");
    let factor = p.terms.lights[0].attenuation;
    assert!(factor < 0.99, "the scene attenuates: {factor}");
    let lines = report(&p);
    let named = |n: &str| lines.iter().find(|l| l.name == n).unwrap_or_else(|| panic!("no {n}: {lines:?}"));
    assert_eq!(named("at").value, num(1.0 / factor, 4));
    // Where the factor is shown, it says so: "1/at = 0.9182".
    let shown = format!("1/at = {}", num(factor, 4));
    assert!(lines.iter().any(|l| l.value == shown), "no {shown}: {lines:?}");
    for term in ["Iamb", "Idif", "Ispec"] {
        named(&format!("spot · {term} / at"));
    }
    assert!(lines.iter().all(|l| !l.name.contains("1 / (k") && !l.name.starts_with("at ")), "{lines:?}");
}

/// The probe names the side it lit as a `Side` and each light by its `LightId`; its JSON
/// (`phonglab probe --json`) still writes both as numbers: the side 0 or 1, a light's
/// `GL_LIGHTi` index.
#[test]
fn the_probe_writes_its_side_and_lights_as_numbers() {
    use phonglab_core::scene::{LightId, Side};
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes/three-lights.toml");
    let doc = Document::from_toml(&std::fs::read_to_string(file).unwrap()).unwrap();
    let setup = doc.shaded_setup(PowFn::Exact);
    let mesh = doc.view.mesh();
    let job = setup.job(&mesh);
    let mut r = Renderer::new();
    let mut p = probed(&job, &mut r, 101).swap_remove(0);
    assert_eq!(p.side, Side::Front, "the sphere shows its front");
    let ids: Vec<LightId> = p.terms.lights.iter().map(|l| l.index).collect();
    assert_eq!(ids, LightId::all(4).collect::<Vec<_>>(), "the scene's four lights, in order");
    p.side = Side::Back;
    let v = serde_json::to_value(&p).unwrap();
    assert_eq!(v["side"], serde_json::json!(1));
    let written: Vec<_> = v["terms"]["lights"].as_array().unwrap().iter().map(|l| l["index"].clone()).collect();
    assert_eq!(written, [0, 1, 2, 3].map(|i| serde_json::json!(i)));
}
