//! The expressions the reader evaluates: a small subset of Python with NumPy's arrays
//! (numbers, strings, `True`/`False`, lists, `np.array(...)`, `+ - * / **` element by
//! element, names assigned before), tokenised and parsed under the reader's limits
//! ([`MAX_DEPTH`], [`MAX_ELEMENTS`], [`MAX_BYTES`]).

use std::collections::BTreeMap;

use crate::numerics::strict::quoted_line;
use crate::t;

/// The deepest an expression nests: brackets, calls, unary signs and powers (the givens
/// need 3: a list of matrices' rows).
pub const MAX_DEPTH: usize = 32;
/// The most numbers, strings and lists one value holds (eight lights' matrices are 136).
pub const MAX_ELEMENTS: usize = 10_000;
/// The most bytes of strings one value holds.
pub const MAX_BYTES: usize = 1 << 20;
/// The most tokens one expression holds (a value of [`MAX_ELEMENTS`] numbers, each with its
/// sign and comma, and its brackets): refused while tokenizing, before a tree or a token
/// more is built, so a hostile line (`1+1+…`, `----…1`, `1**1**…` of megabytes) costs
/// memory in proportion to [`MAX_TOKENS`], not to its length.
pub const MAX_TOKENS: usize = 8 * MAX_ELEMENTS;

/// A value as the reader evaluates it.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Value {
    Num(f64),
    Str(String),
    Bool(bool),
    /// A list, a tuple or a NumPy array.
    List(Vec<Value>),
}

impl Value {
    /// How deeply lists nest: 0 for a number, 1 for a vector, 2 for a matrix.
    pub(super) fn depth(&self) -> usize {
        match self {
            Value::List(items) => 1 + items.first().map_or(0, Value::depth),
            _ => 0,
        }
    }

    /// What the value holds: its numbers, strings and lists, and its strings' bytes.
    pub(super) fn size(&self) -> Size {
        match self {
            Value::Num(_) | Value::Bool(_) => Size { elements: 1, bytes: 0 },
            Value::Str(s) => Size { elements: 1, bytes: s.len() },
            Value::List(items) => items.iter().fold(Size { elements: 1, bytes: 0 }, |a, v| a.plus(v.size())),
        }
    }

    /// The first number in the value that is not finite, if any.
    pub(super) fn first_not_finite(&self) -> Option<f64> {
        match self {
            Value::Num(x) => (!x.is_finite()).then_some(*x),
            Value::List(items) => items.iter().find_map(Value::first_not_finite),
            _ => None,
        }
    }

    /// The numbers of a flat list (or one number).
    pub(super) fn numbers(&self) -> Option<Vec<f64>> {
        match self {
            Value::Num(x) => Some(vec![*x]),
            Value::List(items) => items.iter().map(|v| if let Value::Num(x) = v { Some(*x) } else { None }).collect(),
            _ => None,
        }
    }
}

/// How much a value holds (see [`Value::size`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Size {
    elements: usize,
    bytes: usize,
}

impl Size {
    pub(super) fn plus(self, other: Size) -> Size {
        Size { elements: self.elements.saturating_add(other.elements), bytes: self.bytes.saturating_add(other.bytes) }
    }

    /// The limit this size passes, in words, if it passes one.
    pub(super) fn passes(self, elements: usize, bytes: usize) -> Option<String> {
        if self.elements > elements {
            Some(t!("import-limit-elements", count = crate::locale::grouped(elements as u64)))
        } else if self.bytes > bytes {
            Some(t!("import-limit-bytes", count = crate::locale::grouped(bytes as u64)))
        } else {
            None
        }
    }
}

/// Why an expression was not read: a construct the reader does not read (the line is
/// reported, or ignored as the worksheet's calculation), or a limit passed (the file is
/// refused).
#[derive(Debug)]
pub(super) enum Failure {
    Unreadable(String),
    Limit(String),
}

impl From<String> for Failure {
    fn from(why: String) -> Self {
        Failure::Unreadable(why)
    }
}

