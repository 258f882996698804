#!/usr/bin/env bash
# Remakes the pictures of kvd view and kvd animate that the README shows:
# three screenshots of viewer pages (headless Chromium, through
# tests/viewer/check_page.py and check_segment_page.py, which check the pages
# too), and a sampled and a
# held frame and a GIF of an animation (ffmpeg), and the plot of the README's
# Python example (matplotlib).
# Usage: data/pictures/regenerate.sh [path/to/kvd] (default: build/kvd of this checkout).
set -euo pipefail
kvd="$(realpath "${1:-$(dirname "$0")/../../build/kvd}")"
cd "$(dirname "$0")/../.."
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
# Selenium is Debian's (python3-selenium): prefer the Python that has it.
py=python3
$py -c 'import selenium' 2>/dev/null || py=/usr/bin/python3
$py tests/viewer/check_page.py "$kvd" "$tmp" data/collisions.json data/segments/rotating-10.json \
  --diff data/stiff/tangential.json=double --events 40
cp "$tmp/viewer-collisions.png" "$tmp/viewer-tangential-diff.png" "$tmp/segment-viewer-rotating-10.png" data/pictures/

view=30,-40,25
args=(data/collisions.json --view "$view" --events 20 --frames 60 --hold 5 --size 480)
"$kvd" animate "${args[@]}" --out "$tmp/collisions.svg" > /dev/null
"$kvd" animate "${args[@]}" --out "$tmp/collisions.mp4" > /dev/null
# The frame numbers of the 20th sampled picture and of the middle of the hold after batch 4.
read -r sampled held < <(python3 - "$tmp/collisions.svg" <<'PY'
import re, sys
frame, sampled, held, seen = 0, None, None, 0
for g in re.findall(r'<g class="frame"[^>]*>', open(sys.argv[1]).read()):
    batch = re.search(r'data-batch="(\d+)"', g)
    if batch and batch.group(1) == "3" and held is None:
        held = frame + 2
    if not batch:
        seen += 1
        if seen == 20:
            sampled = frame
    frame += 5 if batch else 1
print(sampled, held)
PY
)
ffmpeg -loglevel error -y -i "$tmp/collisions.mp4" -vf "select=eq(n\,$sampled)" -frames:v 1 data/pictures/animate-collisions-sampled.png
ffmpeg -loglevel error -y -i "$tmp/collisions.mp4" -vf "select=eq(n\,$held)" -frames:v 1 data/pictures/animate-collisions-event.png
"$kvd" animate data/collisions.json --view "$view" --events 20 --frames 40 --hold 4 --size 320 \
  --out data/pictures/animate-collisions.gif > /dev/null
# The README's Python example: the updates of a run, plotted with matplotlib.
PYTHONPATH="$(dirname "$kvd")/python" $py examples/python/plot_updates.py data/uniform-scale-100.json \
  data/pictures/python-updates.png > /dev/null
echo "data/pictures: viewer, animation and Python pictures remade"
