#!/usr/bin/env python3
"""Each mended finding broken on purpose again: its test must fail (docs/mutants.md).

A mutant is tests/mutants/NAME.patch: three header lines, a blank line, then the diff
that puts the defect back (`git apply` skips the header):

    Finding: what the mutant breaks, in one line
    Targets: the build targets to rebuild (space separated; none for a script's change)
    Test: a ctest -R regular expression naming the test(s) that must now fail

For each mutant: apply it to this checkout, rebuild its targets in BUILD, run its tests,
expect a failure, then take it back out and rebuild. A mutant whose tests still pass
"survived": the finding's test cannot fail the way it should.

  scripts/mutants.py [--build build] [--table docs/mutants.md] [NAME ...]
     (--table: the row of each mutant run is rewritten as it ends; the others' rows are kept)
  scripts/mutants.py --check   (ctest lint.MutantsApply: every header whole, every diff applies)

Exit status 0 when every mutant was caught; 1 otherwise. Needs a built BUILD folder and
files the mutants touch without changes of their own. It edits the checkout's files while
it runs: run it where no other build reads them (a sanitizer build compiling beside it took
a mutant into its objects, 2026-12-03; use a worktree of its own).
"""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
MUTANTS = ROOT / "tests" / "mutants"
HEADER = re.compile(r"^(Finding|Targets|Test):[ \t]*(.*)$", re.MULTILINE)
TABLE_START = "<!-- mutants: scripts/mutants.py writes from here -->"


class Mutant:
    def __init__(self, path):
        self.path = path
        self.name = path.stem
        text = path.read_text()
        fields = dict(HEADER.findall(text.split("\ndiff --git", 1)[0]))
        missing = [key for key in ("Finding", "Targets", "Test") if key not in fields]
        if missing or not fields.get("Test"):
            raise ValueError(f"{path}: header line {missing[0] if missing else 'Test'} is missing or empty")
        self.finding = fields["Finding"].strip()
        self.targets = fields["Targets"].split()
        self.test = fields["Test"].strip()


def run(command, **options):
    return subprocess.run(command, cwd=ROOT, capture_output=True, text=True, **options)


def build(build_dir, targets):
    if not targets:
        return True
    return run(["cmake", "--build", str(build_dir), "--target", *targets]).returncode == 0


def judge(mutant, build_dir):
    """'caught', 'survived', 'no test ran', 'does not build' or 'does not apply' (only the
    first counts as a mutant doing its job: the others say nothing of the test)."""
    if run(["git", "apply", "--check", str(mutant.path)]).returncode != 0:
        return "does not apply"
    run(["git", "apply", str(mutant.path)], check=True)
    try:
        if not build(build_dir, mutant.targets):
            return "does not build"
        tests = run(["ctest", "--test-dir", str(build_dir), "-R", mutant.test, "--timeout", "900"])
        if "No tests were found" in tests.stdout + tests.stderr:
            return "no test ran"
        return "caught" if tests.returncode != 0 else "survived"
    finally:
        run(["git", "apply", "-R", str(mutant.path)], check=True)
        build(build_dir, mutant.targets)


def check(mutants):
    """A mutant that no longer applies guards nothing: the code it breaks has moved."""
    stale = [m for m in mutants if run(["git", "apply", "--check", str(m.path)]).returncode != 0]
    for mutant in stale:
        print(f"{mutant.path.relative_to(ROOT)}: does not apply to this tree (write it again where the code went)")
    if not mutants:
        print(f"mutants.py: no mutant in {MUTANTS.relative_to(ROOT)}")
    return 1 if stale or not mutants else 0


ROW = re.compile(r"^\| `([^`]+)` \|.*\| ([^|]+) \|$", re.MULTILINE)


def table(mutants, results):
    """The table of every mutant: this run's results, and a row an earlier run wrote for each
    mutant not run now (so a run of a few, or one cut short, keeps the others' results)."""
    lines = [TABLE_START, "", "| mutant | what it breaks | test that must fail | result |", "| --- | --- | --- | --- |"]
    for mutant in mutants:
        result = results.get(mutant.name, "not run")
        test = mutant.test.replace("|", "\\|")  # a table cell ends at a bare |, even in code
        lines.append(f"| `{mutant.name}` | {mutant.finding} | `{test}` | {result} |")
    return "\n".join(lines) + "\n"


def write_table(path, results):
    """Rewrites the table in PATH after TABLE_START: every mutant in tests/mutants/."""
    text = path.read_text() if path.exists() else ""
    kept, _, old = text.partition(TABLE_START)
    merged = {name: result.strip() for name, result in ROW.findall(old)}
    merged.update(results)
    every = [Mutant(p) for p in sorted(MUTANTS.glob("*.patch"))]
    path.write_text(kept + table(every, merged))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", help="mutants to run (default: all)")
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--table", type=pathlib.Path, help="write the results' table into this file")
    parser.add_argument("--check", action="store_true", help="only check that each mutant reads and applies")
    arguments = parser.parse_args()
    paths = sorted(MUTANTS.glob("*.patch"))
    if arguments.names:
        paths = [MUTANTS / f"{name}.patch" for name in arguments.names]
    try:
        mutants = [Mutant(path) for path in paths]
    except (OSError, ValueError) as error:
        print(f"mutants.py: {error}", file=sys.stderr)
        return 2
    if arguments.check:
        return check(mutants)
    results = {}
    for mutant in mutants:
        results[mutant.name] = judge(mutant, arguments.build)
        print(f"{mutant.name}: {results[mutant.name]}", flush=True)
        if arguments.table:  # after each: a run cut short keeps what it found
            write_table(arguments.table, results)
    return 0 if all(result == "caught" for result in results.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
