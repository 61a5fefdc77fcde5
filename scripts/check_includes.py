#!/usr/bin/python3
"""Checks that every #include "..." of the project follows the dependency rule written as data
in scripts/include-rules.toml (docs/ARCHITECTURE.md). Exits 0 if it does; else prints one line
per include across the rule (file:line: folder may not include target) and exits 1.

Usage: check_includes.py [--root DIR] [--rules FILE]
A file belongs to the longest folder of the rule that contains it (tests/<folder>/... to the
tests of <folder>); an include "a/b/X.hpp" names the longest folder of the rule it starts with;
an include without a folder is relative to the including file. A source file in a folder the
rule does not name is an error too, so a new folder has to be placed in the rule.
"""
import argparse
import os
import re
import sys
import tomllib

EXTENSIONS = (".cpp", ".hpp", ".h")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SKIP = ("build", ".git", "out")


def closure(depends, folder):
    seen, stack = set(), [folder]
    while stack:
        for d in depends.get(stack.pop(), []):
            if d not in seen:
                seen.add(d)
                stack.append(d)
    return seen


def owner(path, folders):
    """The longest folder of the rule that `path` (relative, '/'-separated) lies in."""
    best = None
    for f in folders:
        if (path == f or path.startswith(f + "/")) and (best is None or len(f) > len(best)):
            best = f
    return best


def allowed_for(rel, rules):
    """(name of the file's folder, folders it may include) or (None, None) if unplaced."""
    depends, tests = rules["depends"], rules.get("tests", {})
    if rel.startswith("tests/"):
        inner = owner(rel[len("tests/"):], depends)
        if inner is None:
            return None, None
        allowed = {inner} | closure(depends, inner) | {"tests"}
        for extra in tests.get(inner, []):
            allowed |= {extra} | closure(depends, extra)
        return "tests/" + inner, allowed
    folder = owner(rel, depends)
    if folder is None:
        return None, None
    return folder, {folder} | closure(depends, folder)


def check(root, rules):
    problems = []
    known = set(rules["depends"]) | {"tests"}
    for top, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if not (top == root and (d in SKIP or d.startswith("build")))]
        for name in sorted(files):
            if not name.endswith(EXTENSIONS):
                continue
            path = os.path.join(top, name)
            rel = os.path.relpath(path, root).replace(os.sep, "/")
            folder, allowed = allowed_for(rel, rules)
            if folder is None:
                problems.append(f"{rel}: its folder is not in the dependency rule "
                                f"(add it to scripts/include-rules.toml)")
                continue
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if not m or "/" not in m.group(1):
                        continue
                    target = owner(m.group(1), known)
                    if target is None:
                        problems.append(f"{rel}:{number}: includes \"{m.group(1)}\", a folder "
                                        f"the dependency rule does not name")
                    elif target not in allowed:
                        problems.append(f"{rel}:{number}: {folder} may not include {target} "
                                        f"(\"{m.group(1)}\")")
    return problems


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", default=os.path.dirname(here))
    ap.add_argument("--rules", default=os.path.join(here, "include-rules.toml"))
    a = ap.parse_args()
    try:
        with open(a.rules, "rb") as f:
            rules = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        print(f"check_includes: {a.rules}: {e}", file=sys.stderr)
        return 2
    problems = check(a.root, rules)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
