#!/usr/bin/env bash
# Regenerates the README's pictures with `tabletop render`, `bench` and `compare` (headless; the
# GIF needs ffmpeg). Usage, after building: docs/make-pictures.sh [TABLETOP]
set -euo pipefail
cd "$(dirname "$0")/.."
tabletop=${1:-build/src/app/tabletop}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# still NAME TIME: the example at TIME seconds, from render's default camera
# (the report's direction, fitted to the scene), so a first render looks alike.
still() {
  "$tabletop" render "scenarios/$1.json" --out-dir "$work/$1" --at "$2" --size 640x480
  cp "$work/$1/t_$(printf '%.3f' "$2").png" "docs/$1.png"
}

still example1_single_cube 1.6
still example2_two_cubes 0.9
still example3_stacked_cubes 0.6
still example4_two_spheres 1.0
"$tabletop" render scenarios/example2_two_cubes.json --fps 20 --size 480x360 --video docs/example2_two_cubes.gif

# The speed-against-error plot of the sliding cube: every rate, 10 and 50
# iterations, both integrators.
"$tabletop" bench scenarios/analytic/cube_slides_to_rest.json --repeats 5 --rates 30,60,120,240,1000,4000 \
  --iterations 10,50 --out-dir "$work/bench" > /dev/null
cp "$work/bench/bench_cube_slides_to_rest.png" docs/bench_cube_slides_to_rest.png

# compare's top view of the misaligned cubes in the three modes.
"$tabletop" compare scenarios/misaligned_cubes.json --plot docs/misaligned_cubes_compare.png > /dev/null
