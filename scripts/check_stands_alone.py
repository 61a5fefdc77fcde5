#!/usr/bin/env python3
"""The project stands alone: no tracked file refers to a path outside the repository (the
design notes and the paper's source the project started from are not part of it; what the code
relies on is in docs/, in the project's words). Usage: check_stands_alone.py [--root DIR]."""
import argparse
import pathlib
import re
import subprocess
import sys

# Names of files that live outside the repository, and paths that lead out of it.
OUTSIDE = re.compile(r"shared/(design|paper)|\.\./shared\b|"
                     r"\b(physics-particles|physics-hydro|coarse-graining|anchors)\.md\b|"
                     r"\bdesign/[a-z-]+\.md\b|paper/huang-[a-z-]+\.tex")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent)
    root = pathlib.Path(ap.parse_args().root)
    files = subprocess.run(["git", "-C", str(root), "ls-files"], capture_output=True, text=True,
                           check=True).stdout.split()
    me = pathlib.Path(__file__).name
    problems = []
    for name in files:
        path = root / name
        if path.name == me or not path.is_file():
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except (UnicodeDecodeError, OSError):
            continue  # binary files
        for number, line in enumerate(text.splitlines(), 1):
            if OUTSIDE.search(line):
                problems.append(f"{name}:{number}: refers outside the repository: {line.strip()}")
    print("\n".join(problems) if problems else f"check_stands_alone: {len(files)} files, none "
          "refers outside the repository")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
