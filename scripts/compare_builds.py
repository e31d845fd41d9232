#!/usr/bin/env python3
"""Runs a fixed set of scenarios with two roughgas binaries, OLD and NEW, and compares what they
write byte for byte: the check that a change meant to keep every output (a restructuring, a
speed-up) kept them.

usage: scripts/python3 scripts/compare_builds.py --old OLD_BINARY --new NEW_BINARY [--work DIR] [--keep]
                                                 [--only PATTERN] [--jobs N]
       scripts/python3 scripts/compare_builds.py --list [--only PATTERN]

Each scenario runs its commands with OLD in WORK/old/SCENARIO and with NEW in WORK/new/SCENARIO, the
working directory of each command (case files and output directories are named relative to it, so
both trees hold the same paths), then compares the two trees: the same set of files, each file the
same bytes: the CSVs, checkpoint/, state/, the cell fields' HDF5 files, the table cache file. A
text file that differs is reported with its first differing line (and a CSV row with the column),
any other file with its first differing byte. Compared after a substitution:
  RGTCACHE files the restitution table cache (contact.cache_file) stores each table's build time
                 in seconds: those doubles and the checksum over them are zeroed, once the checksum
                 has been verified.
The HDF5 files are compared as bytes (roughgas writes no time stamps into them); when two differ,
h5py (where installed) also tells whether their datasets and attributes are equal.

Each command's exit status, stdout and stderr (its transcript) are compared too, with the tree's
root replaced by "<root>" and the binary's path by "<roughgas>" (also the program name in --help's
"Usage:" line), and with these numbers and orders, which depend on timing, masked:
  - progress lines ("roughgas run: 12.3%  4.5e+06 collisions/s  3s elapsed  20s to go"; every 10 s
    and at the end): each becomes "<progress>", consecutive ones one line;
  - the seconds and the rate of "N collisions in S s (R collisions/s; kernel K)" (N and K kept);
  - the seconds of "built in S s" (restitution tables);
  - for a run stopped by a signal and for its resume only: the number of complete rows at the stop
    and the collisions the resumed run did (both depend on when the signal came);
  - sweep's "point K (...) done" lines, which come in the order the points finish: sorted by K;
  - under mpirun with several ranks, stderr's lines, which reach mpirun from the ranks in any
    order: compared sorted.
Each exit status must also be the one the scenario expects (0; 2 for a refusal; 143 for a run
stopped by SIGTERM): a scenario whose commands fail alike with both binaries proves nothing and is
reported as ERROR.

Scenarios (--list prints them with their commands; --only takes shell patterns, comma-separated,
matched against the names):
  case/NAME      each cases/*.toml, run with --set reductions to take a few seconds: fewer grains,
                 shorter runs, smaller boxes with cells of the same size in mean free paths,
                 replicas and histograms on some (CASE_SETS below). case/ice builds the brilliantov
                 tables into a cache file in its tree, runs again with the tables from the file and
                 runs `roughgas restitution` on a small grid (tables from the file too); the other
                 brilliantov cases integrate every contact directly (collision.direct), since the
                 eps^T table takes 15-120 s to build whatever the run's size.
  initial_from   a homogeneous run saving its state (run.save_state), then a box starting from it
                 (initial.from)
  sweep          `roughgas sweep` over alpha: a shear case (steady.csv) and a mixture (scaled.csv)
  merge          `run --replicas` ranges merged by `roughgas merge`: a homogeneous run with
                 histograms and a box with cell fields
  check          `roughgas check` and `check --print` of each shipped case; refusals of check,
                 run, sweep and merge (unknown key or option, values out of range, missing files);
                 `keys`, `--help`, `--version`
  resume/NAME    a run with --checkpoint-every stopped by SIGTERM once its first checkpoint exists,
                 then `run --resume` to the end, beside the same run never stopped; and in
                 WORK/cross/NAME OLD's stopped run resumed by NEW, which must equal OLD's run never
                 stopped (NEW continues OLD's checkpoints). NAME: cooling (replicas in turns,
                 histograms), box (cell fields, spectra).
  mpi/npR        a run of 5 replicas with histograms under `mpirun -np R`, R = 1, 2, 3
  mpi/sweep_np2  the shear sweep under `mpirun -np 2`
The mpi scenarios are skipped (SKIP) when mpirun is not on PATH; they run as tests/e2e/mpi_test.cpp
does: --oversubscribe, --bind-to none, root allowed, one thread per rank.

Every command runs with --threads 2 (under mpirun 1), OMP_WAIT_POLICY=passive, OMP_NUM_THREADS unset
and no standard input. WORK (--work, which must be empty or new; default a new temporary directory)
is removed at the end unless --keep; it holds a copy of cases/, the trees, and logs/SIDE/SCENARIO.log
with each command's raw transcript. --jobs N runs N scenarios at a time (each command has 2
threads: on 2 cores keep N = 1).

Output: one line per scenario, OK, DIFF, ERROR or SKIP with its wall time, each DIFF or ERROR
followed by what differs or failed; then the totals. Exit status 0 when no scenario was DIFF or
ERROR, 1 otherwise, 2 for bad usage (an unknown option, a binary that is not executable, a pattern
that matches nothing, a --work directory that is not empty). Old against old takes 1.5 to 2 minutes
on 2 cores (87, 91 and 106 s measured), a third of it the brilliantov tables of case/ice.
"""
import argparse
import fnmatch
import os
import re
import shlex
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
THREADS = "2"
COMMAND_TIMEOUT = 600.0  # seconds per command
STOP_POLL = 0.01  # seconds between looks for the file a stop waits for
MAX_REPORTED = 12  # differences listed per scenario

