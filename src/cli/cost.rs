//! `phonglab cost`: the cost-of-accuracy study from the command line. Prints a table per
//! object and writes `cost.csv` (every variant) and `cost.png` (the app's chart, painted
//! on the CPU), plus each object's error heat maps of Gouraud and Phong at the middle level.

use std::io::IsTerminal as _;
use std::path::PathBuf;

use anyhow::{Context as _, Result, bail};
use clap::Args;
use phonglab_core::cost::{self, Question, Setup, Study, Timing};
use phonglab_core::{Document, ObjectKind};

use crate::paint::cost_chart::{BACKGROUND, HEAT_FULL_SCALE, cost_chart_ui, takeaways};

/// What to study: the command line's arguments, resolved.
#[derive(Clone, Debug)]
pub struct CostRun {
    /// The objects, in order.
    pub objects: Vec<ObjectKind>,
    /// The lighting and the view (the worksheet's scene by default).
    pub doc: Document,
    /// Where the files go.
    pub out: PathBuf,
    /// Image size in pixels.
    pub size: usize,
    /// The object's turn about y, degrees.
    pub spin: f64,
    /// Rendering threads (0: one per core).
    pub threads: usize,
    /// How long to time each variant.
    pub timing: Timing,
}

/// Runs the study of every chosen object, printing progress on stderr when it is a terminal.
pub fn studies(r: &CostRun) -> Result<Vec<Study>> {
    if !r.spin.is_finite() {
        anyhow::bail!(crate::t!("err-spin"));
    }
    let mut out = Vec::new();
    for &object in &r.objects {
        let mut doc = r.doc.clone();
        doc.view.object = object;
        doc.view.spin_degrees = r.spin.rem_euclid(360.0);
        let shaded = doc.shaded_setup(phonglab_core::PowFn::Exact);
        let setup = Setup::new(&shaded, r.size, BACKGROUND);
        let tty = std::io::stderr().is_terminal();
        let study = cost::run(&setup, r.timing, &mut |p| {
            if tty {
                eprint!("\r\x1b[2K{}: {}/{} {}", object.label(), p.done, p.total, p.what);
            }
            true
        })?
        .context(crate::t!("err-study-stopped"))?;
        if tty {
            eprintln!();
        }
        out.push(study);
    }
    Ok(out)
}

/// The table printed for one study.
pub fn table(study: &Study) -> String {
    use crate::locale::decimal;
    use crate::t;
    let mut s = format!(
        "# {}\n",
        t!(
            "cost-table-title",
            object = study.object.label(),
            size = study.size.to_string(),
            triangles = study.reference_triangles.to_string()
        )
    );
    s.push_str(&format!(
        "{:<36} {:>10} {:>9} {:>10} {:>10} {:>9}\n",
        t!("cost-variant"),
        t!("cost-triangles"),
        t!("cost-ms"),
        t!("cost-mean"),
        t!("cost-max"),
        t!("cost-over-column")
    ));
    for p in &study.points {
        s.push_str(&format!(
            "{:<36} {:>10} {:>9} {:>10} {:>10} {:>9}\n",
            p.variant.name(),
            p.triangles,
            decimal(&format!("{:.3}", p.ms)),
            decimal(&format!("{:.3}", p.error.mean)),
            decimal(&format!("{:.1}", p.error.max)),
            decimal(&format!("{:.2}", 100.0 * p.error.share_over_one))
        ));
    }
    for t in takeaways(study) {
        s.push_str(&format!("# {t}\n"));
    }
    s
}

/// Splits one CSV line into fields (RFC 4180: a quoted field may hold commas, and `""` is
/// a quote).
fn csv_fields(line: &str) -> Vec<String> {
    let (mut out, mut cur, mut quoted, mut chars) = (Vec::new(), String::new(), false, line.chars().peekable());
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut cur)),
            (c, _) => cur.push(c),
        }
    }
    out.push(cur);
    out
}

