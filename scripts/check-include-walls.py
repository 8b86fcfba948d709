#!/usr/bin/env python3
"""The walls between modules, checked before anything links: every `#include "MODULE/..."` (or "../MODULE/...") in
src/ and include/ must follow an arrow of src/modules.txt, directly or through other modules' arrows, and every
folder of src/ and tests/ must be a module there. A module's include path holds all of src/, so without this an
upward include compiles and shows only at link time, if at all (a header-only use never does).

Rules, from src/modules.txt:
  - src/MODULE/ includes its own headers and those of the modules its arrows reach;
  - include/tcsb/ (the public headers) includes itself (tcsb/...) and library modules only;
  - a library module's header, installed under include/tcsb/MODULE/, names a module's header relative to itself
    ("../net/net.h"): a user's include path holds no "net/" of ours, and may hold one of its own;
  - the table itself: every arrow points to a module on a line above, and a library module's only to library ones;
  - every folder of src/ and of tests/ is a module of the table (CMake builds the tests of its modules only);
  - the public headers (include/tcsb/*.h, what a user reads) reach, directly or through each other, only the
    library headers of the API (API_HEADERS below); any other header of a library module is an implementation
    header (dbvt_local.h, incidence_list.h, op_sample.h, tc_softbody_impl.h, ...), which a user must not need.

Usage: python3 scripts/check-include-walls.py [--root DIR]
       python3 scripts/check-include-walls.py --self-test
Exit 0: every include keeps to the table; 1: a forbidden include or an unlisted folder (each named FILE:LINE);
2: bad arguments, or a table it cannot read.
"""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

TABLE = pathlib.Path("src/modules.txt")
PARTS = ("library", "harness", "program")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCES = ("*.h", "*.cpp", "*.h.in")
# The library headers the public headers may reach (docs/library.md lists them): the net and its tree, the body with
# its settings and solver, the listener, the controller and driver with their settings and the world budget, the
# camera. Every other
# header of a library module is an implementation header: installed, because the harness shares the module, but
# never reached from include/tcsb/*.h.
API_HEADERS = {
    "net/net.h", "net/lod_tree.h", "net/net_spec.h",
    "softbody/tc_softbody.h", "softbody/tc_settings.h", "softbody/solver_settings.h", "softbody/material.h",
    "softbody/tc_softbody_solver.h", "softbody/cut_listener.h", "softbody/op_kind.h",
    "feedback/controller.h", "feedback/feedback_settings.h", "feedback/presets.h", "feedback/tree_cut_driver.h",
    "feedback/world_budget.h",
    "view/camera.h", "view/keyframe_path.h", "view/screen_projection.h",
}


class TableError(Exception):
    pass


def read_table(root):
    """{module: (part, [arrows])}, in the table's order; raises TableError naming the line."""
    path = root / TABLE
    try:
        lines = path.read_text().splitlines()
    except OSError as e:
        raise TableError(f"{path}: {e.strerror}")
    modules = {}
    for number, line in enumerate(lines, 1):
        fields = line.split("#", 1)[0].split()
        if not fields:
            continue
        where = f"{TABLE}:{number}"
        if len(fields) < 2:
            raise TableError(f"{where}: a module needs a part ({', '.join(PARTS)})")
        module, part, arrows = fields[0], fields[1], fields[2:]
        if part not in PARTS:
            raise TableError(f"{where}: {module}: part must be one of {', '.join(PARTS)}, got {part}")
        if module in modules:
            raise TableError(f"{where}: {module} is listed twice")
        for arrow in arrows:
            if arrow not in modules:
                raise TableError(f"{where}: {module} -> {arrow}: an arrow must point to a module on a line above")
            if part == "library" and modules[arrow][0] != "library":
                raise TableError(f"{where}: {module} -> {arrow}: a library module reaches library modules only")
        modules[module] = (part, arrows)
    if not modules:
        raise TableError(f"{TABLE}: names no module")
    return modules


def reach(modules):
    """{module: the modules it may include}: itself and what its arrows reach. Arrows point upwards in the table,
    so one pass in its order closes them."""
    reached = {}
    for module, (_, arrows) in modules.items():
        reached[module] = {module}.union(*(reached[a] for a in arrows))
    return reached


