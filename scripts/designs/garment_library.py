"""pygarment 2.0.2's pattern library (panels, edges, interfaces, stitches, the specification
JSON), importable as its own modules expect.

The 2.0.2 wheel installs its packages at the top level (garmentcode, pattern, ...) while their
code imports them as pygarment.garmentcode and pygarment.pattern, and pattern/wrappers.py
imports pygarment.data_config (not in the wheel), cairosvg and matplotlib (drawing only). So:
a package "pygarment" whose path is the folder holding those packages, and empty stand-ins
for the three modules only drawing uses; nothing here draws, and a drawing call would fail
on the stand-in rather than draw wrongly. requirements.txt pins what the rest needs."""

import importlib.util
import os
import sys
import types
import warnings


def _alias_pygarment():
    spec = importlib.util.find_spec("garmentcode")
    if spec is None:
        sys.exit("pygarment is not installed: see scripts/designs/requirements.txt")
    package = types.ModuleType("pygarment")
    package.__path__ = [os.path.dirname(os.path.dirname(spec.origin))]
    sys.modules["pygarment"] = package
    for name in ("pygarment.data_config", "cairosvg", "matplotlib", "matplotlib.pyplot"):
        sys.modules.setdefault(name, types.ModuleType(name))
    package.data_config = sys.modules["pygarment.data_config"]


_alias_pygarment()
# Panel.norm divides by a zero length where three of a panel's bounding-box corners lie in a line
# (a NaN normal, so autonorm leaves the panel as it is): assemble.face_out orients every panel.
warnings.filterwarnings("ignore", "invalid value encountered in divide", RuntimeWarning, "pygarment.garmentcode.panel")

from pygarment.garmentcode.connector import Stitches  # noqa: E402
from pygarment.garmentcode.edge import CurveEdge, Edge, EdgeSequence  # noqa: E402
from pygarment.garmentcode.edge_factory import EdgeSeqFactory  # noqa: E402
from pygarment.garmentcode.interface import Interface  # noqa: E402
from pygarment.garmentcode.panel import Panel  # noqa: E402
from pygarment.pattern.core import BasicPattern  # noqa: E402

__all__ = ["BasicPattern", "CurveEdge", "Edge", "EdgeSeqFactory", "EdgeSequence", "Interface", "Panel", "Stitches"]
