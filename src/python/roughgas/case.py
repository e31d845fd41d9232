"""roughgas.Case: a case as the command line takes it, validated with its messages."""
import os
import warnings

from . import _roughgas, toml_values


class Case:
    """A validated case.

    Case("cases/hcs_rough.toml")      a case file (a path: str or os.PathLike), read as `roughgas run` reads it
    Case({"collision": {...}, ...})   a dict with the case file's tables and keys
    Case.from_toml(text)              TOML text
    Invalid input raises roughgas.InputError with the message of `roughgas check`.
    """

    def __init__(self, source):
        if isinstance(source, Case):
            self._source = source._source.copy()  # set() on one leaves the other as it was
        elif isinstance(source, dict):
            self._source = _roughgas.CaseSource.from_text(toml_values.document(source), "<dict>", False)
        elif isinstance(source, (str, os.PathLike)):
            self._source = _roughgas.CaseSource.from_file(os.fspath(source))
        else:
            raise TypeError(f"Case: a path, a dict or a Case expected, got {type(source).__name__} "
                            "(TOML text: Case.from_toml)")

    @classmethod
    def from_toml(cls, text, name="<string>"):
        if not isinstance(text, str):
            raise TypeError(f"Case.from_toml: TOML text (str) expected, got {type(text).__name__}")
        case = cls.__new__(cls)
        case._source = _roughgas.CaseSource.from_text(text, name, True)
        return case

    def set(self, key, value):
        """`--set KEY=VALUE`, value a Python number, bool, string or list (a str is a TOML string).
        Invalid: InputError, and the case stays as it was. Returns the case, so calls chain."""
        if not isinstance(key, str) or not key:
            raise TypeError(f"Case.set: the key is a dotted name such as \"collision.alpha\", got {key!r}")
        self._source.set(f"{key}={toml_values.value(key, value)}")
        self.__dict__.pop("_contact", None)  # eps_n's and eps_t's functions of the case as it was
        return self

    def check(self, use="run", print=False):
        """What `roughgas check` prints on stdout (the warnings it prints on stderr are Python warnings)."""
        out, warns = self._source.check(use, print)
        for w in warns:
            warnings.warn(f"{self._source.name}: {w}", stacklevel=2)
        return out

    @property
    def name(self):
        """The case file as given, or "<string>", "<dict>"."""
        return self._source.name

    @property
    def sets(self):
        """The --set overrides, "KEY=VALUE" each, in order."""
        return list(self._source.sets)

    def to_toml(self):
        """The resolved case (every default filled in), as `roughgas check --print` prints it."""
        return self._source.resolved_toml()

    def __repr__(self):
        sets = "".join(f" --set {s}" for s in self._source.sets)
        return f"<roughgas.Case {self._source.name}{sets}>"
