#!/usr/bin/env python3
"""Tests mirror their sources, both ways (CONTRIBUTING.md, "Tests and benchmarks").

A unit test of `<layer>/<folder>/Name.cpp` (or `.h`, `.py`) is `tests/<layer>/<folder>/test_Name.cpp`
(or `.py`); a test whose subject is a whole scenario (a garment on a body, a program's
command line, shipped scenes, Coin's own bugs) lives in a `scenarios/` folder of its layer,
or in tests/scenes/. So a reader finds a source's tests by its name, and a scenario's by
its folder. Two rules:
  - a test file that mirrors no source is a finding;
  - a source (a .cpp with its .h beside it, under one of SOURCE_LAYERS) without its mirrored
    test is named, and the check fails when fewer than MIN_MIRRORED of the sources have one.
A program's entry point (main.cpp, precompute.cpp, a tool's make_dress.cpp) has no header,
so it is no source here: its tests are its command line's, in scenarios/. EXEMPT names the
few sources with a header that have no test of their own, each with why.

  scripts/check-test-layout.py [ROOT]   (default: the repository root; exit 1 when a test
                                          mirrors nothing or the share is below MIN_MIRRORED;
                                          one line a finding, then the share)
"""
import fnmatch
import pathlib
import sys

# coin-bugs: the reproducers of Coin's own bugs, beside their scene files.
SCENARIO_FOLDERS = {"scenarios", "scenes", "coin-bugs"}
SOURCE_SUFFIXES = (".cpp", ".h", ".py")
SOURCE_LAYERS = ("sim", "io", "nodes", "guard", "headless", "session", "viewer", "bench", "tools", "serve")
MIN_MIRRORED = 0.90
# Sources with a header and no test of their own, by pattern, each with why: counted neither as
# mirrored nor as missing.
EXEMPT = {
    # figment-bench's subcommands (runDrapeStudy, ...): entry points that time what they run and
    # write the CSV of medians. A test may not time anything; what a study computes lives in
    # tested sources (sim/, session/), and its command line in tests/bench/scenarios/.
    "bench/*Study.cpp": "a figment-bench study: timings, tested as the command line",
}


def tests_mirroring_nothing(root):
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


def sources(root):
    """The sources a test should mirror, relative to root, sorted; EXEMPT left out."""
    found = []
    for layer in SOURCE_LAYERS:
        for path in (root / layer).rglob("*.cpp"):
            relative = path.relative_to(root).as_posix()
            exempt = any(fnmatch.fnmatchcase(relative, pattern) for pattern in EXEMPT)
            if path.with_suffix(".h").exists() and not exempt:
                found.append(relative)
    return sorted(found)


def is_mirrored(root, source):
    path = pathlib.PurePosixPath(source)
    folder = root / "tests" / path.parent
    return any((folder / f"test_{path.stem}{suffix}").exists() for suffix in (".cpp", ".py"))


def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent
    found = list(tests_mirroring_nothing(root))
    for line in found:
        print(line)
    all_sources = sources(root)
    exempt = sum(1 for layer in SOURCE_LAYERS for path in (root / layer).rglob("*.cpp")
                 if path.with_suffix(".h").exists()) - len(all_sources)
    missing = [source for source in all_sources if not is_mirrored(root, source)]
    for source in missing:
        stem = pathlib.PurePosixPath(source)
        print(f"{source}: no test of its own (tests/{stem.parent}/test_{stem.stem}.cpp)")
    mirrored = len(all_sources) - len(missing)
    share = mirrored / len(all_sources) if all_sources else 1.0
    print(f"{mirrored} of {len(all_sources)} sources have a mirrored test ({share:.0%}; at least "
          f"{MIN_MIRRORED:.0%} must); {exempt} exempt (EXEMPT)")
    return 1 if found or share < MIN_MIRRORED else 0


if __name__ == "__main__":
    sys.exit(main())