/// docs/performance.md's tables of a `cost.csv`: one Markdown table per object, its rows as the CSV
/// has them (docs/performance.md shows exactly this, and a test keeps the two equal).
pub fn markdown_tables(csv: &str) -> Result<String> {
    let mut lines = csv.lines();
    let header = csv_fields(lines.next().context("an empty cost.csv")?);
    let col = |name: &str| header.iter().position(|h| h == name).with_context(|| format!("no column {name}"));
    let (object, variant, tris, ms, mean, max, share) = (
        col("object")?,
        col("variant")?,
        col("triangles")?,
        col("ms_per_frame")?,
        col("mean_error_255")?,
        col("max_error_255")?,
        col("share_over_1_255")?,
    );
    let mut out = String::new();
    let mut current = String::new();
    for (n, line) in lines.enumerate().filter(|(_, l)| !l.trim().is_empty()) {
        let f = csv_fields(line);
        if f.len() != header.len() {
            bail!("cost.csv line {}: {} fields, the header has {}", n + 2, f.len(), header.len());
        }
        let num = |i: usize| f[i].parse::<f64>().with_context(|| format!("cost.csv line {}: {:?}", n + 2, f[i]));
        if f[object] != current {
            current.clone_from(&f[object]);
            if !out.is_empty() {
                out.push('\n');
            }
            out.push_str(&format!("**{current}**\n\n"));
            out.push_str("| variant | triangles | ms/frame | mean error | max error | pixels off > 1/255 |\n");
            out.push_str("|---|---|---|---|---|---|\n");
        }
        // A plain space before `%`: these tables are a committed record (docs/performance.md,
        // compared by a test) and Markdown a program reads, not a sentence that wraps.
        out.push_str(&format!(
            "| {} | {} | {:.2} | {:.2} | {:.1} | {:.1} % |\n",
            f[variant],
            f[tris],
            num(ms)?,
            num(mean)?,
            num(max)?,
            100.0 * num(share)?
        ));
    }
    Ok(out)
}

/// Paints the studies' charts, one under another, into an RGBA image (1 point = 1 pixel
/// at `ppp` 1; 2 for a sharper image).
pub fn chart_png(studies: &[Study], ppp: f32) -> (usize, usize, Vec<u8>) {
    let (w, h_each) = (960.0, 420.0);
    let h = h_each * studies.len() as f32 + 10.0;
    let canvas = crate::paint::egui_cpu::paint_ui(w, h, ppp, |ui| {
        egui::CentralPanel::default().show(ui, |ui| {
            for s in studies {
                ui.strong(crate::t!(
                    "cost-chart-title",
                    object = s.object.label(),
                    size = s.size.to_string(),
                    triangles = s.reference_triangles.to_string()
                ));
                cost_chart_ui(ui, s, h_each - 40.0);
            }
        });
    });
    (canvas.width, canvas.height, canvas.rgba8())
}

/// Is `name` a file of a cost report (so a new report in the same folder replaces it)?
pub fn belongs_to_a_report(name: &str) -> bool {
    matches!(name, "cost.csv" | "cost.md" | "cost.png") || (name.starts_with("heat-") && name.ends_with(".png"))
}

/// Refuses a study past the memory budget, before anything is drawn
/// ([`crate::io::budget::cost_bytes`]).
fn within_budget(a: &CostRun) -> Result<()> {
    let views: Vec<phonglab_core::View> =
        a.objects.iter().map(|&object| phonglab_core::View { object, ..a.doc.view.clone() }).collect();
    let what = crate::t!("budget-what-cost", count = views.len() as i64, size = a.size as i64);
    crate::io::budget::check(&what, crate::io::budget::cost_bytes(&views, a.size as u64)).map_err(anyhow::Error::msg)
}

