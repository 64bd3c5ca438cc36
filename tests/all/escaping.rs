//! A scene's name is data in every program phonglab writes, whatever it holds: property
//! tests over arbitrary Unicode names, with the hostile pieces (`"""`, `'''`, `*/`, CR, LF,
//! U+2028, NUL, ESC, backslashes, trigraphs, bidirectional controls) mixed in.
//!
//! - The PyOpenGL program, the notebook's code cells and its "Copy as script" parse with
//!   Python's own `ast`, into a tree of the same shape as the export of the name `x`
//!   (string constants aside), and the program's docstring holds the name's title exactly.
//! - The openFrameworks files, preprocessed by g++ itself (comments gone, lines spliced,
//!   trigraphs on), give the same tokens outside string literals as for the name `x`, and
//!   compile with `-Wall -Werror` against the stand-in oF header.
//! - The notebook is valid JSON, and its title cell stays one Markdown paragraph.
//! - Python and C++ string literals made by the escaping helpers read back as the text.
//!
//! They need python3 and g++, which `scripts/test` installs (`scripts/deps.sh`); without
//! them the tests fail and say so, rather than pass untested.

use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::sync::Mutex;

use phonglab_core::Document;
use phonglab_core::escape;
use phonglab_core::export::{notebook, openframeworks, pyopengl};
use proptest::prelude::*;
use proptest::strategy::ValueTree;

/// The pieces an attack is made of, mixed with arbitrary characters.
const HOSTILE: &[&str] = &[
    "\"\"\"",
    "'''",
    "\"",
    "'",
    "*/",
    "/*",
    "//",
    "\r",
    "\n",
    "\r\n",
    "\u{2028}",
    "\u{2029}",
    "\u{0}",
    "\u{1b}[31m",
    "\u{1b}]0;title\u{7}",
    "\\",
    "\\\n",
    "??/",
    "??=",
    "#",
    "{{",
    "}}",
    "{x:doc}",
    "$x$",
    "<script>",
    "\u{202e}",
    "\u{2066}",
    "\u{85}",
    "\u{9b}",
    "\u{feff}",
    "\t",
    "\u{b}",
    "\u{c}",
    "é",
    "ç",
    "—",
    "𝛼",
    "import os",
    ";",
    "\\x",
    "%s",
];

fn name_strategy() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        3 => proptest::sample::select(HOSTILE).prop_map(str::to_string),
        2 => any::<char>().prop_map(|c| c.to_string()),
        1 => "[a-zA-Z ]{1,6}",
    ];
    proptest::collection::vec(piece, 0..12).prop_map(|v| v.concat())
}

fn named(name: &str) -> Document {
    Document { name: name.to_string(), ..Default::default() }
}

/// One Python process that answers requests line by line (JSON): the shape of a source's
/// syntax tree (its string constants replaced by "S") and its string constants, or the
/// value of a literal. One process for every case keeps the property tests fast.
struct PythonChecker {
    _child: Child,
    input: ChildStdin,
    output: BufReader<ChildStdout>,
}

const CHECKER: &str = r#"
import ast, json, sys
class Strings(ast.NodeTransformer):
    def visit_Constant(self, node):
        if isinstance(node.value, str):
            self.found.append(node.value)
            return ast.copy_location(ast.Constant("S"), node)
        return node
for line in sys.stdin:
    request = json.loads(line)
    try:
        if "literal" in request:
            reply = {"value": ast.literal_eval(request["literal"])}
        else:
            tree = ast.parse(request["source"])
            t = Strings(); t.found = []
            shape = ast.dump(t.visit(tree))
            reply = {"shape": shape, "strings": t.found}
    except Exception as e:
        reply = {"error": type(e).__name__ + ": " + str(e)}
    print(json.dumps(reply), flush=True)
"#;

impl PythonChecker {
    fn start() -> PythonChecker {
        let mut child = Command::new("python3")
            .args(["-c", CHECKER])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .expect("python3 is needed by this test (scripts/test installs it: scripts/deps.sh python3-numpy)");
        let input = child.stdin.take().unwrap();
        let output = BufReader::new(child.stdout.take().unwrap());
        PythonChecker { _child: child, input, output }
    }

    fn ask(&mut self, request: serde_json::Value) -> serde_json::Value {
        writeln!(self.input, "{request}").unwrap();
        self.input.flush().unwrap();
        let mut line = String::new();
        self.output.read_line(&mut line).unwrap();
        serde_json::from_str(&line).unwrap()
    }

    /// The tree's shape and its strings, or the parse error.
    fn parse(&mut self, source: &str) -> Result<(String, Vec<String>), String> {
        let r = self.ask(serde_json::json!({ "source": source }));
        if let Some(e) = r["error"].as_str() {
            return Err(e.to_string());
        }
        let strings = r["strings"].as_array().unwrap().iter().map(|s| s.as_str().unwrap().to_string()).collect();
        Ok((r["shape"].as_str().unwrap().to_string(), strings))
    }

