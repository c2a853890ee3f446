#!/usr/bin/env bash
# Regenerates docs/eval/report.md (and its charts) with the full `projsurf eval` at the checked-out
# commit, from the repository root after a build (build/projsurf). The report says the commit and
# the date; the per-frame pictures that eval writes beside its own copy (gallery/, labels/) are
# not committed, so their links become plain names here.
#   bash scripts/eval_report.sh [OUT]    (OUT: where eval writes its full output, default /tmp/projsurf-eval)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/projsurf-eval}
build/projsurf eval --no-progress --out "$out"
commit=$(git rev-parse --short HEAD)
{
    echo "<!-- Made by scripts/eval_report.sh at $commit on $(date -u +%Y-%m-%d): build/projsurf eval --out $out -->"
    echo
    echo "*Regenerated at commit $commit on $(date -u +%Y-%m-%d) by \`bash scripts/eval_report.sh\`.*"
    echo
    python3 - "$out/report.md" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
lines = [l for l in text.split('\n') if not re.match(r'^\s*!\[[^\]]*\]\((gallery|labels)/[^)]*\)\s*$', l)]
text = '\n'.join(lines)
text = re.sub(r'!\[([^\]]*)\]\((gallery|labels)/[^)]*\)', r'\1', text)
text = re.sub(r'\[([^\]]*)\]\((gallery|labels)/[^)]*\)', r'\1', text)
sys.stdout.write(text)
PY
} > docs/eval/report.md
cp "$out"/{keystone,outliers,success_cluttered,success_uncluttered,timing}.png docs/eval/
echo "eval_report: wrote docs/eval/report.md at $commit"
