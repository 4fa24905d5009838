#!/usr/bin/env python3
"""Fails on a test file that does not mirror a source (CONTRIBUTING.md, "Tests and benchmarks").

A unit test of `<layer>/<folder>/Name.cpp` (or `.h`, `.py`) is `tests/<layer>/<folder>/test_Name.cpp`
(or `.py`); a test whose subject is a whole scenario (a garment on a body, a program's
command line, shipped scenes, Coin's own bugs) lives in a `scenarios/` folder of its layer,
or in tests/scenes/. So a reader finds a source's tests by its name, and a scenario's by
its folder.

  scripts/check-test-layout.py [ROOT]   (default: the repository root; exit 1 and one line a finding)
"""
import pathlib
import sys

# coin-bugs: the reproducers of Coin's own bugs, beside their scene files.
SCENARIO_FOLDERS = {"scenarios", "scenes", "coin-bugs"}
SOURCE_SUFFIXES = (".cpp", ".h", ".py")


def findings(root):
    tests = root / "tests"
    for path in sorted(tests.rglob("test_*")):
        if path.suffix not in (".cpp", ".py"):
            continue
        relative = path.relative_to(tests)
        if SCENARIO_FOLDERS & set(relative.parts[:-1]):
            continue
        subject = relative.parent / path.stem[len("test_"):]
        if any((root / subject).with_suffix(suffix).exists() for suffix in SOURCE_SUFFIXES):
            continue
        yield (f"tests/{relative}: mirrors no source ({subject}.cpp/.h/.py); a scenario test "
               f"goes in tests/{relative.parts[0]}/scenarios/")


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    found = list(findings(root))
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
