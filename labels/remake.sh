#!/bin/sh
# Re-makes every label from what was drawn (labels/drawn/) and the real frames: writes the
# drawing into the label, then the label tool finds the no-reading holes, fits the surfaces,
# shrinks the drawn obstacle boxes to the depth (except those kept as drawn) and recomputes the
# best rectangle. Run from the repository root after building projsurf_label_tool.
#   labels/remake.sh [../shared/data/real]
set -e
REAL=${1:-../shared/data/real}
TOOL=build/tests/projsurf_label_tool
kept() {
    case "$1" in
        7scenes_redkitchen_000250) echo "TV" ;;
        7scenes_redkitchen_000450) echo "left TV;right TV" ;;
        ufsec_livingroom_sofa_1) echo "window with blinds" ;;
        ufsec_livingroom_sofa_2) echo "framed pictures;window with blinds" ;;
        *) echo "" ;;
    esac
}
for drawn in labels/drawn/*.txt; do
    frame=$(basename "$drawn" .txt)
    label=labels/real/$frame.yaml
    [ -f "$label" ] || $TOOL init "$REAL/$frame" "$label"
    python3 labels/apply_drawn.py "$drawn" "$label"
    $TOOL update "$REAL/$frame" "$label" --holes 30 --refine "$(kept "$frame")" > /dev/null
done
