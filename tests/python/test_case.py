"""roughgas.Case: the command line's parsing, --set, validation and `roughgas check`."""
import math
import random

import pytest

import roughgas

SMALL = {"run.particles": 2000, "run.end": 2.0}


def hcs_rough_dict():
    return {
        "run": {"kind": "cooling", "particles": 2000, "density": 0.01, "replicas": 2, "seed": 3, "end": 2.0,
                "output_every": 0.5},
        "species": [{"name": "grain", "mass": 1.0, "radius": 0.5, "inertia": 0.4, "fraction": 1.0,
                     "temperature": 1.0, "rotational_temperature": 1.0}],
        "collision": {"model": "constant", "alpha": 0.9, "beta": 1.0},
    }


def test_file_string_and_dict_give_the_same_resolved_case(case_path):
    from_file = roughgas.Case(case_path("hcs_rough"))
    with open(case_path("hcs_rough")) as f:
        from_text = roughgas.Case.from_toml(f.read())
    d = hcs_rough_dict()
    d["run"].update(particles=50000, replicas=4, seed=1, end=400.0, output_every=2.0, output_spacing="linear")
    from_dict = roughgas.Case(d)
    assert from_file.to_toml() == from_text.to_toml() == from_dict.to_toml()
    assert from_dict.name == "<dict>" and from_text.name == "<string>"


def test_check_prints_what_the_command_line_prints(cli, case_path):
    for name in ("hcs_rough", "box_shear_mode"):
        path = case_path(name)
        assert roughgas.Case(path).check() == cli("check", path).stdout
        assert roughgas.Case(path).check(print=True) == cli("check", path, "--print").stdout


def test_check_of_a_box_states_its_stability(cli, case_path):
    path = case_path("box_shear_mode")
    out = roughgas.Case(path).check()
    assert out.startswith(f"{path}: valid\n")
    assert len(out.splitlines()) == 2  # the stability statement, as the command line prints it


def test_set_is_the_command_lines_set(cli, case_path):
    path = case_path("hcs_rough")
    case = roughgas.Case(path).set("collision.alpha", 0.7).set("run.particles", 2000)
    assert case.sets == ["collision.alpha=0.7", "run.particles=2000"]
    expected = cli("check", path, "--print", "--set", "collision.alpha=0.7", "--set", "run.particles=2000").stdout
    assert case.check(print=True) == expected


def test_a_bad_key_raises_the_command_lines_message(cli, case_path):
    path = case_path("hcs_rough")
    case = roughgas.Case(path)
    with pytest.raises(roughgas.InputError) as e:
        case.set("collision.alpha", 1.5)
    done = cli("check", path, "--set", "collision.alpha=1.5", check=False)
    assert done.returncode == 2
    assert done.stderr.strip() == str(e.value)
    assert e.value.key == "collision.alpha"
    assert "collision.alpha" in str(e.value) and "1.5" in str(e.value)
    assert case.sets == []  # the case is left as it was
    assert isinstance(e.value, ValueError)


def test_an_unknown_key_is_named(case_path):
    with pytest.raises(roughgas.InputError) as e:
        roughgas.Case(case_path("hcs_rough")).set("collision.alpah", 0.7)
    assert "collision.alpah" in str(e.value)
    d = hcs_rough_dict()
    d["collision"]["alpah"] = 0.7
    with pytest.raises(roughgas.InputError) as e:
        roughgas.Case(d)
    assert "alpah" in str(e.value)
    assert str(e.value).startswith("<dict>: ")  # no line:column of text the user never wrote


def test_nan_and_infinity_are_refused_with_the_key(case_path):
    for bad in (math.nan, math.inf, -math.inf):
        with pytest.raises(roughgas.InputError) as e:
            roughgas.Case(case_path("hcs_rough")).set("collision.alpha", bad)
        assert e.value.key == "collision.alpha"


def test_wrong_python_types_raise_type_errors(case_path):
    case = roughgas.Case(case_path("hcs_rough"))
    with pytest.raises(TypeError, match="collision.alpha"):
        case.set("collision.alpha", object())
    with pytest.raises(TypeError):
        case.set(3, 0.7)
    with pytest.raises(TypeError):
        roughgas.Case(42)
    with pytest.raises(TypeError):
        roughgas.Case.from_toml(b"[run]")
    with pytest.raises(roughgas.InputError):  # a string where a number belongs: the parser's message
        case.set("collision.alpha", "0.7")
    with pytest.raises(roughgas.InputError):
        roughgas.Case.from_toml("[run\nkind = ")
    with pytest.raises(roughgas.InputError):
        roughgas.Case("/nonexistent/case.toml")


def test_a_copy_is_independent(case_path):
    a = roughgas.Case(case_path("hcs_rough"))
    b = roughgas.Case(a).set("collision.alpha", 0.7)
    assert a.sets == [] and b.sets == ["collision.alpha=0.7"]


def test_fuzzed_dicts_are_valid_or_refused_never_a_crash():
    """Random changes to a valid dict: each gives a valid case or InputError/TypeError."""
    rng = random.Random(7)
    values = [0, -1, 1, 0.5, -0.5, 1e300, -1e-300, math.nan, math.inf, True, "x", "", [], [1, 2], {}, {"a": 1},
              None, 2**70, "constant", "\u00e9\x00"]
    outcomes = {"valid": 0, "refused": 0}
    for _ in range(300):
        d = hcs_rough_dict()
        for _ in range(rng.randint(1, 3)):
            table = rng.choice(["run", "collision", "species"])
            target = d["species"][0] if table == "species" else d[table]
            key = rng.choice(list(target) + ["unknown_key"])
            target[key] = rng.choice(values)
        try:
            roughgas.Case(d)
            outcomes["valid"] += 1
        except (roughgas.InputError, TypeError):
            outcomes["refused"] += 1
    assert outcomes["refused"] > 0 and outcomes["valid"] + outcomes["refused"] == 300
