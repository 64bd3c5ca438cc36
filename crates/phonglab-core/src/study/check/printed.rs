//! The values a student's work printed, read back: `name = value` lines in NumPy's print
//! formats (an array wrapped over several lines, `e` notation, `0.` and `-0.`, a list with
//! commas, a scalar as Python writes it), from a script's printed text or from the outputs
//! a notebook saved. Nothing is run: the text is only read.
//!
//! Each number keeps how precisely it was printed (half a unit of its last digit), so a
//! value is compared "to the printed digits".

/// One value printed under a name (`vlv`, or `vlv[0]` for a light of several).
#[derive(Clone, Debug, PartialEq)]
pub struct PrintedValue {
    /// The name before ` = `.
    pub name: String,
    /// Its numbers, in order (a matrix's rows one after the other).
    pub numbers: Vec<f64>,
    /// Half a unit of each number's last printed digit (an array's finest: NumPy pads a
    /// short element, so `0.6` beside `0.55887606` is exact to 8 decimals).
    pub half_units: Vec<f64>,
    /// Half a unit of the last digit each number itself shows (`0.7922`: 0.00005): how
    /// far a value the student rounded may be from the key's.
    pub own_half_units: Vec<f64>,
    /// Was each number printed in fixed notation (`0.5`, not `5e-01`)?
    pub fixed: Vec<bool>,
    /// Half a unit as NumPy's print options would pad it: the finest fixed-notation digit
    /// any array of the work shows (`[0. -0.6 -0.8 0.]` beside 8-decimal arrays, under the
    /// default options, is exact to 8 decimals). A second reading: a value the key's at
    /// these digits, and told apart from every mistake, is right even where its own
    /// digits cannot tell.
    pub padded_half_units: Vec<f64>,
}

/// What a piece of work printed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Printed {
    /// The values, every printing in the order printed (a name printed again is there
    /// again: each printing is checked, a later one never hides an earlier wrong one).
    pub values: Vec<PrintedValue>,
    /// The errors the run stopped with (`ValueError: math domain error`).
    pub errors: Vec<String>,
    /// A notebook's code cells as written (never run): read only to order causes whose
    /// values the printed ones cannot tell apart, by the formula the student wrote.
    pub code: String,
    /// The names printed with a value that could not be read as numbers (`cosTheta = 0.9
    /// rad`, a value wrapped past the cap): where the key has such a step, the work is not
    /// checked whole, so never right.
    pub unread: Vec<String>,
    /// Steps of the key the work holds no value for where it should (the self-check in a
    /// notebook: a cell skipped, or stopped by an error): the work is not checked whole,
    /// so never right. Empty for printed text, whose steps not printed are not asked.
    pub missing: Vec<String>,
    /// A notebook's outputs not from one run in order: the first two code cells whose
    /// execution counts go back (the earlier cell's, then the later cell's: `[5]` above
    /// `[3]`), a cell run again after those below it; a cell of code not run between two
    /// that were; or a count no run gives. Never right.
    pub stale: Option<Stale>,
    /// The values a notebook's cells printed after a cell's error output: Run All stops
    /// at an error, so they are from an earlier run, and are never checked (named).
    pub after_error: Vec<String>,
}

/// Why a notebook's outputs are not one run's, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Stale {
    /// Two code cells whose execution counts go back or repeat: the earlier cell's, then
    /// the later cell's (`[5]` above `[3]`).
    Back(i64, i64),
    /// An execution count that is not a small non-negative integer (`"100"`, `1.5`,
    /// `-1`, past 2^64), as the notebook's JSON writes it (cut short): no run numbers a
    /// cell so, so nothing says the outputs are in order.
    NotACount(String),
    /// A code cell with no execution count (not run, or its outputs cleared) between
    /// cells numbered as one run's (the count above it, then the count below it): the
    /// outputs below it are not from its code run in order. (An empty cell is never run
    /// by Jupyter, and says nothing.)
    NotRun(i64, i64),
}

/// The largest execution count taken as a run's (a kernel numbers its runs 1, 2, 3...).
pub const MAX_EXECUTION_COUNT: u64 = u32::MAX as u64;

impl Printed {
    /// The value printed last under `name`.
    pub fn get(&self, name: &str) -> Option<&PrintedValue> {
        self.values.iter().rev().find(|v| v.name == name)
    }
}

