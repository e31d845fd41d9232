#!/usr/bin/env python3
"""The commands the shipped cases' comments show run as written.

usage: /usr/bin/python3 tests/scripts/case_comment_commands.py [CASES_DIR]

A case's header comment shows how to run it and draw the result, one command a line indented by
three spaces after '#':

    #   roughgas run cases/hcs_rough.toml --out out/hcs_rough
    #   scripts/python3 scripts/plot.py out/hcs_rough/moments.csv

Checked, for every such command of every cases/*.toml (without importing or running anything):
  - a `roughgas run|restitution` command names its own case file and an --out directory;
  - a script runs through scripts/python3 (the Python that has numpy, matplotlib and h5py), names
    an existing scripts/*.py, and gives only flags its usage line lists, and those the parser it
    builds (argparse's add_argument, when it uses argparse) accepts, each flag that takes a value
    with one; its first argument is the case's --out directory or a file in it.
Exit 1 listing every problem, or when no command is found.
"""
import ast
import glob
import os
import re
import shlex
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMMAND = re.compile(r"^#   (\S.*)$")


def script_flags(path):
    """(flags of the usage line with whether each takes a value, flags of its argparse parser or None)."""
    tree = ast.parse(open(path).read())
    doc = ast.get_docstring(tree) or ""
    usage = next((p for p in doc.split("\n\n") if "usage:" in p), "")
    documented = {}
    for m in re.finditer(r"(--[a-z][a-z-]*)( [A-Z{][^\]|]*)?", usage):
        documented[m.group(1)] = documented.get(m.group(1), False) or m.group(2) is not None
    parsed = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "attr", None) == "add_argument":
            parsed.update(a.value for a in node.args if isinstance(a, ast.Constant) and str(a.value).startswith("--"))
    return documented, parsed or None


def check_case(path):
    problems, commands = [], []
    out_dir = None
    for line_no, line in enumerate(open(path), 1):
        m = COMMAND.match(line.rstrip("\n"))
        if not m:
            continue
        where = f"{os.path.relpath(path, ROOT)}:{line_no}"
        words = shlex.split(m.group(1))
        if words[0] == "roughgas":
            commands.append(words)
            if len(words) < 3 or words[1] not in ("run", "restitution"):
                problems.append(f"{where}: {m.group(1)}: not roughgas run or restitution")
                continue
            if words[2] != os.path.join("cases", os.path.basename(path)):
                problems.append(f"{where}: {m.group(1)}: runs {words[2]}, not this case")
            if "--out" not in words[:-1]:
                problems.append(f"{where}: {m.group(1)}: no --out")
            else:
                out_dir = words[words.index("--out") + 1]
        elif words[0].startswith("scripts/"):
            commands.append(words)
            if words[0] != "scripts/python3" or len(words) < 2:
                problems.append(f"{where}: {m.group(1)}: a script runs as scripts/python3 scripts/NAME.py")
                continue
            script = os.path.join(ROOT, words[1])
            if not (words[1].startswith("scripts/") and words[1].endswith(".py") and os.path.isfile(script)):
                problems.append(f"{where}: {m.group(1)}: {words[1]} is not a script in scripts/")
                continue
            documented, parsed = script_flags(script)
            args = words[2:]
            positional = []
            i = 0
            while i < len(args):
                a = args[i]
                if a.startswith("--"):
                    if a not in documented or (parsed is not None and a not in parsed):
                        problems.append(f"{where}: {m.group(1)}: {words[1]} does not take {a}")
                    elif documented[a]:
                        if i + 1 == len(args) or args[i + 1].startswith("--"):
                            problems.append(f"{where}: {m.group(1)}: {a} without its value")
                        i += 1
                else:
                    positional.append(a)
                i += 1
            if out_dir is None:
                problems.append(f"{where}: {m.group(1)}: no roughgas command with --out before it")
            elif len(positional) != 1 or os.path.normpath(positional[0]).split(os.sep)[:len(
                    os.path.normpath(out_dir).split(os.sep))] != os.path.normpath(out_dir).split(os.sep):
                problems.append(f"{where}: {m.group(1)}: reads {positional}, not the run's {out_dir}")
        # other indented comment lines (a formula, a table) are not commands
    return problems, commands


def main(argv):
    cases = argv[1] if len(argv) > 1 else os.path.join(ROOT, "cases")
    problems, count = [], 0
    for path in sorted(glob.glob(os.path.join(cases, "*.toml"))):
        p, c = check_case(path)
        problems += p
        count += len(c)
    for p in problems:
        print(f"case_comment_commands: {p}", file=sys.stderr)
    if count == 0:
        print(f"case_comment_commands: no command in {cases}/*.toml", file=sys.stderr)
        return 1
    if problems:
        return 1
    print(f"case_comment_commands: {count} commands run as written")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
