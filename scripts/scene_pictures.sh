#!/usr/bin/env bash
# Renders the shipped scenes at 400x300 and puts them in one picture, docs/scenes.png (the
# README shows it). Needs a build in build/ (make build).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
scenes=(sphere_and_flag gouraud_vs_phong npr robot_arm shadows point_shadows planar_shadows normal_map obj_model gltf_model deferred_lights)
for s in "${scenes[@]}"; do "$root/build/apps/tessel" render "$root/scenes/$s.json" --size 400x300 -o "$tmp/$s.png" >/dev/null; done
g++ -std=c++20 -O1 -march=x86-64-v3 -I"$root/include" "$root/scripts/montage.cpp" "$root/build/src/gpu/libtessel_gpu.a" -lstb -lpthread -o "$tmp/montage"
(cd "$tmp" && ./montage "$root/docs/scenes.png" 4 $(printf '%s.png ' "${scenes[@]}"))
rm -rf "$tmp"
echo "wrote docs/scenes.png"
