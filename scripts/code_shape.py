#!/usr/bin/env python3
"""The codebase's shape, for reviews: the core's group graph (which group's files name
which other group, through a group path or through the crate root's re-exports), its
cycles, the longest functions of the core and the app, where processor-specific code and
`unsafe` sit (in the `copies` modules or not), the files over 500 lines, and README.md's
length.
Usage: scripts/code_shape.py [CHECKOUT] [--functions N] (default: this checkout, 15)."""
import collections
import os
import re
import sys


def group_graph(root):
    src = os.path.join(root, "crates/phonglab-core/src")
    lib = open(os.path.join(src, "lib.rs")).read()
    groups = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
    # Names the root re-exports: modules (`pub use model::{scene, ...}`) and types.
    module_group, type_group = {}, {}
    for m in re.finditer(r"pub use (\w+)::\{([^}]*)\};", lib):
        for n in (x.strip() for x in m.group(2).split(",")):
            if m.group(1) in groups and n[:1].islower():
                module_group[n] = m.group(1)
    for m in re.finditer(r"pub use (\w+)::(\w+);", lib):
        if m.group(1) in groups and m.group(2)[:1].islower():
            module_group[m.group(2)] = m.group(1)
    for m in re.finditer(r"pub use (\w+)::\{([^}]*)\};", lib):
        for n in (x.strip() for x in m.group(2).split(",")):
            if n[:1].isupper() and m.group(1) in module_group:
                type_group[n] = module_group[m.group(1)]
    edges = collections.defaultdict(set)
    for g in groups:
        for dp, _, fs in os.walk(os.path.join(src, g)):
            for f in fs:
                if f.endswith(".rs"):
                    for m in re.finditer(r"(?<![\w$])crate::(\w+)(?!!)", open(os.path.join(dp, f)).read()):
                        n = m.group(1)
                        t = n if n in groups else module_group.get(n) or type_group.get(n)
                        if t and t != g:
                            edges[g].add(t)
    return groups, edges


def cycles(groups, edges):
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in groups:
        if v not in index:
            visit(v)
    return out


def functions(root):
    found = []
    for base in ["src", "crates/phonglab-core/src"]:
        for dp, _, fs in os.walk(os.path.join(root, base)):
            for f in fs:
                if not f.endswith(".rs"):
                    continue
                lines = open(os.path.join(dp, f)).read().split("\n")
                for i, line in enumerate(lines):
                    m = re.match(r"\s*(pub(\([^)]*\))? )?(const )?(unsafe )?fn (\w+)", line)
                    if not m or line.rstrip().endswith(";"):
                        continue
                    depth, started, j = 0, False, i
                    while j < len(lines):
                        # Braces inside string and character literals are not the code's.
                        code = re.sub(r'"(?:[^"\\]|\\.)*"|\'[{}]\'', "", lines[j])
                        depth += code.count("{") - code.count("}")
                        started = started or "{" in code
                        if started and depth <= 0:
                            break
                        j += 1
                    found.append((j - i + 1, m.group(5), os.path.relpath(os.path.join(dp, f), root)))
    return sorted(found, reverse=True)


def processor_specific(root):
    """Counts, in the core, of `#[target_feature]` attributes and of `unsafe {` blocks:
    (in copies.rs files, elsewhere)."""
    counts = {"target_feature": [0, 0], "unsafe": [0, 0]}
    src = os.path.join(root, "crates/phonglab-core/src")
    for dp, _, fs in os.walk(src):
        for f in fs:
            if not f.endswith(".rs"):
                continue
            for line in open(os.path.join(dp, f)):
                code = line.split("//")[0]
                where = 0 if f == "copies.rs" else 1
                counts["target_feature"][where] += code.count("#[target_feature(")
                counts["unsafe"][where] += code.count("unsafe {")
    return counts


def long_files(root, limit=500):
    found = []
    for top in ("src", "crates"):
        for dp, _, fs in os.walk(os.path.join(root, top)):
            for f in fs:
                if f.endswith(".rs"):
                    path = os.path.join(dp, f)
                    n = sum(1 for _ in open(path))
                    if n > limit:
                        found.append((n, os.path.relpath(path, root)))
    return sorted(found, reverse=True)


def main():
    args = sys.argv[1:]
    root = next((a for a in args if not a.startswith("--") and not a.isdigit()), ".")
    n = int(args[args.index("--functions") + 1]) if "--functions" in args else 15
    groups, edges = group_graph(root)
    print("core groups and the groups their files name:")
    for g in groups:
        print(f"  {g} -> {', '.join(sorted(edges.get(g, ()))) or '(none)'}")
    print("cycles:", cycles(groups, edges) or "none")
    print(f"longest functions (lines):")
    for lines, name, path in functions(root)[:n]:
        print(f"  {lines:4} {name} ({path})")
    for what, (copies, elsewhere) in processor_specific(root).items():
        print(f"core {what}: {copies} in the copies modules, {elsewhere} elsewhere")
    files = long_files(root)
    print(f"files over 500 lines: {len(files)}")
    for lines, path in files:
        print(f"  {lines:4} {path}")
    readme = os.path.join(root, "README.md")
    print("README.md:", sum(1 for _ in open(readme)), "lines")


main()