ENV = {**os.environ, "OMP_WAIT_POLICY": "passive",
       # mpirun as root and with more ranks than cores, as tests/e2e/mpi_test.cpp runs it
       "OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
       "OMPI_MCA_rmaps_base_oversubscribe": "1"}
ENV.pop("OMP_NUM_THREADS", None)  # every command says --threads

# --set reductions of the shipped cases: each runs in a few seconds and is accepted as it is (a box
# keeps its cells at about the same fraction of a mean free path, so the smaller box has fewer cells,
# and enough grains per cell). A case not named here runs with DEFAULT_SETS (one that refuses them
# shows as ERROR, its refusal quoted: give it an entry). The brilliantov model's eps^T table takes
# 15-120 s to build whatever the run's size: cases/ice.toml builds it (into a cache file in its
# tree, then runs again from the file); the other brilliantov cases integrate each contact directly
# (collision.direct), with few collisions (ice_fig2a's tiny asperities cost about 0.1 s per contact).
DEFAULT_SETS = ["run.particles=20000", "run.end=20"]
# A sweep of a shear case (two of its three points reach their steady state).
SWEEP_SETS = ["run.particles=5000", "run.end=100", "run.replicas=2"]
RESTITUTION_GRID = ["restitution.g_n_points=8", "restitution.g_t_points=6"]
DIRECT = ["collision.direct=true", "run.particles=2000", "run.end=4"]
BOX_3D = ["domain.size=[171.0, 171.0, 171.0]", "domain.cells=[16, 16, 16]"]
SLAB = ["domain.size=[237.5, 237.5, 4.5]", "domain.cells=[50, 50, 1]", "run.particles=25000"]
WALLS = ["run.particles=10000", "run.end=60", "run.replicas=2"]
CASE_SETS = {
    "box_cooling_3d": BOX_3D + ["run.particles=40000", "run.end=20", "run.output_every=2", "run.replicas=2",
                                "fields.every=2", "fields.replicas=2"],
    "box_cooling_3d_medium_roughness": BOX_3D + ["run.particles=40000", "run.end=12", "run.output_every=2",
                                                 "fields.every=3"],
    "box_cooling_3d_strong_roughness": BOX_3D + ["run.particles=40000", "run.end=12", "run.output_every=2",
                                                 "fields.every=3"],
    "box_cooling_slab": SLAB + ["run.end=20", "run.output_every=2", "fields.every=3"],
    "box_cooling_slab_medium_roughness": SLAB + ["run.end=12", "run.output_every=2", "fields.every=3"],
    "box_cooling_slab_strong_roughness": SLAB + ["run.end=12", "run.output_every=2", "run.replicas=2",
                                                 "fields.every=3"],
    "box_couette": WALLS,
    "box_fourier": WALLS,
    "box_conductivity_fourier": WALLS,
    "box_heated_bed": WALLS,
    "box_thermal_walls": WALLS,
    "box_hcs_rough": ["run.particles=40000", "run.end=20", "run.replicas=3"],
    "box_shear_mode": ["domain.size=[135.0, 11.25, 11.25]", "domain.cells=[60, 3, 3]", "run.particles=20000",
                       "run.end=20"],
    "box_usf": ["run.particles=30000", "run.end=30", "run.replicas=2"],
    "hcs_brilliantov": DIRECT,
    "hcs_mixture": ["run.particles=20000", "run.end=60", "run.histogram_every=1.0", "run.histogram_spacing=log",
                    "run.histogram_bins=20"],
    "hcs_rough": ["run.particles=40000", "run.end=60", "run.replicas=3", "run.histogram_every=20"],
    "hcs_smooth": ["run.particles=40000", "run.end=100"],
    "hcs_viscoelastic_ice": ["run.particles=20000", "run.end=60"],
    "ice": ["run.particles=20000", "run.end=20", "contact.cache_file=ice_tables.bin"],
    "ice_fig2a": ["collision.direct=true", "run.particles=40"],
    "ice_fig2b": DIRECT,
    "ice_fig2c": DIRECT,
    "usf_brilliantov": ["collision.direct=true", "run.particles=2000", "run.end=10"],
    "usf_mixture": ["run.particles=20000", "run.end=60"],
    "usf_rough": ["run.particles=20000", "run.end=60", "run.histogram_every=20"],
    "usf_smooth": ["run.particles=20000", "run.end=60"],
    "usf_viscoelastic_ice": ["run.particles=10000", "run.end=60"],
}


