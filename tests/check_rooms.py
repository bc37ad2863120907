#!/usr/bin/env python3
"""The layout rules of docs/architecture.md ("The house kept in its rooms"): no folder of src/
or shaders/ holds more than 16 units directly, and no unit is over 600 lines. A unit is the
files of one stem in one folder (foo.cpp with foo.h, or a lone .h, .hpp, .cpp, .comp or .glsl);
a subfolder is a room of its own, checked by the same rule (its units are not its parent's).
Prints every folder and unit over its limit, with figures, and exits 1 on any.
Usage: check_rooms.py SOURCE_ROOT     the project's src/ and shaders/
       check_rooms.py --self-test     the rules' teeth: trees that break them must fail"""
import os
import subprocess
import sys
import tempfile

MAX_UNITS = 16
MAX_LINES = 600
EXTENSIONS = (".h", ".hpp", ".cpp", ".comp", ".glsl")
TOPS = ("src", "shaders")


def check(root):
    """Returns (violations, folders checked, units checked)."""
    violations = []
    folders = units_seen = 0
    for top in TOPS:
        base = os.path.join(root, top)
        if not os.path.isdir(base):
            violations.append(f"{top}/: missing under {root}")
            continue
        for folder, subdirs, names in os.walk(base):
            subdirs[:] = sorted(d for d in subdirs if not d.startswith((".", "__")))
            lines = {}  # stem -> lines of its files
            for name in sorted(names):
                stem, ext = os.path.splitext(name)
                if ext not in EXTENSIONS:
                    continue
                with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as f:
                    lines[stem] = lines.get(stem, 0) + sum(1 for _ in f)
            rel = os.path.relpath(folder, root).replace(os.sep, "/")
            folders += 1
            units_seen += len(lines)
            if len(lines) > MAX_UNITS:
                violations.append(f"{rel}/: {len(lines)} units > {MAX_UNITS}")
            for stem, n in sorted(lines.items()):
                if n > MAX_LINES:
                    violations.append(f"{rel}/{stem}: {n} lines > {MAX_LINES}")
    return violations, folders, units_seen


def self_test():
    """Runs this checker on made-up trees and expects exit 1 where a rule is broken, 0 where
    every figure is at its limit."""
    def tree(root, units, lines_of_big=0, subfolders=0):
        os.makedirs(os.path.join(root, "shaders"))
        room = os.path.join(root, "src", "room")
        os.makedirs(room)
        for i in range(units):
            open(os.path.join(room, f"unit{i}.h"), "w").write("// a unit\n")
            open(os.path.join(room, f"unit{i}.cpp"), "w").write("// its source\n")
        if lines_of_big:  # one unit split between header and source, as the rule reads it
            half = lines_of_big // 2
            open(os.path.join(room, "big.h"), "w").write("//\n" * half)
            open(os.path.join(room, "big.cpp"), "w").write("//\n" * (lines_of_big - half))
        for i in range(subfolders):
            sub = os.path.join(room, f"sub{i}")
            os.makedirs(sub)
            open(os.path.join(sub, "inner.comp"), "w").write("// a shader\n")

    cases = [  # (name, units, big unit's lines, subfolders, expected exit, expected text)
        ("17 units", 17, 0, 0, 1, "src/room/: 17 units > 16"),
        ("a 601-line unit", 3, 601, 0, 1, "src/room/big: 601 lines > 600"),
        ("16 units and 2 subfolders of their own", 16, 0, 2, 0, "0 over"),
        ("at the limits", 15, 600, 1, 0, "0 over"),
    ]
    failed = 0
    for name, units, big, subs, want_rc, want_text in cases:
        with tempfile.TemporaryDirectory() as root:
            tree(root, units, big, subs)
            run = subprocess.run([sys.executable, os.path.abspath(__file__), root],
                                 capture_output=True, text=True)
        ok = run.returncode == want_rc and want_text in run.stdout
        failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {name}: exit {run.returncode} (want {want_rc}), "
              f"{'says' if want_text in run.stdout else 'does not say'} '{want_text}'")
        if not ok:
            print(run.stdout + run.stderr)
    return 1 if failed else 0


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    if sys.argv[1] == "--self-test":
        return self_test()
    violations, folders, units = check(sys.argv[1])
    for line in violations:
        print(line)
    print(f"check_rooms: {folders} folders and {units} units checked, {len(violations)} over "
          f"the limits ({MAX_UNITS} units a folder, {MAX_LINES} lines a unit)")
    return 1 if violations or folders == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
