#!/usr/bin/env python3
"""The folders of src/projsurf/ as a graph: folder A -> folder B when a file in A includes
"projsurf/B/...". Fails (exit 1, one line per problem) when

  - the graph has a cycle (two folders that include each other, directly or through others);
  - a folder built by projsurf_folder() (in any CMakeLists.txt under src/projsurf) does not link exactly
    the folders its files include (an include it does not link, or a link it does not use);
  - a folder's header includes a folder it links only PRIVATE;
  - a folder's public header (`detection/planes.hpp` beside `detection/planes/`) includes
    another folder's headers, or a file of src/projsurf includes a public header;
  - the same for the sub-folders of eval/ (A -> B when a file in eval/A includes "eval/B/..."):
    a cycle, a library of projsurf_eval_folder() (eval/CMakeLists.txt) that does not link
    exactly the sub-folders its files include, a header including one it links PRIVATE, or
    a source directly in eval/ (in no sub-folder, so in no library);
  - a front end (src/cli, ros/src, python/src) includes a header of src/projsurf that is not
    installed, i.e. that no public header reaches by its includes (cmake/projsurf_library.cmake,
    projsurf_install_public_headers): an installed consumer could not do what that front end
    does. (eval/ and the tests are not front ends.)

  python3 scripts/folder_graph.py [SOURCE_DIR]       (--dot prints the graph for Graphviz)
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"projsurf/(.+)/[^/]+\.hpp"', re.M)
PUBLIC_INCLUDE = re.compile(r'^\s*#\s*include\s+"projsurf/(.+)\.hpp"', re.M)
# What projsurf_install_public_headers() follows: the same form, at the start of a line.
INSTALLED_INCLUDE = re.compile(r'^#include "projsurf/([^"]+)"', re.M)
ANY_INCLUDE = re.compile(r'^\s*#\s*include\s+"projsurf/([^"]+)"', re.M)
FRONT_ENDS = ("src/cli", "ros/src", "python/src")
FOLDER_CALL = re.compile(r"^projsurf_folder\(([^)]*)\)", re.M)
EVAL_INCLUDE = re.compile(r'^\s*#\s*include\s+"eval/(.+)/[^/]+\.hpp"', re.M)
EVAL_FOLDER_CALL = re.compile(r"^projsurf_eval_folder\(([^)]*)\)", re.M)


def is_public_header(path):
    """A folder's public header: `detection/planes.hpp` beside the folder `detection/planes/`."""
    return path.endswith(".hpp") and os.path.isdir(path[: -len(".hpp")])


def folders_of(root):
    """Every folder under src/projsurf/ holding a source or header, as 'detection/default'."""
    out = []
    for dirpath, _, files in os.walk(root):
        if any(f.endswith((".cpp", ".hpp")) and not is_public_header(os.path.join(dirpath, f)) for f in files):
            out.append(os.path.relpath(dirpath, root))
    return sorted(out)


def public_header_problems(root, folders):
    """A public header includes its own folder's headers only, and no file of src/projsurf
    includes a public header (they are for consumers: docs/library.md)."""
    problems = []
    publics = {f for f in folders if os.path.isfile(os.path.join(root, f + ".hpp"))}
    for f in sorted(publics):
        with open(os.path.join(root, f + ".hpp"), encoding="utf-8") as h:
            for target in INCLUDE.findall(h.read()):
                if target != f:
                    problems.append(f"{f}.hpp (the folder's public header) includes projsurf/{target}/")
    for dirpath, _, files in os.walk(root):
        for name in files:
            path = os.path.join(dirpath, name)
            if not name.endswith((".cpp", ".hpp")) or is_public_header(path):
                continue
            with open(path, encoding="utf-8") as h:
                for inc in PUBLIC_INCLUDE.findall(h.read()):
                    if inc in publics:
                        problems.append(f"{os.path.relpath(path, root)} includes the public header projsurf/{inc}.hpp")
    return problems


def installed_headers(root):
    """The headers projsurf_install_public_headers() installs: every folder's public header and
    what it includes, transitively ('detection/detector_config.hpp', relative to src/projsurf)."""
    todo, done = [], set()
    for dirpath, _, files in os.walk(root):
        for name in files:
            if is_public_header(os.path.join(dirpath, name)):
                todo.append(os.path.relpath(os.path.join(dirpath, name), root))
    while todo:
        header = todo.pop()
        if header in done or not os.path.isfile(os.path.join(root, header)):
            continue
        done.add(header)
        with open(os.path.join(root, header), encoding="utf-8") as h:
            todo += INSTALLED_INCLUDE.findall(h.read())
    return done


def front_end_problems(source, root):
    """A front end's include of a header of src/projsurf that is not installed."""
    installed = installed_headers(root)
    problems = []
    for front_end in FRONT_ENDS:
        for dirpath, _, files in sorted(os.walk(os.path.join(source, front_end))):
            for name in sorted(files):
                if not name.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.join(dirpath, name)
                with open(path, encoding="utf-8") as f:
                    for header in ANY_INCLUDE.findall(f.read()):
                        if header not in installed and os.path.isfile(os.path.join(root, header)):
                            problems.append(f"{os.path.relpath(path, source)} includes projsurf/{header}, which no public "
                                            "header includes (not installed: add it to its folder's public header)")
    return problems


