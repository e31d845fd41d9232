"""Python values as TOML, for Case.set and cases given as dicts: the C++ parser then validates them
with the command line's messages. Only what a case file holds: numbers, booleans, strings, arrays of
them, tables and arrays of tables; anything else is a TypeError naming the key."""
import math
import numbers


def value(key, v):
    """The TOML text of one value (the VALUE of --set KEY=VALUE)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # the shortest decimal that reads back to the same double
    if isinstance(v, str):
        return string(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(f"{key}.{i}", e) for i, e in enumerate(v)) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{bare_key(key, k)} = {value(f'{key}.{k}', e)}" for k, e in v.items()) + "}"
    raise TypeError(f"{key}: a number, bool, string, list or dict expected, got {type(v).__name__}")


def string(s):
    escaped = s.replace("\\", "\\\\").replace('"', '\\"')
    escaped = "".join(c if c >= " " or c == "\t" else f"\\u{ord(c):04x}" for c in escaped)
    return f'"{escaped}"'


def bare_key(where, k):
    if not isinstance(k, str):
        raise TypeError(f"{where}: keys must be strings, got {k!r}")
    return k if k and all(c.isalnum() or c in "_-" for c in k) and k.isascii() else string(k)


def document(d):
    """A case as a dict ({"collision": {"alpha": 0.8}, "species": [{...}]}) as a TOML document."""
    if not isinstance(d, dict):
        raise TypeError(f"a case as a dict expected, got {type(d).__name__}")
    lines = []
    for k, v in d.items():  # top-level keys first, then tables, then arrays of tables
        if not isinstance(v, dict) and not is_table_array(v):
            lines.append(f"{bare_key('case', k)} = {value(k, v)}")
    for k, v in d.items():
        if isinstance(v, dict):
            table(lines, bare_key("case", k), k, v, f"[{bare_key('case', k)}]")
    for k, v in d.items():
        if is_table_array(v):
            for i, t in enumerate(v):
                table(lines, bare_key("case", k), f"{k}.{i}", t, f"[[{bare_key('case', k)}]]")
    return "\n".join(lines) + "\n"


def is_table_array(v):
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(t, dict) for t in v)


def table(lines, path, key, t, head):
    lines.append(head)
    for k, v in t.items():
        if not isinstance(v, dict):
            lines.append(f"{bare_key(key, k)} = {value(f'{key}.{k}', v)}")
    for k, v in t.items():  # sub-tables ([material.ice] style) after the table's own keys
        if isinstance(v, dict):
            table(lines, f"{path}.{bare_key(key, k)}", f"{key}.{k}", v, f"[{path}.{bare_key(key, k)}]")
