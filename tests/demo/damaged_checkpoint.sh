#!/usr/bin/env bash
# A damaged checkpoint never crashes a restart nor reaches the results: a
# truncated or mistyped checkpoint.json, an empty or truncated rank file, a
# NaN in its payload and a corrupted array length each stop the restart
# with one line and exit code 2, and so does a restart of a changed case.
# Usage: damaged_checkpoint.sh KOYNA PYTHON
set -u
exe=$1 python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set mesh.size=8 --set time.duration=0.5 --set output.plots=false
        --set output.every=1000 --set run.checkpoint_every=20)
"$exe" --out "$work/good" "${common[@]}" --set run.stop_at_step=30 \
  >/dev/null 2>&1
[ -f "$work/good/checkpoint/checkpoint.json" ] || { echo "no checkpoint"; exit 1; }
fail=0
damage() { # damage NAME PYTHON-CODE: copy the run, damage it, restart it
  local name=$1 code=$2 dir="$work/$1"
  cp -r "$work/good" "$dir"
  "$python" - "$dir/checkpoint" <<PY
import glob, json, os, struct, sys
ck = sys.argv[1]
bins = sorted(glob.glob(os.path.join(ck, "rank*_step*.bin")))
$code
PY
  "$exe" --out "$dir" "${common[@]}" --set run.restart=true \
    >"$work/stdout" 2>"$work/stderr"
  local rc=$? lines
  lines=$(wc -l <"$work/stderr")
  if [ "$rc" -eq 2 ] && [ "$lines" -eq 1 ] && grep -q checkpoint "$work/stderr"; then
    echo "ok   $name: $(cat "$work/stderr")"
  else
    echo "FAIL $name: exit $rc, $lines stderr lines:"; cat "$work/stderr"
    fail=1
  fi
}
damage json_truncated 'open(os.path.join(ck, "checkpoint.json"), "w").write("{\"step\": 2")'
damage json_step_string 'open(os.path.join(ck, "checkpoint.json"), "w").write("{\"step\": \"20\", \"ranks\": 1}")'
damage bin_empty 'open(bins[0], "wb").close()'
damage bin_truncated 'b = open(bins[0], "rb").read(); open(bins[0], "wb").write(b[: len(b) // 2])'
damage bin_nan 'b = bytearray(open(bins[0], "rb").read()); b[-8:] = struct.pack("d", float("nan")); open(bins[0], "wb").write(b)'
damage bin_huge_length 'b = bytearray(open(bins[0], "rb").read()); b[32:40] = struct.pack("q", 1 << 60); open(bins[0], "wb").write(b)'
# A restart of another case (material.E changed) is refused; a changed
# solver setting is allowed (it may be what gets a failing step through).
cp -r "$work/good" "$work/changed"
"$exe" --out "$work/changed" "${common[@]}" --set run.restart=true \
  --set material.E=31e9 >"$work/stdout" 2>"$work/stderr"
rc=$?
if [ "$rc" -eq 2 ] && grep -q "does not match this run" "$work/stderr"; then
  echo "ok   case_changed: $(cat "$work/stderr")"
else
  echo "FAIL case_changed: exit $rc"; cat "$work/stderr"; fail=1
fi
"$exe" --out "$work/changed" "${common[@]}" --set run.restart=true \
  --set solver.factorization=mumps >"$work/stdout" 2>"$work/stderr"
rc=$?
if [ "$rc" -eq 0 ] && grep -q "restarting from the checkpoint at step" "$work/stdout"; then
  echo "ok   solver_changed: restarted"
else
  echo "FAIL solver_changed: exit $rc"; cat "$work/stderr"; fail=1
fi
[ "$fail" -eq 0 ] && echo "all damaged-checkpoint checks passed"
exit "$fail"