/// Evaluates the expression subset (see the module's documentation).
pub(super) fn evaluate(text: &str, env: &BTreeMap<String, Value>) -> Result<Value, Failure> {
    let tokens = tokenize(text)?;
    let mut p = Parser { tokens, pos: 0, env, depth: 0 };
    let v = p.expr()?;
    if p.pos != p.tokens.len() {
        return Err(t!("import-reason-extra", token = quoted_line(&p.tokens[p.pos])).into());
    }
    Ok(v)
}

fn tokenize(text: &str) -> Result<Vec<String>, Failure> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if out.len() >= MAX_TOKENS {
            return Err(Failure::Limit(t!("import-limit-tokens", count = MAX_TOKENS)));
        }
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)) {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
                i += 1;
                if i < chars.len() && (chars[i] == '+' || chars[i] == '-') {
                    i += 1;
                }
                while i < chars.len() && chars[i].is_ascii_digit() {
                    i += 1;
                }
            }
            out.push(chars[start..i].iter().collect());
        } else if c.is_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_' || chars[i] == '.') {
                i += 1;
            }
            out.push(chars[start..i].iter().collect());
        } else if c == '"' || c == '\'' {
            let start = i;
            i += 1;
            while i < chars.len() && chars[i] != c {
                i += 1;
            }
            if i == chars.len() {
                return Err(t!("import-reason-string").into());
            }
            i += 1;
            out.push(chars[start..i].iter().collect());
        } else if c == '*' && chars.get(i + 1) == Some(&'*') {
            out.push("**".into());
            i += 2;
        } else if "+-*/()[],".contains(c) {
            out.push(c.to_string());
            i += 1;
        } else {
            return Err(t!("import-reason-char", char = c.to_string()).into());
        }
    }
    Ok(out)
}

