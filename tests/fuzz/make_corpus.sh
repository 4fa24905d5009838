#!/usr/bin/env bash
# Remakes tests/fuzz/corpus/fuzz_scene from the shipped scenes (small ones only, < 8 KB).
# The names of the shipped meshes become the tiny ones fuzz_scene writes into its working
# folder (body.off, garment.off), so a seed reads in milliseconds; the volume files the
# Mannequin scenes include are copied there by fuzz_scene too. Their capsules, not their radial
# depth volumes: the default body's 17 radial volumes are 89 KB of coefficients, and reading
# them (text check, Coin's parse, each volume's bounds) was over half of each input's time;
# the capsules are 35 KB and take half as long a scene. Radial volumes are still fuzzed, as
# the examples write them inline (examples-RadialDepthVolume.iv). The second body's scene
# takes the default body's volumes. The body's collisionExclude goes: the stand-in body has no
# eyes mesh to leave out, and with it the seed would stop at its MeshFile. fuzz_mesh's seeds
# are hand-written (no third-party meshes in the repository) and are not touched here.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=tests/fuzz/corpus/fuzz_scene
for scene in scenes/*.iv scenes/examples/*.iv scenes/hybrid/*.iv; do
  case "$(basename "$scene")" in .*) continue ;; esac  # work files of other runs
  [ "$(stat -c %s "$scene")" -lt 8192 ] || continue
  name=$(echo "${scene#scenes/}" | tr / -)
  sed -e 's/"\(human\.zae\|HUMAN\.blend\)"/"body.off"/g' \
      -e 's/"\(dress\|skirt\|tshirt\|second-body-dress\)\.obj"/"garment.off"/g' \
      -e 's/"\(\.\.\/\)\?\(human\|second-body\)-volumes\.iv"/"human-capsules.iv"/g' -e '/collisionExclude "human-highpolyeyesMesh"/d' \
      "$scene" >"$out/$name"
done
