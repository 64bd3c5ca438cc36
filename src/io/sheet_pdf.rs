//! Exercise sheets and their keys typeset as PDF (krilla): a proportional text font with
//! Portuguese glyphs (egui's Ubuntu Light) for the words, Hack for the numbers, real
//! headings, vectors and matrices set in brackets with their numbers in columns, and
//! answer boxes sized for what goes in them (one cell per component of a vector).
//!
//! A document is a list of [`Block`]s, laid out top to bottom; a block that does not fit
//! goes to the next page. [`Block::Section`] starts a part on a new page (one exercise, one
//! key) and names it in the footer of each of its pages, so a page that comes loose from its
//! exercise still says whose it is, beside "page k of n" counted in the whole document. Sheets to
//! hand out give each part an even number of pages ([`Pages::Duplex`]): printed on both
//! sides, every exercise is its own sheet(s) of paper. Nothing depends on the clock or on
//! chance: the same blocks give the same bytes.

use anyhow::{Context, Result};
use krilla::geom::{PathBuilder, Point, Rect};
use krilla::page::PageSettings;
use krilla::paint::Stroke;
use krilla::text::{Font, TextDirection};

/// One piece of a page.
#[derive(Clone, Debug, PartialEq)]
pub enum Block {
    /// The document's title.
    Title(String),
    /// A section's heading.
    Heading(String),
    /// A paragraph (wrapped).
    Text(String),
    /// A choice to tick: an empty box, and the choice's words beside it (wrapped).
    Tick(String),
    /// Ruled lines to write an answer on, this many.
    Ruled(usize),
    /// Lines to write on: ("Class", "Name", "Date").
    WriteOn(Vec<String>),
    /// `name = [a b c d]`, the numbers in columns inside brackets, and a note after them.
    Vector {
        /// The worksheet's name.
        name: String,
        /// The numbers, formatted.
        values: Vec<String>,
        /// Said after the brackets.
        note: String,
    },
    /// `name =` and a matrix in brackets.
    Matrix {
        /// The worksheet's name.
        name: String,
        /// The rows of formatted numbers.
        rows: Vec<Vec<String>>,
    },
    /// A step to compute: its number and title, `name =` and a box of `cells` cells.
    Answer {
        /// "3. Light in eye space".
        label: String,
        /// The step's name.
        name: String,
        /// One per component.
        cells: usize,
    },
    /// A step of the key: its number and title, its formula, and `name = value`.
    KeyStep {
        /// "3. Light in eye space".
        label: String,
        /// The formula.
        formula: String,
        /// `name = value`, as explain prints it.
        line: String,
    },
    /// Start a part on a new page: its pages' footer says this, and "page k of n".
    Section(String),
    /// Figures side by side, each a square picture with its caption under it.
    Figures(Vec<Figure>),
}

/// A figure: a square RGBA8 picture with its caption (a renderer's pixels are an `Image`; a figure is one placed on a page).
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Said under it.
    pub caption: String,
    /// Its side in pixels.
    pub px: usize,
    /// `px * px * 4` bytes, rows top to bottom.
    pub rgba: std::sync::Arc<Vec<u8>>,
}

/// The side of a picture on the page, in points: two fit across.
const PICTURE: f32 = 200.0;

/// How the parts of a document are paginated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pages {
    /// Each part as long as it is (for reading on a screen, or printing one-sided).
    Plain,
    /// Each part padded with a blank page to an even count, so that printed on both sides
    /// no sheet of paper holds two parts.
    Duplex,
}

/// The page: A4 in points, and the margins.
const PAGE: (f32, f32) = (595.0, 842.0);
const MARGIN: f32 = 56.0;

/// The fonts and how wide their text is.
struct Fonts {
    text: Font,
    mono: Font,
    text_face: ttf_parser::Face<'static>,
    mono_face: ttf_parser::Face<'static>,
}

impl Fonts {
    fn new() -> Result<Fonts> {
        let text = Font::new(epaint_default_fonts::UBUNTU_LIGHT.to_vec().into(), 0).context("the text font")?;
        let mono = Font::new(epaint_default_fonts::HACK_REGULAR.to_vec().into(), 0).context("the number font")?;
        let text_face = ttf_parser::Face::parse(epaint_default_fonts::UBUNTU_LIGHT, 0).context("the text font")?;
        let mono_face = ttf_parser::Face::parse(epaint_default_fonts::HACK_REGULAR, 0).context("the number font")?;
        Ok(Fonts { text, mono, text_face, mono_face })
    }

