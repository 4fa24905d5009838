#!/usr/bin/env python3
"""Writes ctest's cost seed (tests/costs/release.txt) from a whole run's JUnit report: each
test of 2 s and more with its time, the longest first, so that a fresh build's `ctest -j`
starts the longest tests first (tests/CMakeLists.txt). The report's times, not the build's
CTestCostData.txt: ctest averages that over every run, a filtered or failed one too.
Names with spaces (a parameterised test's "# GetParam() = ..." comment) cannot be written
in the seed's format and are left out, as ctest itself reads them.

    scripts/test-costs.py build/junit.xml > tests/costs/release.txt
"""
import sys
import xml.etree.ElementTree as ElementTree

if len(sys.argv) != 2:
    sys.exit("usage: test-costs.py JUNIT.xml")
try:
    cases = ElementTree.parse(sys.argv[1]).getroot().iter("testcase")
except (OSError, ElementTree.ParseError) as error:
    sys.exit("test-costs: %s: %s" % (sys.argv[1], error))
costs = sorted(((float(case.get("time", "0")), case.get("name", "")) for case in cases), reverse=True)
for seconds, name in costs:
    if seconds >= 2.0 and name and " " not in name:
        print("%s 1 %.1f" % (name, seconds))
print("---")
