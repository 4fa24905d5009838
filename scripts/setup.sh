#!/usr/bin/env bash
# Installs what is missing (Debian packages), configures once and builds incrementally.
# Shared by the README's two commands and by CI; fast and quiet on a second run.
#   scripts/setup.sh                 everything: every program, the tests and their tools
#   scripts/setup.sh TARGET...       only those build targets and the packages they need (the
#                                    README's first command: figment-view), without the
#                                    tests, their tools or the service's packages
set -euo pipefail
cd "$(dirname "$0")/.."
targets=("$@")

# What a build of figment-view (or any other program but the service's) needs: the compiler,
# Coin, OSMesa, assimp, Eigen; libpng-dev: PNG files written byte for byte (io/PngFile);
# assimp-testmodels: the default scanned mannequin (human.zae) the shipped scenes dress;
# python3: scripts/fetch-makehuman.py, below (a minimal Debian has no Python).
build_packages=(cmake ninja-build g++ pkg-config python3
  libcoin-dev libsimage-dev libosmesa6-dev libassimp-dev libeigen3-dev libpng-dev
  libcli11-dev nlohmann-json3-dev assimp-testmodels)
# The service (figment-serve, figment-precompute): libcpp-httplib-dev for its HTTP;
# libhiredis-dev for the shared cache and work queue in Redis.
service_packages=(libcpp-httplib-dev libhiredis-dev)
# The tests and their tools: GoogleTest; python3-matplotlib: figment-bench's plots;
# python3-pivy: the guard's call from a pivy program (tests/guard/test_GuardC.py); chromium,
# chromium-driver, python3-selenium: the page tested in a real browser
# (tests/serve/scenarios/test_page.py); redis-server: the tests that start a Redis of their
# own; nginx: the load balancer the deployment test puts before two instances
# (docs/deploy.md); wrk: bench/serve-load.sh; clang-format: ctest's lint.Formatting;
# python3-venv: the contract test's Schemathesis, pinned by hash in a venv of the build
# folder (tests/serve/contract/requirements.txt).
test_packages=(libgtest-dev python3-matplotlib python3-pivy
  chromium chromium-driver python3-selenium wrk redis-server nginx clang-format python3-venv)

# By need: named targets get the build's packages (and the service's for its programs);
# everything (no target named) gets them all, and every test must be registered.
service_target=0 tests_target=0
for target in "${targets[@]}"; do
  case "$target" in figment-serve | figment-precompute | figment_serve) service_target=1 ;;
  figment-view | figment-bench | figment-* | figment_*) ;;
  *) service_target=1 tests_target=1 ;; esac
done
packages=("${build_packages[@]}")
if ((${#targets[@]} == 0 || tests_target)); then
  packages+=("${service_packages[@]}" "${test_packages[@]}")
elif ((service_target)); then
  packages+=("${service_packages[@]}")
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
# node: the Khronos glTF validator for the export tests (tools/gltf). Debian's nodejs unless a
# node is already there (another vendor's, say). Not Debian's npm: some 400 packages to unpack
# on a fresh machine for one tarball (scripts/fetch-npm-lock.py installs it, below).
if ((${#targets[@]} == 0)); then
  command -v node >/dev/null || missing+=(nodejs)
fi
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# The validator at the version and integrity hash package-lock.json pins, as npm ci would
# install it; again only when the lock file changed since (the tests use it: not for a build of
# named targets).
if ((${#targets[@]} == 0)) && { [ ! -f tools/gltf/node_modules/.package-lock.json ] ||
  [ tools/gltf/package-lock.json -nt tools/gltf/node_modules/.package-lock.json ]; }; then
  python3 scripts/fetch-npm-lock.py tools/gltf
fi

build=${FIGMENT_BUILD_DIR:-build}
if ((${#targets[@]} == 0)); then
  # Everything: the tests and the service on, and a test that would be left out (a program
  # missing) stops the configure (cmake/FigmentLeftOut.cmake). Configured again each time, in
  # seconds, so that a build first made for figment-view alone gains them.
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFIGMENT_BUILD_TESTS=ON -DFIGMENT_BUILD_SERVICE=ON \
    -DFIGMENT_REQUIRE_ALL_TESTS=ON >/dev/null
else
  # Named targets: a first configure leaves out the tests and the service unless one of
  # them was named; a later one only turns on what a named target needs.
  options=()
  [ -f "$build/CMakeCache.txt" ] || options+=(-DCMAKE_BUILD_TYPE=Release -DFIGMENT_BUILD_TESTS=OFF -DFIGMENT_BUILD_SERVICE=OFF)
  if ((service_target)); then options+=(-DFIGMENT_BUILD_SERVICE=ON); fi
  if ((tests_target)); then options+=(-DFIGMENT_BUILD_TESTS=ON); fi
  if ((${#options[@]})); then cmake -S . -B "$build" -G Ninja "${options[@]}" >/dev/null; fi
fi
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
# FIGMENT_SETUP_BUILD=0: the packages, the tools and the configure only (.ci/run sanitize, whose
# sanitized trees build themselves).
if [ "${FIGMENT_SETUP_BUILD:-1}" != 0 ]; then
  cmake --build "$build" -j "$(scripts/cores.sh)" ${targets[@]:+--target "${targets[@]}"} | { grep -vE '^\[[0-9]+/[0-9]+\] ' || true; }
fi
