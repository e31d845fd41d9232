"""roughgas.run and roughgas.load: the command line's run, its files and its numbers."""
import os

import numpy as np
import pytest

import roughgas

SETS = ["run.particles=2000", "run.end=4", "run.replicas=2"]


def python_case(path):
    case = roughgas.Case(path)
    for s in SETS:
        key, value = s.split("=")
        case.set(key, float(value) if "." in value else int(value))
    return case


def read_text(path):
    with open(path) as f:
        return f.read()


def same(a, b):
    return np.array_equal(a, b, equal_nan=True)


@pytest.fixture(scope="module")
def runs(tmp_path_factory, request):
    """The rough cooling case run by the command line and by roughgas.run, same case and seed."""
    from conftest import cli_binary, SOURCE_DIR
    import subprocess

    base = tmp_path_factory.mktemp("runs")
    path = os.path.join(SOURCE_DIR, "cases", "hcs_rough.toml")
    sets = [a for s in SETS for a in ("--set", s)]
    subprocess.run([cli_binary(), "run", path, "--out", base / "cli", "--quiet", "--seed", "5", *sets], check=True,
                   capture_output=True)
    result = roughgas.run(python_case(path), out=base / "py", progress=False, seed=5)
    return base, result


def test_the_csvs_are_the_command_lines_byte_for_byte(runs):
    base, result = runs
    for name in ("moments.csv", "scaled.csv", "replicas/moments_0.csv", "replicas/moments_1.csv"):
        assert read_text(base / "cli" / name) == read_text(base / "py" / name), name


def test_the_arrays_are_the_csvs_numbers(runs):
    base, result = runs
    cli = roughgas.load(base / "cli")
    assert list(result.moments) == list(cli.moments)
    assert "T_tr" in result.moments and "theta_err" in result.moments
    for column, values in cli.moments.items():
        assert same(result.moments[column], values), column
        assert values.dtype == np.float64
    # The numbers of the text, read independently of the module.
    lines = [l for l in read_text(base / "cli" / "moments.csv").splitlines() if not l.startswith("#")]
    names = lines[0].split(",")
    t_tr = np.array([float(l.split(",")[names.index("T_tr")]) for l in lines[1:]])
    assert same(result.moments["T_tr"], t_tr)
    assert result.summary_kind == "scaled" and "theta" in result.summary and "theta_err" in result.summary
    assert len(result.replicas) == 2
    assert result.profiles is None


def test_columns_are_views_of_one_moved_buffer(runs):
    base, result = runs
    columns = result.arrays("moments")
    owners = set()
    for values in columns.values():
        assert not values.flags.owndata  # a view ...
        assert values.base is not None and values.base.base is not None  # ... of the array over the buffer
        assert values.flags.c_contiguous
        owners.add(id(values.base))
    assert len(owners) == 1
    buffer = next(iter(columns.values())).base
    assert type(buffer.base).__name__ == "PyCapsule"  # the C++ vector's memory, handed over, not copied


def test_a_run_without_out_leaves_no_directory(case_path, tmp_path):
    before = set(os.listdir(tmp_path))
    result = roughgas.run(python_case(case_path("hcs_smooth")), progress=False, threads=1)
    assert not os.path.exists(result.dir)
    assert len(result.moments["t"]) > 1
    assert set(os.listdir(tmp_path)) == before


def test_a_case_from_a_dict_runs_as_its_file(case_path, tmp_path, cli):
    path = case_path("hcs_smooth")
    cli("run", path, "--out", tmp_path / "cli", "--quiet", *[a for s in SETS for a in ("--set", s)])
    from_text = roughgas.Case.from_toml(read_text(path))
    for s in SETS:
        key, value = s.split("=")
        from_text.set(key, float(value) if "." in value else int(value))
    result = roughgas.run(from_text, out=tmp_path / "py", progress=False)
    cli_run = roughgas.load(tmp_path / "cli")
    for column, values in cli_run.moments.items():
        assert same(result.moments[column], values), column


def test_an_existing_run_is_refused_without_force(runs, case_path):
    base, _ = runs
    with pytest.raises(roughgas.InputError, match="use --force|--resume"):
        roughgas.run(python_case(case_path("hcs_rough")), out=base / "py", progress=False)