def included_folder(name):
    """The folder an include names ("net" for "net/net.h" and "../net/net.h"), None for a file beside the includer."""
    parts = pathlib.PurePosixPath(name).parts
    if parts and parts[0] == "..":
        parts = parts[1:]
    return parts[0] if len(parts) > 1 else None


def sources(folder):
    return sorted(f for pattern in SOURCES for f in folder.rglob(pattern) if f.is_file())


def violations(root):
    """Every broken wall as "FILE:LINE: why", and the number of module includes checked."""
    modules = read_table(root)
    reached = reach(modules)
    library = {m for m, (part, _) in modules.items() if part == "library"}
    found, checked = [], 0
    src = root / "src"
    folders = sorted(d.name for d in src.iterdir() if d.is_dir()) if src.is_dir() else []
    for folder in folders:
        if folder not in modules:
            found.append(f"src/{folder}/: a folder that {TABLE} does not name (add its line and arrows)")
    for module in modules:
        if module not in folders:
            found.append(f"{TABLE}: {module} has no folder src/{module}/")
    # CMake builds tests/MODULE/ for the modules of the table only: any other folder's tests would never run.
    tests = root / "tests"
    for folder in sorted(d.name for d in tests.iterdir() if d.is_dir()) if tests.is_dir() else []:
        if folder not in modules:
            found.append(f"tests/{folder}/: tests of no module of {TABLE}, which CMake would not build")
    # (folder, the modules its files may include, how to say so, whether its headers are installed)
    scopes = [(src / m, reached[m], f"{m} may include {', '.join(sorted(reached[m]))}", m in library)
              for m in folders if m in modules]
    scopes.append((root / "include", library | {"tcsb"}, "the public headers may include library modules only: "
                   + ", ".join(sorted(library)), False))
    for folder, allowed, rule, installed in scopes:
        for path in sources(folder):
            relative_only = installed and path.suffix == ".h"
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                target = included_folder(match.group(1))
                if target is None:
                    continue
                checked += 1
                if target not in allowed:
                    name = path.relative_to(root).as_posix()
                    known = "" if target in modules or target == "tcsb" else f" ({target}/ is not a module)"
                    found.append(f'{name}:{number}: "{match.group(1)}"{known}: {rule} ({TABLE})')
                elif relative_only and not match.group(1).startswith("../"):
                    name = path.relative_to(root).as_posix()
                    found.append(f'{name}:{number}: "{match.group(1)}": an installed header names a module\'s header '
                                 f'relative to itself, "../{match.group(1)}" ({TABLE})')
    return found, checked


def quoted_includes(path):
    """(line number, included name) of every #include "..." of a file."""
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        match = INCLUDE.match(line)
        if match:
            yield number, match.group(1)


def implementation_reached(root):
    """Every implementation header a public header reaches, as "FILE:LINE: why". A public header names another one
    as "tcsb/X.h" and a library header as "MODULE/X.h" (installed beside it); a library header names another as
    "../MODULE/X.h"."""
    found = []
    public = root / "include" / "tcsb"
    for start in sorted(public.glob("*.h")) if public.is_dir() else []:
        seen = set()
        stack = [(start, None)]
        while stack:
            path, module = stack.pop()
            for number, name in quoted_includes(path):
                parts = pathlib.PurePosixPath(name).parts
                if parts and parts[0] == "..":
                    parts = parts[1:]
                if len(parts) != 2:
                    continue
                if module is None and parts[0] == "tcsb":
                    target, key = public / parts[1], None
                else:
                    key = "/".join(parts)
                    target = root / "src" / key
                    if key not in API_HEADERS:
                        where = path.relative_to(root).as_posix()
                        found.append(f'{where}:{number}: "{name}" is an implementation header, reached from '
                                     f"{start.relative_to(root).as_posix()}: the public headers reach only the API's "
                                     f"(API_HEADERS in {pathlib.Path(__file__).name}; docs/library.md)")
                        continue
                if target in seen or not target.is_file():
                    continue
                seen.add(target)
                stack.append((target, key))
    return sorted(set(found))