class Step:
    """One command of a scenario. `args` follow the binary (or mpirun's options and the binary);
    `expect` is the exit status it must have; `stop` = (signal, path): the signal is sent once the
    path (relative to the working directory) exists; `stop_point` marks a transcript whose counts
    depend on when a stop came (masked); `binary` = "old" or "new" fixes the binary of a step of the
    cross tree."""

    def __init__(self, args, expect=0, ranks=0, stop=None, stop_point=False, binary=None):
        self.args, self.expect, self.ranks = args, expect, ranks
        self.stop, self.stop_point, self.binary = stop, stop_point, binary

    def shown(self):
        """The command as a report shows it (the cases as cases/NAME.toml)."""
        pre = ["mpirun", "-np", str(self.ranks)] if self.ranks else []
        who = f"[{self.binary.upper()}] " if self.binary else ""
        args = [shlex.quote(a.replace("{cases}", "cases")) for a in self.args]
        stop = f"  ({signal.Signals(self.stop[0]).name} once {self.stop[1]} exists)" if self.stop else ""
        return who + " ".join(pre + ["roughgas"] + args) + stop


class Scenario:
    """Steps run in WORK/old/NAME and WORK/new/NAME, compared; `cross` steps run in WORK/cross/NAME,
    and each pair of `cross_pairs` (a directory of the old tree, the same of the cross tree) must be
    the same files."""

    def __init__(self, name, what, steps, cross=(), cross_pairs=(), needs_mpi=False):
        self.name, self.what, self.steps = name, what, steps
        self.cross, self.cross_pairs, self.needs_mpi = list(cross), list(cross_pairs), needs_mpi


def case(name):
    """A shipped case, as the commands name it ({cases} becomes the path of WORK/cases from the
    command's working directory)."""
    return "{cases}/" + name + ".toml"


def sets(items):
    out = []
    for s in items:
        out += ["--set", s]
    return out


def run(case_name, out, extra=(), expect=0, **kw):
    return Step(["run", case(case_name), "--out", out, "--threads", THREADS] + list(extra), expect, **kw)


def shipped_cases():
    return sorted(os.path.splitext(f)[0] for f in os.listdir(os.path.join(ROOT, "cases")) if f.endswith(".toml"))


def case_scenarios():
    out = []
    for name in shipped_cases():
        reduction = CASE_SETS.get(name, DEFAULT_SETS)
        steps = [run(name, name, sets(reduction))]
        what = " ".join(reduction)
        if any(s.startswith("contact.cache_file=") for s in reduction):
            # Again with the tables from the cache file the first run wrote, and `roughgas restitution`
            # of the case on a small grid, its tables from the file too.
            steps += [run(name, name + "_cached", sets(reduction)),
                      Step(["restitution", case(name), "--out", "restitution", "--threads", THREADS]
                           + sets(reduction + RESTITUTION_GRID))]
            what += "; run again from the cache file; restitution " + " ".join(RESTITUTION_GRID)
        out.append(Scenario("case/" + name, what, steps))
    return out


# The runs stopped by a signal: each long enough (a few seconds) that the signal, sent once the
# first checkpoint exists, comes well before the end. (case, reductions, --checkpoint-every, signal)
RESUME_CASES = {
    "cooling": ("hcs_rough", ["run.particles=50000", "run.end=40", "run.replicas=3", "run.histogram_every=10"], "2",
                signal.SIGTERM),
    "box": ("box_cooling_3d", BOX_3D + ["run.particles=50000", "run.end=24", "run.output_every=2", "run.replicas=2",
                                        "fields.every=2", "fields.replicas=2"], "2", signal.SIGINT),
}


def resume_scenarios():
    out = []
    for key, (name, reduction, every, sig) in RESUME_CASES.items():
        opts = sets(reduction) + ["--checkpoint-every", every]
        stopped = 128 + sig
        steps = [run(name, "full", opts),
                 run(name, "stopped", opts, expect=stopped, stop=(sig, "stopped/checkpoint/replica_0.bin"),
                     stop_point=True),
                 Step(["run", "--resume", "stopped", "--threads", THREADS], stop_point=True)]
        # OLD's stopped run is in a directory named "full" too: what names its directory (the XDMF
        # sidecars, stdout) then compares with the old tree's run never stopped.
        cross = [run(name, "full", opts, expect=stopped, stop=(sig, "full/checkpoint/replica_0.bin"), stop_point=True,
                     binary="old"),
                 Step(["run", "--resume", "full", "--threads", THREADS], stop_point=True, binary="new")]
        out.append(Scenario("resume/" + key, f"{name} {' '.join(reduction)} --checkpoint-every {every}, stopped by "
                            f"{signal.Signals(sig).name}", steps, cross, [("full", "full")]))
    return out


def mpi_scenarios():
    reduction = ["run.particles=20000", "run.end=30", "run.replicas=5", "run.histogram_every=10"]
    out = []
    for ranks in (1, 2, 3):
        out.append(Scenario(f"mpi/np{ranks}", "hcs_rough reduced: " + " ".join(reduction),
                            [Step(["run", case("hcs_rough"), "--out", "run", "--threads", "1"] + sets(reduction),
                                  ranks=ranks)], needs_mpi=True))
    out.append(Scenario("mpi/sweep_np2", "usf_rough over collision.alpha=0.6:0.9:3, " + " ".join(SWEEP_SETS),
                        [Step(["sweep", case("usf_rough"), "--param", "collision.alpha=0.6:0.9:3", "--out", "sweep",
                               "--threads", "1"] + sets(SWEEP_SETS), ranks=2)], needs_mpi=True))
    return out