/// Why a notebook's outputs cannot be read.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OutputsError {
    /// Not a notebook's JSON.
    #[error("{0}")]
    NotANotebook(String),
    /// Saved without its outputs: it has to be run first.
    #[error("{0}")]
    NoOutputs(String),
    /// It prints more numbers than [`MAX_VALUES`]: refused whole, never checked in part.
    #[error("{0}")]
    TooMany(String),
}

/// The most numbers read from one piece of work, all its printings together (a worksheet
/// prints about twenty values of four; eight lights, two sides, some hundreds of values):
/// numbers, not printings, so a thousand-number array counts a thousand.
pub const MAX_VALUES: usize = 16384;
/// The most numbers one value holds (a matrix is 16).
pub const MAX_NUMBERS: usize = 1024;
/// The most errors kept (a run stops at its first; a script's text may hold a few).
pub const MAX_ERRORS: usize = 64;
/// The most lines one printed value wraps over (NumPy puts at least one number on a line).
pub const MAX_VALUE_LINES: usize = MAX_NUMBERS + 1;

/// The values printed in `text`, as [`read_printed_text`]; a text printing more than
/// [`MAX_VALUES`] numbers gives none, its refusal in `errors` (nothing is checked in part).
pub fn printed_text(text: &str) -> Printed {
    read_printed_text(text).unwrap_or_else(|e| Printed { errors: vec![e.to_string()], ..Printed::default() })
}

/// The values printed in `text`, a script's standard output (or a notebook's outputs, one
/// after the other); refused when it prints more than [`MAX_VALUES`] numbers (junk printed
/// first must not push the work past a cap and out of the check). Linear in the text: a
/// value's continuation lines are joined at most [`MAX_VALUE_LINES`] and its brackets
/// counted as they come.
pub fn read_printed_text(text: &str) -> Result<Printed, OutputsError> {
    let mut out = Printed::default();
    let mut lines = text.lines().peekable();
    let mut read = 0usize;
    while let Some(line) = lines.next() {
        if let Some(error) = error_line(line) {
            if out.errors.len() < MAX_ERRORS {
                out.errors.push(error);
            }
            continue;
        }
        let Some((name, rest)) = line.split_once('=') else { continue };
        let name = name.trim();
        if !is_name(name) {
            continue;
        }
        // An array wraps over lines until its brackets close; a matrix starts on the next.
        let mut value = rest.trim().to_string();
        if value.is_empty()
            && let Some(next) = lines.next_if(|l| l.trim_start().starts_with('['))
        {
            value = next.trim().to_string();
        }
        // An array's repr (`array([...],\n      dtype=float32)`) wraps until its parenthesis
        // closes too.
        let repr = value.starts_with("array(") || value.starts_with("np.array(");
        let mut open = depth(&value, repr);
        let mut joined = 0;
        while open > 0 && joined < MAX_VALUE_LINES && value.len() < 64 * MAX_NUMBERS {
            let Some(next) = lines.next() else { break };
            value.push(' ');
            value.push_str(next.trim());
            open += depth(next, repr);
            joined += 1;
        }
        match numbers(name, &value).filter(|_| open <= 0) {
            Some(v) => {
                read += v.numbers.len();
                if read > MAX_VALUES {
                    return Err(OutputsError::TooMany(crate::t!("check-too-many-values", count = MAX_VALUES)));
                }
                out.values.push(v);
            }
            None if !out.unread.iter().any(|n| n == name) && out.unread.len() < MAX_ERRORS => {
                out.unread.push(name.to_string());
            }
            None => {}
        }
    }
    array_precision(&mut out);
    Ok(out)
}

