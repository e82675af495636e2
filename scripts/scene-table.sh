#!/usr/bin/env bash
# The README's table "Measured on the RTL": every shipped scene drawn by raster_top in
# Verilator (`render --engine rtl`, which fails unless image, depth and cycles equal the
# scanline model's), one Markdown row per scene. Extra arguments go to every render, e.g.
# `scripts/scene-table.sh --param L=13`. Needs a release build (`cargo build --release`), or
# another edgepaint named by EDGEPAINT (the images and cycles are the same).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/tools-env.sh
source scripts/tools-env.sh
bin=${EDGEPAINT:-target/release/edgepaint}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "| scene | size | triangles (drawn) | cycles | pixels written | pixels per clock | latency | cycles between triangles (mean) |"
echo "|---|---|---|---:|---:|---:|---|---:|"
for spec in cube:320x240 sphere:320x240 cone:320x240 torus:320x240 pawn:320x240 house:320x240 clip:320x240 all:640x480; do
    scene=${spec%%:*}
    size=${spec#*:}
    line=$("$bin" render --engine rtl --top raster_top "scenes/$scene.json" --size "$size" -o "$out/$scene.png" "$@" 2>&1 | grep '^render rtl')
    python3 - "$scene" "$size" "$line" <<'EOF'
import re, sys
scene, size, line = sys.argv[1:]
def num(pattern):
    m = re.search(pattern, line)
    if not m:
        sys.exit(f"scene-table: {scene}: no match for {pattern!r} in: {line}")
    return m.groups()
tri_in, drawn = num(r"(\d+) triangles in, (\d+) drawn")
(cycles,) = num(r"; (\d+) cycles \(model::cycles")
(written,) = num(r"(\d+) pixels written")
(ppc,) = num(r"([\d.]+) pixels per clock")
lat_min, lat_med = num(r"first pixel (\d+)/(\d+)/")
(between,) = num(r"([\d.]+) cycles between triangles")
f = lambda n: f"{int(n):,}"
print(f"| {scene} | {size} | {f(tri_in)} ({f(drawn)}) | {f(cycles)} | {f(written)} | {ppc} | "
      f"{lat_min} / {f(lat_med)} | {f(round(float(between)))} |")
EOF
done
