"""What the measurement scripts (bench_table.py, bench_targets.py, bench_accuracy.py, make_reference.py)
share: where they ran (machine, load average, commit), how they run a Google Benchmark binary and
`roughgas run` (idle OpenMP threads sleep)."""
import json
import os
import platform
import re
import resource
import subprocess
import sys
import time

# Idle OpenMP threads (roughgas's loops over replicas, sweep points and table builds; a replica's
# own threads always wait passively) sleep instead of spinning: on a machine shared with other work
# a spinning thread takes CPU from the thread it waits for (measured with OpenMP threads inside a
# replica: 2 threads 3x slower than 1 at load 4 on 2 cores with libgomp's default spinning; same
# CPU time per collision as 1 thread when passive).
BENCH_ENV = {**os.environ, "OMP_WAIT_POLICY": os.environ.get("OMP_WAIT_POLICY", "passive")}


def rough_case(n, end, every, replicas=1):
    """The text of a case file: a rough gas (alpha 0.9, beta 0.5) of n particles, `end` and `every`
    in collisions per particle; the gas the run-level benchmarks time."""
    return f"""[run]
particles = {n}
end = {end}
output_every = {every}
replicas = {replicas}
[[species]]
mass = 1.0
radius = 0.5
[collision]
model = "constant"
alpha = 0.9
beta = 0.5
"""


def loadavg():
    """The 1-minute load average (/proc/loadavg)."""
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def cpu_times():
    """(all, stolen) jiffies of the machine's CPUs since boot (/proc/stat): `stolen` is the time the
    hypervisor ran something else while this VM wanted to run; None where there is no /proc/stat."""
    try:
        with open("/proc/stat") as f:
            v = [int(x) for x in f.readline().split()[1:]]
    except OSError:
        return None
    return sum(v[:8]), (v[7] if len(v) > 7 else 0)


def stolen_since(t0):
    """The share of CPU time the hypervisor took since cpu_times() returned t0, as text."""
    t1 = cpu_times()
    if t0 is None or t1 is None or t1[0] <= t0[0]:
        return "unknown"
    return f"{100 * (t1[1] - t0[1]) / (t1[0] - t0[0]):.0f} %"


def machine():
    """The CPU as lscpu names it, with its family and model numbers: a VM's model name ("AMD EPYC") can
    stay the same while the CPU under it changes (two CPUs of different speed have been seen under
    the same "AMD EPYC", with the same caches)."""
    model, family, number, l2, l3 = "?", "?", "?", "?", "?"
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in out.splitlines():
            k, _, v = line.partition(":")
            v = v.strip()
            if k == "Model name":
                model = v
            elif k == "CPU family":
                family = v
            elif k == "Model":
                number = v
            elif k == "L2 cache":
                l2 = v
            elif k == "L3 cache":
                l3 = v
    except OSError:
        pass
    return (f"{model} (family {family}, model {number}), {os.cpu_count()} CPUs, L2 {l2}, L3 {l3}, "
            f"{platform.node()}")


def commit():
    """The checkout's commit, with '+changes' when the work tree differs from it."""
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        head = subprocess.run(["git", "-C", here, "rev-parse", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", here, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    return head + ("+changes" if dirty else "")


def short_commit():
    """commit() shortened to 12 hex digits, keeping its '+changes' mark."""
    c = commit()
    return c[:12] + ("+changes" if c.endswith("+changes") else "")


def measured_line(rounds, what, load0, steal0):
    """The line a load or box benchmark prints above its table: date, machine, commit, rounds, what
    the figures are (`what`), the load before and after and the CPU time the hypervisor took since
    cpu_times() returned steal0."""
    return (f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} on {machine()}; commit "
            f"{short_commit()}; {rounds} alternating rounds; {what}; load (1 min) {load0} before, {loadavg()} "
            f"after; CPU time stolen by the hypervisor {stolen_since(steal0)}.\n")


def benchmark_iterations(binary, flt, reps, out_json):
    """Runs the benchmarks of one filter in one call, `reps` randomly interleaved repetitions each, the
    JSON kept in out_json; returns {name: [the repetitions' result dicts]}, the name without its
    /min_time, /real_time and /iterations suffixes."""
    cmd = [binary, f"--benchmark_filter={flt}", f"--benchmark_repetitions={reps}",
           "--benchmark_enable_random_interleaving=true", "--benchmark_report_aggregates_only=false",
           "--benchmark_format=json", f"--benchmark_out={out_json}", "--benchmark_out_format=json"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=BENCH_ENV)
    with open(out_json) as f:
        data = json.load(f)
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "iteration":
            name = re.sub(r"/min_time:[^/]*|/real_time|/iterations:\d+", "", b["run_name"])
            runs.setdefault(name, []).append(b)
    return runs


def single_rate(binary, flt):
    """items/s of the one benchmark that `flt` selects, in a call of its own (wall-clock rate)."""
    r = subprocess.run([binary, f"--benchmark_filter={flt}", "--benchmark_format=json"], check=True,
                       capture_output=True, text=True, env=BENCH_ENV)
    return _first_rate(r.stdout)


def pair_rate(binary, flt):
    """The summed items/s of two processes of the same benchmark started at once (nothing shared but
    the machine: the ceiling of what two threads of one process can reach)."""
    cmd = [binary, f"--benchmark_filter={flt}", "--benchmark_format=json"]
    procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=BENCH_ENV)
             for _ in range(2)]
    outs = [p.communicate()[0] for p in procs]
    if any(p.returncode for p in procs):
        raise RuntimeError(f"{' '.join(cmd)} failed")
    return sum(_first_rate(o) for o in outs)


