#!/bin/sh
# Re-makes every label from what was drawn (labels/drawn/tune/, check/) and the real frames: writes the
# drawing into the label, then the label tool finds the no-reading holes, fits the surfaces,
# shrinks the drawn obstacle boxes to the depth (except those the drawing's K line keeps as
# drawn) and recomputes the best rectangle. Run from the repository root after building
# projsurf_label_tool. A frame is looked for in REAL (../shared/data/real), then in the
# repository's own data/real (the frames whose licence lets them ship).
#   labels/remake.sh [../shared/data/real]
set -e
REAL=${1:-../shared/data/real}
TOOL=${TOOL:-build/tests/projsurf_label_tool}
for drawn in labels/drawn/*/*.txt; do
    frame=$(basename "$drawn" .txt)
    half=$(basename "$(dirname "$drawn")")  # tune or check: the label goes to the same half
    label=labels/real/$half/$frame.yaml
    dir=$REAL/$frame
    [ -d "$dir" ] || dir=data/real/$frame
    if [ ! -d "$dir" ]; then echo "remake: $frame: no frame in $REAL or data/real, skipped" >&2; continue; fi
    kept=$(sed -n 's/^K //p' "$drawn")
    [ -f "$label" ] || $TOOL init "$dir" "$label"
    python3 labels/apply_drawn.py "$drawn" "$label"
    $TOOL update "$dir" "$label" --holes 30 --refine "$kept" > /dev/null
done