def check(root):
    try:
        found, checked = violations(root)
        found += implementation_reached(root)
    except TableError as e:
        print(f"check-include-walls: {e}", file=sys.stderr)
        return 2
    for v in found:
        print(v, file=sys.stderr)
    if found:
        print(f"check-include-walls: {len(found)} broken walls", file=sys.stderr)
        return 1
    print(f"check-include-walls: {checked} module includes keep to {TABLE}")
    return 0


def self_test(repo):
    """The real table over scratch trees: a clean tree passes, each kind of forbidden include fails, by name."""
    ok = True

    def run(files, expect, mentions=""):
        nonlocal ok
        with tempfile.TemporaryDirectory() as scratch:
            root = pathlib.Path(scratch)
            (root / TABLE).parent.mkdir(parents=True)
            shutil.copy(repo / TABLE, root / TABLE)
            for module in read_table(root):
                (root / "src" / module).mkdir()
            for name, text in files.items():
                (root / name).parent.mkdir(parents=True, exist_ok=True)
                (root / name).write_text(text)
            result = subprocess.run([sys.executable, __file__, "--root", str(root)], capture_output=True, text=True)
        if result.returncode != expect or mentions not in result.stderr:
            ok = False
            print(f"self-test: {sorted(files)}: expected exit {expect} naming '{mentions}', got {result.returncode}:\n"
                  f"{result.stderr}", file=sys.stderr)

    clean = {
        "src/softbody/body.h": '#include "../net/net.h"\n#include "../softbody/body_part.h"\n',
        "src/softbody/body.cpp": '#include "softbody/body.h"\n#include "net/lod_tree.h"\n#include "body_part.h"\n',
        "src/cli/main.cpp": '#include "report/console_report.h"\n#include "net/net.h"\n',
        "include/tcsb/tcsb.h": '#include "tcsb/net.h"\n#include "feedback/controller.h"\n',
    }
    run(clean, 0)
    run({**clean, "src/net/upward.h": '#pragma once\n#include "softbody/tc_softbody.h"\n'}, 1, "src/net/upward.h:2")
    run({"src/net/relative.h": '#include "../feedback/controller.h"\n'}, 1, "src/net/relative.h:1")
    run({"src/feedback/harness.cpp": '#include "suite/suite.h"\n'}, 1, "src/feedback/harness.cpp:1")
    run({"src/gate/sideways.cpp": '#include "run/runner.h"\n'}, 1, "src/gate/sideways.cpp:1")
    run({"include/tcsb/public.h": '#include "suite/suite.h"\n'}, 1, "include/tcsb/public.h:1")
    run({"src/case/unknown.h": '#include "nowhere/thing.h"\n'}, 1, "nowhere/ is not a module")
    run({"src/newmodule/a.cpp": "int a;\n"}, 1, "src/newmodule/")
    run({"tests/nomodule/a_test.cpp": "int a;\n"}, 1, "tests/nomodule/")
    run({"src/feedback/installed.h": '#include "softbody/tc_softbody.h"\n'}, 1, '"../softbody/tc_softbody.h"')
    run({"include/tcsb/body.h": '#include "softbody/dbvt_local.h"\n'}, 1, "include/tcsb/body.h:1")
    run({"include/tcsb/tcsb.h": '#include "tcsb/body.h"\n', "include/tcsb/body.h": '#include "softbody/tc_softbody.h"\n',
         "src/softbody/tc_softbody.h": '#pragma once\n#include "../softbody/incidence_list.h"\n'},
        1, "src/softbody/tc_softbody.h:2")
    if ok:
        print("check-include-walls self-test: ok")
    return 0 if ok else 1


class OneLineParser(argparse.ArgumentParser):
    """Bad arguments: exit 2 and one line, as the other scripts' (argparse prints its usage on a second line)."""

    def error(self, message):
        print(f"check-include-walls: {message} (usage: check-include-walls.py [--root DIR] | --self-test)",
              file=sys.stderr)
        sys.exit(2)


def main():
    repo = pathlib.Path(__file__).resolve().parent.parent
    parser = OneLineParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=pathlib.Path, default=repo, help="the source tree (default: this one)")
    parser.add_argument("--self-test", action="store_true", help="check the checker on scratch trees")
    args = parser.parse_args()
    return self_test(repo) if args.self_test else check(args.root)


if __name__ == "__main__":
    sys.exit(main())
