#!/usr/bin/env bash
# Writes the decks of the thesis's Chapter 4 study into input/tether2d/study/:
# a/b in {0.25, 0.5, 1} x lambda in {1, 5, 10} x Ca in {0.01, 0.025, 0.05, 0.1, 0.25}, 256 points,
# N_GL = 6, RKF45 with eps = 1e-6 (thesis App. A.8), equilibrium at an L2 change of the
# positions below 1e-7 per step (Fig. 4.4). The tethered stage runs to tau = k (t - t0) / lambda
# of 50 (Ca <= 0.025), 100 (Ca = 0.05) or 200 (Ca >= 0.1): the thesis's plots end at 10 and 200.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir="$here/input/tether2d/study"
mkdir -p "$dir"
for ab in 0.25 0.5 1; do
  for lambda in 1 5 10; do
    for ca in 0.01 0.025 0.05 0.1 0.25; do
      case $ca in 0.01|0.025) end=50 ;; 0.05) end=100 ;; *) end=200 ;; esac
      cat > "$dir/ab${ab}_lambda${lambda}_ca${ca}.xml" <<DECK
<!-- Thesis Chapter 4: a/b = $ab, lambda = $lambda, Ca = $ca (written by utils/make-tether2d-decks.sh). -->
<ParameterList name="tether2d">
  <ParameterList name="Flow">
    <Parameter name="Capillary number" type="double" value="$ca"/>
    <Parameter name="Viscosity ratio" type="double" value="$lambda"/>
  </ParameterList>
  <ParameterList name="Wall">
    <Parameter name="Enabled" type="bool" value="true"/>
  </ParameterList>
  <ParameterList name="Cell">
    <Parameter name="Aspect ratio" type="double" value="$ab"/>
    <Parameter name="Number of points" type="int" value="256"/>
    <Parameter name="Lowest point height" type="double" value="0.005"/>
  </ParameterList>
  <ParameterList name="Tether">
    <Parameter name="Enabled" type="bool" value="true"/>
    <Parameter name="Anchor height" type="double" value="0.005"/>
    <Parameter name="Preparation tolerance" type="double" value="1e-3"/>
    <Parameter name="Minimum preparation time" type="double" value="0.5"/>
    <Parameter name="Maximum preparation time" type="double" value="50"/>
  </ParameterList>
  <ParameterList name="Discretisation">
    <Parameter name="Gauss-Legendre points" type="int" value="6"/>
    <Parameter name="Log-weighted points" type="int" value="6"/>
    <Parameter name="Near-singular distance" type="double" value="2"/>
  </ParameterList>
  <ParameterList name="Time integration">
    <Parameter name="End time" type="double" value="$end"/>
    <Parameter name="Method" type="string" value="RKF45"/>
    <Parameter name="Tolerance" type="double" value="1e-6"/>
    <Parameter name="Initial step" type="double" value="1e-3"/>
    <Parameter name="Steady criterion" type="string" value="L2Change"/>
    <Parameter name="Steady tolerance" type="double" value="1e-7"/>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Interval" type="double" value="0.5"/>
    <Parameter name="Snapshot every" type="int" value="20"/>
    <Parameter name="Checkpoint every" type="int" value="20"/>
  </ParameterList>
</ParameterList>
DECK
    done
  done
done
ls "$dir" | wc -l
