#!/usr/bin/env bash
# Writes the twocell3d decks into input/twocell3d/ (thesis Chapter 6, Section 6.1):
#   demo.xml        two cells side by side at h/a = 1.25, level 2, to t = 1 (80 s on 2 cores)
#   side-by-side/   Delta x = 0, Delta z0/a in {0.5, 1, 2, 3, 4, 5, 7.5, 10}
#   in-line/        Delta z = 0, Delta x0/a in {1, 2, 3, 4, 5, 7.5, 10, 20}
#   isolated/       the single cell at the same heights and settings (the reference the
#                   thesis compares with)
# each at h/a = 2.5 and 1.25, with the heights held fixed (as in the thesis, after
# Uijttewaal et al. 1993: *-fixed.xml) and free (*-free.xml). Ca = 0.3, Skalak C = 2.5, no
# prestress, lambda = 1.
#
# Delta x0/a, Delta z0/a: the thesis (Fig 6.1) places cell (1) at (Delta x/2a, h/a, Delta z/2a)
# and cell (2) at (-Delta x/2a, h/a, -Delta z/2a), so Delta is a centre-to-centre distance
# in the figures. The initial values Delta z0/a = 0.5 and 1 cannot be centre distances of
# two cells of radius a (they would overlap); they are the gaps between the surfaces of the
# two spheres at the start, centre distance 2a + Delta0. The figures confirm it: the closest
# separations plotted are Delta z/a = 2.68 and 3.13 (from 2.5 and 3, side-by-side cells move
# apart) and Delta x/a = 2.65, 3.76, 4.87, 6.96, 9.49 (from 3, 4, 5, 7 and 9.5: the
# upstream cell catches up). Here Cell 0 is the thesis's cell (1), Cell 1 its cell (2).
#
# Settings as input/cell3d/: mesh level 3 (the thesis's), N_Q = 7, N_GL = 6, RKF45 with
# tolerance 1e-6, to t = 15 or steady shape (fixed height), wall shear stress map around
# both cells (spacing 0.5), 'Cells/Minimum gap' 0.05.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
root="$here/input/twocell3d"
mkdir -p "$root/side-by-side" "$root/in-line" "$root/isolated"

# cell NAME X Y Z LEVEL FIXED
cell() {
  cat <<CELL
    <ParameterList name="$1">
      <Parameter name="Shape" type="string" value="Sphere"/>
      <Parameter name="Radius" type="double" value="1.0"/>
      <Parameter name="Center" type="Array(double)" value="{$2, $3, $4}"/>
      <Parameter name="Mesh level" type="int" value="$5"/>
      <Parameter name="Membrane law" type="string" value="Skalak"/>
      <Parameter name="Area dilation C" type="double" value="2.5"/>
      <Parameter name="Prestress" type="double" value="0.0"/>
      <Parameter name="Fixed height" type="bool" value="$6"/>
    </ParameterList>
CELL
}