    /// The width of `s` at `size` points, as [`Pen::text`] draws it (its control
    /// characters written visibly).
    fn width(&self, s: &str, size: f32, mono: bool) -> f32 {
        let face = if mono { &self.mono_face } else { &self.text_face };
        let units: f32 = phonglab_core::escape::pdf::text(s)
            .chars()
            .map(|c| face.glyph_index(c).and_then(|g| face.glyph_hor_advance(g)).unwrap_or(0) as f32)
            .sum();
        units * size / f32::from(face.units_per_em())
    }

    /// `text` broken into lines no wider than `width`: at spaces, and a word wider than the
    /// width (a long name) between its characters.
    fn wrap(&self, text: &str, size: f32, width: f32, mono: bool) -> Vec<String> {
        let mut lines = Vec::new();
        let mut line = String::new();
        let words = text.split_whitespace().flat_map(|w| self.split_word(w, size, width, mono));
        for word in words {
            let word = word.as_str();
            let candidate = if line.is_empty() { word.to_string() } else { format!("{line} {word}") };
            if self.width(&candidate, size, mono) > width && !line.is_empty() {
                lines.push(std::mem::replace(&mut line, word.to_string()));
            } else {
                line = candidate;
            }
        }
        if !line.is_empty() {
            lines.push(line);
        }
        lines
    }

    /// `word` as pieces no wider than `width` (itself, if it fits).
    fn split_word(&self, word: &str, size: f32, width: f32, mono: bool) -> Vec<String> {
        let mut pieces = vec![String::new()];
        for c in word.chars() {
            let last = pieces.last_mut().expect("a piece");
            last.push(c);
            if self.width(last, size, mono) > width && last.chars().count() > 1 {
                last.pop();
                pieces.push(c.to_string());
            }
        }
        pieces
    }

    /// `text` cut to `width`, ending in "…" where it was cut.
    fn cut(&self, text: &str, size: f32, width: f32) -> String {
        if self.width(text, size, false) <= width {
            return text.to_string();
        }
        let mut out = String::new();
        for c in text.chars() {
            if self.width(&format!("{out}{c}…"), size, false) > width {
                break;
            }
            out.push(c);
        }
        format!("{out}…")
    }

    /// Where a vector's note starts, right of its brackets, and its lines: beside the
    /// brackets where it fits in what is left of `width`, else under them, wrapped.
    fn vector_note(&self, name: &str, values: &[String], note: &str, width: f32) -> (f32, Vec<String>) {
        if note.is_empty() {
            return (0.0, Vec::new());
        }
        let col = column_width(self, &values.iter().collect::<Vec<_>>());
        let left = self.width(&format!("{name} ="), NUMBERS, true) + 8.0;
        let beside = left + 8.0 + values.len() as f32 * col + 10.0;
        let (x, room) = if width - beside >= 120.0 { (beside, width - beside) } else { (0.0, width) };
        (x, self.wrap(note, BODY - 1.0, room, false))
    }
}

/// Sizes, in points.
const TITLE: f32 = 18.0;
const HEADING: f32 = 13.0;
const BODY: f32 = 10.5;
const NUMBERS: f32 = 9.5;
/// How far a choice's words stand right of its box.
const TICK_INDENT: f32 = 18.0;
/// The distance between ruled lines: room for handwriting.
const RULED: f32 = 24.0;

/// A page being drawn: its surface's draw calls are collected, then replayed on a page.
enum Mark {
    Text { at: (f32, f32), text: String, size: f32, mono: bool },
    Line { from: (f32, f32), to: (f32, f32), width: f32 },
    Rect { x: f32, y: f32, w: f32, h: f32 },
    Image { x: f32, y: f32, side: f32, px: u32, rgba: std::sync::Arc<Vec<u8>> },
}

/// One laid-out page: the part it belongs to and its marks.
struct LaidOut {
    part: usize,
    marks: Vec<Mark>,
}

