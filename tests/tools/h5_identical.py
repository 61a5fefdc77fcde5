#!/usr/bin/python3
"""Exits 0 if two HDF5 files hold the same objects with bit-identical contents, else prints
the first differences and exits 1. h5diff is not enough here: it reports datasets of
different shapes as "not comparable" and still exits 0.

Usage: h5_identical.py A.h5 B.h5 [--only /group ...] [--exclude /path ...]
Datasets are compared by dtype, shape and raw bytes; attributes by value (NaN equals NaN
bitwise through the bytes of numeric arrays)."""
import argparse
import sys

import h5py
import numpy as np


def collect(f, only, exclude):
    items = {}

    def visit(name, obj):
        path = "/" + name
        if any(path == e or path.startswith(e.rstrip("/") + "/") for e in exclude):
            return
        if only and not any(path == o or path.startswith(o.rstrip("/") + "/") for o in only):
            return
        items[path] = obj

    f.visititems(visit)
    if not only:
        items["/"] = f
    return items


def attr_bytes(value):
    a = np.asarray(value)
    if a.dtype.kind in "OSU":
        return repr(a.tolist()).encode()
    return a.dtype.str.encode() + repr(a.shape).encode() + a.tobytes()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--only", action="append", default=[])
    ap.add_argument("--exclude", action="append", default=[])
    args = ap.parse_args()
    problems = []
    for path in (args.a, args.b):
        try:
            h5py.File(path, "r").close()
        except OSError as e:
            print(f"h5_identical: {path}: cannot open ({e})", file=sys.stderr)
            return 1
    with h5py.File(args.a, "r") as fa, h5py.File(args.b, "r") as fb:
        ia = collect(fa, args.only, args.exclude)
        ib = collect(fb, args.only, args.exclude)
        if not ia:
            problems.append(f"nothing to compare in {args.a} (--only {args.only})")
        for path in sorted(set(ia) ^ set(ib)):
            problems.append(f"{path}: only in {args.a if path in ia else args.b}")
        for path in sorted(set(ia) & set(ib)):
            oa, ob = ia[path], ib[path]
            if isinstance(oa, h5py.Dataset) != isinstance(ob, h5py.Dataset):
                problems.append(f"{path}: a dataset in one file, a group in the other")
                continue
            if isinstance(oa, h5py.Dataset):
                if oa.dtype != ob.dtype or oa.shape != ob.shape:
                    problems.append(f"{path}: {oa.dtype}{oa.shape} against {ob.dtype}{ob.shape}")
                    continue
                va, vb = oa[()], ob[()]
                if isinstance(va, np.ndarray) and va.dtype.kind not in "OSU":
                    same = va.tobytes() == vb.tobytes()
                else:
                    same = repr(va) == repr(vb)
                if not same:
                    problems.append(f"{path}: contents differ")
            if sorted(oa.attrs) != sorted(ob.attrs):
                problems.append(f"{path}: attributes {sorted(oa.attrs)} against {sorted(ob.attrs)}")
                continue
            for name in oa.attrs:
                if attr_bytes(oa.attrs[name]) != attr_bytes(ob.attrs[name]):
                    problems.append(f"{path}: attribute {name} differs")
    for p in problems[:20]:
        print(f"h5_identical: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
