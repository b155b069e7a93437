#!/usr/bin/env python3
"""core/README.md's floor table against core's real includes (called by check_layering.sh).

The table opens core/README.md: one row per folder, `| floor | `folder/` | holds |`. A folder's floor
is one above the highest floor it includes (floor 1 includes no other core folder), so the table
says both who may include whom and where a folder sits. Fails, naming the folder and the include,
when a folder is missing from the table, the table names a folder that does not exist, a folder
includes one on its own floor or above, or a folder sits on another floor than its includes put it.
"""
import pathlib
import re
import sys

ROW = re.compile(r"^\|\s*(\d+)\s*\|\s*`([a-z_]+)/`\s*\|")
INCLUDE = re.compile(r'^\s*#\s*include\s*"core/([a-z_]+)/', re.M)


def table_floors(readme):
    floors = {}
    for number, line in enumerate(readme.read_text(encoding="utf-8").splitlines(), 1):
        match = ROW.match(line)
        if match:
            floors[match.group(2)] = (int(match.group(1)), number)
    return floors


def folder_includes(folder):
    """{included folder: first file:line that includes it}, the folder itself left out."""
    found = {}
    for path in sorted(folder.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in INCLUDE.finditer(text):
            other = match.group(1)
            if other != folder.name and other not in found:
                line = text.count("\n", 0, match.start()) + 1
                found[other] = f"{path.relative_to(folder.parent.parent)}:{line}"
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    core, readme = root / "core", root / "core" / "README.md"
    floors = table_floors(readme)
    folders = sorted(p.name for p in core.iterdir() if p.is_dir())
    problems = []
    if not floors:
        problems.append(f"{readme}: no floor table (rows `| floor | `folder/` | holds |`)")
    for name in folders:
        if name not in floors:
            problems.append(f"core/{name}/ is not in core/README.md's floor table: add a row with its floor")
    for name, (_, line) in floors.items():
        if name not in folders:
            problems.append(f"core/README.md:{line}: core/{name}/ does not exist")
    for name in folders:
        if name not in floors:
            continue
        floor, line = floors[name]
        includes = folder_includes(core / name)
        lowest = 1
        for other, where in sorted(includes.items()):
            if other not in floors:
                continue
            other_floor = floors[other][0]
            lowest = max(lowest, other_floor + 1)
            if other_floor >= floor:
                problems.append(f"{where}: core/{name}/ (floor {floor}) includes core/{other}/ (floor {other_floor}): "
                                "a folder includes only floors below its own")
        if lowest < floor:  # above: the include that puts it higher is reported
            problems.append(f"core/README.md:{line}: core/{name}/ is on floor {floor} but its includes put it on "
                            f"floor {lowest} (one above the highest it includes): correct the table")
    for problem in problems:
        print(problem)
    count = max((f for f, _ in floors.values()), default=0)
    print(f"checked core's {len(folders)} folders against its {count}-floor table: "
          f"{'clean' if not problems else 'VIOLATIONS'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
