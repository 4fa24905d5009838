#!/usr/bin/env python3
"""Fails a test run that passed by not running: reads ctest's JUnit report.

A run is whole when every test it registered ran and passed (none skipped, none not run,
none failed) and the number of tests is the one the README states ("every test (N").
ctest itself exits 0 when a gtest case skips (GTEST_SKIP: a model file missing) or a
script exits with its SKIP_RETURN_CODE, so CI runs this after ctest (.ci/run).

  ctest --test-dir build --output-junit junit.xml ...
  scripts/check-test-run.py build/junit.xml [--readme README.md]
  scripts/check-test-run.py --self-test

Exit status 0 when the run is whole; 1 with one line per test that did not run or pass,
and a last line with the counts.
"""
import argparse
import pathlib
import re
import sys
import xml.etree.ElementTree as ElementTree

ROOT = pathlib.Path(__file__).resolve().parent.parent
README_COUNT = re.compile(r"every test \((\d+)")


def outcomes(junit_text):
    """(name, outcome) for each testcase: 'passed', 'failed', 'skipped (why)', 'not run' or 'disabled'."""
    root = ElementTree.fromstring(junit_text)
    for case in root.iter("testcase"):
        name = case.get("name", "?")
        status = case.get("status", "run")
        if case.find("failure") is not None or case.find("error") is not None or status == "fail":
            yield name, "failed"
        elif case.find("skipped") is not None:
            yield name, f"skipped ({case.find('skipped').get('message', '')})"
        elif status in ("notrun", "disabled"):
            yield name, "disabled" if status == "disabled" else "not run"
        else:
            yield name, "passed"


def readme_count(readme_text):
    found = README_COUNT.search(readme_text)
    return int(found.group(1)) if found else None


def judge(junit_text, expected):
    """The lines to print for a run; empty when the run is whole."""
    results = list(outcomes(junit_text))
    lines = [f"{name}: {outcome}" for name, outcome in results if outcome != "passed"]
    if expected is None:
        lines.append("README.md states no count of tests (\"every test (N\")")
    elif len(results) != expected:
        lines.append(f"{len(results)} tests registered, README.md says {expected}")
    if lines:
        passed = sum(1 for _, outcome in results if outcome == "passed")
        lines.append(f"check-test-run: {passed} of {len(results)} tests ran and passed")
    return lines


def junit(cases):
    body = "".join(f'<testcase name="{name}" status="{status}">{inner}</testcase>' for name, status, inner in cases)
    return f'<?xml version="1.0"?><testsuite tests="{len(cases)}">{body}</testsuite>'


def self_test():
    """The rules on samples: each must be judged as written beside it."""
    passed = ("a.Passes", "run", "")
    samples = [
        (junit([passed, ("b.Passes", "run", "")]), 2, True),
        (junit([passed, ("b.Skips", "run", '<skipped message="SKIP_REGULAR_EXPRESSION matched"/>')]), 2, False),
        (junit([passed, ("b.NotRun", "notrun", '<skipped message="SKIP_RETURN_CODE=77"/>')]), 2, False),
        (junit([passed, ("b.Disabled", "disabled", "")]), 2, False),
        (junit([passed, ("b.Fails", "fail", '<failure message="Failed"/>')]), 2, False),
        (junit([passed]), 2, False),  # a test left out of the registration
        (junit([passed]), None, False),
    ]
    wrong = [i for i, (text, expected, whole) in enumerate(samples) if (not judge(text, expected)) != whole]
    count_read = readme_count("builds and runs every test (1123; 9 min") == 1123
    if wrong or not count_read:
        print(f"check-test-run: self-test misjudged samples {wrong}, README count read: {count_read}")
        return 1
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("junit", nargs="?", type=pathlib.Path)
    parser.add_argument("--readme", type=pathlib.Path, default=ROOT / "README.md")
    parser.add_argument("--self-test", action="store_true")
    arguments = parser.parse_args()
    if arguments.self_test:
        return self_test()
    if arguments.junit is None:
        parser.error("the JUnit file is needed (ctest --output-junit FILE)")
    if not arguments.junit.is_file():
        print(f"check-test-run: {arguments.junit}: no such file (ctest --output-junit wrote none)")
        return 1
    lines = judge(arguments.junit.read_text(), readme_count(arguments.readme.read_text()))
    for line in lines:
        print(line)
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main())