def other_scenarios():
    out = []
    aged = ["run.particles=20000", "run.end=10", "run.save_state=true", "run.replicas=2"]
    box = ["run.particles=20000", "run.end=10", "run.replicas=3", "initial.from=aged", "collision.beta=1.0"]
    out.append(Scenario("initial_from", f"hcs_rough {' '.join(aged)}; box_hcs_rough {' '.join(box)}",
                        [run("hcs_rough", "aged", sets(aged)), run("box_hcs_rough", "box", sets(box))]))
    mixture = ["run.particles=5000", "run.end=60", "run.replicas=2"]
    out.append(Scenario("sweep", f"usf_rough over collision.alpha=0.6:0.9:3, {' '.join(SWEEP_SETS)}; hcs_mixture "
                        f"over pair.1.alpha=0.6:0.9:3, {' '.join(mixture)}",
                        [Step(["sweep", case("usf_rough"), "--param", "collision.alpha=0.6:0.9:3", "--out", "shear",
                               "--threads", THREADS] + sets(SWEEP_SETS)),
                         Step(["sweep", case("hcs_mixture"), "--param", "pair.1.alpha=0.6:0.9:3", "--out",
                               "cooling", "--threads", THREADS] + sets(mixture))]))
    hom = ["run.particles=20000", "run.end=30", "run.replicas=4", "run.histogram_every=10"]
    box = BOX_3D + ["run.particles=20000", "run.end=10", "run.output_every=2", "run.replicas=3",
                    "fields.every=2", "fields.replicas=3"]
    steps = []
    for name, reduction, prefix in (("hcs_rough", hom, "hcs"), ("box_cooling_3d", box, "box")):
        steps += [run(name, f"{prefix}_a", sets(reduction) + ["--replicas", "0:2"]),
                  run(name, f"{prefix}_b", sets(reduction) + ["--replicas", f"2:{replicas_of(reduction)}"]),
                  Step(["merge", f"{prefix}_a", f"{prefix}_b", "--out", f"{prefix}_merged", "--threads", THREADS])]
    out.append(Scenario("merge", f"hcs_rough {' '.join(hom)}; box_cooling_3d {' '.join(box)}; ranges 0:2 and 2:R",
                        steps))
    out.append(check_scenario())
    return out


def replicas_of(reduction):
    return next(s.split("=")[1] for s in reduction if s.startswith("run.replicas="))


def check_scenario():
    steps = [Step(["--version"]), Step(["--help"]), Step(["run", "--help"]), Step(["keys"]),
             Step(["keys", "--output"]), Step(["keys", "--cli"])]
    for name in shipped_cases():
        steps += [Step(["check", case(name)]), Step(["check", case(name), "--print"])]
    steps += [
        Step(["check", case("ice"), "--for", "restitution"]),
        Step(["check", case("hcs_rough"), "--for", "restitution"], expect=2),
        Step(["check", case("hcs_rough"), "--set", "collision.alpha=1.3"], expect=2),
        Step(["check", case("hcs_rough"), "--set", "run.particlez=5"], expect=2),
        Step(["check", case("hcs_rough"), "--set", "run.end=-1"], expect=2),
        Step(["check", case("hcs_rough"), "--set", "collision.model=elastic"], expect=2),
        Step(["check", case("box_hcs_rough"), "--set", "domain.cells=[2, 2, 2]"], expect=2),
        Step(["check", case("no_such_case")], expect=2),
        Step(["run", case("hcs_rough"), "--out", "refused", "--set", "species.0.radius=-1"], expect=2),
        Step(["run", case("hcs_rough"), "--out", "refused", "--threadz", "2"], expect=2),
        Step(["run", "--resume", "no_such_run"], expect=2),
        Step(["sweep", case("hcs_rough"), "--param", "collision.alpha=0.5:1.5:3", "--out", "refused"], expect=2),
        Step(["merge", "no_such_range", "--out", "refused"], expect=2),
    ]
    return Scenario("check", "check, check --print of every case; refusals; keys, --help, --version", steps)


def all_scenarios():
    return case_scenarios() + other_scenarios() + resume_scenarios() + mpi_scenarios()


# ---- running ----------------------------------------------------------------------------------------

class Transcript:
    def __init__(self, step, status, out, err, seconds, note=""):
        self.step, self.status, self.out, self.err, self.seconds, self.note = step, status, out, err, seconds, note


_running = set()  # the commands running now (Popen), ended on Ctrl-C
_running_lock = threading.Lock()
_stopping = threading.Event()  # set on Ctrl-C: no command starts any more


def end_group(p, grace=5.0):
    """Ends a command's process group: SIGTERM (roughgas stops at its next step; mpirun passes it on
    to the ranks), then SIGKILL after `grace` seconds."""
    for sig, wait in ((signal.SIGTERM, grace), (signal.SIGKILL, None)):
        try:
            os.killpg(p.pid, sig)
        except ProcessLookupError:
            return
        try:
            p.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            pass


