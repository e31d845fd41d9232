"""roughgas.eps_n and eps_t: the contact model of `roughgas restitution` over NumPy arrays."""
import numpy as np
import pytest

import roughgas

GRID = ["restitution.g_n_points=7", "restitution.g_t_points=3", "contact.cache=false"]


@pytest.fixture(scope="module")
def ice(tmp_path_factory):
    """The ice case's direct integration as `roughgas restitution` writes it, on a small grid."""
    from conftest import cli_binary, SOURCE_DIR
    import os
    import subprocess

    path = os.path.join(SOURCE_DIR, "cases", "ice.toml")
    out = tmp_path_factory.mktemp("restitution")
    subprocess.run([cli_binary(), "restitution", path, "--out", out, "--force",
                    *[a for s in GRID for a in ("--set", s)]], check=True, capture_output=True)
    return roughgas.Case(path), roughgas.load_csv(out / "normal.csv"), roughgas.load_csv(out / "tangential.csv")


def test_direct_eps_n_is_the_commands(ice):
    case, normal, _ = ice
    assert np.array_equal(roughgas.eps_n(normal["g_N"], case), normal["eps_N"])


def test_direct_eps_t_is_the_commands(ice):
    case, _, tangential = ice
    assert np.array_equal(roughgas.eps_t(tangential["g_N"], tangential["g_T"], case), tangential["eps_T"])


def test_the_tables_agree_with_the_integration(ice):
    case, normal, tangential = ice
    g = normal["g_N"][(normal["g_N"] > 1e-3) & (normal["g_N"] < 5)]
    direct, table = roughgas.eps_n(g, case), roughgas.eps_n(g, case, tabulated=True)
    assert np.max(np.abs(table - direct)) < 1e-3
    assert not np.array_equal(table, direct)  # the tables are interpolated: a different path


def test_shapes_broadcast_and_are_kept(ice):
    case, _, _ = ice
    g = np.full((3, 4), 0.5)
    assert roughgas.eps_n(g, case).shape == (3, 4)
    e = roughgas.eps_t(np.array([[0.5], [1.0]]), np.array([0.1, 0.2, 0.3]), case)
    assert e.shape == (2, 3)
    assert roughgas.eps_t(0.5, 0.1, case).shape == ()


def test_material_keys_change_the_result(ice):
    case, _, _ = ice
    g = np.array([0.1, 1.0])
    softer = roughgas.eps_n(g, case, material={"dissipation": 1e-5})
    assert np.all(softer > roughgas.eps_n(g, case))  # less dissipation: more elastic
    assert case.sets == []  # set on a copy


def test_bad_speeds_raise(ice):
    case, _, _ = ice
    for bad in ([0.5, -1.0], [np.nan], [0.0], [np.inf]):
        with pytest.raises(ValueError, match="g_n"):
            roughgas.eps_n(bad, case)
    with pytest.raises(ValueError, match="g_t"):
        roughgas.eps_t([1.0], [-0.1], case)
    with pytest.raises(ValueError):  # shapes that do not broadcast
        roughgas.eps_t(np.ones(3), np.ones(4), case)
    with pytest.raises(TypeError):
        roughgas.eps_n(["a"], case)
    with pytest.raises(roughgas.InputError, match="material.dissipation"):
        roughgas.eps_n([1.0], case, material={"dissipation": -1.0})


def test_a_case_without_a_contact_model_is_refused(case_path):
    with pytest.raises(roughgas.InputError):
        roughgas.eps_n([1.0], roughgas.Case(case_path("hcs_rough")))


def test_a_material_and_a_grain_without_a_case_file(ice):
    """The ice case's material and grain given as dicts: the same eps_N and eps_T as the case's."""
    case, normal, tangential = ice
    material = {"young_modulus": 1.0e10, "poisson_ratio": 0.3, "dissipation": 5.300775e-05,
                "asperity": 1.0e-6, "friction": 0.014142135623730951}
    grain = {"radius": 0.01, "mass": 4.188790204786391e-3}
    contact = {"form": "eq24", "end": "force", "tolerance": 1e-12}
    assert np.array_equal(roughgas.eps_n(normal["g_N"], material=material, grain=grain, contact=contact),
                          normal["eps_N"])
    assert np.array_equal(roughgas.eps_t(tangential["g_N"], tangential["g_T"], material=material, grain=grain,
                                         contact=contact), tangential["eps_T"])
    with pytest.raises(TypeError, match="grain="):
        roughgas.eps_n(normal["g_N"], material=material)
    with pytest.raises(roughgas.InputError, match="material.poisson_ratio"):
        roughgas.eps_n(normal["g_N"], material={**material, "poisson_ratio": 0.7}, grain=grain)
