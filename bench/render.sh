#!/usr/bin/env bash
# Usage: bench/render.sh BUILD_DIR
# Rendering at poster size: rules/dots.acr (its %draw: a dot coloured by placement order, with a
# rim) grown into rect:4000,4000 at --resolution 4096 and written at --width 4096 to each
# format, one process per output so that each peak memory (GNU time's maximum resident set) is
# its own. The growth's own peak and time come from a run whose output is a 16 px PNG (drawing
# 444,626 dots on 16 px costs nothing worth counting). For each format: peak MB, growth and render
# seconds (--metrics), file bytes per element. The goals (docs/rendering.md): SVG at most 100
# bytes per element, its peak at most 10 % over the growth's and under 400 MB, its render time at
# most a third of the growth's; PDF, PS and EPS peaks under twice the growth's.
# Last line: one JSON object. ACANTHUS_BENCH_RENDER_SIDE and _PX make it smaller (a quick try).
# needs: acanthus
set -euo pipefail
BUILD="$1"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ACANTHUS="$BUILD/compiler/acanthus"
SIDE="${ACANTHUS_BENCH_RENDER_SIDE:-4000}"
PX="${ACANTHUS_BENCH_RENDER_PX:-4096}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$ACANTHUS" build "$ROOT/rules/dots.acr" -o "$work/dots" >&2

# run NAME OUTPUT WIDTH -> "peak_kb growth_s render_s elements bytes"
run() {
  local name=$1 out=$2 width=$3
  /usr/bin/time -f "%M" -o "$work/$name.time" "$work/dots" --region "rect:$SIDE,$SIDE" \
    --resolution "$PX" --width "$width" --quiet --metrics -o "$work/$out" >"$work/$name.json"
  python3 - "$work/$name.json" "$work/$name.time" "$work/$out" <<'PY'
import json, os, sys
m = json.load(open(sys.argv[1]))
peak = open(sys.argv[2]).read().split()[-1]
print(peak, m["seconds"]["growth"], m["seconds"]["render"], m["elements"], os.path.getsize(sys.argv[3]))
PY
  rm -f "$work/$out"
}

declare -A peak growth render bytes
elements=0
for f in growth svg pdf ps eps; do
  if [ "$f" = growth ]; then r=$(run growth g.png 16); else r=$(run "$f" "out.$f" "$PX"); fi
  read -r peak[$f] growth[$f] render[$f] elements bytes[$f] <<<"$r"
  printf '%-6s peak %7.1f MB  growth %6.2f s  render %6.2f s  %8.1f bytes/element\n' "$f" \
    "$(echo "${peak[$f]} / 1024" | bc -l)" "${growth[$f]}" "${render[$f]}" \
    "$(echo "${bytes[$f]} / $elements" | bc -l)" >&2
done

python3 - "$elements" "$SIDE" "$PX" \
  "${peak[growth]}" "${growth[growth]}" \
  "${peak[svg]}" "${growth[svg]}" "${render[svg]}" "${bytes[svg]}" \
  "${peak[pdf]}" "${render[pdf]}" "${bytes[pdf]}" \
  "${peak[ps]}" "${render[ps]}" "${bytes[ps]}" \
  "${peak[eps]}" "${render[eps]}" "${bytes[eps]}" <<'PY'
import json, sys
a = sys.argv[1:]
n, side, px = int(a[0]), int(a[1]), int(a[2])
mb = lambda kb: round(int(kb) / 1024, 1)
growth_peak, growth_s = mb(a[3]), float(a[4])
out = {"bench": "render", "pattern": "dots", "region": f"rect:{side},{side}", "resolution": px,
       "elements": n, "growth_peak_mb": growth_peak, "growth_seconds": round(growth_s, 2)}
svg_peak, svg_growth_s, svg_render_s, svg_bytes = mb(a[5]), float(a[6]), float(a[7]), int(a[8])
out["svg"] = {"peak_mb": svg_peak, "render_seconds": round(svg_render_s, 2),
              "bytes_per_element": round(svg_bytes / n, 1),
              "peak_over_growth": round(svg_peak / growth_peak, 3),
              "render_over_growth": round(svg_render_s / svg_growth_s, 3)}
for k, fmt in enumerate(["pdf", "ps", "eps"]):
    p, r, b = mb(a[9 + 3 * k]), float(a[10 + 3 * k]), int(a[11 + 3 * k])
    out[fmt] = {"peak_mb": p, "render_seconds": round(r, 2), "bytes_per_element": round(b / n, 1),
                "peak_over_growth": round(p / growth_peak, 3)}
out["goals"] = {
    "svg_bytes_per_element_le_100": out["svg"]["bytes_per_element"] <= 100,
    "svg_peak_le_1.1x_growth": out["svg"]["peak_over_growth"] <= 1.1,
    "svg_peak_under_400mb": svg_peak < 400,
    "svg_render_le_third_of_growth": out["svg"]["render_over_growth"] <= 1 / 3,
    **{f"{fmt}_peak_under_2x_growth": out[fmt]["peak_over_growth"] < 2 for fmt in ("pdf", "ps", "eps")},
}
print(json.dumps(out))
PY