    fn literal(&mut self, literal: &str) -> Result<String, String> {
        let r = self.ask(serde_json::json!({ "literal": literal }));
        r["value"].as_str().map(str::to_string).ok_or_else(|| r["error"].to_string())
    }
}

static PYTHON: Mutex<Option<PythonChecker>> = Mutex::new(None);

fn python<R>(f: impl FnOnce(&mut PythonChecker) -> R) -> R {
    let mut guard = PYTHON.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    f(guard.get_or_insert_with(PythonChecker::start))
}

/// The Python sources a document exports to: the PyOpenGL program, the notebook's code
/// cells joined, and the notebook as a script.
fn python_sources(doc: &Document) -> Vec<(&'static str, String)> {
    let cells = notebook::cells(doc, &phonglab_core::export::key(doc));
    let code: Vec<&str> = cells
        .iter()
        .filter_map(|c| match c {
            notebook::Cell::Code(code) => Some(code.as_str()),
            notebook::Cell::Markdown(_) => None,
        })
        .collect();
    vec![
        ("the PyOpenGL program", pyopengl::program(doc, &phonglab_core::export::shaded_key(doc)).unwrap()),
        ("the notebook's code cells", code.join("\n")),
        ("the notebook as a script", notebook::script(&cells)),
    ]
}

fn python_shapes_match(name: &str) -> Result<(), TestCaseError> {
    let reference = python_sources(&named("x"));
    let hostile = python_sources(&named(name));
    for ((what, x), (_, h)) in reference.iter().zip(&hostile) {
        let (x_shape, _) = python(|p| p.parse(x)).unwrap();
        let parsed = python(|p| p.parse(h));
        let (h_shape, strings) = parsed.map_err(|e| TestCaseError::fail(format!("{what} does not parse: {e}")))?;
        prop_assert!(x_shape == h_shape, "{what}: the tree differs from the name x's");
        if *what == "the PyOpenGL program" {
            let title = phonglab::t!("py-title", scene = name, shading = "Gouraud");
            prop_assert!(strings[0].starts_with(&title), "the docstring holds the title exactly: {:?}", strings[0]);
        }
    }
    Ok(())
}

fn notebook_stays_json(name: &str) -> Result<(), TestCaseError> {
    let doc = named(name);
    let ipynb = notebook::notebook(&doc, &phonglab_core::export::key(&doc));
    let nb: serde_json::Value =
        serde_json::from_str(&ipynb).map_err(|e| TestCaseError::fail(format!("not JSON: {e}")))?;
    let title = nb["cells"][0]["source"].as_array().unwrap();
    let reference: serde_json::Value =
        serde_json::from_str(&notebook::notebook(&named("x"), &phonglab_core::export::key(&named("x")))).unwrap();
    prop_assert_eq!(title.len(), reference["cells"][0]["source"].as_array().unwrap().len(), "the title's lines");
    let scene_line = title.iter().filter_map(|l| l.as_str()).find(|l| l.contains("**")).unwrap();
    prop_assert!(scene_line.contains(&escape::markdown::text(name)), "{scene_line:?}");
    Ok(())
}

fn cxx() -> &'static str {
    let ok = Command::new("g++").arg("--version").output().is_ok_and(|o| o.status.success());
    assert!(ok, "g++ is needed by this test (scripts/test installs it: scripts/deps.sh g++)");
    "g++"
}

fn standin() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/of_standin")
}

/// C++ tokens of preprocessed text, string and character literals as `"S"`.
fn tokens(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c == '"' || c == '\'' {
            i += 1;
            while i < chars.len() && chars[i] != c {
                i += if chars[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push("\"S\"".to_string());
        } else if c.is_alphanumeric() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_' || chars[i] == '.') {
                i += 1;
            }
            out.push(chars[start..i].iter().collect());
        } else {
            out.push(c.to_string());
            i += 1;
        }
    }
    out
}