# deck FILE COMMENT H DX DZ (centre distances; DX = DZ = "" for one cell) LEVEL FIXED END
#      STEADY INTERVAL STRIDE
deck() {
  local file=$1 comment=$2 h=$3 dx=$4 dz=$5 level=$6 fixed=$7 end=$8 steady=$9 interval=${10}
  local stride=${11}
  local directory cells upstream downstream halfwidth
  directory="out/twocell3d/$(basename "$(dirname "$file")")/$(basename "$file" .xml)"
  if [ -z "$dx" ]; then
    cells=$(cell "Cell 0" 0.0 "$h" 0.0 "$level" "$fixed")
    upstream=6; downstream=6; halfwidth=4
  else
    cells="$(cell "Cell 0" "$(awk -v d="$dx" 'BEGIN { print d / 2 }')" "$h" \
                 "$(awk -v d="$dz" 'BEGIN { print d / 2 }')" "$level" "$fixed")
$(cell "Cell 1" "$(awk -v d="$dx" 'BEGIN { print -d / 2 }')" "$h" \
       "$(awk -v d="$dz" 'BEGIN { print -d / 2 }')" "$level" "$fixed")"
    upstream=$(awk -v d="$dx" 'BEGIN { print 6 + d / 2 }')
    downstream=$upstream
    halfwidth=$(awk -v d="$dz" 'BEGIN { print 4 + d / 2 }')
  fi
  cat > "$file" <<DECK
<!-- $comment
     (written by utils/make-twocell3d-decks.sh) -->
<ParameterList name="twocell3d">
  <ParameterList name="Flow">
    <Parameter name="Capillary number" type="double" value="0.3"/>
    <Parameter name="Viscosity ratio" type="double" value="1.0"/>
  </ParameterList>
  <ParameterList name="Wall">
    <Parameter name="Enabled" type="bool" value="true"/>
  </ParameterList>
  <ParameterList name="Cells">
    <Parameter name="Minimum gap" type="double" value="0.05"/>
$cells
  </ParameterList>
  <ParameterList name="Time integration">
    <Parameter name="End time" type="double" value="$end"/>
    <Parameter name="Method" type="string" value="RKF45"/>
    <Parameter name="Tolerance" type="double" value="1e-6"/>
    <Parameter name="Initial step" type="double" value="1e-3"/>
    <Parameter name="Steady tolerance" type="double" value="$steady"/>
  </ParameterList>
  <ParameterList name="Discretisation">
    <Parameter name="Quadrature points" type="int" value="7"/>
    <Parameter name="Singular quadrature points" type="int" value="6"/>
    <Parameter name="Near-singular distance" type="double" value="1"/>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Directory" type="string" value="$directory"/>
    <Parameter name="Interval" type="double" value="$interval"/>
    <Parameter name="Snapshot stride" type="int" value="$stride"/>
    <ParameterList name="Wall shear stress">
      <Parameter name="Enabled" type="bool" value="true"/>
      <Parameter name="Upstream extent" type="double" value="$upstream"/>
      <Parameter name="Downstream extent" type="double" value="$downstream"/>
      <Parameter name="Half width" type="double" value="$halfwidth"/>
      <Parameter name="Spacing" type="double" value="0.5"/>
      <Parameter name="Threshold" type="double" value="1.05"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
DECK
}

plus2() { awk -v d="$1" 'BEGIN { print 2 + d }'; }

deck "$root/demo.xml" \
  "Demo: two Skalak capsules (C = 2.5, Ca = 0.3) side by side at h/a = 1.25, heights held fixed,
     surfaces 0.5 a apart at the start (thesis Chapter 6): they deform, tank-treading, and
     move apart across the flow." \
  1.25 0 2.5 2 true 1.0 0 0.1 2
sed -i 's|out/twocell3d/twocell3d/demo|out/twocell3d-demo|' "$root/demo.xml"

for h in 2.5 1.25; do
  for mode in fixed free; do
    fixed=$([ "$mode" = fixed ] && echo true || echo false)
    steady=$([ "$mode" = fixed ] && echo 1e-3 || echo 0)
    for d in 0.5 1 2 3 4 5 7.5 10; do
      deck "$root/side-by-side/h$h-dz$d-$mode.xml" \
        "Thesis Section 6.2 (Figs 6.2-6.6): side by side (Delta x = 0) at h/a = $h ($mode height),
     surfaces Delta z0/a = $d apart at the start (centre distance $(plus2 "$d") a)." \
        "$h" 0 "$(plus2 "$d")" 3 "$fixed" 15 "$steady" 0.1 10
    done
    for d in 1 2 3 4 5 7.5 10 20; do
      deck "$root/in-line/h$h-dx$d-$mode.xml" \
        "Thesis Section 6.3 (Figs 6.7-6.12): in line (Delta z = 0) at h/a = $h ($mode height),
     surfaces Delta x0/a = $d apart at the start (centre distance $(plus2 "$d") a)." \
        "$h" "$(plus2 "$d")" 0 3 "$fixed" 15 "$steady" 0.1 10
    done
    deck "$root/isolated/h$h-$mode.xml" \
      "Thesis Chapter 6 reference: the isolated cell at h/a = $h ($mode height), the same settings." \
      "$h" "" "" 3 "$fixed" 15 "$steady" 0.1 10
  done
done
echo "wrote $(find "$root" -name '*.xml' | wc -l) decks under $root"