/// The blocks laid out into pages of marks, each with its part (the blocks before the first
/// [`Block::Section`] are part 0).
fn layout(fonts: &Fonts, blocks: &[Block]) -> Vec<LaidOut> {
    let width = PAGE.0 - 2.0 * MARGIN;
    let mut pages = vec![LaidOut { part: 0, marks: Vec::new() }];
    let mut part = 0;
    let mut y = MARGIN;
    for (i, block) in blocks.iter().enumerate() {
        if let Block::Section(_) = block {
            part += 1;
            match pages.last_mut() {
                Some(last) if last.marks.is_empty() => last.part = part,
                _ => pages.push(LaidOut { part, marks: Vec::new() }),
            }
            y = MARGIN;
            continue;
        }
        let height = block_height(fonts, block, width);
        // A heading stays with the block under it.
        let needed = match (block, blocks.get(i + 1)) {
            (Block::Heading(_), Some(next)) => height + block_height(fonts, next, width),
            _ => height,
        };
        if y + needed > PAGE.1 - MARGIN && !pages.last().is_some_and(|p| p.marks.is_empty()) {
            pages.push(LaidOut { part, marks: Vec::new() });
            y = MARGIN;
        }
        let page = pages.last_mut().expect("a page");
        draw_block(fonts, block, y, width, &mut page.marks);
        y += height;
    }
    pages
}

/// Pads each part to an even number of pages with a page that says it is blank.
fn pad_to_even(fonts: &Fonts, pages: Vec<LaidOut>) -> Vec<LaidOut> {
    // A part's pages follow one another (layout starts each part on a new page).
    let runs: Vec<(usize, usize)> = pages.chunk_by(|a, b| a.part == b.part).map(|r| (r[0].part, r.len())).collect();
    let mut out = Vec::with_capacity(pages.len() + runs.len());
    let mut pages = pages.into_iter();
    for (part, len) in runs {
        out.extend(pages.by_ref().take(len));
        if len % 2 == 1 {
            let text = crate::t!("pdf-blank-page");
            let x = (PAGE.0 - fonts.width(&text, BODY, false)) / 2.0;
            out.push(LaidOut {
                part,
                marks: vec![Mark::Text { at: (x, PAGE.1 / 2.0), text, size: BODY, mono: false }],
            });
        }
    }
    out
}

/// Each page's footer: its part's name on the left, "page k of n" (in the whole document,
/// as a PDF viewer and a printer count) on the right.
fn add_footers(fonts: &Fonts, pages: &mut [LaidOut], names: &[String]) {
    let size = BODY - 2.0;
    let base = PAGE.1 - MARGIN / 2.0;
    let count = pages.len();
    for (k, page) in pages.iter_mut().enumerate() {
        let name = names.get(page.part).cloned().unwrap_or_default();
        let number = crate::t!("pdf-page", page = (k + 1).to_string(), pages = count.to_string());
        let x = PAGE.0 - MARGIN - fonts.width(&number, size, false);
        if !name.is_empty() {
            // Cut where it would reach the page number.
            let name = fonts.cut(&phonglab_core::escape::pdf::text(&name), size, x - MARGIN - 12.0);
            page.marks.push(Mark::Text { at: (MARGIN, base), text: name, size, mono: false });
        }
        page.marks.push(Mark::Text { at: (x, base), text: number, size, mono: false });
    }
}

/// The height of a step's label, wrapped: `BODY * 1.4` for one line.
fn label_height(fonts: &Fonts, label: &str, width: f32) -> f32 {
    fonts.wrap(label, BODY, width, false).len().max(1) as f32 * BODY * 1.35 + BODY * 0.05
}

/// The rows of a vector's or a matrix's numbers: the widest number sets every column.
fn column_width(fonts: &Fonts, values: &[&String]) -> f32 {
    values.iter().map(|v| fonts.width(v, NUMBERS, true)).fold(0.0, f32::max) + 10.0
}

fn block_height(fonts: &Fonts, block: &Block, width: f32) -> f32 {
    match block {
        Block::Title(t) => fonts.wrap(t, TITLE, width, false).len() as f32 * TITLE * 1.3 + 10.0,
        Block::Heading(h) => fonts.wrap(h, HEADING, width, false).len().max(1) as f32 * HEADING * 1.3 + 8.0,
        Block::Text(t) => fonts.wrap(t, BODY, width, false).len() as f32 * BODY * 1.35 + 6.0,
        Block::Tick(t) => fonts.wrap(t, BODY, width - TICK_INDENT, false).len() as f32 * BODY * 1.35 + 6.0,
        Block::Ruled(n) => *n as f32 * RULED + 8.0,
        Block::WriteOn(_) => BODY * 2.6 + 8.0,
        Block::Vector { name, values, note } => {
            let (x, lines) = fonts.vector_note(name, values, note, width);
            // Under the brackets (x = 0), each line of the note takes a line more.
            let under = if x == 0.0 { lines.len() } else { lines.len().saturating_sub(1) };
            NUMBERS * 1.6 + 5.0 + under as f32 * (BODY - 1.0) * 1.3
        }
        Block::Matrix { rows, .. } => rows.len() as f32 * NUMBERS * 1.5 + 14.0,
        Block::Answer { label, .. } => label_height(fonts, label, width) + 30.0,
        Block::KeyStep { label, formula, line } => {
            label_height(fonts, label, width)
                + fonts.wrap(formula, NUMBERS - 1.0, width - 14.0, true).len() as f32 * NUMBERS * 1.3
                + fonts.wrap(line, NUMBERS, width - 14.0, true).len().max(1) as f32 * NUMBERS * 1.5
                + 8.0
        }
        Block::Section(_) => 0.0,
        Block::Figures(_) => PICTURE + BODY * 2.6 + 10.0,
    }
}

