#!/usr/bin/python3
"""Puts each message of phonglab's Fluent catalogues in the catalogue of the crate that uses it.

    scripts/split-catalogue.py          # rewrite both catalogues, in all three languages
    scripts/split-catalogue.py --check  # say what would move, change nothing (exit 1 if any)

The core's catalogue is crates/phonglab-core/i18n/{en,pt-PT,pt-BR}.ftl, the app's
i18n/{en,pt-PT,pt-BR}.ftl. A message the core's sources use stays in (or goes to) the core's,
whether or not the app uses it too: the app's lookup reads both, the core's only its own. A
message only the app's sources use goes to the app's. Ids, texts, comments and order are kept;
each message keeps its section (`## name`), in the order the sections first appear.

"Used by a crate's sources" is the rule tests/i18n.rs checks, read the same way:
- the id as a string literal ("id") anywhere in the crate's .rs files (a `t!("id")`, a
  `tr("id")`, a table of ids, a `message_id()` arm);
- an id built from parts: the core's `material-name-*` (materials::display_name); the app's
  `preset-*` (io/scenes.rs), `cli-*` (the command line's help, by command, argument and
  value), and `material-*` / `back-*` (a material field's label, `{side}-{field}`);
- a `{ id }` reference from a message that lives in that crate's catalogue.

Run it after merging a branch that added messages to either catalogue, then
`cargo test --test all i18n::`.
"""

import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
LANGS = ["en", "pt-PT", "pt-BR"]
CORE_DIR = ROOT / "crates/phonglab-core/i18n"
APP_DIR = ROOT / "i18n"
CORE_SRC = ROOT / "crates/phonglab-core/src"
APP_SRC = ROOT / "src"
# The Python package's extension module looks up the core's catalogue (phonglab_core::t!).
PY_SRC = ROOT / "crates/phonglab-py/src"
CORE_PREFIXES = ["material-name-"]
APP_PREFIXES = ["preset-", "cli-", "material-", "back-"]
APP_HEADERS = {
    "en": "# phonglab's app messages in English: the window's, the command line's and the files'.\n"
    "# The core's messages are in crates/phonglab-core/i18n/en.ftl.\n",
    "pt-PT": "# As mensagens da aplicação do phonglab em português de Portugal: as da janela, as da\n"
    "# linha de comandos e as dos ficheiros. As do núcleo estão em crates/phonglab-core/i18n/pt-PT.ftl.\n",
    "pt-BR": "# As mensagens do aplicativo phonglab em português do Brasil: as da janela, as da\n"
    "# linha de comando e as dos arquivos. As do núcleo estão em crates/phonglab-core/i18n/pt-BR.ftl.\n",
}
ID = re.compile(r"^([a-zA-Z][a-zA-Z0-9_-]*)\s*=")
REF = re.compile(r"\{\s*([a-zA-Z][a-zA-Z0-9_-]*)\s*\}")


def continues(lines, k):
    """Is line k part of the message above it? Indented lines, a select's closing brace, and
    blank lines inside a pattern (an indented line follows them) are."""
    line = lines[k]
    if line.startswith((" ", "\t", "}")):
        return True
    if line.strip():
        return False
    rest = next((x for x in lines[k:] if x.strip()), "")
    return rest.startswith((" ", "\t"))


def parse(path):
    """The file's header (its opening comment) and its entries: (section key, id, lines)."""
    if not path.exists():
        return [], []
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    header, k = [], 0
    while k < len(lines) and lines[k].startswith("# "):
        header.append(lines[k])
        k += 1
    entries, section, seen, comment = [], ("", 0), {}, []
    while k < len(lines):
        line = lines[k]
        k += 1
        if line.startswith("## "):
            name = line[3:].strip()
            seen[name] = seen.get(name, 0) + 1
            section, comment = (name, seen[name]), []
        elif line.startswith("#"):
            comment.append(line)
        elif ID.match(line):
            body = [line]
            while k < len(lines) and continues(lines, k):
                body.append(lines[k])
                k += 1
            entries.append((section, ID.match(line).group(1), comment + body))
            comment = []
    return header, entries


def sources(folder):
    return "".join(p.read_text(encoding="utf-8") for p in sorted(folder.rglob("*.rs")))


def used_by(text, prefixes, ident):
    return f'"{ident}"' in text or any(ident.startswith(p) for p in prefixes)


def classify(entries):
    """Each id's catalogue: "core" or "app"."""
    core_text, app_text = sources(CORE_SRC) + sources(PY_SRC), sources(APP_SRC)
    refs = {i: set(REF.findall("".join(x for x in lines if not x.startswith("#")))) for _, i, lines in entries}
    in_core = {i for i in refs if used_by(core_text, CORE_PREFIXES, i)}
    in_app = {i for i in refs if used_by(app_text, APP_PREFIXES, i)}
    # Unused messages stay in the core (tests/i18n.rs names them).
    place = {i: ("core" if i in in_core or i not in in_app else "app") for i in refs}
    changed = True
    while changed:  # a message another message names lives where that one does, or in the core
        changed = False
        for ident, named in refs.items():
            for other in named & refs.keys():
                if place[other] == "app" and place[ident] == "core":
                    place[other], changed = "core", True
    return place


def render(header, entries, order):
    """The catalogue's text: its header, then each section that has messages here."""
    out = list(header)
    for key in order:
        group = [lines for section, _, lines in entries if section == key]
        if group:
            out += ["\n", f"## {key[0]}\n", "\n"] if key[0] else ["\n"]
            out += [line for lines in group for line in lines]
    return "".join(out)


def sections_in_order(entries, app_ids):
    """The core's sections in its order, each section only the app's has after the one
    before it in the app's."""
    order = list(dict.fromkeys(section for section, i, _ in entries if i not in app_ids))
    before = None
    for section in dict.fromkeys(section for section, i, _ in entries if i in app_ids):
        if section not in order:
            order.insert(order.index(before) + 1 if before in order else 0, section)
        before = section
    return order


def main():
    check = "--check" in sys.argv[1:]
    pooled = {}
    for lang in LANGS:
        core_header, core = parse(CORE_DIR / f"{lang}.ftl")
        _, app = parse(APP_DIR / f"{lang}.ftl")
        pooled[lang] = (core_header, core + [(s, i, ls) for s, i, ls in app], {i for _, i, _ in app})
    place = classify(pooled["en"][1])
    moves = 0
    for lang in LANGS:
        core_header, entries, was_app = pooled[lang]
        order = sections_in_order(entries, was_app)
        for where in ["core", "app"]:
            chosen = [e for e in entries if place.get(e[1], "core") == where]
            header = core_header if where == "core" else [APP_HEADERS[lang]]
            text = render(header, chosen, order)
            path = (CORE_DIR if where == "core" else APP_DIR) / f"{lang}.ftl"
            old = path.read_text(encoding="utf-8") if path.exists() else ""
            if text != old and not check:
                path.parent.mkdir(exist_ok=True)
                part = path.with_name(path.name + ".part")
                part.write_text(text, encoding="utf-8")
                part.replace(path)  # whole or not at all
        moved = sorted(i for _, i, _ in entries if (place.get(i) == "app") != (i in was_app))
        if lang == "en":
            moves = len(moved)
            for i in moved:
                print(f"{i}: to the {place[i]}'s catalogue")
    app_count = sum(1 for p in place.values() if p == "app")
    print(f"{len(place)} messages: {len(place) - app_count} in the core's catalogue, {app_count} in the app's")
    return 1 if check and moves else 0


if __name__ == "__main__":
    sys.exit(main())
