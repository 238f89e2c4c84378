#!/usr/bin/env bash
# Usage: inkscape/render-screenshots.sh ACANTHUS OUT_DIR
# The pictures of docs/inkscape.md, made by the extension itself on a greeting-card drawing:
# before (two shapes drawn in Inkscape), after (flowers in the heart, spirals in the medallion,
# each a run of the extension on its selection), both exported by Inkscape.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
acanthus="$(realpath "$1")"; out="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cat > "$work/card.svg" <<'SVG'
<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     width="240mm" height="150mm" viewBox="0 0 240 150">
  <g inkscape:groupmode="layer" inkscape:label="Card" id="card">
    <rect x="2" y="2" width="236" height="146" rx="6" style="fill:#fbf6ec;stroke:#8a6d3b;stroke-width:0.8"/>
    <path id="heart" style="fill:#f6e3d6;stroke:#7a2e2e;stroke-width:0.6"
          transform="translate(12,16) scale(0.76)"
          d="M 80,38 C 72,16 56,6 40,6 C 18,6 4,24 4,46 C 4,84 44,112 80,146
             C 116,112 156,84 156,46 C 156,24 142,6 120,6 C 104,6 88,16 80,38 Z"/>
    <g transform="rotate(-8,184,75)">
      <ellipse id="medallion" cx="184" cy="75" rx="44" ry="58"
               style="fill:#e4ecf6;stroke:#22407a;stroke-width:0.6"/>
    </g>
  </g>
</svg>
SVG
export PYTHONPATH=/usr/share/inkscape/extensions ACANTHUS_EXECUTABLE="$acanthus"
script="$ROOT/inkscape/acanthus_fill.py"
python=/usr/bin/python3
"$python" "$script" --id=heart --rules="$ROOT/rules/flowers.acr" --params="flower_radius=2.6" \
  --rng_seed=4 --resolution=512 "$work/card.svg" > "$work/step1.svg"
"$python" "$script" --id=medallion --rules="$ROOT/rules/spiral.acr" \
  --params="smallest=1.5, line_width=1.2" --rng_seed=2 --resolution=512 "$work/step1.svg" > "$work/card-filled.svg"
export_png() { inkscape --export-type=png --export-filename="$2" --export-width=960 "$1" 2>/dev/null; }
export_png "$work/card.svg" "$out/inkscape-before.png"
export_png "$work/card-filled.svg" "$out/inkscape-after.png"

