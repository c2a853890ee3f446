#!/usr/bin/env python3
"""Lists the C++ functions longer than a screen: from the first line of the signature to the
closing brace, over --max lines (80). Exit 1 when it lists any.

  python3 scripts/long_functions.py [--max 80] [--exclude DIR]... [--allow FILE] PATH...

--allow FILE names functions still waiting to be split, one "path: name" a line ('#' starts
a comment): they are listed but do not fail, and an entry that is no longer long fails (so
the file only shrinks).

PATH is a .cpp/.hpp file or a folder (searched recursively). A function is a brace block at
namespace or class level whose head (the text since the last ';', '{' or '}') holds a '(' and
is not a control statement; lambdas and blocks inside a function count towards it.
"""
import argparse
import os
import re
import sys

CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else|return)\b")
NOT_FUNCTION = re.compile(r"^\s*(namespace|struct|class|union|enum|extern)\b|=\s*$")


def code_only(text):
    """The text with comments, preprocessor lines, string and character literals blanked
    (newlines kept)."""
    text = re.sub(r"(?m)^[ \t]*#(?:[^\n]*\\\n)*[^\n]*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, last line) of every function defined in the file."""
    with open(path, encoding="utf-8", errors="replace") as f:
        text = code_only(f.read())
    found = []
    stack = []  # per open brace: True if it is (inside) a function body
    head_start = 0  # offset where the current head began
    line_of = [0]
    for ch in text:
        line_of.append(line_of[-1] + (ch == "\n"))
    for i, ch in enumerate(text):
        if ch in ";{}":
            in_function = bool(stack) and bool(stack[-1])  # a function's brace is a tuple: true
            if ch == "{":
                head = text[head_start:i]
                is_function = (not in_function and "(" in head and not CONTROL.match(head)
                               and not NOT_FUNCTION.search(head.split("(")[0]))
                if is_function:
                    name = re.findall(r"([~\w:]+|operator\s*\S+)\s*\(", head)
                    first = head_start + len(head) - len(head.lstrip())
                    stack.append(("fn", name[0] if name else "?", line_of[first] + 1))
                else:
                    stack.append(in_function)
            elif ch == "}" and stack:
                top = stack.pop()
                if isinstance(top, tuple):
                    found.append((top[1], top[2], line_of[i] + 1))
            head_start = i + 1
    return found


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--max", type=int, default=80)
    ap.add_argument("--exclude", action="append", default=[])
    ap.add_argument("--allow")
    ap.add_argument("paths", nargs="+")
    args = ap.parse_args(argv[1:])
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
    excluded = [os.path.abspath(e) for e in args.exclude]
    files = []
    for p in args.paths:
        if os.path.isdir(p):
            for d, _, names in os.walk(p):
                files += [os.path.join(d, n) for n in names if n.endswith((".cpp", ".hpp"))]
        else:
            files.append(p)
    long = []
    for f in sorted(files):
        a = os.path.abspath(f)
        if any(a.startswith(e + os.sep) or a == e for e in excluded):
            continue
        shown = os.path.relpath(a, root) if a.startswith(root + os.sep) else f  # as the allow file names it
        for name, first, last in functions(a):
            if last - first + 1 > args.max:
                long.append((last - first + 1, shown, first, name))
    allowed = set()
    if args.allow:
        with open(args.allow, encoding="utf-8") as f:
            for line in f:
                line = line.split("#")[0].strip()
                if line:
                    path, _, name = line.partition(":")
                    allowed.add((os.path.normpath(path.strip()), name.strip()))
    failed = False
    for lines, f, first, name in sorted(long, reverse=True):
        waiting = (os.path.normpath(f), name) in allowed
        failed |= not waiting
        print(f"{f}:{first}: {name}: {lines} lines" + (" (allowed, waiting to be split)" if waiting else ""))
    still_long = {(os.path.normpath(f), name) for _, f, _, name in long}
    for path, name in sorted(allowed - still_long):
        print(f"{path}: {name}: allowed as long but is not (any more): take it off {args.allow}")
        failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