/// The values a notebook's saved outputs printed; a notebook whose code cells have no
/// outputs at all was saved without running, and is refused saying how to run it.
pub fn notebook_outputs(text: &str) -> Result<Printed, OutputsError> {
    let nb: serde_json::Value = serde_json::from_str(text)
        .map_err(|e| OutputsError::NotANotebook(crate::t!("import-not-notebook", reason = e.to_string())))?;
    let cells = nb["cells"].as_array().ok_or_else(|| {
        OutputsError::NotANotebook(crate::t!("import-not-notebook", reason = crate::t!("import-no-cells")))
    })?;
    let mut text = String::new();
    let mut after = String::new();
    let mut code = String::new();
    let mut any = false;
    // The cell errors (any `ename`: `KeyboardInterrupt`, `Exception` too), in order.
    let mut errors: Vec<String> = Vec::new();
    // Each code cell's count, in order (`None`: not run); empty cells left out.
    let mut counts: Vec<Option<i64>> = Vec::new();
    let mut not_a_count: Option<String> = None;
    // A self-check cell's error, the run's once a cell below it has outputs.
    let mut self_check_error: Option<(String, Option<i64>)> = None;
    for cell in cells.iter().filter(|c| c["cell_type"] == "code") {
        let source = joined(&cell["source"]);
        code.push_str(&source);
        code.push('\n');
        let count = execution_count(&cell["execution_count"]);
        match &count {
            // A cell of comments only changes nothing when run (the exported self-check
            // cell left commented out): like an empty cell, it says nothing of the order.
            Ok(n) if !only_comments(&source) => counts.push(*n),
            Ok(_) => {}
            Err(shown) => {
                not_a_count.get_or_insert(shown.clone());
            }
        }
        // The self-check's table echoes the formulas and both values of every step
        // (`vlv = vertexPos - lightPos`): phonglab's words, never the student's work. Its
        // error (phonglab not installed: `ModuleNotFoundError`) stopped the run there, which
        // matters only to the cells below it: it is the run's error once a cell below has
        // outputs (then from an earlier run), and the work's printed steps above it stand.
        let self_check = calls_self_check(&source);
        let outputs = cell["outputs"].as_array().map(Vec::as_slice).unwrap_or_default();
        // A cell below the self-check's error, numbered after it, was run after it (one at a
        // time): its outputs are current, and the self-check changed nothing they read.
        let here = count.as_ref().ok().copied().flatten();
        if !outputs.is_empty()
            && let Some((e, at)) = self_check_error.take()
            && !matches!((at, here), (Some(at), Some(here)) if here > at)
            && errors.len() < MAX_ERRORS
        {
            errors.push(e);
        }
        for output in outputs {
            any = true;
            // After an error, Run All runs nothing more: what follows is from an earlier run.
            let into = if errors.is_empty() { &mut text } else { &mut after };
            match output["output_type"].as_str() {
                Some("stream") if !self_check => into.push_str(&joined(&output["text"])),
                Some("error") if self_check => self_check_error = Some((cell_error(output), here)),
                Some("error") if errors.len() < MAX_ERRORS => errors.push(cell_error(output)),
                _ => {}
            }
            into.push('\n');
        }
    }
    if !any {
        return Err(OutputsError::NoOutputs(crate::t!("check-no-outputs")));
    }
    let mut p = read_printed_text(&text)?;
    p.errors.extend(errors);
    p.errors.truncate(MAX_ERRORS);
    let mut after_error: Vec<String> = Vec::new();
    let mut named = std::collections::HashSet::new();
    for v in read_printed_text(&after)?.values {
        if named.insert(v.name.clone()) {
            after_error.push(v.name);
        }
    }
    let numbered: Vec<i64> = counts.iter().flatten().copied().collect();
    let back = numbered.windows(2).find(|w| w[1] <= w[0]).map(|w| Stale::Back(w[0], w[1]));
    let stale = not_a_count.map(Stale::NotACount).or(back).or_else(|| not_run_between(&counts));
    Ok(Printed { code, stale, after_error, ..p })
}

/// Is `source` only comments and blank lines (Python's `#`)?
fn only_comments(source: &str) -> bool {
    source.lines().map(str::trim).all(|l| l.is_empty() || l.starts_with('#'))
}

/// The first code cell not run (`None`) with a numbered one above it and one below, as
/// [`Stale::NotRun`] (the counts above and below it). Cells not run above every numbered
/// one, or below, are not between (a notebook written by a program numbers none).
fn not_run_between(counts: &[Option<i64>]) -> Option<Stale> {
    let (mut above, mut gap) = (None, false);
    for count in counts {
        match (*count, above) {
            (Some(below), Some(above)) if gap => return Some(Stale::NotRun(above, below)),
            (Some(n), _) => above = Some(n),
            (None, Some(_)) => gap = true,
            (None, None) => {}
        }
    }
    None
}

