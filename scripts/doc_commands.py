#!/usr/bin/env python3
"""Runs the shell commands that README.md and docs/*.md show as runnable, as they are shown.

usage: scripts/python3 scripts/doc_commands.py [--build BUILD_DIR] [--particles N] [--timeout S]
                                               [--keep] [--list] [FILE.md ...]

The convention: a fenced ```sh block is runnable when the line directly before its opening fence is

    <!-- runnable -->

(an HTML comment, invisible in the rendered page; no blank line between it and the fence). Every
other ```sh block is an illustration (a synopsis with [OPTIONS], a command that takes hours) and is
not run. Markers inside another fenced block are text, not markers. A marker that is not directly
followed by a ```sh fence is an error, and so is a run that finds no runnable block in any file:
a formatting slip must not make the check pass by running nothing.

One fresh scratch directory per Markdown file (deleted at the end unless --keep) holds
  cases/, scripts/   symlinks to the source tree's folders,
  build/roughgas     a bash wrapper that execs BUILD_DIR/roughgas with the same arguments, but for
                     `run` and `sweep` (not `run --resume`, not --help) appends
                     `--set run.particles=N` (--particles, default 2000), so that the documented
                     commands run with few particles; the last --set of a key wins, so this
                     overrides a particle count the command gives itself.
The file's runnable blocks run there in document order, each as `bash -euo pipefail -c BLOCK`
with the scratch directory as working directory, the environment unchanged but
OMP_WAIT_POLICY=passive, and a time limit (--timeout, default 300 s per block). A block may use
what an earlier block of the same file wrote (a plot after a run); blocks of different files see
nothing of each other. Documented commands therefore write relative paths (out/...), read cases/
and scripts/, and call build/roughgas.

Per block one line: FILE:LINE of the opening fence, the block's first command, wall time and exit
status. Every block runs even after a failure; each failure is reported with the block and the
tails of its stdout and stderr, and the exit status is 1. --list only prints the blocks found
(exit 1 on a misplaced marker or when there are none).
Default files: README.md and docs/*.md of the source tree this script is in.
"""
import argparse
import glob
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MARKER = "<!-- runnable -->"
TAIL_LINES = 30  # of stdout and of stderr, for a failed block

WRAPPER = """#!/usr/bin/env bash
# build/roughgas of scripts/doc_commands.py: {real} with run.particles={particles} for new runs and sweeps.
real={real_q}
case "${{1-}}" in
  run|sweep)
    for a in "$@"; do
      case "$a" in --resume|--resume=*|-h|--help) exec "$real" "$@" ;; esac
    done
    exec "$real" "$@" --set run.particles={particles} ;;
esac
exec "$real" "$@"
"""


class Block:
    def __init__(self, path, line, text):
        self.path = path  # as displayed
        self.line = line  # 1-based line of the opening fence
        self.text = text

    def where(self):
        return f"{self.path}:{self.line}"

    def first_command(self):
        for s in self.text.splitlines():
            s = s.strip()
            if s and not s.startswith("#"):
                return s
        return "(empty)"


def fence_open(stripped):
    """(fence characters, info string) when the line opens a fenced code block, else None."""
    for ch in "`~":
        if stripped.startswith(ch * 3):
            n = len(stripped) - len(stripped.lstrip(ch))
            info = stripped[n:].strip()
            if ch == "`" and "`" in info:
                return None  # inline code, not a fence
            return ch * n, info
    return None


def is_fence_close(stripped, fence):
    return stripped.startswith(fence) and stripped.strip(fence[0]) == ""


