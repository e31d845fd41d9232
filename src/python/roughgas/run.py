"""roughgas.run and roughgas.resume: `roughgas run` in this process, then its files as a Result."""
import numbers
import os
import shutil
import signal
import tempfile

from . import _roughgas
from .case import Case
from .result import load


def run(case, out=None, threads=None, progress=True, *, seed=None, force=False, checkpoint_every=None):
    """Runs the case as `roughgas run CASE --out OUT` does and returns load(OUT).

    out: the run's directory (None: a temporary one, removed afterwards); threads: --threads (None:
    the CPUs this process may use; results do not depend on it); progress: the progress line on
    stderr (False: --quiet); seed: --seed; force: --force; checkpoint_every: --checkpoint-every.
    Ctrl-C (SIGINT) stops the run at the next step with a checkpoint and the CSV so far in `out`
    (resume with roughgas.resume(out)) and raises KeyboardInterrupt.
    """
    case = case if isinstance(case, Case) else Case(case)
    threads = _count("threads", threads)
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0):
        raise ValueError(f"seed: an integer >= 0 expected, got {seed!r}")
    every = 0.0
    if checkpoint_every is not None:
        every = float(checkpoint_every)
        if not every > 0 or every == float("inf"):
            raise ValueError(f"checkpoint_every: must be a number > 0, got {checkpoint_every!r}")
    temporary = out is None
    directory = tempfile.mkdtemp(prefix="roughgas-run-") if temporary else os.fspath(out)
    try:
        status = _roughgas.run_case(case._source, directory, threads, not progress, bool(force),
                                    None if seed is None else int(seed), every)
        _raise_for(status, None if temporary else directory)
        result = load(directory)
        if temporary:  # the fields are read when asked for: read them before the directory goes
            for snapshots in result.fields.values():
                for snapshot in snapshots:
                    snapshot.read_all()
        return result
    finally:
        if temporary:
            shutil.rmtree(directory, ignore_errors=True)


def resume(dir, threads=None, progress=True):
    """`roughgas run --resume DIR`: continues a stopped run, then returns load(DIR)."""
    status = _roughgas.resume_run(os.fspath(dir), _count("threads", threads), not progress)
    _raise_for(status, os.fspath(dir))
    return load(dir)


def _count(name, n):
    if n is None:
        return 0
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"{name}: an integer > 0 expected, got {type(n).__name__}")
    if n <= 0:
        raise ValueError(f"{name}: must be a number > 0, got {n}")
    return int(n)


def _raise_for(status, directory):
    if status == 0:
        return
    if status > 128:
        name = signal.Signals(status - 128).name
        where = (f": the checkpoint and the CSV so far are in {directory} (roughgas.resume continues it)"
                 if directory else "")
        raise KeyboardInterrupt(f"roughgas.run stopped by {name}{where}")
    raise RuntimeError(f"roughgas run: exit status {status}")