def test_bad_arguments_raise(case_path, tmp_path):
    case = python_case(case_path("hcs_smooth"))
    with pytest.raises(ValueError):
        roughgas.run(case, out=tmp_path / "a", threads=0)
    with pytest.raises(TypeError):
        roughgas.run(case, out=tmp_path / "a", threads=1.5)
    with pytest.raises(ValueError):
        roughgas.run(case, out=tmp_path / "a", seed=-1)
    with pytest.raises(ValueError):
        roughgas.run(case, out=tmp_path / "a", checkpoint_every=float("nan"))
    with pytest.raises(TypeError):
        roughgas.run(12, out=tmp_path / "a")
    with pytest.raises(FileNotFoundError):
        roughgas.load(tmp_path / "nothing")


def test_a_box_run_has_profiles_and_spectra(case_path, tmp_path, cli):
    path = case_path("box_shear_mode")
    sets = ["run.particles=2000", "run.end=2"]
    cli("run", path, "--out", tmp_path / "cli", "--quiet", *[a for s in sets for a in ("--set", s)])
    case = roughgas.Case(path).set("run.particles", 2000).set("run.end", 2.0)
    result = roughgas.run(case, out=tmp_path / "py", progress=False)
    cli_run = roughgas.load(tmp_path / "cli")
    for table in ("profiles", "spectra", "modes"):
        ours, theirs = result.arrays(table), cli_run.arrays(table)
        assert list(ours) == list(theirs) and len(ours["t"]) > 0, table
        for column in theirs:
            assert same(ours[column], theirs[column]), (table, column)


INTERRUPTED = """
import sys
import roughgas
case = roughgas.Case(sys.argv[1]).set("run.particles", 100000).set("run.end", 100.0)
try:
    roughgas.run(case, out=sys.argv[2], threads=1, progress=False)
except KeyboardInterrupt as e:
    print("stopped:", e)
"""


def test_sigint_stops_a_run_with_a_checkpoint_that_resumes(case_path, tmp_path, cli):
    """SIGINT during roughgas.run: KeyboardInterrupt, a checkpoint in `out`; roughgas.resume then
    writes the moments the run without a stop writes (the command line's guarantee)."""
    import signal
    import subprocess
    import sys
    import time

    path = case_path("hcs_rough")
    out = tmp_path / "stopped"
    env = dict(os.environ)
    p = subprocess.Popen([sys.executable, "-c", INTERRUPTED, path, str(out)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env)
    deadline = time.monotonic() + 60
    while not (out / "moments.csv").exists() and not os.path.exists(out / "checkpoint") and p.poll() is None:
        assert time.monotonic() < deadline
        time.sleep(0.05)
    time.sleep(0.5)
    p.send_signal(signal.SIGINT)
    stdout, stderr = p.communicate(timeout=120)
    assert p.returncode == 0, stderr
    assert "stopped: roughgas.run stopped by SIGINT" in stdout, (stdout, stderr)
    assert (out / "checkpoint").is_dir()
    resumed = roughgas.resume(out, threads=1, progress=False)
    cli("run", path, "--out", tmp_path / "whole", "--quiet", "--threads", "1", "--set", "run.particles=100000",
        "--set", "run.end=100.0")
    assert read_text(tmp_path / "whole" / "moments.csv") == read_text(out / "moments.csv")
    assert len(resumed.moments["t"]) == len(roughgas.load(tmp_path / "whole").moments["t"])


def test_tables_are_pandas_frames_when_pandas_is_importable(runs, monkeypatch):
    """With pandas importable every table is pandas.DataFrame(columns, copy=False) of the same arrays
    (a stand-in module records the call: pandas is not among the test machine's packages); arrays()
    stays {column: array}."""
    import roughgas.result

    class Frame:
        def __init__(self, columns, copy=True):
            self.columns, self.copy = columns, copy

    monkeypatch.setattr(roughgas.result, "pandas", type("pandas", (), {"DataFrame": Frame}))
    base, _ = runs
    r = roughgas.load(base / "cli")
    assert isinstance(r.moments, Frame) and r.moments.copy is False
    assert r.moments.columns is r.arrays("moments")
    assert all(isinstance(x, Frame) for x in r.replicas) and len(r.replicas) == 2
    assert isinstance(r.summary, dict)  # the summary row stays a dict of floats