/// The oF files of `doc` written to a fresh folder.
fn of_files(doc: &Document, tag: &str) -> (std::path::PathBuf, Vec<(String, String)>) {
    static N: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = N.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("phonglab-escaping-{}-{tag}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let files = openframeworks::app(doc, &phonglab_core::export::shaded_key(doc)).unwrap();
    for (file, text) in &files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    (dir, files)
}

fn preprocessed(dir: &Path, file: &str) -> Result<String, String> {
    let out = Command::new(cxx())
        .args(["-E", "-P", "-trigraphs", "-std=c++17", "-I"])
        .arg(standin())
        .arg("-I")
        .arg(dir)
        .arg(dir.join(file))
        .output()
        .unwrap();
    if !out.status.success() {
        return Err(String::from_utf8_lossy(&out.stderr).into_owned());
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

fn cpp_tokens_match(name: &str) -> Result<(), TestCaseError> {
    let (x_dir, _) = of_files(&named("x"), "x");
    let (dir, files) = of_files(&named(name), "name");
    for (file, _) in &files {
        let x = tokens(&preprocessed(&x_dir, file).unwrap());
        let h = tokens(&preprocessed(&dir, file).map_err(|e| TestCaseError::fail(format!("{file}: {e}")))?);
        prop_assert!(x == h, "{file}: the tokens outside comments and strings differ from the name x's");
    }
    for file in ["ofApp.cpp", "main.cpp"] {
        let out = Command::new(cxx())
            .args(["-std=c++17", "-fsyntax-only", "-Wall", "-Werror", "-trigraphs", "-I"])
            .arg(standin())
            .arg("-I")
            .arg(&dir)
            .arg(dir.join(file))
            .output()
            .unwrap();
        prop_assert!(out.status.success(), "{file} does not compile: {}", String::from_utf8_lossy(&out.stderr));
    }
    std::fs::remove_dir_all(&dir).ok();
    std::fs::remove_dir_all(&x_dir).ok();
    Ok(())
}

/// A comment of `name` at the end of a line, then a line of code: the code stays code.
fn comments_end_at_their_line(name: &str) -> Result<(), TestCaseError> {
    let one_assignment = python(|p| p.parse("after = 1\n")).unwrap().0;
    let sources = [
        format!("# {}\nafter = 1\n", escape::python::comment(name)),
        // "Copy as script": a Markdown cell becomes comments (the script of any cell text).
        notebook::script(&[notebook::Cell::Markdown(name.to_string()), notebook::Cell::Code("after = 1".into())]),
    ];
    for source in sources {
        let parsed = python(|p| p.parse(&source)).map_err(TestCaseError::fail)?;
        prop_assert_eq!(&parsed.0, &one_assignment, "{:?}", source);
    }
    let dir = std::env::temp_dir().join(format!("phonglab-comment-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (file, comment) in [("c.cpp", escape::cpp::comment(name)), ("g.cpp", escape::glsl::comment(name))] {
        std::fs::write(dir.join(file), format!("// {comment}\nint after;\n")).unwrap();
        let text = preprocessed(&dir, file).map_err(TestCaseError::fail)?;
        prop_assert_eq!(tokens(&text), ["int", "after", ";"], "{:?}", comment);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn a_comment_ends_at_its_line(name in name_strategy()) {
        comments_end_at_their_line(&name)?;
    }

    #[test]
    fn a_name_is_data_in_the_python_programs(name in name_strategy()) {
        python_shapes_match(&name)?;
        notebook_stays_json(&name)?;
    }

    #[test]
    fn a_name_is_data_in_the_openframeworks_app(name in name_strategy()) {
        cpp_tokens_match(&name)?;
    }

    #[test]
    fn python_literals_read_back_as_the_text(name in name_strategy()) {
        prop_assert_eq!(python(|p| p.literal(&escape::python::string(&name))), Ok(name.clone()));
        let triple = format!("\"\"\"{}\"\"\"", escape::python::triple_quoted(&name, false));
        prop_assert_eq!(python(|p| p.literal(&triple)), Ok(name.clone()));
        let block = format!("\"\"\"{}\"\"\"", escape::python::triple_quoted(&name, true));
        // A block keeps its line feeds raw; a carriage return is escaped, so nothing changes.
        prop_assert_eq!(python(|p| p.literal(&block)), Ok(name.clone()));
    }
}

/// The attacks the issue names, each written out, so a failure reads plainly.
#[test]
fn the_reported_attacks_are_data() {
    for name in [
        "x\"\"\"\nimport os; os.system('echo pwned')\n\"\"\"",
        "x\nint pwned = 1;",
        "x\rint pwned = 1;",
        "x\\",
        "x??/",
        "x\u{2028}import os",
        "\u{1b}[2J\u{1b}[31mred",
    ] {
        python_shapes_match(name).unwrap();
        notebook_stays_json(name).unwrap();
        cpp_tokens_match(name).unwrap();
        comments_end_at_their_line(name).unwrap();
    }
}

/// C++ literals made by the helper, compiled and run: each prints exactly its text.
#[test]
fn cpp_literals_read_back_as_the_text() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let names: Vec<String> =
        (0..200).map(|_| name_strategy().new_tree(&mut runner).unwrap().current().replace('\0', "")).collect();
    let dir = std::env::temp_dir().join(format!("phonglab-cpp-literals-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut program = String::from("#include <cstdio>\nint main() {\n");
    for n in &names {
        program.push_str(&format!("    std::fputs({}, stdout);\n    std::fputc(0, stdout);\n", escape::cpp::string(n)));
    }
    program.push_str("}\n");
    std::fs::write(dir.join("literals.cpp"), &program).unwrap();
    let exe = dir.join("literals");
    let built = Command::new(cxx())
        .args(["-std=c++17", "-trigraphs", "-Wall", "-Werror", "-o"])
        .arg(&exe)
        .arg(dir.join("literals.cpp"))
        .output()
        .unwrap();
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let out = Command::new(&exe).output().unwrap();
    let printed: Vec<&[u8]> = out.stdout.split(|b| *b == 0).collect();
    for (k, n) in names.iter().enumerate() {
        assert_eq!(printed[k], n.as_bytes(), "literal {k}: {}", escape::cpp::string(n));
    }
    std::fs::remove_dir_all(&dir).ok();
}
