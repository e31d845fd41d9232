"""roughgas from Python (docs/python.md): the same cases, runs and files as the command line.

    Case          a case from a TOML file, a TOML string or a dict; set() is --set, check() is `roughgas check`
    run           `roughgas run`: the result's arrays are the numbers of the CSVs it writes
    load          a run directory's files as the same result; load_csv: one CSV
    eps_n, eps_t  a case's restitution over NumPy arrays, direct or from the run's tables
    collide       the collision rule over arrays of pre-collision states
    InputError    invalid input (the command line's exit status 2), with the command line's message
"""
from ._roughgas import InputError, __version__
from .case import Case
from .collision import collide
from .restitution import eps_n, eps_t
from .result import FieldsSnapshot, Result, load, load_csv
from .run import resume, run

__all__ = ["Case", "FieldsSnapshot", "InputError", "Result", "collide", "eps_n", "eps_t", "load", "load_csv", "resume", "run", "__version__"]
