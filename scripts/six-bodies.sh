#!/usr/bin/env bash
# The six chart bodies of tests/io/scenarios/test_SixBodyDrapes.cpp side by side: each
# sex's smallest, middle and largest size (scenes/sizes/chart.txt), each made by
# figment-body and dressed in garments cut round it with the styles' ease
# (sim/garment/GarmentStyle.h: girth ease / 2 pi as the stand-off), draped side by side by
# figment-view. Writes docs/images/six-bodies.png (the strap dress on the women, the
# T-shirt on the men) and docs/images/six-bodies-skirt.png (the flared skirt on all six).
#   scripts/six-bodies.sh [BUILD_DIR] [OUT_DIR]   (about a minute on one core)
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(cd "${1:-build}" && pwd)/bin"
out="$(mkdir -p "${2:-docs/images}" && cd "${2:-docs/images}" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}

# Each sex's smallest, middle (n / 2) and largest size of the chart, as the test picks
# them: sex size stature bust waist hip (m), and a Monk skin tone for each.
tones=(2 5 8 3 9 6)
bodies=$(awk '!/^#/ && NF >= 7 { row[$1, ++n[$1]] = $1 " " $2 " " $4 " " $5 " " $6 " " $7 }
  END { for (s = 0; s < 2; ++s) { sex = s ? "male" : "female"; c = n[sex]
          print row[sex, 1]; print row[sex, int(c / 2) + 1]; print row[sex, c] } }' scenes/sizes/chart.txt |
  paste -d' ' - <(printf '%s\n' "${tones[@]}"))
[ "$(wc -l <<< "$bodies")" -eq 6 ] || { echo "six-bodies.sh: scenes/sizes/chart.txt: not three sizes per sex" >&2; exit 1; }

while read -r sex size stature bust waist hip _; do
  name=$sex-$size
  "$bin/figment-body" --sex "$sex" --stature "$stature" --bust-girth "$bust" --waist-girth "$waist" \
    --hip-girth "$hip" -o "$work/$name.obj" > "$work/$name.json"
  # The styles' girth ease: dress 6 cm, skirt 3 cm at the waist, T-shirt 10 cm.
  "$bin/figment-make-dress" --body "$work/$name.obj" --clearance 0.009549 -o "$work/$name-dress.obj" > /dev/null
  "$bin/figment-make-skirt" --body "$work/$name.obj" --waist-clearance 0.004775 -o "$work/$name-skirt.obj" > /dev/null
  "$bin/figment-make-tshirt" --body "$work/$name.obj" --ease 0.015915 -o "$work/$name-tshirt.obj" > /dev/null
done <<< "$bodies"

# The scene: each body (a HumanBody made to the same four dimensions) and its garment
# under one Translation, 1 m apart; the garment women wear, then the one men wear.
scene() {
  local women=$1 men=$2 x=0 sex size stature bust waist hip tone garment gender id
  printf '#Inventor V2.1 ascii\n\nSeparator {\n'
  printf '  DirectionalLight { direction -0.4 -0.5 -1 intensity 0.75 }\n'
  printf '  DirectionalLight { direction 0.6 -0.3 0.8 intensity 0.5 }\n'
  while read -r sex size stature bust waist hip tone; do
    garment=$women gender=0 id=${sex}_$size
    [ "$sex" = male ] && garment=$men gender=1
    cat <<BODY
  Separator {
    Translation { translation $x 0 0 }
    Separator {
      ShapeHints { vertexOrdering COUNTERCLOCKWISE  shapeType SOLID  creaseAngle 1.0 }
      DEF Body_$id HumanBody {
        gender $gender  stature $stature  bustGirth $bust  waistGirth $waist  hipGirth $hip  skinTone $tone
      }
    }
    Separator {
      Material { diffuseColor 0.12 0.25 0.70  specularColor 0.15 0.15 0.2  shininess 0.3 }
      ShapeHints { vertexOrdering COUNTERCLOCKWISE  shapeType UNKNOWN_SHAPE_TYPE  creaseAngle 1.0 }
      Switch { whichChild -1  DEF Pattern_$id MeshFile { fileName "$sex-$size-$garment.obj" } }
      Coordinate3 {
        point = ClothEngine {
          restPoints = USE Pattern_$id.point
          coordIndex = USE Pattern_$id.coordIndex
          body USE Body_$id
          material "jersey"
          friction 0.5
          maxTime 10
        } . positions
      }
      ClothingLayer { coordIndex = USE Pattern_$id.coordIndex  displaySubdivision 1 }
    }
  }
BODY
    x=$(awk -v x="$x" 'BEGIN { print x + 1.0 }')
  done <<< "$bodies"
  printf '}\n'
}

scene dress tshirt > "$work/six-bodies.iv"
scene skirt skirt > "$work/six-bodies-skirt.iv"
for picture in six-bodies six-bodies-skirt; do
  "$bin/figment-view" "$work/$picture.iv" --no-cache --strict --size 1200x420 -o "$out/$picture.png"
done
