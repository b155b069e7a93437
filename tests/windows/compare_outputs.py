#!/usr/bin/env python3
"""Compares the Linux lmc's outputs with the Windows lmc.exe's (tests/windows/run_under_wine.sh):
every file both wrote, byte for byte. Files whose bytes legitimately differ between any two runs
(times of day, process ids, paths as each system spells them) are listed in VARYING with why; for
them only the line count is compared. Exit 1 when any other file differs or exists on one side only.

usage: compare_outputs.py LINUX_DIR WINDOWS_DIR"""
import fnmatch
import os
import sys

# name pattern -> why its bytes differ between two runs on any system
VARYING = {
    "journal.jsonl": "UTC times of each event and the process id",
    "journal.cut-*": "named for the time of the cut",
    "manifest.txt": "written with the session's times",
    "*.sidecar.json": "host clock readings of the recording run",
    "session.json": "the input paths as each system spells them, and the run's times",
    "dataset_description.json": "the export's time",
    "*_scans.tsv": "acquisition times of day",
    "*.log": "run times",
}
SKIP_DIRS = {"cache"}


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
    same, varying, differ = [], [], []
    only = sorted(set(linux) ^ set(windows))
    for rel in sorted(set(linux) & set(windows)):
        a, b = open(linux[rel], "rb").read(), open(windows[rel], "rb").read()
        if a == b:
            same.append(rel)
            continue
        why = next((w for pat, w in VARYING.items() if fnmatch.fnmatch(os.path.basename(rel), pat)), None)
        if why is not None:
            varying.append((rel, why, a.count(b"\n") == b.count(b"\n")))
        else:
            line = next((i for i, (x, y) in enumerate(zip(a.split(b"\n"), b.split(b"\n"))) if x != y), None)
            differ.append((rel, line))
    print(f"compare: {len(same)} file(s) byte-identical, {len(varying)} differing where runs always differ, "
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
