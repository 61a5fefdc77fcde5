#!/usr/bin/python3
"""Checks CITATION.cff against the Citation File Format 1.2.0 (citation-file-format.github.io,
schema 1.2.0): the required keys, no key the schema does not define, the types and patterns of
the keys used here, references and authors as persons or entities; and that it names the
project's version (CMakeLists.txt) and licence (LICENSE). Exits 0 if it does; else prints one
line per problem and exits 1.

Usage: check_citation.py [--root DIR] [--file CITATION.cff]
"""
import argparse
import os
import re
import sys

import yaml

ROOT_KEYS = {"abstract", "authors", "cff-version", "commit", "contact", "date-released", "doi",
             "identifiers", "keywords", "license", "license-url", "message",
             "preferred-citation", "references", "repository", "repository-artifact",
             "repository-code", "title", "type", "url", "version"}
ROOT_REQUIRED = {"authors", "cff-version", "message", "title"}
PERSON_KEYS = {"address", "affiliation", "alias", "city", "country", "email", "family-names",
               "fax", "given-names", "name-particle", "name-suffix", "orcid", "post-code",
               "region", "tel", "website"}
ENTITY_KEYS = {"address", "alias", "city", "country", "date-end", "date-start", "email", "fax",
               "location", "name", "orcid", "post-code", "region", "tel", "website"}
REFERENCE_REQUIRED = {"authors", "title", "type"}
# The reference keys of the schema that a citation of a paper or a program uses.
REFERENCE_KEYS = REFERENCE_REQUIRED | {
    "abstract", "collection-title", "commit", "date-published", "doi", "end", "identifiers",
    "issn", "issue", "journal", "keywords", "license", "month", "notes", "pages", "publisher",
    "repository-code", "start", "url", "version", "volume", "year"}
REFERENCE_TYPES = {"article", "book", "conference-paper", "data", "generic", "report",
                   "software", "software-code", "thesis", "unpublished", "website"}
SPDX = {"BSD 3-Clause License": "BSD-3-Clause", "MIT License": "MIT",
        "BSD 2-Clause License": "BSD-2-Clause", "Apache License": "Apache-2.0"}


def nonempty_string(value):
    return isinstance(value, str) and len(value) > 0


def check_people(where, people, problems):
    if not isinstance(people, list) or not people:
        problems.append(f"{where}: expected a non-empty list of persons or entities")
        return
    for i, p in enumerate(people):
        if not isinstance(p, dict):
            problems.append(f"{where}[{i}]: expected a mapping")
            continue
        keys = ENTITY_KEYS if "name" in p else PERSON_KEYS
        for k in sorted(set(p) - keys):
            problems.append(f"{where}[{i}]: unknown key '{k}'")
        for k, v in p.items():
            if not nonempty_string(v):
                problems.append(f"{where}[{i}].{k}: expected a non-empty string")


def check_reference(where, ref, problems):
    if not isinstance(ref, dict):
        problems.append(f"{where}: expected a mapping")
        return
    for k in sorted(REFERENCE_REQUIRED - set(ref)):
        problems.append(f"{where}: missing required key '{k}'")
    for k in sorted(set(ref) - REFERENCE_KEYS):
        problems.append(f"{where}: unknown key '{k}'")
    if ref.get("type") not in REFERENCE_TYPES:
        problems.append(f"{where}.type: '{ref.get('type')}' is not a reference type")
    if "authors" in ref:
        check_people(f"{where}.authors", ref["authors"], problems)
    for k in ("title", "abstract", "notes", "journal"):
        if k in ref and not nonempty_string(ref[k]):
            problems.append(f"{where}.{k}: expected a non-empty string")
    for k in ("year", "volume", "start", "end", "month"):
        if k in ref and not isinstance(ref[k], int):
            problems.append(f"{where}.{k}: expected an integer")
    if "doi" in ref and not re.match(r"^10\.\d{4,9}(\.\d+)?/\S+$", str(ref["doi"])):
        problems.append(f"{where}.doi: '{ref['doi']}' is not a DOI")


def check(cff, project_version, licence_title):
    problems = []
    if not isinstance(cff, dict):
        return ["the file is not a YAML mapping"]
    for k in sorted(ROOT_REQUIRED - set(cff)):
        problems.append(f"missing required key '{k}'")
    for k in sorted(set(cff) - ROOT_KEYS):
        problems.append(f"unknown key '{k}'")
    if cff.get("cff-version") != "1.2.0":
        problems.append(f"cff-version: '{cff.get('cff-version')}', expected '1.2.0' (a string)")
    for k in ("message", "title", "abstract"):
        if k in cff and not nonempty_string(cff[k]):
            problems.append(f"{k}: expected a non-empty string")
    if cff.get("type", "software") not in ("software", "dataset"):
        problems.append(f"type: '{cff['type']}', expected software or dataset")
    check_people("authors", cff.get("authors"), problems)
    kw = cff.get("keywords", ["x"])
    if not isinstance(kw, list) or not kw or not all(nonempty_string(k) for k in kw):
        problems.append("keywords: expected a non-empty list of strings")
    for i, ref in enumerate(cff.get("references", [])):
        check_reference(f"references[{i}]", ref, problems)
    if "preferred-citation" in cff:
        check_reference("preferred-citation", cff["preferred-citation"], problems)
    if str(cff.get("version")) != project_version:
        problems.append(f"version: '{cff.get('version')}', the project's is '{project_version}'")
    if cff.get("license") != SPDX.get(licence_title):
        problems.append(f"license: '{cff.get('license')}', LICENSE is the "
                        f"{licence_title} ({SPDX.get(licence_title, 'unknown SPDX identifier')})")
    return problems


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", default=os.path.join(os.path.dirname(__file__), ".."))
    parser.add_argument("--file", default=None)
    args = parser.parse_args()
    path = args.file or os.path.join(args.root, "CITATION.cff")
    with open(os.path.join(args.root, "CMakeLists.txt")) as f:
        version = re.search(r"project\(granwave VERSION ([0-9.]+)", f.read()).group(1)
    with open(os.path.join(args.root, "LICENSE")) as f:
        licence_title = f.readline().strip()
    try:
        with open(path) as f:
            cff = yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        print(f"{path}: {e}".replace("\n", " "))
        return 1
    problems = check(cff, version, licence_title)
    for p in problems:
        print(f"{path}: {p}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