def run_step(step, binary, cwd, case_dir, mpirun):
    """Runs one step in `cwd` to its end (at most COMMAND_TIMEOUT): its Transcript. A stop step gets
    its signal once its file exists; the note says when the command ended before that, or was ended."""
    args = [a.replace("{cases}", case_dir) for a in step.args]
    launcher = [mpirun, "--oversubscribe", "--bind-to", "none", "-np", str(step.ranks)] if step.ranks else []
    t0 = time.monotonic()
    note = ""
    with open(os.devnull) as devnull, tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        with _running_lock:
            if _stopping.is_set():
                raise KeyboardInterrupt
            # A session of its own: a stop signal reaches the command alone, and a timeout or Ctrl-C
            # ends all that it started.
            p = subprocess.Popen(launcher + [binary] + args, cwd=cwd, env=ENV, stdin=devnull, stdout=out,
                                 stderr=err, start_new_session=True)
            _running.add(p)
        try:
            if step.stop:
                sig, path = step.stop
                while p.poll() is None and not os.path.exists(os.path.join(cwd, path)):
                    if time.monotonic() - t0 > COMMAND_TIMEOUT:
                        break
                    time.sleep(STOP_POLL)
                if p.poll() is None:
                    p.send_signal(sig)
                else:
                    note = f"it ended before {path} existed: no {signal.Signals(sig).name} was sent"
            try:
                status = p.wait(timeout=max(1.0, COMMAND_TIMEOUT - (time.monotonic() - t0)))
            except subprocess.TimeoutExpired:
                end_group(p)
                status = p.wait()
                note = f"ended after {COMMAND_TIMEOUT:g} s"
        finally:
            with _running_lock:
                _running.discard(p)
        if _stopping.is_set():
            raise KeyboardInterrupt
        out.seek(0)
        err.seek(0)
        text_out = out.read().decode("utf-8", errors="replace")
        text_err = err.read().decode("utf-8", errors="replace")
    return Transcript(step, status, text_out, text_err, time.monotonic() - t0, note)


def end_running():
    """After Ctrl-C: no command starts any more, and the running ones are ended."""
    with _running_lock:
        _stopping.set()
        running = list(_running)
    for p in running:
        end_group(p)


# ---- masking ----------------------------------------------------------------------------------------

PROGRESS = re.compile(r"^(roughgas \w+): +[0-9.]+%  \S+ collisions/s  \S+ elapsed  \S+ to go$")
WORK_DONE = re.compile(r"(\S+) collisions in \S+ s \(\S+ collisions/s; kernel ")
BUILT = re.compile(r"built in [0-9.]+ s")
STOPPED_ROWS = re.compile(r"(stopped by SIG[A-Z]+: )\d+( complete rows?)")
USAGE = re.compile(r"^(Usage: )\S+")  # --help names the program as it was started
SWEEP_DONE = re.compile(r"^roughgas sweep: point (\d+) \(.*\) done")


def mask(text, step, root, binary):
    """The transcript text with the timing-dependent numbers masked (the module's docstring lists
    them), the tree's root replaced by <root> and the binary's path by <roughgas>."""
    text = text.replace(binary, "<roughgas>").replace(os.path.realpath(binary), "<roughgas>").replace(root, "<root>")
    lines, out = text.split("\n"), []
    for line in lines:
        line = USAGE.sub(r"\1<roughgas>", line)
        m = PROGRESS.match(line.rstrip("\r"))
        if m:
            line = m.group(1) + ": <progress>"
            if out and out[-1] == line:
                continue
        line = WORK_DONE.sub(lambda m: ("<n>" if step.stop_point else m.group(1))
                             + " collisions in <s> s (<rate> collisions/s; kernel ", line)
        line = BUILT.sub("built in <s> s", line)
        if step.stop_point:
            line = STOPPED_ROWS.sub(r"\1<n>\2", line)
        out.append(line)
    # sweep's points in the order they finished: sorted by point, in place
    i = 0
    while i < len(out):
        j = i
        while j < len(out) and SWEEP_DONE.match(out[j]):
            j += 1
        if j > i + 1:
            out[i:j] = sorted(out[i:j], key=lambda s: int(SWEEP_DONE.match(s).group(1)))
        i = max(j, i + 1)
    return "\n".join(out)


# ---- comparing --------------------------------------------------------------------------------------

def first_line_difference(a, b):
    """(line number, line of a, line of b) of the first line where two texts differ (None past the end)."""
    la, lb = a.split("\n"), b.split("\n")
    for k in range(max(len(la), len(lb))):
        x = la[k] if k < len(la) else None
        y = lb[k] if k < len(lb) else None
        if x != y:
            return k + 1, x, y
    return None


