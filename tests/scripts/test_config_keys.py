#!/usr/bin/env python3
"""scripts/config_keys.py on small made-up headers: every field of DetectorConfig and the structs
it nests becomes a key (nested ones under their field's name), a field saying "not a key:" does
not, and any other field stops the build naming its line. This is what lets the key table go
without a count: a new field is a key or the build says why not. Run by ctest (config_keys_rules);
exit 0 when all hold.
  python3 tests/scripts/test_config_keys.py SOURCE_DIR"""
import os
import subprocess
import sys
import tempfile

GOOD = """struct InnerOptions {
    int steps = 3;  ///< [1, 2^24] steps taken
    double filled = 0.0;  ///< not a key: a stage fills it in
};

struct DetectorConfig {
    double width = 0.5;  ///< (0, 10] m, how wide
    ///< (more doc below)
    bool enabled = true;  ///< whether it runs
    InnerOptions inner;
};
"""

# (what is wrong, the field line put in DetectorConfig, a word the message must hold)
BAD = [
    ("a number without its range", "    double height = 1.0;  ///< m, how high\n", "must start with its range"),
    ("a type that is no setting", "    float height = 1.0f;  ///< [0, 1] m, how high\n", "has no key type"),
    ("a field without doc", "    bool on = true;\n", "no doc"),
    ("a range end that is no number", "    int n = 1;  ///< [1, many] how many\n", "is no number of a range"),
    ("no field of the fixed form", "    int a = 1, b = 2;  ///< [0, 9] two at once\n", "not a field of the fixed form"),
]


def run(script, tree, header_text):
    header = os.path.join(tree, "config.hpp")
    out = os.path.join(tree, "keys.cpp")
    with open(header, "w", encoding="utf-8") as f:
        f.write(header_text)
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([sys.executable, script, out, header], capture_output=True, text=True, check=False)
    table = open(out, encoding="utf-8").read() if os.path.exists(out) else ""
    return r.returncode, r.stderr, table


def main(argv):
    script = os.path.join(argv[1], "scripts", "config_keys.py")
    failures = []
    with tempfile.TemporaryDirectory() as tree:
        rc, err, table = run(script, tree, GOOD)
        if rc != 0:
            failures.append(f"the good header: exit {rc}: {err}")
        for key in ('"width"', '"enabled"', '"inner.steps"'):
            if key not in table:
                failures.append(f"the good header: no key {key} in the table")
        if "filled" in table:
            failures.append('the good header: the "not a key:" field is in the table')
        for what, line, word in BAD:
            text = GOOD.replace("struct DetectorConfig {\n", "struct DetectorConfig {\n" + line)
            rc, err, table = run(script, tree, text)
            # The line of the bad field: the header's 7th (DetectorConfig opens on the 6th).
            if rc == 0 or word not in err or "config.hpp:7:" not in err or table:
                failures.append(f"{what}: exit {rc}, table written: {bool(table)}, message: {err.strip()!r}")
    for f in failures:
        print("test_config_keys: " + f)
    if not failures:
        print(f"test_config_keys: {1 + len(BAD)} cases pass")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
