#!/usr/bin/python3
"""The size limits of the project's style (docs/ARCHITECTURE.md, "Shape of the code"):
no source file over 450 lines, no function over 80 lines or nested more than 4 deep.

Usage: check_code_shape.py BUILD_DIR... [--report] [--only PREFIX ...] [--max-file 450]
                           [--max-function 80] [--max-nesting 4] [-j JOBS]

Every C++ file of the repository (tests and benchmarks included) is counted for lines; the
functions are found by parsing each translation unit of BUILD_DIR/compile_commands.json with
libclang (Debian's python3-clang-14), so macros (TEST, TEST_F) and templates are seen as the
compiler sees them (with clang's precompiled headers, without GCC's). With several build
trees, a file is parsed with the command of the first tree that compiles it: .ci/run names
the sanitizer build (clang 14, precompiled headers libclang reads) and then the Release build
(GCC), which alone compiles the test tiers the sanitizers do not run. A file that libclang
cannot parse without errors is an offender: its functions would go uncounted. A function's
length is the lines from its name to its closing brace; its nesting is the deepest chain of
if / for / while / do / switch / try / lambda inside it (an `else if` continues its `if` and
does not nest). Functions defined in headers are counted once. Exits 1 and lists the
offenders if a limit is exceeded; --report lists the largest figures per folder whatever the
limits; --only limits the check to files under the given folders (e.g. --only studies
tests/studies).
"""
import argparse
import json
import os
import shlex
import sys
from concurrent.futures import ProcessPoolExecutor

SOURCE_DIRS = ("scene", "h5", "files", "particles", "coarse_grain", "hydro", "studies", "tests", "bench")
EXTENSIONS = (".cpp", ".hpp", ".h")
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def clang():
    import clang.cindex as ci
    if not ci.Config.loaded:
        for lib in ("/usr/lib/llvm-14/lib/libclang.so.1", "/usr/lib/x86_64-linux-gnu/libclang-14.so.1"):
            if os.path.exists(lib):
                ci.Config.set_library_file(lib)
                break
    return ci


def source_files():
    for top in SOURCE_DIRS:
        for folder, _, files in os.walk(os.path.join(ROOT, top)):
            for name in sorted(files):
                if name.endswith(EXTENSIONS):
                    yield os.path.join(folder, name)


def arguments(entry):
    args = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    # clang's precompiled headers (the sanitizer build's) are libclang's own format: kept, a
    # test file parses in a fraction of the time. They hold the sanitizer options they were
    # made with, and clang refuses a header made with other options, so those stay too.
    # GCC's (-include .../cmake_pch.hxx, read as .gch) are not: libclang parses the headers.
    by_clang = "clang" in os.path.basename(args[0])
    out, skip = [], False
    for a in args[1:]:
        if skip:
            skip = False
            continue
        if a in ("-o", "-c"):
            skip = a == "-o"
            continue
        if a == entry["file"] or a.startswith("-W") or (a.startswith("-fsanitize") and not by_clang):
            continue
        out.append(a)
    if by_clang:
        return out + ["-Wno-everything"]
    kept = []
    for a in out:
        if "cmake_pch" in a:
            if kept and kept[-1] == "-include":
                kept.pop()
            continue
        kept.append(a)
    return kept + ["-Wno-everything"]


NESTING_KINDS = None


def nesting(cursor, ci, depth=0):
    """Deepest chain of control statements below `cursor`."""
    best = depth
    kids = list(cursor.get_children())
    for i, child in enumerate(kids):
        k = child.kind
        nested = k in NESTING_KINDS
        # `else if`: the if that is the else-branch (third child) of an if continues it.
        if k == ci.CursorKind.IF_STMT and cursor.kind == ci.CursorKind.IF_STMT and i == len(kids) - 1 \
                and i >= 2:
            nested = False
        best = max(best, nesting(child, ci, depth + 1 if nested else depth))
    return best


FUNCTION_KINDS = None


def functions_of(entry):
    global NESTING_KINDS, FUNCTION_KINDS
    ci = clang()
    K = ci.CursorKind
    NESTING_KINDS = {K.IF_STMT, K.FOR_STMT, K.CXX_FOR_RANGE_STMT, K.WHILE_STMT, K.DO_STMT,
                     K.SWITCH_STMT, K.CXX_TRY_STMT, K.LAMBDA_EXPR}
    FUNCTION_KINDS = {K.FUNCTION_DECL, K.CXX_METHOD, K.CONSTRUCTOR, K.DESTRUCTOR,
                      K.FUNCTION_TEMPLATE, K.CONVERSION_FUNCTION}
    os.chdir(entry["directory"])
    tu = ci.Index.create().parse(entry["file"], args=arguments(entry))
    found = []
    errors = [d for d in tu.diagnostics if d.severity >= ci.Diagnostic.Error]
    if errors:
        path = os.path.relpath(os.path.realpath(entry["file"]), ROOT)
        found.append((path, 0, f"not parsed ({len(errors)} errors, first: {errors[0].spelling})",
                      -1, 0))

    def visit(cursor):
        for c in cursor.get_children():
            loc = c.location
            if loc.file is None or not os.path.realpath(loc.file.name).startswith(ROOT + os.sep):
                continue
            if c.kind in FUNCTION_KINDS and c.is_definition():
                path = os.path.relpath(os.path.realpath(loc.file.name), ROOT)
                lines = c.extent.end.line - c.extent.start.line + 1
                body = [b for b in c.get_children() if b.kind == K.COMPOUND_STMT]
                depth = nesting(body[-1], ci) if body else 0
                found.append((path, c.extent.start.line, c.spelling, lines, depth))
            elif c.kind in (K.NAMESPACE, K.CLASS_DECL, K.STRUCT_DECL, K.CLASS_TEMPLATE,
                            K.UNEXPOSED_DECL, K.LINKAGE_SPEC):
                visit(c)

    visit(tu.cursor)
    return found


