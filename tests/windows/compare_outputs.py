#!/usr/bin/env python3
"""Compares the Linux lmc's outputs with the Windows lmc.exe's (tests/windows/run_under_wine.sh):
every file both wrote, byte for byte. Files whose bytes legitimately differ between any two runs
(times of day, process ids, paths as each system spells them) are listed in VARYING with why; for
them only the line count is compared. A TRC file's first line names its own path; the rest must be
identical. The simulator's recordings (*.raw.txt, and its Vicon *.trc) are computed with the C library's sin and cos,
which are not correctly rounded: glibc's and MinGW-w64's differ in the last bit for some angles
(cos(pi/2) is -6.123233995736766e-17 on one, -6.123031769111886e-17 on the other), so their numbers
must agree to 1e-9 relative (or 1e-12 absolute), not to the bit. What `lmc process` computes from
those recordings inherits the difference: its fused tracks agree to the same 1e-9 (1e-13 seen), and
its summaries (JSON) to 1e-6 relative or 1e-7 absolute, because their angles go through acos and
atan2 near 0 and a standard deviation over frames (3e-8 degrees seen); a summary's input paths are
compared as paths below each run's folder, since each system spells them its own way (Z:\\... with
backslashes under Wine). Exit 1 when any other file differs or exists on one side only.

usage: compare_outputs.py LINUX_DIR WINDOWS_DIR"""
import fnmatch
import json
import os
import re
import sys

# name pattern -> why its bytes differ between two runs on any system
VARYING = {
    "journal.jsonl": "UTC times of each event and the process id",
    "journal.cut-*": "named for the time of the cut",
    "manifest.txt": "written with the session's times",
    "LMC_*.session.json": "host clock readings (host_ns, UTC) of the recording run",
    "session.json": "the input paths as each system spells them, and the run's times",
    "dataset_description.json": "the export's time",
    "*_scans.tsv": "acquisition times of day",
    "*.log": "run times",
}
SKIP_DIRS = {"cache"}
FIRST_LINE_NAMES_ITSELF = "*.trc"
NUMERIC_TOLERANCE = ("*.raw.txt", "*.trc", "*.fused.txt")
JSON_TOLERANCE = ("*.summary.json",)


def numbers_agree(a, b):
    """Same text but for numbers that agree to 1e-9 relative or 1e-12 absolute."""
    split = lambda text: re.split(rb"([\t,\n ])", text)
    ta, tb = split(a), split(b)
    if len(ta) != len(tb):
        return False
    for x, y in zip(ta, tb):
        if x == y:
            continue
        try:
            fx, fy = float(x), float(y)
        except ValueError:
            return False
        if abs(fx - fy) > max(1e-12, 1e-9 * max(abs(fx), abs(fy))):
            return False
    return True


def below_run(value, root):
    """A path string below `root` (a Linux path, or Wine's Z:\\ spelling of one) as ROOT/relative."""
    if re.match(r"^[A-Za-z]:\\", value):
        value = value[2:].replace("\\", "/")
    root = os.path.abspath(root)
    return "ROOT/" + os.path.relpath(value, root) if value.startswith(root + "/") else value


def json_agrees(a, b, root_a, root_b):
    """Same structure and strings (paths below each run's folder), numbers to 1e-6 relative or 1e-7 absolute."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(json_agrees(a[k], b[k], root_a, root_b) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(json_agrees(x, y, root_a, root_b) for x, y in zip(a, b))
    if isinstance(a, str) and isinstance(b, str):
        return below_run(a, root_a) == below_run(b, root_b)
    numbers = (int, float)
    if isinstance(a, numbers) and isinstance(b, numbers) and not isinstance(a, bool) and not isinstance(b, bool):
        return abs(a - b) <= max(1e-7, 1e-6 * max(abs(a), abs(b)))
    return a == b


def files(root):
    out = {}
    for d, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if x not in SKIP_DIRS]
        for n in names:
            p = os.path.join(d, n)
            out[os.path.relpath(p, root)] = p
    return out


def main():
    linux, windows = files(sys.argv[1]), files(sys.argv[2])
    same, varying, differ, close = [], [], [], []
    only = sorted(set(linux) ^ set(windows))
    for rel in sorted(set(linux) & set(windows)):
        a, b = open(linux[rel], "rb").read(), open(windows[rel], "rb").read()
        if a == b:
            same.append(rel)
            continue
        name = os.path.basename(rel)
        if fnmatch.fnmatch(name, FIRST_LINE_NAMES_ITSELF):
            a, b = a.split(b"\n", 1)[-1], b.split(b"\n", 1)[-1]
            if a == b:
                same.append(rel)
                continue
        if any(fnmatch.fnmatch(name, pat) for pat in NUMERIC_TOLERANCE) and numbers_agree(a, b):
            close.append(rel)
            continue
        if any(fnmatch.fnmatch(name, pat) for pat in JSON_TOLERANCE) and json_agrees(
                json.loads(a), json.loads(b), sys.argv[1], sys.argv[2]):
            close.append(rel)
            continue
        why = next((w for pat, w in VARYING.items() if fnmatch.fnmatch(os.path.basename(rel), pat)), None)
        if why is not None:
            varying.append((rel, why, a.count(b"\n") == b.count(b"\n")))
        else:
            line = next((i for i, (x, y) in enumerate(zip(a.split(b"\n"), b.split(b"\n"))) if x != y), None)
            differ.append((rel, line))
    print(f"compare: {len(same)} file(s) byte-identical (a TRC's own path aside), "
          f"{len(close)} simulated recording(s) or processed output(s) equal within the tolerances above but not to "
          f"the bit (the C library's sin, cos, acos and atan2), "
          f"{len(varying)} differing where runs always differ, "
          f"{len(differ)} differing otherwise, {len(only)} on one side only")
    for rel, why, lines_equal in varying:
        print(f"  varies  {rel}: {why}{'' if lines_equal else ' (and its line count differs)'}")
    for rel, line in differ:
        print(f"  DIFFERS {rel} (first at line {None if line is None else line + 1})")
    for rel in only:
        print(f"  ONLY    {rel} ({'Linux' if rel in linux else 'Windows'})")
    return 1 if differ or only or any(not eq for _, _, eq in varying) else 0


if __name__ == "__main__":
    sys.exit(main())