/// `phonglab cost`: the studies, their tables on stdout, and the files, written as one
/// report ([`crate::io::file_set::write_set`]) after the folder was tried before the study.
pub fn run(a: &CostRun) -> Result<()> {
    within_budget(a)?;
    crate::io::atomic_write::check_folder_destination(&a.out)?;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(a.threads).build()?;
    let studies = pool.install(|| studies(a))?;
    let mut set = crate::io::file_set::FileSet::default();
    let mut csv = String::new();
    for (i, s) in studies.iter().enumerate() {
        println!("{}", table(s));
        let part = cost::to_csv(s);
        csv.push_str(if i == 0 { &part } else { part.split_once('\n').map_or("", |(_, rest)| rest) });
        // The middle level's Gouraud and Phong error maps.
        let mid = cost::levels(s.object)[2];
        for (p, map) in s.points.iter().zip(&s.error_maps) {
            if p.variant.question == Question::Shading
                && p.variant.level == mid
                && p.variant.shading != phonglab_core::Shading::Flat
            {
                let rgba = cost::heat_map_rgba(map, &s.reference, HEAT_FULL_SCALE);
                let name = format!("heat-{}-{}-{mid}.png", s.object.key(), p.variant.shading.label().to_lowercase());
                set.add(name, crate::io::image::encode_png(s.size, s.size, &rgba)?);
            }
        }
    }
    let tables = markdown_tables(&csv)?;
    set.add("cost.csv", csv);
    set.add("cost.md", tables);
    let (w, h, rgba) = chart_png(&studies, 1.5);
    set.add("cost.png", crate::io::image::encode_png(w, h, &rgba)?);
    let notices = crate::io::file_set::write_set(&a.out, &set, belongs_to_a_report)?;
    for n in &notices {
        super::say(n);
    }
    super::say(&crate::t!("cost-wrote", files = set.to_string(), out = crate::io::reasons::shown(&a.out)));
    Ok(())
}

/// `phonglab cost`.
#[derive(Args, Debug)]
pub struct CostArgs {
    /// The object to study (default: all three).
    #[arg(long, value_enum)]
    pub object: Option<ObjectKind>,
    /// Where to write cost.csv, cost.png and the heat maps.
    #[arg(long, default_value = ".")]
    pub out: PathBuf,
    /// Image width and height in pixels.
    #[arg(long, default_value_t = 512, value_parser = clap::value_parser!(u32).range(16..=2048))]
    pub size: u32,
    /// A scene file (TOML) for the lighting and the view; default: the worksheet's scene.
    #[arg(long)]
    pub scene: Option<PathBuf>,
    /// Turn the object this many degrees about y (the cylinder shows its side at 30).
    #[arg(long, default_value_t = 30.0)]
    pub spin: f64,
    /// Threads for rendering (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
    /// Quick timings (3 frames or 0.1 s per variant) instead of careful ones.
    #[arg(long)]
    pub quick: bool,
}

/// Runs `phonglab cost`.
pub fn run_args(a: &CostArgs) -> Result<()> {
    if let Some(scene) = &a.scene {
        // The report replaces every file of an earlier report in the folder.
        let mut names: Vec<String> = ["cost.csv", "cost.md", "cost.png"].map(String::from).to_vec();
        let earlier = std::fs::read_dir(&a.out).into_iter().flatten().flatten();
        names.extend(earlier.map(|e| e.file_name().to_string_lossy().into_owned()).filter(|n| belongs_to_a_report(n)));
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let scene = (scene.as_path(), crate::io::same_file::Input::Scene);
        crate::io::same_file::refuse_outputs_in_folder(&a.out, &names, &[scene]).map_err(anyhow::Error::msg)?;
    }
    let doc = match &a.scene {
        Some(p) => super::scene_file(p)?,
        None => phonglab_core::Document::default(),
    };
    run(&CostRun {
        objects: a.object.map_or(phonglab_core::ObjectKind::ALL.to_vec(), |o| vec![o]),
        doc,
        out: a.out.clone(),
        size: a.size as usize,
        spin: a.spin,
        threads: crate::platform::threads::asked(a.threads).map_err(anyhow::Error::msg)?,
        timing: if a.quick { phonglab_core::cost::Timing::QUICK } else { phonglab_core::cost::Timing::CAREFUL },
    })
}
