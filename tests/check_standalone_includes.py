#!/usr/bin/env python3
"""Compiles every first-party source file of a configured build on its own (-fsyntax-only).

A unity batch compiles several files as one, so a file that uses a name without including its
header builds as long as an earlier file of its batch includes that header; another batch size (the
release preset's 8 against the check preset's 32) or another compiler then fails on it. Here each
file is compiled alone, with its target's own flags as compile_commands.json gives them, so every
build configuration's batches can only hold files that stand alone.

The shared precompiled header stays in: every build configuration includes it, so what it brings
(Eigen, the JSON library, a few standard headers) is part of every file as the project builds it.

Each file takes seconds (the whole tree about 20 minutes of CPU), so ctest runs the quick reading
of the same rule (check_includes.py) and this is for a change's files before it lands:
    tests/check_standalone_includes.py build/check --changed main

Usage: check_standalone_includes.py BUILD_DIR [--jobs N] [--list] [--changed REF] [FILE_REGEX]
Exit status: 0 when every file compiles alone, 1 when one does not (its errors are printed), 2 for
a build folder without compile_commands.json.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

# Flags that name the output or its dependency file: a syntax check writes neither.
DROP_WITH_VALUE = {"-o", "-c", "-MT", "-MF", "-MQ"}
DROP_ALONE = {"-MD", "-MMD"}


def sources_of(entry):
    """The first-party files one compile_commands entry compiles: a unity batch's included files,
    or the entry's own file."""
    path = Path(entry["file"])
    if not path.is_absolute():
        path = Path(entry["directory"]) / path
    if "/Unity/unity_" in str(path):
        included = re.findall(r'^#include "([^"]+)"', path.read_text(), re.MULTILINE)
        return [Path(p) for p in included]
    return [path]


def standalone_command(entry, source):
    args = entry.get("arguments") or shlex.split(entry["command"])
    out, skip = [], False
    batch_file = entry["file"]
    for a in args:
        if skip:
            skip = False
            continue
        if a in DROP_WITH_VALUE:
            skip = True
            continue
        if a in DROP_ALONE or a == batch_file:
            continue
        out.append(a)
    return out + ["-fsyntax-only", str(source)]


def collect(build_dir, source_dir):
    db = json.loads((build_dir / "compile_commands.json").read_text())
    jobs = {}
    for entry in db:
        for src in sources_of(entry):
            src = src.resolve()
            # First-party files only: generated anchors and Debian's sources are not ours to check.
            if build_dir in src.parents or source_dir not in src.parents:
                continue
            jobs.setdefault(src, (entry["directory"], standalone_command(entry, src)))
    return jobs


def check(job):
    src, (directory, cmd) = job
    r = subprocess.run(cmd, cwd=directory, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return src, r.returncode, r.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build_dir", type=Path)
    ap.add_argument("file_regex", nargs="?", default="", help="only files whose path matches")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--list", action="store_true", help="print the files and their commands, compile nothing")
    ap.add_argument("--changed", metavar="REF", help="only the files that differ from git REF (and the working tree's)")
    a = ap.parse_intermixed_args()
    build_dir = a.build_dir.resolve()
    if not (build_dir / "compile_commands.json").is_file():
        print(f"check_standalone_includes: {build_dir}/compile_commands.json not found (configure first)",
              file=sys.stderr)
        return 2
    source_dir = Path(__file__).resolve().parent.parent
    jobs = sorted(collect(build_dir, source_dir).items())
    if a.file_regex:
        jobs = [j for j in jobs if re.search(a.file_regex, str(j[0]))]
    if a.changed:
        names = subprocess.run(["git", "diff", "--name-only", a.changed], cwd=source_dir, capture_output=True,
                               text=True, check=True).stdout.split()
        changed = {(source_dir / n).resolve() for n in names}
        jobs = [j for j in jobs if j[0] in changed]
    if a.list:
        for src, (_, cmd) in jobs:
            print(src.relative_to(source_dir), " ".join(cmd))
        return 0
    failed = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        for src, status, output in pool.map(check, jobs):
            if status != 0:
                failed.append(src)
                print(f"--- {src.relative_to(source_dir)} does not compile on its own:\n{output}")
    if failed:
        print(f"check_standalone_includes: {len(failed)} of {len(jobs)} files do not compile on their own "
              "(each must include the headers of every name it uses): " +
              ", ".join(str(f.relative_to(source_dir)) for f in failed))
        return 1
    print(f"check_standalone_includes: all {len(jobs)} files compile on their own")
    return 0


if __name__ == "__main__":
    sys.exit(main())