def folder(path):
    parts = path.split(os.sep)
    depth = 3 if parts[0] == "tests" and len(parts) > 3 else 2
    return os.sep.join(parts[:depth]) if len(parts) > depth else os.sep.join(parts[:-1])


def compile_entries(builds, selected):
    """The compile command of each selected project file, from the first build tree that
    compiles it; None (after saying why) if a tree has no database or names a missing file."""
    entries, seen = [], set()
    for build in builds:
        db = os.path.join(build, "compile_commands.json")
        if not os.path.exists(db):
            print(f"check_code_shape: {db} not found (configure with CMake first)", file=sys.stderr)
            return None
        with open(db) as f:
            # The project's own files only: not the files CMake makes in the build tree
            # (the precompiled headers' sources), which may lie under ROOT too.
            mine = [e for e in json.load(f)
                    if os.path.realpath(e["file"]).startswith(ROOT + os.sep)
                    and os.path.relpath(os.path.realpath(e["file"]), ROOT).split(os.sep)[0]
                    in SOURCE_DIRS
                    and selected(os.path.relpath(os.path.realpath(e["file"]), ROOT))]
        stale = [e["file"] for e in mine if not os.path.exists(e["file"])]
        if stale:
            print(f"check_code_shape: {db} names {stale[0]}, which does not exist "
                  f"({len(stale)} such files; reconfigure the build with CMake)", file=sys.stderr)
            return None
        new = [e for e in mine if os.path.realpath(e["file"]) not in seen]
        seen.update(os.path.realpath(e["file"]) for e in new)
        entries += new
    return entries


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build", nargs="+")
    ap.add_argument("--report", action="store_true")
    ap.add_argument("--max-file", type=int, default=450)
    ap.add_argument("--max-function", type=int, default=80)
    ap.add_argument("--max-nesting", type=int, default=4)
    ap.add_argument("-j", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--only", nargs="+", default=[])
    a = ap.parse_args()
    only = [p.rstrip("/") for p in a.only]

    def selected(rel):
        return not only or any(rel == p or rel.startswith(p + "/") for p in only)

    entries = compile_entries(a.build, selected)
    if entries is None:
        return 2
    functions, problems = {}, []
    with ProcessPoolExecutor(max_workers=a.j) as pool:
        for found in pool.map(functions_of, entries):
            for path, line, name, lines, depth in found:
                if lines < 0:
                    problems.append(f"{path}: {name}")
                    continue
                functions[(path, line)] = (name, lines, depth)
    per_folder = {}
    for path in source_files():
        rel = os.path.relpath(path, ROOT)
        if not selected(rel):
            continue
        with open(path, encoding="utf-8") as f:
            n = sum(1 for _ in f)
        per_folder.setdefault(folder(rel), [0, 0, ("", 0), ("", 0)])[0] += n
        per_folder[folder(rel)][1] = max(per_folder[folder(rel)][1], n)
        if n > a.max_file:
            problems.append(f"{rel}: {n} lines (limit {a.max_file})")
    for (path, line), (name, lines, depth) in sorted(functions.items()):
        if not selected(path):
            continue
        entry = per_folder.setdefault(folder(path), [0, 0, ("", 0), ("", 0)])
        if lines > entry[2][1]:
            entry[2] = (f"{name} ({os.path.basename(path)}:{line})", lines)
        if depth > entry[3][1]:
            entry[3] = (f"{name} ({os.path.basename(path)}:{line})", depth)
        if lines > a.max_function:
            problems.append(f"{path}:{line}: {name}: {lines} lines (limit {a.max_function})")
        if depth > a.max_nesting:
            problems.append(f"{path}:{line}: {name}: nested {depth} deep (limit {a.max_nesting})")
    if a.report:
        print(f"{'folder':32} {'lines':>6} {'largest file':>12}  longest function / deepest nesting")
        for name, (total, largest, longest, deepest) in sorted(per_folder.items()):
            print(f"{name:32} {total:6} {largest:12}  {longest[1]:4} {longest[0]}")
            print(f"{'':53}{deepest[1]:4} {deepest[0]}")
        shown = [v for (p, _), v in functions.items() if selected(p)]
        over = sum(1 for _, l, _ in shown if l > a.max_function)
        deep = sum(1 for _, _, d in shown if d > a.max_nesting)
        print(f"functions: {len(shown)}; over {a.max_function} lines: {over}; "
              f"nested over {a.max_nesting}: {deep}")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