def includes_of(root, folder, include=INCLUDE):
    """{included folder: (the first header including it or None, the first file)} for the files in `folder`."""
    found = {}
    path = os.path.join(root, folder)
    for name in sorted(os.listdir(path)):
        if not name.endswith((".cpp", ".hpp")) or is_public_header(os.path.join(path, name)):
            continue
        with open(os.path.join(path, name), encoding="utf-8") as f:
            text = f.read()
        for target in include.findall(text):
            if target == folder:
                continue
            header, first = found.get(target, (None, name))
            found[target] = (header or (name if name.endswith(".hpp") else None), first)
    return found


def declared_links(cmake_text, folders, call_re=FOLDER_CALL, prefix="projsurf_"):
    """{folder: {linked folder: 'PUBLIC'|'PRIVATE'}} from the projsurf_folder() calls."""
    by_target = {prefix + f.replace("/", "_"): f for f in folders}
    out = {}
    for call in call_re.findall(cmake_text):
        words = call.split()
        folder, scope, links = words[0], "PUBLIC", {}
        for w in words[1:]:
            if w in ("PUBLIC", "PRIVATE", "INTERFACE"):
                scope = w
            elif w in by_target:
                links[by_target[w]] = scope
        out[folder] = links
    return out


def link_problems(links, uses, prefix="projsurf_", include_root="projsurf/"):
    """Each library links exactly the folders its files include, PUBLIC when a header does."""
    problems = []
    for folder, linked in sorted(links.items()):
        for g, (header, first) in sorted(uses.get(folder, {}).items()):
            target = prefix + g.replace("/", "_")
            if g not in linked:
                problems.append(f"{folder}: {first} includes {include_root}{g}/ but its library does not link {target}")
            elif header and linked[g] == "PRIVATE":
                problems.append(f"{folder}: the header {header} includes {include_root}{g}/, but {target} is linked PRIVATE")
        for g in sorted(set(linked) - set(uses.get(folder, {}))):
            problems.append(f"{folder}: links {prefix}{g.replace('/', '_')} but includes nothing of {g}/")
    return problems


def check_eval(source):
    """eval/'s sub-folders, one library each (projsurf_eval_folder() in eval/CMakeLists.txt):
    (problems, (folders, edges, libraries))."""
    root = os.path.join(source, "eval")
    if not os.path.isdir(root):
        return [], (0, 0, 0)
    problems = [f"eval/{name} is in no sub-folder of eval/, so in no library"
                for name in sorted(os.listdir(root)) if name.endswith((".cpp", ".hpp"))]
    folders = sorted(d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d)))
    uses = {f: includes_of(root, f, EVAL_INCLUDE) for f in folders}
    graph = {f: set(uses[f]) for f in folders}
    for f in folders:
        for g in sorted(graph[f]):
            if g not in folders:
                problems.append(f"eval/{f}: includes eval/{g}/, which is no sub-folder of eval/")
    cycle = find_cycle(graph)
    if cycle:
        problems.append("cycle between eval/'s sub-folders: " + " -> ".join(cycle))
    cmake = os.path.join(root, "CMakeLists.txt")
    text = open(cmake, encoding="utf-8").read() if os.path.isfile(cmake) else ""
    links = declared_links(text, folders, EVAL_FOLDER_CALL, "projsurf_eval_")
    for f in folders:
        if f not in links:
            problems.append(f"eval/{f}: no projsurf_eval_folder({f} ...) in eval/CMakeLists.txt")
    problems += ["eval/" + p for p in link_problems(links, uses, "projsurf_eval_", "eval/")]
    return problems, (len(folders), sum(len(g) for g in graph.values()), len(links))


def find_cycle(graph):
    """One cycle as a list of folders, or None (depth-first search, three colours)."""
    state, stack = {}, []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if state.get(nxt) is None:
                cycle = visit(nxt)
                if cycle:
                    return cycle
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if state.get(node) is None:
            cycle = visit(node)
            if cycle:
                return cycle
    return None


def main(argv):
    source = next((a for a in argv[1:] if not a.startswith("--")), os.path.join(os.path.dirname(__file__), ".."))
    root = os.path.join(source, "src", "projsurf")
    folders = folders_of(root)
    uses = {f: includes_of(root, f) for f in folders}
    graph = {f: set(uses[f]) for f in folders}
    if "--dot" in argv:
        print("digraph projsurf {")
        for f in folders:
            for g in sorted(graph[f]):
                print(f'  "{f}" -> "{g}";')
        print("}")
        return 0

    problems = []
    for f in folders:
        for g in graph[f]:
            if g not in folders:
                problems.append(f"{f}: includes projsurf/{g}/, which is no folder of src/projsurf")
    problems += public_header_problems(root, folders)
    problems += front_end_problems(source, root)
    cycle = find_cycle(graph)
    if cycle:
        problems.append("cycle between folders: " + " -> ".join(cycle))

    cmake_text = ""
    for dirpath, _, files in sorted(os.walk(root)):
        if "CMakeLists.txt" in files:
            with open(os.path.join(dirpath, "CMakeLists.txt"), encoding="utf-8") as f:
                cmake_text += f.read() + "\n"
    links = declared_links(cmake_text, folders)
    problems += link_problems(links, uses)
    eval_problems, eval_counts = check_eval(source)
    problems += eval_problems

    for p in problems:
        print("folder_graph: " + p)
    if problems:
        return 1
    print(f"folder_graph: {len(folders)} folders, {sum(len(g) for g in graph.values())} edges, no cycle; "
          f"{len(links)} folder libraries link exactly what they include; the front ends include installed "
          f"headers only; eval/: {eval_counts[0]} sub-folders, {eval_counts[1]} edges, no cycle, "
          f"{eval_counts[2]} libraries link exactly the sub-folders they include")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