def clip_pair(x, y, n=150):
    """Two differing lines as shown in a report: from a little before their first differing character."""
    if x is None or y is None:
        return tuple("(no such line: it ends before)" if s is None else repr(s[:n] + ("..." if len(s) > n else ""))
                     for s in (x, y))
    k = next((i for i in range(min(len(x), len(y))) if x[i] != y[i]), min(len(x), len(y)))
    start = max(0, k - n // 3)
    return tuple(("..." if start else "") + repr(s[start:start + n]) + ("..." if len(s) > start + n else "")
                 for s in (x, y))


def csv_column(text, x, y):
    """", column NAME" of the first field where two rows of a roughgas CSV differ (its header is the
    first line not starting with '#'); "" for other lines."""
    if x is None or y is None or x.startswith("#") or y.startswith("#"):
        return ""
    header = next((line for line in text.split("\n") if not line.startswith("#")), "")
    names, fx, fy = header.split(","), x.split(","), y.split(",")
    if x == header or len(fx) != len(names) or len(fy) != len(names):
        return ""
    k = next(i for i in range(len(fx)) if fx[i] != fy[i])
    return f", column {names[k]}"


def clip(s, n=150):
    return repr(s if len(s) <= n else s[:n] + "...")


def text_of(data):
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


def h5_note(a_path, b_path):
    """What h5py says of two HDF5 files whose bytes differ: their datasets and attributes equal or not."""
    try:
        import h5py
        import numpy as np
    except ImportError:
        return "h5py is not installed: contents not compared"

    def same(x, y):
        x, y = np.asarray(x), np.asarray(y)
        if x.dtype.kind in "fc" and y.dtype.kind in "fc":
            return np.array_equal(x, y, equal_nan=True)
        return x.shape == y.shape and bool(np.all(x == y))

    try:
        with h5py.File(a_path, "r") as fa, h5py.File(b_path, "r") as fb:
            items = []
            fa.visit(items.append)
            other = []
            fb.visit(other.append)
            if sorted(items) != sorted(other):
                return f"objects differ: {sorted(set(items) ^ set(other))}"
            for name in [""] + items:
                oa, ob = (fa[name], fb[name]) if name else (fa, fb)
                if sorted(oa.attrs) != sorted(ob.attrs) or any(not same(oa.attrs[k], ob.attrs[k]) for k in oa.attrs):
                    return f"attributes of /{name} differ"
                if isinstance(oa, h5py.Dataset) and not same(oa[()], ob[()]):
                    return f"dataset /{name} differs"
            return "datasets and attributes equal (h5py): the files differ in layout or metadata only"
    except (OSError, ValueError) as e:
        return f"h5py could not compare them: {e}"


def fnv1a64(data):
    """The checksum of roughgas's binary files (include/roughgas/core/bytes.hpp): FNV-1a with 64 bits,
    its offset basis as roughgas has it (1469598103934665603; FNV's published one is 14695981039346656037)."""
    h = 1469598103934665603
    for byte in data:
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def table_cache_masked(data):
    """A restitution table cache file ("RGTCACHE", docs/reference.md) with the build time that each
    table's payload carries (the last double of a normal table's, the first of a tangential table's)
    and the checksum over them zeroed; None, with the reason, when the file is not such a file or its
    checksum is wrong."""
    if data[:8] != b"RGTCACHE" or len(data) < 32:
        return None, "not a table cache file"
    if struct.unpack_from("<Q", data, len(data) - 8)[0] != fnv1a64(data[:-8]):
        return None, "its checksum is wrong"
    out = bytearray(data)
    try:
        entries = struct.unpack_from("<Q", data, 16)[0]
        pos = 24
        for _ in range(entries):
            key_bytes = struct.unpack_from("<Q", data, pos)[0]
            key = data[pos + 8:pos + 8 + key_bytes]
            pos += 8 + key_bytes
            doubles = struct.unpack_from("<Q", data, pos)[0]
            pos += 8
            if b" normal_table " in key:
                seconds = pos + 8 * (doubles - 1)
            elif b" tangential_table " in key:
                seconds = pos
            else:
                return None, f"an entry of unknown kind ({key[:40]!r})"
            out[seconds:seconds + 8] = bytes(8)
            pos += 8 * doubles
    except struct.error:
        return None, "it is truncated"
    if pos != len(data) - 8:
        return None, "its entries do not end at the checksum"
    out[-8:] = bytes(8)
    return bytes(out), ""


def files_under(d):
    found = set()
    for base, _, files in os.walk(d):
        for f in files:
            found.add(os.path.relpath(os.path.join(base, f), d))
    return found


def compare_trees(a_dir, b_dir, label_a, label_b, shown):
    """The differences between the files under a_dir and b_dir, as lines; `shown` prefixes the
    relative paths."""
    diffs = []
    fa, fb = files_under(a_dir), files_under(b_dir)
    for f in sorted(fa - fb):
        diffs.append(f"{shown}{f}: only in {label_a}")
    for f in sorted(fb - fa):
        diffs.append(f"{shown}{f}: only in {label_b}")
    for f in sorted(fa & fb):
        pa, pb = os.path.join(a_dir, f), os.path.join(b_dir, f)
        with open(pa, "rb") as x, open(pb, "rb") as y:
            da, db = x.read(), y.read()
        if da[:8] == b"RGTCACHE" and db[:8] == b"RGTCACHE":
            (ma, why_a), (mb, why_b) = table_cache_masked(da), table_cache_masked(db)
            if ma is None or mb is None:
                diffs.append(f"{shown}{f}: table cache file of {label_a if ma is None else label_b}: "
                             f"{why_a or why_b}")
                continue
            da, db = ma, mb
        if da == db:
            continue
        ta, tb = text_of(da), text_of(db)
        if ta is not None and tb is not None:
            k, x, y = first_line_difference(ta, tb)
            where = f"line {k}" + csv_column(ta, x, y)
            x, y = clip_pair(x, y)
            diffs.append(f"{shown}{f}: {where} differs\n      {label_a}: {x}\n      {label_b}: {y}")
        else:
            k = next((i for i in range(min(len(da), len(db))) if da[i] != db[i]), min(len(da), len(db)))
            d = f"{shown}{f}: {len(da)} and {len(db)} bytes, first difference at byte {k}"
            if f.endswith(".h5"):
                d += "; " + h5_note(pa, pb)
            diffs.append(d)
    return diffs


def compare_transcripts(ta, tb, a_root, b_root, a_bin, b_bin):
    diffs = []
    for k, (x, y) in enumerate(zip(ta, tb)):
        what = f"command {k + 1} ({x.step.shown()})"
        if x.status != y.status:
            diffs.append(f"{what}: exit status {x.status} (old) and {y.status} (new)")
        for stream, sx, sy in (("stdout", x.out, y.out), ("stderr", x.err, y.err)):
            mx, my = mask(sx, x.step, a_root, a_bin), mask(sy, y.step, b_root, b_bin)
            if stream == "stderr" and x.step.ranks > 1:  # the ranks' lines reach mpirun in any order
                mx, my = "\n".join(sorted(mx.split("\n"))), "\n".join(sorted(my.split("\n")))
            if mx != my:
                n, lx, ly = first_line_difference(mx, my)
                lx, ly = clip_pair(lx, ly)
                diffs.append(f"{what}: {stream} line {n} differs\n      old: {lx}\n      new: {ly}")
    return diffs


def status_problems(transcripts, side):
    problems = []
    for k, t in enumerate(transcripts):
        if t.status != t.step.expect or t.note:
            tail = (t.err.strip().splitlines() or ["(no stderr)"])[-1]
            problems.append(f"{side}, command {k + 1} ({t.step.shown()}): exit status {t.status}, expected "
                            f"{t.step.expect}{'; ' + t.note if t.note else ''}; stderr ends: {clip(tail)}")
    return problems


# ---- scenarios run and judged --------------------------------------------------------------------

class Result:
    def __init__(self, scenario, verdict, lines, seconds):
        self.scenario, self.verdict, self.lines, self.seconds = scenario, verdict, lines, seconds


def write_log(path, cwd, transcripts):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        for k, t in enumerate(transcripts):
            f.write(f"== command {k + 1}: {t.step.shown()}\n   in {cwd}\n   exit status {t.status} "
                    f"(expected {t.step.expect}), {t.seconds:.2f} s{'; ' + t.note if t.note else ''}\n")
            f.write(f"-- stdout\n{t.out}-- stderr\n{t.err}\n")


def run_steps(steps, binaries, root, work, side, scenario):
    os.makedirs(root)
    case_dir = os.path.relpath(os.path.join(work, "cases"), root)
    mpirun = shutil.which("mpirun")
    transcripts = [run_step(s, binaries[s.binary or side], root, case_dir, mpirun) for s in steps]
    write_log(os.path.join(work, "logs", side, scenario.name + ".log"), root, transcripts)
    return transcripts


def run_scenario(sc, work, binaries, mpi_skip):
    """Runs a scenario with both binaries and judges it: its Result. `mpi_skip`: why the mpi
    scenarios cannot run here, or None."""
    t0 = time.monotonic()
    if sc.needs_mpi and mpi_skip:
        return Result(sc, "SKIP", [mpi_skip], 0.0)
    try:
        roots = {side: os.path.join(work, side, sc.name) for side in ("old", "new", "cross")}
        got = {side: run_steps(sc.steps, binaries, roots[side], work, side, sc) for side in ("old", "new")}
        diffs = compare_trees(roots["old"], roots["new"], "old", "new", "")
        diffs += compare_transcripts(got["old"], got["new"], roots["old"], roots["new"], binaries["old"],
                                     binaries["new"])
        problems = status_problems(got["old"], "old") + status_problems(got["new"], "new")
        if sc.cross:
            cross = run_steps(sc.cross, binaries, roots["cross"], work, "cross", sc)
            problems += status_problems(cross, "cross")
            for a, b in sc.cross_pairs:
                diffs += compare_trees(os.path.join(roots["old"], a), os.path.join(roots["cross"], b), "old", "cross",
                                       f"old {a} vs cross {b}: ")
    except KeyboardInterrupt:
        raise
    except Exception as e:  # a fault of this script or of the machine (a full disk), reported with the scenario
        return Result(sc, "ERROR", [f"{type(e).__name__}: {e}"], time.monotonic() - t0)
    verdict = "DIFF" if diffs else "ERROR" if problems else "OK"
    return Result(sc, verdict, diffs + problems, time.monotonic() - t0)


def report(r, width):
    print(f"{r.verdict:5} {r.scenario.name:{width}} {r.seconds:6.1f} s", flush=True)
    for line in r.lines[:MAX_REPORTED]:
        print("      " + line)
    if len(r.lines) > MAX_REPORTED:
        print(f"      ... and {len(r.lines) - MAX_REPORTED} more")
    sys.stdout.flush()


def version_of(binary):
    try:
        p = subprocess.run([binary, "--version"], capture_output=True, text=True, timeout=60, env=ENV)
        return p.stdout.strip() or p.stderr.strip()
    except (OSError, subprocess.TimeoutExpired) as e:
        return f"(--version failed: {e})"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old", metavar="OLD_BINARY", help="the roughgas binary of the code before the change")
    ap.add_argument("--new", metavar="NEW_BINARY", help="the roughgas binary of the code after it")
    ap.add_argument("--work", metavar="DIR", help="scratch directory, empty or new (default: a new temporary one)")
    ap.add_argument("--keep", action="store_true", help="keep the scratch directory (its path is printed)")
    ap.add_argument("--only", metavar="PATTERN", help="only the scenarios matching these shell patterns "
                    "(comma-separated, e.g. 'case/hcs_*,resume/*')")
    ap.add_argument("--jobs", type=int, default=1, metavar="N", help="scenarios run at a time (default 1)")
    ap.add_argument("--list", action="store_true", help="print the scenarios and their commands, run nothing")
    a = ap.parse_args()

    scenarios = all_scenarios()
    if a.only:
        patterns = [p.strip() for p in a.only.split(",") if p.strip()]
        scenarios = [s for s in scenarios if any(fnmatch.fnmatchcase(s.name, p) for p in patterns)]
        if not scenarios:
            ap.error(f"--only {a.only!r} matches no scenario (--list names them)")
    if a.list:
        for s in scenarios:
            print(f"{s.name}: {s.what}")
            for step in s.steps:
                print(f"    {step.shown()}" + (f"   [exit {step.expect}]" if step.expect else ""))
            for step in s.cross:
                print(f"    cross: {step.shown()}" + (f"   [exit {step.expect}]" if step.expect else ""))
            for x, y in s.cross_pairs:
                print(f"    compared: old {x} with cross {y}")
        print(f"{len(scenarios)} scenarios")
        return 0
    if not a.old or not a.new:
        ap.error("--old and --new are required (or --list)")
    if a.jobs < 1:
        ap.error("--jobs must be at least 1")
    binaries = {}
    for side, path in (("old", a.old), ("new", a.new)):
        path = os.path.abspath(path)
        if not (os.path.isfile(path) and os.access(path, os.X_OK)):
            ap.error(f"--{side} {path}: not an executable file")
        binaries[side] = path
    if a.work:
        work = os.path.abspath(a.work)
        if os.path.exists(work) and (not os.path.isdir(work) or os.listdir(work)):
            ap.error(f"--work {work}: exists and is not an empty directory")
        os.makedirs(work, exist_ok=True)
    else:
        work = tempfile.mkdtemp(prefix="compare_builds.")
    work = os.path.realpath(work)

    versions = {side: version_of(path) for side, path in binaries.items()}
    if not shutil.which("mpirun"):
        mpi_skip = "mpirun is not on PATH"
    elif not any(v.endswith("(MPI)") for v in versions.values()):
        mpi_skip = "neither binary was built with MPI (--version ends with (MPI))"
    else:
        mpi_skip = None
    print(f"old: {binaries['old']} ({versions['old']})")
    print(f"new: {binaries['new']} ({versions['new']})")
    print(f"work: {work}; {len(scenarios)} scenarios, {a.jobs} at a time", flush=True)
    if mpi_skip and any(s.needs_mpi for s in scenarios):
        print(f"notice: the mpi scenarios are skipped: {mpi_skip}", flush=True)
    t0 = time.monotonic()
    results = []
    pool = ThreadPoolExecutor(max_workers=a.jobs)
    try:
        shutil.copytree(os.path.join(ROOT, "cases"), os.path.join(work, "cases"))
        width = max(len(s.name) for s in scenarios)
        futures = [pool.submit(run_scenario, s, work, binaries, mpi_skip) for s in scenarios]
        for f in futures:  # reported in the list's order, whatever the order they finish in
            results.append(f.result())
            report(results[-1], width)
        pool.shutdown()
    except KeyboardInterrupt:
        end_running()
        pool.shutdown(cancel_futures=True)
        print("interrupted", file=sys.stderr)
        return 130
    finally:
        if a.keep:
            print(f"scratch directory kept: {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)
    counts = {v: sum(r.verdict == v for r in results) for v in ("OK", "DIFF", "ERROR", "SKIP")}
    print(f"{len(results)} scenarios: {counts['OK']} OK, {counts['DIFF']} DIFF, {counts['ERROR']} ERROR, "
          f"{counts['SKIP']} skipped; {time.monotonic() - t0:.0f} s", flush=True)
    return 0 if counts["DIFF"] == 0 and counts["ERROR"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
