#!/usr/bin/python3
"""Checks that the headless GPU renderer stays headless (issue 15, item 3): the standard library only.

  scripts/check-gpu-target.py   fails when a source of gpu/ includes a Qt Widgets header or a header of
                                widgets/, when gpu/CMakeLists.txt links Qt Widgets or kerf_widgets, or when
                                kerf-cli's commands (app/cli/) include a header of widgets/ or link
                                kerf_widgets: kerf_gpu is Qt Gui and OpenGL only, so kerf-cli renders
                                offscreen without Qt Widgets.
"""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
# Qt Widgets and Qt OpenGL Widgets, by module path; their class headers come from the installed Qt where
# there is one, else the few that a renderer would be tempted to use.
WIDGETS_MODULES = ("QtWidgets", "QtOpenGLWidgets")
FALLBACK_WIDGETS_HEADERS = {"QWidget", "QApplication", "QOpenGLWidget", "QMainWindow", "QLabel"}
WIDGETS_LINK = re.compile(r"\b(Qt[56]?::(Widgets|OpenGLWidgets)|kerf_widgets)\b")


def installed_widgets_headers():
    names = set()
    for module in WIDGETS_MODULES:
        for folder in glob.glob(f"/usr/include/*/qt6/{module}") + glob.glob(f"/usr/include/qt6/{module}"):
            names.update(n for n in os.listdir(folder) if n.startswith("Q") and "." not in n)
    return names or FALLBACK_WIDGETS_HEADERS


def widgets_own_headers():
    folder = os.path.join(ROOT, "widgets")
    return {n for n in os.listdir(folder) if n.endswith((".hpp", ".h"))} if os.path.isdir(folder) else set()


def sources(folder):
    for path in sorted(glob.glob(os.path.join(ROOT, folder, "**", "*"), recursive=True)):
        if path.endswith(SOURCE_SUFFIXES):
            yield path


def include_problems(folder, qt_widgets, own_widgets):
    problems = []
    for path in sources(folder):
        rel = os.path.relpath(path, ROOT)
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                name = m.group(2)
                module = name.split("/")[0]
                if qt_widgets is not None and (module in WIDGETS_MODULES or name in qt_widgets):
                    problems.append(f"{rel}:{number}: Qt Widgets header: {line.strip()}")
                elif m.group(1) == '"' and "/" not in name and name in own_widgets and \
                        not os.path.exists(os.path.join(os.path.dirname(path), name)):
                    problems.append(f"{rel}:{number}: header of widgets/: {line.strip()}")
    return problems


def link_problems(cmake, target):
    """Lines of `cmake` that link `target` (or, without one, anything) to Qt Widgets or kerf_widgets."""
    problems = []
    path = os.path.join(ROOT, cmake)
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            code = line.split("#", 1)[0]
            if "target_link_libraries" in code and (target is None or target in code) and \
                    WIDGETS_LINK.search(code):
                problems.append(f"{cmake}:{number}: links Qt Widgets: {line.strip()}")
    return problems


def main(argv):
    if argv:
        print(__doc__.strip())
        return 2
    qt_widgets, own_widgets = installed_widgets_headers(), widgets_own_headers()
    problems = include_problems("gpu", qt_widgets, own_widgets)
    problems += include_problems(os.path.join("app", "cli"), None, own_widgets)
    problems += link_problems(os.path.join("gpu", "CMakeLists.txt"), None)
    problems += link_problems(os.path.join("app", "CMakeLists.txt"), "kerf_cli_commands")
    for line in problems:
        print("error:", line)
    if problems:
        print("check-gpu-target.py: FAILED")
        return 1
    print("check-gpu-target.py: ok (gpu/ and kerf-cli's commands use no Qt Widgets)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