def _first_rate(text):
    return [b["items_per_second"] for b in json.loads(text)["benchmarks"] if b.get("run_type") == "iteration"][0]


BOX_DENSITY = 0.02  # sigma = 1: mean free path 1/(sqrt(2) pi n) = 11.254


def box_deck(n, end, output_every, time_step, beta=-1.0, partners="random", extra=""):
    """The DSMC reference deck for n grains (bench_box.py, bench_spectra.py): an elastic gas of
    smooth (beta = -1) or rough (beta = 1) spheres in a periodic cube of cells of 0.42 mean free
    paths with 20 grains each; `extra` is appended (further tables)."""
    lam = 1.0 / (2 ** 0.5 * 3.141592653589793 * BOX_DENSITY)
    cells = max(1, round((n / 20) ** (1 / 3)))
    side = cells * 0.42 * lam
    return (f"[run]\nparticles = {n}\nend = {end}\noutput_every = {output_every}\n"
            f"density = {BOX_DENSITY}\nseed = 1\n\n[[species]]\nmass = 1.0\nradius = 0.5\n\n"
            f"[collision]\nmodel = \"constant\"\nalpha = 1.0\nbeta = {beta}\n\n"
            f"[domain]\nsize = [{side}, {side}, {side}]\ncells = [{cells}, {cells}, {cells}]\n"
            f"time_step = {time_step}\npartners = \"{partners}\"\n" + extra)


def timed(cmd, who):
    """Wall seconds of a command, which must succeed (else the script `who` exits with its stderr)."""
    t0 = time.perf_counter()
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        sys.exit(f"{who}: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    return time.perf_counter() - t0


def run_roughgas(roughgas, case, out, sets=(), threads=1):
    """`roughgas run CASE --out OUT --force --quiet --threads T --set S...`; returns a dict with the
    CLI's own wall time of the collisions ("collisions in ... s"), the CPU time of the whole process
    (tables included), the wall time of the whole process, and the load average before and after."""
    cmd = [roughgas, "run", case, "--out", out, "--force", "--quiet", "--threads", str(threads)]
    for s in sets:
        cmd += ["--set", s]
    load0, usage0, wall0 = loadavg(), resource.getrusage(resource.RUSAGE_CHILDREN), time.monotonic()
    r = subprocess.run(cmd, capture_output=True, text=True, env=BENCH_ENV)
    wall, usage1, load1 = time.monotonic() - wall0, resource.getrusage(resource.RUSAGE_CHILDREN), loadavg()
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr}")
    m = re.search(r"collisions in ([0-9.eE+-]+) s", r.stdout)
    cpu = (usage1.ru_utime + usage1.ru_stime) - (usage0.ru_utime + usage0.ru_stime)
    return {"seconds": float(m.group(1)), "cpu_seconds": cpu, "process_seconds": wall, "load_before": load0,
            "load_after": load1, "stdout": r.stdout}


if __name__ == "__main__":
    # A module, not a command: run directly (with or without -h/--help) it prints what it holds.
    print(__doc__)