/// A code cell's execution count: `None` where it has none (`null`, or absent: a
/// notebook written by a program), the count where it is a small non-negative integer,
/// else the JSON as written, cut to 24 characters (a string, a fraction, a negative, a
/// number past 2^64).
fn execution_count(count: &serde_json::Value) -> Result<Option<i64>, String> {
    if count.is_null() {
        return Ok(None);
    }
    match count.as_u64().filter(|n| *n <= MAX_EXECUTION_COUNT) {
        Some(n) => Ok(Some(n as i64)),
        None => Err(count.to_string().chars().take(24).collect()),
    }
}

/// A cell's error output as one line, `ename: evalue` (the value's first line), whatever
/// its name (`KeyboardInterrupt`, `Exception`, `LinAlgError`).
fn cell_error(output: &serde_json::Value) -> String {
    let name = output["ename"].as_str().unwrap_or("");
    let value = output["evalue"].as_str().unwrap_or("").lines().next().unwrap_or("");
    let name = if name.is_empty() { "Error" } else { name };
    format!("{name}: {value}").trim().chars().take(200).collect()
}

/// Does a cell's `source` run the notebook's self-check (`phonglab.check(globals())`,
/// outside a comment)? What it prints is the check's table, not the student's values.
pub fn calls_self_check(source: &str) -> bool {
    source.lines().any(|line| {
        let code = line.split('#').next().unwrap_or("");
        code.contains("phonglab.check(") || code.contains("check(globals()")
    })
}

/// A notebook's multi-line text: one string, or a list of lines.
fn joined(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::String(s) => s.clone(),
        serde_json::Value::Array(parts) => parts.iter().filter_map(|p| p.as_str()).collect(),
        _ => String::new(),
    }
}

/// `ValueError: math domain error`, the last line of a Python traceback.
fn error_line(line: &str) -> Option<String> {
    let (kind, _) = line.split_once(": ")?;
    let is_error = kind.ends_with("Error") && kind.chars().all(|c| c.is_ascii_alphanumeric() || c == '.');
    is_error.then(|| line.trim().chars().take(200).collect())
}

/// A printed name: an identifier, with an index for a light of several (`vlv[0]`).
fn is_name(name: &str) -> bool {
    let (base, index) = match name.split_once('[') {
        Some((b, rest)) => (b, Some(rest)),
        None => (name, None),
    };
    let ident = !base.is_empty()
        && base.len() <= 64
        && base.starts_with(|c: char| c.is_ascii_alphabetic())
        && base.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    ident
        && index
            .is_none_or(|i| i.strip_suffix(']').is_some_and(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit())))
}

/// How many brackets (and parentheses, where `parens`) are still open in `s`.
fn depth(s: &str, parens: bool) -> i64 {
    let opens = |c: char| c == '[' || (parens && c == '(');
    let closes = |c: char| c == ']' || (parens && c == ')');
    s.chars().map(|c| opens(c) as i64 - closes(c) as i64).sum()
}

/// The floating-point types whose name an array's repr ends with (`dtype=float32`; NumPy
/// 1.24 and 2.4 both write it so, without `np.`, which is read as well).
const FLOAT_DTYPES: [&str; 6] = ["float16", "float32", "float64", "np.float16", "np.float32", "np.float64"];

/// `value` without the type NumPy's repr ends an array of another type than float64 with
/// (`array([0.1, 0.2], dtype=float32)`: what a notebook shows for a float32 array, and
/// `repr()`), where it is a float's: the values are read as printed. Any other value
/// is as it was.
fn without_float_dtype(value: &str) -> String {
    let typed = value.strip_suffix(')').and_then(|v| v.rsplit_once("dtype=")).and_then(|(head, dtype)| {
        let head = head.trim_end().strip_suffix(',')?;
        FLOAT_DTYPES.contains(&dtype.trim()).then(|| format!("{})", head.trim_end()))
    });
    typed.unwrap_or_else(|| value.to_string())
}

