#!/usr/bin/env python3
"""Writes the key table of the detector's settings (frontend/settings/detector_config_keys.hpp) from the
one place each setting is declared: its field in DetectorConfig and the structs it nests.

  python3 scripts/config_keys.py OUT.cpp HEADER...

A setting is one field line: its default, then a trailing doc comment in a fixed form,

    double min_fill = 0.5;  ///< (0, 1] share of a cell's points that must be readings

the range it accepts first for a number (`[lo, hi]`, `(lo, hi]` when lo itself is refused; lo
and hi are numbers or short expressions such as `pi/2`, `2^24`, `2^32-1`), then the doc: unit
first where there is one, what it does, its source. Booleans and the enums (Method, HullKind,
SuitabilityMode) take no range. The doc may go on over `///<` lines below. A field whose doc
starts with "not a key:" is no setting (a stage fills it in). A field whose type is another
struct of the headers nests its keys under its name (`planes.regions.min_fill`). The key is the
field's path, so it cannot drift from the struct; the field `aspect` is read as --aspect reads
it (a number or "W:H"). Any other field, or a number without its range, stops the build with
the line to mend.
"""
import math
import re
import sys

LEAF_TYPES = {
    "bool": "bool", "int": "int", "unsigned": "unsigned", "double": "double",
    "std::vector<double>": "std::vector<double>", "Method": "Method", "HullKind": "HullKind",
    "SuitabilityMode": "SuitabilityMode",
}
RANGED = {"int", "unsigned", "double", "std::vector<double>"}
FIELD = re.compile(r"^(?P<type>[\w:]+(?:<[\w:, ]+>)?)\s+(?P<name>\w+)\s*(?:=\s*(?P<default>.*)|\{.*\})?$")
RANGE = re.compile(r"^(?P<open>[\[(])\s*(?P<lo>[^,\]]+?)\s*,\s*(?P<hi>[^\]]+?)\s*\]\s*(?P<doc>.*)$")
NUMBER = re.compile(r"^[0-9.eE+\-*/^() ]*(pi)?[0-9.eE+\-*/^() ]*$")


class DeclarationError(Exception):
    pass


def statements(body, path, first_line):
    """(code, doc, line) of each statement at the top of a struct body; member functions skipped."""
    out, code, doc, depth, start = [], "", [], 0, None
    for offset, line in enumerate(body):
        text, _, comment = line.partition("//")
        stripped = line.strip()
        if stripped.startswith("///<"):
            if out and not code.strip():
                out[-1][1].append(stripped[4:].strip())
            continue
        if not text.strip():
            continue
        if start is None:
            start = first_line + offset
        code += " " + text.strip()
        if comment.startswith("/<"):
            doc.append(comment[2:].strip())
        depth += text.count("{") - text.count("}")
        if depth == 0 and (code.rstrip().endswith(";") or code.rstrip().endswith("}")):
            out.append((" ".join(code.split()), doc, start))
            code, doc, start = "", [], None
    return out


def parse_structs(paths):
    """{struct name: [(type, name, doc, where)]} of every struct in the headers."""
    structs = {}
    for path in paths:
        lines = open(path, encoding="utf-8").read().split("\n")
        i = 0
        while i < len(lines):
            m = re.match(r"^struct (\w+) \{\s*$", lines[i])
            if not m:
                i += 1
                continue
            end = lines.index("};", i)
            fields = []
            for code, doc, line in statements(lines[i + 1:end], path, i + 2):
                if "(" in code.split("=")[0] or not code.endswith(";"):
                    continue  # a member function
                f = FIELD.match(code[:-1].strip())
                if not f or "," in re.sub(r"\([^()]*\)|\{[^{}]*\}", "", f.group("default") or ""):
                    raise DeclarationError(f"{path}:{line}: not a field of the fixed form: {code}")
                fields.append((f.group("type"), f.group("name"), " ".join(doc).strip(), f"{path}:{line}"))
            structs[m.group(1)] = fields
            i = end + 1
    return structs


def bound(text, where):
    if not NUMBER.match(text):
        raise DeclarationError(f"{where}: '{text}' is no number of a range")
    return float(eval(text.replace("^", "**"), {"__builtins__": {}}, {"pi": math.pi}))


def keys(structs, struct="DetectorConfig", prefix=""):
    """(type, key, lo, hi, lo_open, doc) of every setting under `struct`, in the fields' order."""
    out = []
    for type_, name, doc, where in structs[struct]:
        key = prefix + name
        if type_ in structs:
            out += keys(structs, type_, key + ".")
            continue
        if doc.startswith("not a key:"):
            continue
        if type_ not in LEAF_TYPES:
            raise DeclarationError(f"{where}: {key}: type {type_} has no key type (a setting is one of "
                                   f"{', '.join(LEAF_TYPES)})")
        lo, hi, lo_open = None, None, False
        if type_ in RANGED:
            r = RANGE.match(doc)
            if not r:
                raise DeclarationError(f"{where}: {key}: its doc must start with its range, [lo, hi] or (lo, hi]")
            lo, hi = bound(r.group("lo"), where), bound(r.group("hi"), where)
            lo_open, doc = r.group("open") == "(", r.group("doc")
        if not doc:
            raise DeclarationError(f"{where}: {key}: no doc")
        out.append((LEAF_TYPES[type_], key, lo, hi, lo_open, doc))
    return out


def cpp_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def cpp_number(v):
    return repr(float(v))


def entry(type_, key, lo, hi, lo_open, doc):
    field = f"[](DetectorConfig &c) -> {type_} & {{ return c.{key}; }}"
    kr = "KeyRange{}" if lo is None else f"KeyRange{{{cpp_number(lo)}, {cpp_number(hi)}, {str(lo_open).lower()}}}"
    if key == "aspect":
        return f"ConfigKey{{{cpp_string(key)}, KeyType::Double, {kr}, {cpp_string(doc)}, AspectField{{{field}}}}}"
    return f"declaredKey<{type_}>({cpp_string(key)}, {field}, {kr}, {cpp_string(doc)})"


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out_path, headers = argv[1], argv[2:]
    try:
        table = keys(parse_structs(headers))
    except DeclarationError as e:
        sys.exit(f"config_keys.py: {e}")
    names = ", ".join(h.split("src/")[-1] for h in headers)
    body = ",\n".join("        " + entry(*k) for k in table)
    text = f"""// Written by scripts/config_keys.py from {names}: do not edit; the settings are declared there.
#include "projsurf/frontend/settings/detector_config_table.hpp"

namespace projsurf::frontend {{

std::vector<ConfigKey> declaredConfigKeys() {{
    return {{
{body},
    }};
}}

}}  // namespace projsurf::frontend
"""
    try:
        if open(out_path, encoding="utf-8").read() == text:
            return
    except OSError:
        pass
    with open(out_path, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main(sys.argv)
