#!/usr/bin/env python3
"""scripts/folder_graph.py on small made-up trees: the rule that the front ends include installed
headers only (reached from a public header) fails naming the file and the header, and passes once
the public header includes it. Run by ctest (folder_graph_rules); exit 0 when all hold.
  python3 tests/scripts/test_folder_graph.py SOURCE_DIR"""
import os
import subprocess
import sys
import tempfile


def write(root, path, text=""):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w", encoding="utf-8") as f:
        f.write(text)


def run(script, tree):
    r = subprocess.run([sys.executable, script, tree], capture_output=True, text=True, check=False)
    return r.returncode, r.stdout


def main(argv):
    script = os.path.join(argv[1], "scripts", "folder_graph.py")
    failures = []
    with tempfile.TemporaryDirectory() as tree:
        # One folder, its public header offering shown.hpp (and, through it, reached.hpp); hidden.hpp
        # is reached by nothing.
        write(tree, "src/projsurf/CMakeLists.txt", "projsurf_folder(things)\n")
        write(tree, "src/projsurf/things.hpp", '#pragma once\n#include "projsurf/things/shown.hpp"\n')
        write(tree, "src/projsurf/things/shown.hpp", '#pragma once\n#include "projsurf/things/reached.hpp"\n')
        write(tree, "src/projsurf/things/reached.hpp", "#pragma once\n")
        write(tree, "src/projsurf/things/hidden.hpp", "#pragma once\n")
        write(tree, "src/projsurf/things/shown.cpp", '#include "projsurf/things/hidden.hpp"\n')
        write(tree, "src/cli/main.cpp", '#include "projsurf/things/reached.hpp"\n')
        write(tree, "eval/CMakeLists.txt", "projsurf_eval_folder(report)\n")
        write(tree, "eval/report/report.cpp", '#include "projsurf/things/hidden.hpp"\n')  # not a front end
        write(tree, "tests/t.cpp", '#include "projsurf/things/hidden.hpp"\n')  # nor the tests
        rc, out = run(script, tree)
        if rc != 0:
            failures.append(f"installed includes only: exit {rc}, expected 0:\n{out}")

        write(tree, "ros/src/node.cpp", '#include "projsurf/things/hidden.hpp"\n')
        rc, out = run(script, tree)
        expected = "folder_graph: ros/src/node.cpp includes projsurf/things/hidden.hpp, which no public header"
        if rc != 1 or expected not in out or out.count("\n") != 1:
            failures.append(f"the node including hidden.hpp: exit {rc}, expected 1 and one line '{expected}...':\n{out}")

        write(tree, "src/projsurf/things.hpp",
              '#pragma once\n#include "projsurf/things/hidden.hpp"\n#include "projsurf/things/shown.hpp"\n')
        rc, out = run(script, tree)
        if rc != 0:
            failures.append(f"hidden.hpp in the public header: exit {rc}, expected 0:\n{out}")
    for f in failures:
        print("test_folder_graph: " + f)
    if not failures:
        print("test_folder_graph: 3 cases pass")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
