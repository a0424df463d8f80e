#!/usr/bin/env bash
# Warnings reach the log and summary.json "warnings": a record shorter than
# the analysis (El Centro lasts 31.16 s; 32 s asked: zero acceleration after
# its end), and an empty case file (every value a default or an override);
# the size estimate is printed before meshing.
# Usage: warnings.sh KOYNA PYTHON
set -eu
exe=$1 python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: >"$work/empty.toml"
"$exe" --case "$work/empty.toml" --out "$work/run" --set mesh.size=8 \
  --set time.duration=32 --set time.dt=0.02 --set output.plots=false \
  --set output.every=10000 \
  --set motion.horizontal.record="$(cd "$(dirname "$0")/../.." && pwd)/data/records/elcentro_1940_ns.at2" \
  >"$work/log" 2>&1
grep -q "warning: .*lasts 31.16 s" "$work/log"
grep -q "warning: .*empty.toml gives no keys" "$work/log"
# The size estimate comes before the mesh (issue 16): its line precedes the
# model line "damseis: N cells, M dofs".
estimate=$(grep -n -m1 "size estimate before meshing: about .* cells, .* dofs, .* GB of memory, .* ms per linear time step" "$work/log" | cut -d: -f1)
model=$(grep -n -m1 "^damseis: [0-9]* cells" "$work/log" | cut -d: -f1)
[ -n "$estimate" ] && [ -n "$model" ] && [ "$estimate" -lt "$model" ]
"$python" - "$work/run/summary.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["warnings"]
print("summary warnings:", w)
assert any("lasts 31.16 s" in x for x in w)
assert any("gives no keys" in x for x in w)
PY
