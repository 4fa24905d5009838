#!/usr/bin/env bash
# Renders every figment-view picture in docs/images again, as the README and docs say
# each was made (one line a picture: scene, output, options). The charts and the wind
# animation have their own commands (figment-bench's plot scripts, scripts/wind-figures.py).
# The six chart bodies' pictures are made from bodies and garments the tools make first
# (scripts/six-bodies.sh, run at the end).
#   scripts/docs-pictures.sh [BUILD_DIR]   (default: build; about a minute on one core;
#   FIGMENT_PICTURES_OUT=DIR writes them there instead, to compare)
set -euo pipefail
cd "$(dirname "$0")/.."
view="${1:-build}/bin/figment-view"
out=${FIGMENT_PICTURES_OUT:-docs/images}
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
while read -r scene picture options; do
  [ -z "$scene" ] && continue
  # shellcheck disable=SC2086  # options are words
  "$view" "scenes/$scene" -o "$out/$picture" $options
done <<'LIST'
dress.iv dress-front.png --size 480x560
dress.iv dress-side.png --size 480x560 --view 30,10
dress.iv dress-back.png --size 480x560 --view back
outfit-skirt.iv fig6-2-skirt.png --size 480x560
outfit-skirt.iv fig6-2-skirt-side.png --size 480x560 --view 30,10
outfit-layers.iv fig6-3-layers.png --size 480x560
outfit-layers.iv fig6-3-layers-side.png --size 480x560 --view 30,10
dress-progressive.iv fig4-2a-progressive.png --size 360x420 --view 30,10 --stop-at 1
dress-progressive.iv fig4-2b-progressive.png --size 360x420 --view 30,10 --stop-at 4
dress-progressive.iv fig4-2c-progressive.png --size 360x420 --view 30,10 --stop-at 7
dress-progressive.iv fig4-2d-progressive.png --size 360x420 --view 30,10
close-fit.iv fig5-2a-depth-buffer.png --size 360x420 --depth-buffer-only
close-fit.iv fig5-2b-hybrid.png --size 360x420
dress.iv fig5-3a-no-stencil.png --size 360x420 --view 60,10 --keep-stencil-fields --display-subdivision 0
dress.iv fig5-3b-stencil.png --size 360x420 --view 60,10 --display-subdivision 0
mannequin.iv volumes-radial.png --size 360x560 --show-volumes
mannequin.iv volumes-radial-side.png --size 360x560 --show-volumes --view 60,10
mannequin-capsules.iv volumes-capsules.png --size 360x560 --show-volumes
posed.iv posed.png --size 360x560 --view 30,10
second-body.iv second-body.png --size 360x560
tshirt.iv tshirt.png --size 360x420 --view 30,10
human-posed-arm.iv human-posed-arm.png --size 480x640 --view 25,10
human-posed-sitting.iv human-posed-sitting.png --size 480x480 --view 40,10
human-underwear.iv human-underwear.png --size 560x480
LIST
scripts/six-bodies.sh "${1:-build}" "$out"