def parse(path, shown):
    """The runnable blocks of one Markdown file, and the errors found (misplaced markers,
    unterminated runnable blocks)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    blocks, errors = [], []
    fence = None  # the open fence of the block we are in, if any
    i = 0
    while i < len(lines):
        s = lines[i].strip()
        if fence is not None:
            if is_fence_close(s, fence):
                fence = None
            i += 1
            continue
        if s == MARKER:
            nxt = lines[i + 1].strip() if i + 1 < len(lines) else ""
            opened = fence_open(nxt)
            if opened is None or opened[0][0] != "`" or opened[1].split()[:1] != ["sh"]:
                errors.append(f"{shown}:{i + 1}: '{MARKER}' is not directly followed by a ```sh fence "
                              f"(next line: {nxt!r})")
                i += 1
                continue
            start, body = i + 2, []
            j = start
            while j < len(lines) and not is_fence_close(lines[j].strip(), opened[0]):
                body.append(lines[j])
                j += 1
            if j == len(lines):
                errors.append(f"{shown}:{i + 2}: runnable ```sh block is not closed")
                break
            blocks.append(Block(shown, i + 2, textwrap.dedent("\n".join(body)) + "\n"))
            i = j + 1
            continue
        opened = fence_open(s)
        if opened is not None:
            fence = opened[0]
        i += 1
    return blocks, errors


def make_scratch(roughgas, particles):
    d = tempfile.mkdtemp(prefix="doc_commands.")
    for name in ("cases", "scripts"):
        os.symlink(os.path.join(ROOT, name), os.path.join(d, name))
    os.mkdir(os.path.join(d, "build"))
    wrapper = os.path.join(d, "build", "roughgas")
    real_q = "'" + roughgas.replace("'", "'\\''") + "'"
    with open(wrapper, "w") as f:
        f.write(WRAPPER.format(real=roughgas, real_q=real_q, particles=particles))
    os.chmod(wrapper, 0o755)
    return d


def run_block(block, cwd, env, timeout):
    """(exit status or None on timeout, stdout, stderr, seconds). The block runs in its own
    process group, so that a timeout ends everything it started."""
    t0 = time.monotonic()
    p = subprocess.Popen(["bash", "-euo", "pipefail", "-c", block.text], cwd=cwd, env=env,
                         stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, errors="replace", start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
        status = p.returncode
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = p.communicate()
        status = None
    return status, out, err, time.monotonic() - t0


def tail(text, n=TAIL_LINES):
    lines = text.rstrip("\n").splitlines()
    cut = lines[-n:]
    head = [f"    ... ({len(lines) - n} lines before)"] if len(lines) > n else []
    return "\n".join(head + ["    " + s for s in cut]) if cut else "    (empty)"


def shown_path(path):
    a = os.path.abspath(path)
    return os.path.relpath(a, ROOT) if a.startswith(ROOT + os.sep) else path


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="*", metavar="FILE.md", help="default: README.md and docs/*.md")
    ap.add_argument("--build", default="build", metavar="BUILD_DIR", help="build directory holding roughgas (default: build)")
    ap.add_argument("--particles", type=int, default=2000, metavar="N", help="run.particles of run and sweep (default 2000)")
    ap.add_argument("--timeout", type=float, default=300.0, metavar="S", help="seconds per block (default 300)")
    ap.add_argument("--keep", action="store_true", help="keep the scratch directories (their paths are printed)")
    ap.add_argument("--list", action="store_true", help="only print the runnable blocks found")
    a = ap.parse_args()
    if a.particles < 1:
        ap.error("--particles must be positive")

    files = a.files or [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
    per_file, errors = [], []
    for path in files:
        if not os.path.isfile(path):
            errors.append(f"{path}: no such file")
            continue
        blocks, errs = parse(path, shown_path(path))
        per_file.append((path, blocks))
        errors += errs
    total = sum(len(b) for _, b in per_file)
    if total == 0:
        errors.append(f"no runnable block (a ```sh fence directly after '{MARKER}') in "
                      + ", ".join(shown_path(p) for p in files))

    if a.list:
        for _, blocks in per_file:
            for b in blocks:
                print(f"{b.where()}:")
                print(textwrap.indent(b.text.rstrip("\n"), "    "))
        print(f"{total} runnable block(s) in {len(per_file)} file(s)", flush=True)
        for e in errors:
            print(f"error: {e}", file=sys.stderr)
        return 1 if errors else 0

    roughgas = os.path.join(os.path.abspath(a.build), "roughgas")
    if not os.access(roughgas, os.X_OK):
        print(f"error: {roughgas} is not an executable (--build)", file=sys.stderr)
        return 1
    env = dict(os.environ, OMP_WAIT_POLICY="passive")
    failures = []
    for path, blocks in per_file:
        if not blocks:
            continue
        scratch = make_scratch(roughgas, a.particles)
        try:
            for b in blocks:
                status, out, err, secs = run_block(b, scratch, env, a.timeout)
                verdict = f"exit {status}" if status is not None else f"timeout after {a.timeout:g} s"
                ok = status == 0
                print(f"{'ok  ' if ok else 'FAIL'} {b.where()}  {b.first_command()}  ({secs:.1f} s, {verdict})",
                      flush=True)
                if not ok:
                    failures.append(b)
                    print(textwrap.indent(b.text.rstrip("\n"), "  | "))
                    print(f"  stdout (last {TAIL_LINES} lines):\n{tail(out)}")
                    print(f"  stderr (last {TAIL_LINES} lines):\n{tail(err)}", flush=True)
        finally:
            if a.keep:
                print(f"  scratch directory of {shown_path(path)}: {scratch}")
            else:
                shutil.rmtree(scratch, ignore_errors=True)

    print(f"{total} runnable block(s), {len(failures)} failed"
          + (f": {', '.join(b.where() for b in failures)}" if failures else ""), flush=True)
    for e in errors:
        print(f"error: {e}", file=sys.stderr)
    return 1 if failures or errors else 0


if __name__ == "__main__":
    sys.exit(main())
