#!/usr/bin/env python3
"""Installs the packages a package-lock.json pins into node_modules beside it, as `npm ci`
would for packages without install scripts: each package's tarball from the npm registry,
checked against the lock file's integrity hash (SHA-512) before anything is unpacked, and the
lock file copied to node_modules/.package-lock.json (scripts/setup.sh compares its time).

Why not npm: Debian's npm brings some 400 packages (335 of them node-* libraries) that CI's
fresh machine spends minutes unpacking, for one tarball (tools/gltf: the glTF validator, no
dependencies, no scripts). node alone runs it.

    python3 scripts/fetch-npm-lock.py tools/gltf
"""
import base64
import hashlib
import io
import json
import pathlib
import shutil
import sys
import tarfile
import urllib.request

REGISTRY = "https://registry.npmjs.org"


def install(folder):
    lock_file = folder / "package-lock.json"
    lock = json.loads(lock_file.read_text())
    modules = folder / "node_modules"
    shutil.rmtree(modules, ignore_errors=True)
    for where, entry in lock.get("packages", {}).items():
        if not where:
            continue  # the project itself
        if entry.get("hasInstallScript"):
            sys.exit(f"fetch-npm-lock.py: {where} has install scripts: use npm ci")
        name = where.rsplit("node_modules/", 1)[1]
        url = entry.get("resolved") or f"{REGISTRY}/{name}/-/{name.split('/')[-1]}-{entry['version']}.tgz"
        algorithm, _, expected = entry["integrity"].partition("-")
        if algorithm != "sha512":
            sys.exit(f"fetch-npm-lock.py: {where}: integrity {algorithm}, not sha512")
        with urllib.request.urlopen(url, timeout=60) as response:
            data = response.read()
        actual = base64.b64encode(hashlib.sha512(data).digest()).decode()
        if actual != expected:
            sys.exit(f"fetch-npm-lock.py: {url} does not match the lock file's integrity hash")
        target = folder / where
        with tarfile.open(fileobj=io.BytesIO(data), mode="r:gz") as archive:
            for member in archive.getmembers():
                parts = pathlib.PurePosixPath(member.name).parts
                if not (member.isfile() or member.isdir()) or ".." in parts or len(parts) < 2:
                    continue  # npm's tarballs hold package/...: no links, nothing outside
                path = target.joinpath(*parts[1:])
                if member.isdir():
                    path.mkdir(parents=True, exist_ok=True)
                    continue
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_bytes(archive.extractfile(member).read())
    shutil.copyfile(lock_file, modules / ".package-lock.json")


if __name__ == "__main__":
    install(pathlib.Path(sys.argv[1]))
