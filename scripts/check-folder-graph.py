#!/usr/bin/python3
"""Checks the include graph of core/ (issue 15, item 3): the standard library only, runs anywhere.

  scripts/check-folder-graph.py            fails on a Qt/OpenGL include in core, a Qt/OpenGL library linked
                                            by core/CMakeLists.txt, or a folder dependency that is neither
                                            allowed nor listed as known debt
  scripts/check-folder-graph.py --strict   also fails on the known debt (the goal: an empty KNOWN_DEBT)
  scripts/check-folder-graph.py --graph    prints every folder dependency with one example include

A folder of core/ may include headers of the folders ALLOWED lists for it: the intended one-way graph,
lowest folder first. KNOWN_DEBT lists today's dependencies that break it (they close cycles) and what
would have to move to remove each; a new dependency outside both lists fails, so the debt cannot grow.
A debt entry that is gone is reported, to be deleted from the list.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORE = os.path.join(ROOT, "core")
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".def", ".inl", ".glsl")

# The intended layers, lowest first; a folder may include the folders listed for it.
ALLOWED = {
    "util": set(),
    "model": set(),  # the one-source GLSL/C++ kernels (model/kernels) and the noise's C++ interface
    "image": {"util"},  # in-memory images; their files are io/'s
    "geometry": {"util"},
    "params": {"util"},
    "field": {"util", "geometry", "params", "model"},
    "material": {"field", "model", "params"},  # the wood kernels' CPU back-end (material/wood_kernels.hpp)
    "render": {"util", "image", "geometry", "params", "field", "material"},
    "rings": {"util", "image", "geometry", "render"},
    "io": {"util", "image", "geometry", "params", "field", "render", "rings"},
    "fit": {"util", "image", "geometry", "params", "field", "model", "material", "render", "rings", "io"},
    # texture/ locates crop points in the tree once and shades them per candidate (WoodMaterial::locate/shade)
    "texture": {"util", "image", "geometry", "params", "field", "material", "render", "io", "fit"},
    "appearance": {"util", "image", "geometry", "params", "field", "render", "io"},  # photo-true, beside texture
    "mesh": {"util", "image", "geometry", "render", "io"},
    # field: the ring uncertainty volume; appearance: images, depth stacks and parts in the photo-true appearance
    "export": {"util", "image", "geometry", "field", "render", "io", "mesh", "appearance"},
    "demo": {"util", "image", "model", "material", "render", "rings", "io"},
}

# Dependencies that break the layering today (each closes a cycle), and what would have to move. Empty:
# the graph is one-way (issue 15 item 3); a new entry needs a reason and a plan to remove it.
KNOWN_DEBT = {}

# Qt or OpenGL headers, which core must never include (core/ builds without them).
QT_GL_INCLUDE = re.compile(
    r"#\s*include\s*[<\"](Q[A-Z]\w*|Qt\w*/|q\w+\.h|GL/|GLES\d*/|EGL/|KHR/|epoxy/|glad/|GLFW/)")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
QT_GL_LINK = re.compile(r"\b(Qt[56]?::\w+|OpenGL::\w+|Qt[56]?(Core|Gui|Widgets|OpenGL)\b)")


def sources():
    for folder, _, files in os.walk(CORE):
        for name in sorted(files):
            if name.endswith(SOURCE_SUFFIXES):
                yield os.path.join(folder, name)


def folder_of(path):
    parts = os.path.relpath(path, CORE).split(os.sep)
    return parts[0] if len(parts) > 1 else None


def scan():
    """(edges: {(from, to): first 'file -> include'}, problems: [str])"""
    edges, problems = {}, []
    for path in sources():
        source = folder_of(path)
        rel = os.path.relpath(path, ROOT)
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                if QT_GL_INCLUDE.search(line):
                    problems.append(f"{rel}:{number}: Qt/OpenGL include in core: {line.strip()}")
                m = INCLUDE.match(line)
                if not m or source is None:
                    continue
                target = m.group(1).split("/")[0] if "/" in m.group(1) else source
                if target != source and os.path.isdir(os.path.join(CORE, target)):
                    edges.setdefault((source, target), f"{rel}:{number} -> {m.group(1)}")
    cmake = os.path.join(CORE, "CMakeLists.txt")
    if os.path.exists(cmake):
        with open(cmake, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                code = line.split("#", 1)[0]
                if QT_GL_LINK.search(code):
                    problems.append(f"core/CMakeLists.txt:{number}: core links Qt/OpenGL: {line.strip()}")
    return edges, problems


def cycles(nodes, edges):
    """Strongly connected components with more than one folder (Tarjan)."""
    successors = {n: sorted(t for (s, t) in edges if s == n) for n in nodes}
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(n):
        index[n] = low[n] = len(index)
        stack.append(n)
        on_stack.add(n)
        for m in successors[n]:
            if m not in index:
                visit(m)
                low[n] = min(low[n], low[m])
            elif m in on_stack:
                low[n] = min(low[n], index[m])
        if low[n] == index[n]:
            component = []
            while True:
                m = stack.pop()
                on_stack.discard(m)
                component.append(m)
                if m == n:
                    break
            if len(component) > 1:
                out.append(sorted(component))

    for n in sorted(nodes):
        if n not in index:
            visit(n)
    return out


def main(argv):
    strict, show = "--strict" in argv, "--graph" in argv
    unknown = [a for a in argv if a not in ("--strict", "--graph")]
    if unknown:
        print(__doc__.strip())
        return 2
    allowed_edges = {(s, t) for s, targets in ALLOWED.items() for t in targets}
    if cycles(ALLOWED, allowed_edges):
        print("check-folder-graph.py: ALLOWED itself has a cycle:", cycles(ALLOWED, allowed_edges))
        return 2
    folders = sorted(d for d in os.listdir(CORE) if os.path.isdir(os.path.join(CORE, d)))
    edges, problems = scan()
    for folder in folders:
        if folder not in ALLOWED:
            problems.append(f"core/{folder}/ is a new folder: give it a place in ALLOWED")
    debt = []
    for (s, t), example in sorted(edges.items()):
        if (s, t) in allowed_edges:
            continue
        if (s, t) in KNOWN_DEBT:
            debt.append(f"{s} -> {t} ({example}): {KNOWN_DEBT[(s, t)]}")
        else:
            problems.append(f"core/{s}/ may not include core/{t}/ (not in ALLOWED): {example}")
    gone = [f"{s} -> {t}" for (s, t) in KNOWN_DEBT if (s, t) not in edges]

    if show:
        for (s, t), example in sorted(edges.items()):
            print(f"{s:>9} -> {t:<9} {example}")
    print(f"core/: {len(folders)} folders, {len(edges)} folder dependencies")
    for component in cycles(folders, edges):
        print("cycle:", " <-> ".join(component))
    for line in debt:
        print("known debt:", line)
    for line in gone:
        print(f"debt paid: {line} no longer exists; delete it from KNOWN_DEBT")
    for line in problems:
        print("error:", line)
    if problems or (strict and debt):
        print("check-folder-graph.py: FAILED")
        return 1
    print("check-folder-graph.py: ok" + ("" if not debt else f" ({len(debt)} known debt entries)"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