/// A bracket from `top` to `bottom` at `x`, opening right (`left`) or left.
fn bracket(page: &mut Vec<Mark>, x: f32, top: f32, bottom: f32, left: bool) {
    let serif = if left { 4.0 } else { -4.0 };
    page.push(Mark::Line { from: (x, top), to: (x, bottom), width: 0.8 });
    page.push(Mark::Line { from: (x, top), to: (x + serif, top), width: 0.8 });
    page.push(Mark::Line { from: (x, bottom), to: (x + serif, bottom), width: 0.8 });
}

/// Draws `block` at `y` on `page`, `width` points wide from the margin.
fn draw_block(fonts: &Fonts, block: &Block, y: f32, width: f32, page: &mut Vec<Mark>) {
    let mut pen = Pen { fonts, page, x: MARGIN, width };
    match block {
        Block::Title(t) => pen.paragraph(t, y, TITLE, 1.3),
        Block::Heading(h) => {
            let lines = fonts.wrap(h, HEADING, width, false);
            for (i, line) in lines.iter().enumerate() {
                pen.text((MARGIN, y + 6.0 + HEADING + i as f32 * HEADING * 1.3), line, HEADING, false);
            }
            let rule = y + 10.0 + HEADING + lines.len().saturating_sub(1) as f32 * HEADING * 1.3;
            pen.page.push(Mark::Line { from: (MARGIN, rule), to: (MARGIN + width, rule), width: 0.4 });
        }
        Block::Text(t) => pen.paragraph(t, y, BODY, 1.35),
        Block::Tick(t) => pen.tick(t, y),
        Block::Ruled(n) => {
            for k in 1..=*n {
                let at = y + k as f32 * RULED;
                pen.page.push(Mark::Line { from: (MARGIN, at), to: (MARGIN + width, at), width: 0.4 });
            }
        }
        Block::WriteOn(labels) => pen.write_on(labels, y),
        Block::Vector { name, values, note } => pen.vector(name, values, note, y),
        Block::Matrix { name, rows } => pen.matrix(name, rows, y),
        Block::Answer { label, name, cells } => pen.answer(label, name, *cells, y),
        Block::KeyStep { label, formula, line } => pen.key_step(label, formula, line, y),
        Block::Section(_) => {}
        Block::Figures(pictures) => {
            for (k, p) in pictures.iter().enumerate() {
                let x = MARGIN + k as f32 * (PICTURE + 20.0);
                let rgba = p.rgba.clone();
                pen.page.push(Mark::Image { x, y: y + 4.0, side: PICTURE, px: p.px as u32, rgba });
                for (i, line) in fonts.wrap(&p.caption, BODY - 1.0, PICTURE, false).iter().take(2).enumerate() {
                    pen.text((x, y + PICTURE + 6.0 + (BODY - 1.0) * (1.0 + 1.3 * i as f32)), line, BODY - 1.0, false);
                }
            }
        }
    }
}

/// What draws a block: the fonts, the page's marks, the left margin and the width.
struct Pen<'a> {
    fonts: &'a Fonts,
    page: &'a mut Vec<Mark>,
    x: f32,
    width: f32,
}