struct Parser<'a> {
    tokens: Vec<String>,
    pos: usize,
    env: &'a BTreeMap<String, Value>,
    /// How deeply the expression nests where the parser is (see [`MAX_DEPTH`]).
    depth: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&str> {
        self.tokens.get(self.pos).map(String::as_str)
    }

    fn expect(&mut self, token: &str) -> Result<(), Failure> {
        if self.peek() == Some(token) {
            self.pos += 1;
            Ok(())
        } else {
            Err(t!("import-reason-expected", token = token, found = quoted_line(self.peek().unwrap_or(""))).into())
        }
    }

    /// Runs `f` one level deeper, refusing past [`MAX_DEPTH`] (a hostile file's ten
    /// thousand brackets would overflow the stack).
    fn deeper(&mut self, f: impl FnOnce(&mut Self) -> Result<Value, Failure>) -> Result<Value, Failure> {
        if self.depth >= MAX_DEPTH {
            return Err(Failure::Limit(t!("import-limit-depth", depth = MAX_DEPTH)));
        }
        self.depth += 1;
        let v = f(self);
        self.depth -= 1;
        v
    }

    /// `term (('+' | '-') term)*`
    fn expr(&mut self) -> Result<Value, Failure> {
        self.deeper(|p| {
            let mut v = p.term()?;
            while let Some(op) = p.peek().filter(|t| *t == "+" || *t == "-").map(str::to_string) {
                p.pos += 1;
                let w = p.term()?;
                v = arithmetic(&v, &w, &op)?;
            }
            Ok(v)
        })
    }

    /// `factor (('*' | '/') factor)*`
    fn term(&mut self) -> Result<Value, Failure> {
        let mut v = self.power()?;
        while let Some(op) = self.peek().filter(|t| *t == "*" || *t == "/").map(str::to_string) {
            self.pos += 1;
            let w = self.power()?;
            v = arithmetic(&v, &w, &op)?;
        }
        Ok(v)
    }

    /// `unary ('**' power)?`
    fn power(&mut self) -> Result<Value, Failure> {
        let v = self.unary()?;
        if self.peek() == Some("**") {
            self.pos += 1;
            let w = self.deeper(Self::power)?;
            return Ok(arithmetic(&v, &w, "**")?);
        }
        Ok(v)
    }

    fn unary(&mut self) -> Result<Value, Failure> {
        match self.peek() {
            Some("-") => {
                self.pos += 1;
                let v = self.deeper(Self::unary)?;
                Ok(arithmetic(&Value::Num(0.0), &v, "-")?)
            }
            Some("+") => {
                self.pos += 1;
                self.deeper(Self::unary)
            }
            _ => self.atom(),
        }
    }

    /// A value in a list: refused once the list holds more than a value may.
    fn push_item(items: &mut Vec<Value>, size: &mut Size, v: Value) -> Result<(), Failure> {
        *size = size.plus(v.size());
        if let Some(limit) = size.passes(MAX_ELEMENTS, MAX_BYTES) {
            return Err(Failure::Limit(limit));
        }
        items.push(v);
        Ok(())
    }

    fn atom(&mut self) -> Result<Value, Failure> {
        let Some(token) = self.peek().map(str::to_string) else { return Err(t!("import-reason-end").into()) };
        self.pos += 1;
        match token.as_str() {
            "(" | "[" => {
                let close = if token == "(" { ")" } else { "]" };
                let mut items = Vec::new();
                let mut size = Size { elements: 1, bytes: 0 };
                let mut tuple = token == "[";
                while self.peek() != Some(close) {
                    let item = self.expr()?;
                    Self::push_item(&mut items, &mut size, item)?;
                    if self.peek() == Some(",") {
                        self.pos += 1;
                        tuple = true;
                    } else {
                        break;
                    }
                }
                self.expect(close)?;
                // `(x)` is x; `(x, y)` and `[x]` are sequences.
                if !tuple && items.len() == 1 { Ok(items.remove(0)) } else { Ok(Value::List(items)) }
            }
            "np.array" | "numpy.array" | "float" | "np.float64" => {
                self.expect("(")?;
                let v = self.expr()?;
                self.expect(")")?;
                // `float("nan")`, `float('inf')`: the number (refused later as not finite).
                match v {
                    Value::Str(s) if token != "np.array" && token != "numpy.array" => s
                        .trim()
                        .to_ascii_lowercase()
                        .parse::<f64>()
                        .map(Value::Num)
                        .map_err(|_| t!("import-reason-number", token = quoted_line(&s)).into()),
                    v => Ok(v),
                }
            }
            // Not a finite number: read, so that a given holding one is refused, naming it.
            "np.nan" | "np.NaN" | "np.NAN" | "numpy.nan" | "math.nan" | "m.nan" => Ok(Value::Num(f64::NAN)),
            "np.inf" | "np.Inf" | "np.infty" | "numpy.inf" | "math.inf" | "m.inf" => Ok(Value::Num(f64::INFINITY)),
            "True" => Ok(Value::Bool(true)),
            "False" => Ok(Value::Bool(false)),
            "m.pi" | "math.pi" | "np.pi" => Ok(Value::Num(std::f64::consts::PI)),
            t if t.starts_with(['"', '\'']) => Ok(Value::Str(t[1..t.len() - 1].to_string())),
            t if t.starts_with(|c: char| c.is_ascii_digit() || c == '.') => {
                Ok(t.parse::<f64>().map(Value::Num).map_err(|_| t!("import-reason-number", token = quoted_line(t)))?)
            }
            // Every assigned value is within the limits, so its copy is too.
            t => Ok(self.env.get(t).cloned().ok_or_else(|| t!("import-reason-name", name = quoted_line(t)))?),
        }
    }
}

/// `a op b` on numbers, element by element on lists (a number with a list: each element).
fn arithmetic(a: &Value, b: &Value, op: &str) -> Result<Value, String> {
    match (a, b) {
        (Value::Num(x), Value::Num(y)) => Ok(Value::Num(match op {
            "+" => x + y,
            "-" => x - y,
            "*" => x * y,
            "/" => x / y,
            _ => x.powf(*y),
        })),
        (Value::List(xs), Value::List(ys)) if xs.len() == ys.len() => {
            Ok(Value::List(xs.iter().zip(ys).map(|(x, y)| arithmetic(x, y, op)).collect::<Result<_, _>>()?))
        }
        (Value::List(xs), y @ Value::Num(_)) => {
            Ok(Value::List(xs.iter().map(|x| arithmetic(x, y, op)).collect::<Result<_, _>>()?))
        }
        (x @ Value::Num(_), Value::List(ys)) => {
            Ok(Value::List(ys.iter().map(|y| arithmetic(x, y, op)).collect::<Result<_, _>>()?))
        }
        _ => Err(t!("import-reason-arithmetic", op = op.to_string())),
    }
}
