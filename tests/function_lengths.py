#!/usr/bin/env python3
"""Lengths of the C++ functions under the given folders, by their definitions' first and last lines.

    tests/function_lengths.py [--over N] [--fail-over N] [--max-over-80 N] [FOLDER ...]

Prints every function longer than --over lines (default 80), longest first, as `lines file:first
name`, then how many are over 80 and over 150. --fail-over N fails when one is longer than N;
--max-over-80 N fails when more than N are over 80. A function is a brace block at namespace or
class scope whose head ends in a parameter list (lambdas and blocks inside a function count as part
of it); its first line is where its head begins, after the previous declaration. Comments, strings
and preprocessor lines are blanked first, so braces in them do not count.
"""
import argparse
import pathlib
import re
import sys

SCOPE_HEAD = re.compile(r"\b(namespace|class|struct|union|enum)\b[^;()]*$|\bextern\s*\"C\"\s*$|=\s*$|\)\s*=\s*$")
FUNCTION_HEAD = re.compile(r"\)[\s\w:&<>,*]*(->[^{;]*)?$|\)\s*:[^;]*$")
CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else)\b")


NOISE = re.compile(
    r"//[^\n]*|/\*.*?\*/|R\"([^(\s]*)\(.*?\)\1\"|\"(?:\\.|[^\"\\\n])*\"|(?<![0-9A-Za-z_])'(?:\\.|[^'\\\n])*'"
    r"|^[ \t]*#(?:[^\n]*\\\n)*[^\n]*",
    re.S | re.M,
)
EVENT = re.compile(r"[{};]|\b(?:public|private|protected)\s*:")


def blank(text):
    """Comments, string and character literals and preprocessor lines as spaces (newlines kept)."""
    return NOISE.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def functions(path):
    text = blank(path.read_text(encoding="utf-8", errors="replace"))
    found = []
    stack = []  # per open brace: ("scope" | "function" | "block", start offset of its head)
    head_start = 0  # where the current declaration at scope level began
    depth_in_function = 0  # open braces at and inside the current function body
    for match in EVENT.finditer(text):
        i, c = match.start(), match.group(0)
        in_function = depth_in_function > 0
        if c == "{":
            if in_function:
                stack.append(("block", i))
                depth_in_function += 1
                continue
            head = text[head_start:i].strip()
            if SCOPE_HEAD.search(head) or not head:
                stack.append(("scope", i))
                head_start = i + 1
            elif FUNCTION_HEAD.search(head) and not CONTROL.match(head):
                first = head_start + (len(text[head_start:i]) - len(text[head_start:i].lstrip()))
                stack.append(("function", first))
                depth_in_function = 1
            else:
                stack.append(("block", i))
        elif c == "}":
            if not stack:
                continue
            kind, first = stack.pop()
            if in_function:
                depth_in_function -= 1
            if kind == "function":
                first_line = text.count("\n", 0, first) + 1
                last_line = text.count("\n", 0, i) + 1
                name = re.search(r"([~\w:]+(?:operator\S*)?)\s*\(", text[first:i])
                found.append((last_line - first_line + 1, first_line, name.group(1) if name else "?"))
            if depth_in_function == 0:
                head_start = i + 1
        elif not in_function:  # ";" or an access specifier ends a declaration at scope level
            head_start = match.end()
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folders", nargs="*", default=["core", "devices", "app"])
    parser.add_argument("--over", type=int, default=80)
    parser.add_argument("--fail-over", type=int)
    parser.add_argument("--max-over-80", type=int)
    parser.add_argument("--root", default=".")
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    rows = []
    for folder in args.folders:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix in (".h", ".cpp"):
                for lines, first, name in functions(path):
                    rows.append((lines, f"{path.relative_to(root)}:{first}", name))
    rows.sort(key=lambda r: (-r[0], r[1]))
    for lines, where, name in rows:
        if lines > args.over:
            print(f"{lines:5d} {where} {name}")
    over80 = sum(1 for r in rows if r[0] > 80)
    over150 = sum(1 for r in rows if r[0] > 150)
    print(f"{len(rows)} functions in {', '.join(args.folders)}: {over80} over 80 lines, {over150} over 150")
    status = 0
    if args.fail_over is not None and rows and rows[0][0] > args.fail_over:
        print(f"FAILED: a function is longer than {args.fail_over} lines")
        status = 1
    if args.max_over_80 is not None and over80 > args.max_over_80:
        print(f"FAILED: {over80} functions are over 80 lines (at most {args.max_over_80})")
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