impl Pen<'_> {
    /// `s` with its baseline's left end at `at`: every text drawn passes here, so a control
    /// character in a name is written visibly (`\u{1B}`), never drawn as a missing glyph.
    fn text(&mut self, at: (f32, f32), s: &str, size: f32, mono: bool) {
        self.page.push(Mark::Text { at, text: phonglab_core::escape::pdf::text(s), size, mono });
    }

    /// `t` wrapped to the width, lines `leading` times the size apart.
    fn paragraph(&mut self, t: &str, y: f32, size: f32, leading: f32) {
        for (i, line) in self.fonts.wrap(t, size, self.width, false).iter().enumerate() {
            self.text((self.x, y + size + i as f32 * size * leading), line, size, false);
        }
    }

    /// A box to tick, on the first line's baseline, and the words wrapped beside it.
    fn tick(&mut self, t: &str, y: f32) {
        let side = BODY * 0.9;
        self.page.push(Mark::Rect { x: self.x, y: y + BODY - side + 1.0, w: side, h: side });
        let (x, width) = (self.x, self.width);
        (self.x, self.width) = (x + TICK_INDENT, width - TICK_INDENT);
        self.paragraph(t, y, BODY, 1.35);
        (self.x, self.width) = (x, width);
    }

    /// Each label with a line to write on; the name's line the longest.
    fn write_on(&mut self, labels: &[String], y: f32) {
        let base = y + BODY * 2.0;
        let shares = [0.25, 0.5, 0.25];
        let mut at = self.x;
        for (k, label) in labels.iter().enumerate() {
            let w = self.width * shares.get(k).copied().unwrap_or(0.25);
            self.text((at, base), &format!("{label}:"), BODY, false);
            let from = at + self.fonts.width(&format!("{label}: "), BODY, false);
            self.page.push(Mark::Line { from: (from, base + 2.0), to: (at + w - 12.0, base + 2.0), width: 0.5 });
            at += w;
        }
    }

    /// `name = [values]`, the numbers right-aligned in columns between brackets, and a note.
    fn vector(&mut self, name: &str, values: &[String], note: &str, y: f32) {
        let base = y + NUMBERS * 1.2;
        let lead = format!("{name} =");
        self.text((self.x, base), &lead, NUMBERS, true);
        let col = column_width(self.fonts, &values.iter().collect::<Vec<_>>());
        let left = self.x + self.fonts.width(&lead, NUMBERS, true) + 8.0;
        let (top, bottom) = (base - NUMBERS * 0.9, base + NUMBERS * 0.35);
        bracket(self.page, left, top, bottom, true);
        for (k, v) in values.iter().enumerate() {
            let right = left + 4.0 + (k + 1) as f32 * col;
            self.text((right - self.fonts.width(v, NUMBERS, true), base), v, NUMBERS, true);
        }
        let end = left + 8.0 + values.len() as f32 * col;
        bracket(self.page, end, top, bottom, false);
        let (x, lines) = self.fonts.vector_note(name, values, note, self.width);
        // Beside the brackets, on their baseline; or under them.
        let first = if x == 0.0 { base + NUMBERS * 0.35 + (BODY - 1.0) * 1.3 } else { base };
        for (i, line) in lines.iter().enumerate() {
            self.text((self.x + x, first + i as f32 * (BODY - 1.0) * 1.3), line, BODY - 1.0, false);
        }
    }

    /// `name =` and the rows of a matrix, right-aligned in columns between brackets.
    fn matrix(&mut self, name: &str, rows: &[Vec<String>], y: f32) {
        let lead = format!("{name} =");
        let line = NUMBERS * 1.5;
        let top = y + 6.0;
        let middle = top + rows.len() as f32 * line / 2.0 + NUMBERS / 2.0 - 2.0;
        self.text((self.x, middle), &lead, NUMBERS, true);
        let cells: Vec<&String> = rows.iter().flatten().collect();
        let col = column_width(self.fonts, &cells);
        let left = self.x + self.fonts.width(&lead, NUMBERS, true) + 8.0;
        let columns = rows.first().map_or(0, Vec::len);
        for (r, row) in rows.iter().enumerate() {
            let base = top + NUMBERS + r as f32 * line;
            for (c, v) in row.iter().enumerate() {
                let right = left + 4.0 + (c + 1) as f32 * col;
                self.text((right - self.fonts.width(v, NUMBERS, true), base), v, NUMBERS, true);
            }
        }
        let bottom = top + rows.len() as f32 * line + 2.0;
        bracket(self.page, left, top, bottom, true);
        bracket(self.page, left + 8.0 + columns as f32 * col, top, bottom, false);
    }

    /// A step to answer: its label, `name =` and a box of `cells` cells to write in.
    fn answer(&mut self, label: &str, name: &str, cells: usize, y: f32) {
        let x = self.x;
        self.paragraph(label, y, BODY, 1.35);
        let base = y + label_height(self.fonts, label, self.width) + 17.0;
        let lead = format!("{name} =");
        self.text((x + 14.0, base), &lead, NUMBERS, true);
        // Every box starts in one column (past the longest name, vertexNormal).
        let left = (x + 14.0 + self.fonts.width(&lead, NUMBERS, true) + 8.0).max(x + 110.0);
        // Room for 8 significant digits, a sign and a decimal mark in each cell.
        let cell = self.fonts.width("-0,00000000", NUMBERS, true) + 14.0;
        let w = cell * cells as f32;
        self.page.push(Mark::Rect { x: left, y: base - 15.0, w, h: 22.0 });
        for k in 1..cells {
            let cx = left + k as f32 * cell;
            self.page.push(Mark::Line { from: (cx, base - 10.0), to: (cx, base + 2.0), width: 0.3 });
        }
    }

    /// A step of the key: its label, its formula wrapped, and its value.
    fn key_step(&mut self, label: &str, formula: &str, line: &str, y: f32) {
        let x = self.x;
        self.paragraph(label, y, BODY, 1.35);
        let mut at = y + label_height(self.fonts, label, self.width);
        for f in self.fonts.wrap(formula, NUMBERS - 1.0, self.width - 14.0, true) {
            at += NUMBERS * 1.3;
            self.text((x + 14.0, at), &f, NUMBERS - 1.0, true);
        }
        for l in self.fonts.wrap(line, NUMBERS, self.width - 14.0, true) {
            at += NUMBERS * 1.5;
            self.text((x + 14.0, at), &l, NUMBERS, true);
        }
    }
}