/// The numbers of one printed value, each with half a unit of its last digit; `None` when
/// something in it is not a number.
fn numbers(name: &str, value: &str) -> Option<PrintedValue> {
    // NumPy 2 writes a list of its scalars with their type: `[np.float64(0.0596), ...]`.
    let unwrapped = ["np.float64", "np.float32", "np.float16", "np.int64", "np.int32"]
        .iter()
        .fold(without_float_dtype(value.trim()), |s, t| s.replace(t, " "));
    let mut v = unwrapped.trim();
    for wrap in ["np.float64(", "float64(", "array(", "np.array("] {
        if let Some(inner) = v.strip_prefix(wrap) {
            v = inner.strip_suffix(')')?;
        }
    }
    let cleaned: String = v.chars().map(|c| if matches!(c, '[' | ']' | ',' | '(' | ')') { ' ' } else { c }).collect();
    let mut numbers = Vec::new();
    let mut half_units = Vec::new();
    let mut fixed = Vec::new();
    for token in cleaned.split_whitespace() {
        let (x, half) = number(token)?;
        numbers.push(x);
        half_units.push(half);
        fixed.push(!token.contains(['e', 'E']));
        if numbers.len() > MAX_NUMBERS {
            return None;
        }
    }
    let own_half_units = half_units.clone();
    (!numbers.is_empty()).then(|| PrintedValue {
        name: name.to_string(),
        numbers,
        padded_half_units: half_units.clone(),
        half_units,
        own_half_units,
        fixed,
    })
}

/// One number as NumPy or Python prints it (`0.`, `-0.`, `1.5e-05`, `3`), with half a unit
/// of its last digit.
fn number(token: &str) -> Option<(f64, f64)> {
    let x: f64 = if token.ends_with('.') { token.trim_end_matches('.').parse().ok()? } else { token.parse().ok()? };
    if !x.is_finite() {
        return Some((x, 0.0));
    }
    let (mantissa, exp) = match token.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().ok()?),
        None => (token, 0),
    };
    // A whole number with no point is Python's int, exact (`0` is not 0.139 rounded).
    if !token.contains(['.', 'e', 'E']) {
        return Some((x, 0.0));
    }
    let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len() as i32);
    Some((x, 0.5 * crate::numerics::elementary::powi(10.0, exp - decimals)))
}

