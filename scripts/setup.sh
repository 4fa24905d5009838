#!/usr/bin/env bash
# Installs what is missing (Debian packages), configures once and builds incrementally.
# Shared by the README's two commands and by CI; fast and quiet on a second run.
#   scripts/setup.sh                 everything: every program, the tests and their tools
#   scripts/setup.sh TARGET...       only those build targets (the README's first command:
#                                    figment-view), without the tests' own tools
set -euo pipefail
cd "$(dirname "$0")/.."
targets=("$@")

# libpng-dev: PNG files written byte for byte (io/PngFile); python3-pivy: the guard's
# call from a pivy program (tests/guard/test_GuardC.py). libcpp-httplib-dev: figment-serve's
# HTTP; chromium, chromium-driver, python3-selenium: its page tested in a real browser
# (tests/serve/scenarios/test_page.py); wrk: bench/serve-load.sh; clang-format: ctest's
# lint.Formatting (scripts/check-format.sh). libhiredis-dev, redis-server: figment-serve's
# shared cache and work queue, and the tests that start a Redis of their own; nginx: the
# load balancer the deployment test puts before two instances (docs/deploy.md).
# python3-venv: the contract test's Schemathesis, pinned by hash in a venv of the build
# folder (tests/serve/contract/requirements.txt).
packages=(cmake ninja-build g++ pkg-config
  libcoin-dev libsimage-dev libosmesa6-dev libassimp-dev libeigen3-dev libpng-dev
  libgtest-dev libcli11-dev nlohmann-json3-dev
  assimp-testmodels python3-matplotlib python3-pivy
  libcpp-httplib-dev chromium chromium-driver python3-selenium wrk
  libhiredis-dev redis-server nginx
  clang-format python3-venv)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
# node and npm: the Khronos glTF validator for the export tests (tools/gltf). Debian's
# nodejs and npm unless a node with its npm is already there (another vendor's, say).
command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# The validator at the version and integrity hash package-lock.json pins; again only when
# the lock file changed since (the tests use it: not for a build of named targets).
if ((${#targets[@]} == 0)) && { [ ! -f tools/gltf/node_modules/.package-lock.json ] ||
  [ tools/gltf/package-lock.json -nt tools/gltf/node_modules/.package-lock.json ]; }; then
  (cd tools/gltf && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
fi

build=${FIGMENT_BUILD_DIR:-build}
[ -f "$build/CMakeCache.txt" ] || cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
# Schemathesis for serve.Contract (the tests' tool: not for a build of named targets), at
# the versions and hashes the requirements file pins; again only when that file changed.
contract="$build/contract-venv"
if ((${#targets[@]} == 0)) && { [ ! -f "$contract/installed" ] ||
  [ tests/serve/contract/requirements.txt -nt "$contract/installed" ]; }; then
  rm -rf "$contract"
  /usr/bin/python3 -m venv "$contract"
  "$contract/bin/pip" install --quiet --disable-pip-version-check --require-hashes --only-binary :all: \
    -r tests/serve/contract/requirements.txt
  touch "$contract/installed"
fi
# MakeHuman's CC0 body model (docs/bodies.md), where the build looks for it by default.
python3 scripts/fetch-makehuman.py "$build/data/makehuman"
cmake --build "$build" -j "$(nproc)" ${targets[@]:+--target "${targets[@]}"} | { grep -vE '^\[[0-9]+/[0-9]+\] ' || true; }