/// The PDF of `blocks`, its parts paginated as `pages` says.
pub fn pdf(blocks: &[Block], pages: Pages) -> Result<Vec<u8>> {
    let fonts = Fonts::new()?;
    let mut doc = krilla::Document::new();
    let names: Vec<String> = std::iter::once(String::new())
        .chain(blocks.iter().filter_map(|b| match b {
            Block::Section(name) => Some(name.clone()),
            _ => None,
        }))
        .collect();
    let mut laid_out = layout(&fonts, blocks);
    if pages == Pages::Duplex {
        laid_out = pad_to_even(&fonts, laid_out);
    }
    add_footers(&fonts, &mut laid_out, &names);
    for LaidOut { marks, .. } in laid_out {
        let settings = PageSettings::from_wh(PAGE.0, PAGE.1).context("A4")?;
        let mut page = doc.start_page_with(settings);
        let mut surface = page.surface();
        for m in &marks {
            match m {
                Mark::Text { at, text, size, mono } => {
                    let font = if *mono { fonts.mono.clone() } else { fonts.text.clone() };
                    surface.set_fill(Some(krilla::paint::Fill::default()));
                    surface.set_stroke(None);
                    surface.draw_text(Point::from_xy(at.0, at.1), font, *size, text, false, TextDirection::Auto);
                }
                Mark::Line { from, to, width } => {
                    let mut path = PathBuilder::new();
                    path.move_to(from.0, from.1);
                    path.line_to(to.0, to.1);
                    if let Some(path) = path.finish() {
                        surface.set_fill(None);
                        surface.set_stroke(Some(Stroke { width: *width, ..Default::default() }));
                        surface.draw_path(&path);
                    }
                }
                Mark::Image { x, y, side, px, rgba } => {
                    let image = krilla::image::Image::from_rgba8(rgba.to_vec(), *px, *px);
                    if let Some(size) = krilla::geom::Size::from_wh(*side, *side) {
                        surface.push_transform(&krilla::geom::Transform::from_translate(*x, *y));
                        surface.draw_image(image, size);
                        surface.pop();
                    }
                }
                Mark::Rect { x, y, w, h } => {
                    let mut path = PathBuilder::new();
                    if let Some(r) = Rect::from_xywh(*x, *y, *w, *h) {
                        path.push_rect(r);
                    }
                    if let Some(path) = path.finish() {
                        surface.set_fill(None);
                        surface.set_stroke(Some(Stroke { width: 0.7, ..Default::default() }));
                        surface.draw_path(&path);
                    }
                }
            }
        }
        surface.finish();
        page.finish();
    }
    doc.finish().map_err(|e| anyhow::anyhow!(crate::t!("pdf-cannot-write", error = format!("{e:?}"))))
}