/// NumPy prints an array's elements with as many digits as the one that needs most, up to
/// its precision, so a short element (`0.6` beside `0.55887606`) is exact to that array's
/// finest digit: an array's numbers in fixed notation take the finest unit printed in that
/// same array. Each printing has its own digits (`np.round(I, 4)`, a `"%.2f"` join,
/// `np.printoptions(precision=3)` around one print): a value is judged at the digits it
/// was printed with, never at another printing's. An array of whole numbers only
/// (`[0. 0. 1. 0.]`) shows no digit of its own: it takes the finest the work's other
/// arrays show (the print options' precision), never finer than NumPy's default 8
/// decimals (a list of Python's 17-digit floats is no print option).
fn array_precision(p: &mut Printed) {
    let own_finest = |v: &PrintedValue| {
        v.half_units
            .iter()
            .zip(&v.fixed)
            .filter(|(h, f)| **f && **h > 0.0)
            .map(|(h, _)| *h)
            .fold(f64::INFINITY, f64::min)
    };
    let work_finest = p
        .values
        .iter()
        .filter(|v| v.numbers.len() > 1)
        .map(own_finest)
        .filter(|h| *h < 0.5)
        .fold(f64::INFINITY, f64::min)
        .max(0.5e-8);
    let padded = p
        .values
        .iter()
        .filter(|v| v.numbers.len() > 1)
        .map(own_finest)
        .filter(|h| *h > 0.0)
        .fold(f64::INFINITY, f64::min);
    for v in p.values.iter_mut().filter(|v| v.numbers.len() > 1 && padded.is_finite()) {
        for (h, _) in v.padded_half_units.iter_mut().zip(&v.fixed).filter(|(_, f)| **f) {
            *h = h.min(padded);
        }
    }
    for v in p.values.iter_mut().filter(|v| v.numbers.len() > 1) {
        let mut finest = own_finest(v);
        if finest >= 0.5 && work_finest.is_finite() {
            finest = work_finest;
        }
        if !finest.is_finite() {
            continue;
        }
        for (h, _) in v.half_units.iter_mut().zip(&v.fixed).filter(|(_, f)| **f) {
            *h = h.min(finest);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numpys_formats_are_read_with_their_digits() {
        let text = "vertexNormal =  [0.  0.6 0.8 -0. ]\nvlv =  [ 0.79220526  0.55887606\n -0.2450885   0.        ]\n\
                    cosTheta =  0.13925483139909867\nIspec =  [4.0551e-04 2.8017e-04 1.7179e-04 0.0000e+00]\n\
                    vlv[1] = [1, 2, 3, 0]\nmodelview = \n [[ 1.0e+00  0.0e+00]\n [ 0.0e+00  8.0e-01]]\nnot a value\n\
                    ValueError: math domain error\n";
        let p = printed_text(text);
        let normal = p.get("vertexNormal").unwrap();
        assert_eq!(normal.numbers, vec![0.0, 0.6, 0.8, 0.0]);
        // Its own finest digit: another array's 8 decimals say nothing of this printing.
        assert_eq!(normal.half_units[0], 0.05);
        assert_eq!(normal.half_units[1], 0.05);
        // Whole numbers only: the work's other arrays' finest (8 decimals here).
        assert_eq!(printed_text("v = [0. 1.]\nw = [0.25 0.5]\n").get("v").unwrap().half_units, vec![0.005, 0.005]);
        assert_eq!(p.get("vlv").unwrap().half_units[3], 0.5e-8);
        assert_eq!(p.get("vlv").unwrap().numbers, vec![0.79220526, 0.55887606, -0.2450885, 0.0]);
        assert_eq!(p.get("cosTheta").unwrap().numbers, vec![0.13925483139909867]);
        let ispec = p.get("Ispec").unwrap();
        assert_eq!(ispec.numbers[0], 4.0551e-4);
        assert!((ispec.half_units[0] - 0.5e-8).abs() < 1e-20);
        // An array in e notation does not make the fixed ones finer.
        let q = printed_text("a = [8.24368169e-11 0.00000000e+00]\nb = [0.5 0.25]\n");
        assert_eq!(q.get("b").unwrap().half_units, vec![0.5e-2, 0.5e-2]);
        // NumPy 2's list of its scalars is read.
        let l = printed_text("I =  [np.float64(0.0596), np.float64(0.0)]\n");
        assert_eq!(l.get("I").unwrap().numbers, vec![0.0596, 0.0]);
        assert!(l.unread.is_empty());
        assert_eq!(p.get("vlv[1]").unwrap().numbers, vec![1.0, 2.0, 3.0, 0.0]);
        assert_eq!(p.get("modelview").unwrap().numbers, vec![1.0, 0.0, 0.0, 0.8]);
        assert_eq!(p.errors, vec!["ValueError: math domain error".to_string()]);
    }

    #[test]
    fn a_float32_arrays_repr_is_read_as_printed_its_type_dropped() {
        // As NumPy 1.24 and 2.4 print `repr()` of float32 and float16 arrays (the type on
        // a line of its own where the values fill the last), and a scalar array.
        let text = "vlv = array([ 0.7922053 ,  0.55887604, -0.2450885 ,  0.        ], dtype=float32)\n\
                    w = array([0.14285715, 0.2857143 , 0.42857143, 0.5714286 , 0.71428573],\n      dtype=float32)\n\
                    h = array([0.1, 0.2], dtype=float16)\nd = array([0.1, 0.2], dtype=np.float64)\n\
                    s = array(0.5, dtype=float32)\nn = array([1, 2], dtype=object)\nat = 5.2\n";
        let p = printed_text(text);
        assert_eq!(p.get("vlv").unwrap().numbers, vec![0.7922053, 0.55887604, -0.2450885, 0.0]);
        assert_eq!(p.get("vlv").unwrap().own_half_units[0], 0.5e-7);
        assert_eq!(p.get("w").unwrap().numbers, vec![0.14285715, 0.2857143, 0.42857143, 0.5714286, 0.71428573]);
        assert_eq!(p.get("h").unwrap().numbers, vec![0.1, 0.2]);
        assert_eq!(p.get("d").unwrap().numbers, vec![0.1, 0.2]);
        assert_eq!(p.get("s").unwrap().numbers, vec![0.5]);
        assert_eq!(p.get("at").unwrap().numbers, vec![5.2]);
        // A type that is no float's is not read as numbers.
        assert_eq!(p.unread, vec!["n".to_string()]);
    }

    #[test]
    fn a_notebook_saved_without_running_is_told_to_run_first() {
        let nb = r#"{"cells": [{"cell_type": "code", "source": ["x = 1"], "outputs": []}]}"#;
        assert!(matches!(notebook_outputs(nb), Err(OutputsError::NoOutputs(_))));
        let ran = r#"{"cells": [{"cell_type": "code", "source": ["x = 1"], "outputs": [{"output_type": "stream", "name": "stdout", "text": ["at =  5.2\n"]}]}]}"#;
        assert_eq!(notebook_outputs(ran).unwrap().get("at").unwrap().numbers, vec![5.2]);
    }

    #[test]
    fn the_self_checks_own_table_is_not_read_as_the_students_values() {
        // The vectors cell printed vlv reversed; the self-check cell, run after it, echoes
        // the formula and the key's value under the same name.
        let nb = r##"{"cells": [
            {"cell_type": "code", "source": ["vlv = lightPos - vertexPos\n", "print('vlv = ', vlv)"],
             "outputs": [{"output_type": "stream", "name": "stdout", "text": ["vlv =  [-0.79 -0.55 0.24 0.]\n"]}]},
            {"cell_type": "code", "source": ["import phonglab; phonglab.check(globals()) # the check\n"],
             "outputs": [{"output_type": "stream", "name": "stdout", "text": [
                "    vlv = vertexPos - lightPos\n", "vlv: yours [-0.79 -0.55 0.24 0], the key's [0.79 0.55 -0.24 0]: wrong\n"]}]},
            {"cell_type": "code", "source": ["# import phonglab; phonglab.check(globals())\n", "at = 2"],
             "outputs": [{"output_type": "stream", "name": "stdout", "text": ["at =  2\n"]}]}
        ]}"##;
        let p = notebook_outputs(nb).unwrap();
        let names: Vec<&str> = p.values.iter().map(|v| v.name.as_str()).collect();
        assert_eq!(names, vec!["vlv", "at"]);
        assert_eq!(p.get("vlv").unwrap().numbers, vec![-0.79, -0.55, 0.24, 0.0]);
        assert!(p.unread.is_empty(), "{:?}", p.unread);
        assert!(p.code.contains("phonglab.check(globals())"));
        assert!(calls_self_check("phonglab.check(globals(), lang='pt-PT')"));
        assert!(!calls_self_check("# run phonglab.check(globals()) at the end\nx = 1"));
    }

    #[test]
    fn junk_printed_past_the_cap_refuses_the_work_whole() {
        let mut text = String::from("vlv =  [9. 9. 9. 0.]\n");
        for k in 0..MAX_VALUES {
            text.push_str(&format!("junk{k} = 1\n"));
        }
        text.push_str("vlv =  [0.1 0.2 0.3 0.]\n");
        assert!(matches!(read_printed_text(&text), Err(OutputsError::TooMany(_))));
        let p = printed_text(&text);
        assert!(p.values.is_empty() && p.errors.len() == 1, "{:?}", p.errors);
        let short: String = (0..MAX_VALUES).map(|k| format!("v{k} = {k}\n")).collect();
        assert_eq!(read_printed_text(&short).unwrap().values.len(), MAX_VALUES);
    }

    #[test]
    fn a_name_printed_again_keeps_every_printing() {
        let p = printed_text("vlv =  [9. 9. 9. 0.]\nvlv =  [0.1 0.2 0.3 0.]\n");
        let vlv: Vec<&[f64]> = p.values.iter().filter(|v| v.name == "vlv").map(|v| v.numbers.as_slice()).collect();
        assert_eq!(vlv, vec![&[9.0, 9.0, 9.0, 0.0][..], &[0.1, 0.2, 0.3, 0.0][..]]);
        assert_eq!(p.get("vlv").unwrap().numbers, vec![0.1, 0.2, 0.3, 0.0]);
    }

    #[test]
    fn a_value_joins_at_most_its_cap_of_lines_and_the_reading_goes_on() {
        let mut text = String::from("vlv =  [");
        text.push_str(&"\n".repeat(2 * MAX_VALUE_LINES));
        text.push_str("0]\nok = 5\n");
        let p = printed_text(&text);
        assert!(p.get("vlv").is_none(), "{:?}", p.get("vlv"));
        assert_eq!(p.get("ok").unwrap().numbers, vec![5.0]);
        let errors: String = (0..1000).map(|_| "ValueError: x\n").collect();
        assert_eq!(printed_text(&errors).errors.len(), MAX_ERRORS);
    }
}
