#!/usr/bin/env bash
# The output folder of a run (results/output_folder.h):
#  1. a run in a folder that holds an earlier run's results deletes exactly
#     the files that run wrote (a nonlinear run's dam_points.csv and
#     strain_rates.png are gone after a linear run in the same folder), and
#     nothing of the user's (notes.txt, mydata.csv stay; the run warns that
#     mydata.csv is not its own);
#  2. output.overwrite = refuse stops with exit 2 and one line, and changes
#     nothing;
#  3. run.restart = true without a checkpoint stops with exit 2, one line,
#     and writes nothing;
#  4. an unusable --out (empty, an existing file, a path under a file, a
#     device, a place that cannot be written) stops with exit 2 and one line
#     before any work, and creates nothing.
# Usage: output_folder.sh KOYNA
set -u
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
check() { # check NAME CONDITION...
  local name=$1
  shift
  if "$@"; then echo "ok   $name"; else echo "FAIL $name"; fail=1; fi
}
one_line_exit2() { # one_line_exit2 NAME ARGS...: exit 2, one stderr line
  local name=$1
  shift
  "$exe" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ "$rc" -eq 2 ] && [ "$lines" -eq 1 ]; then
    echo "ok   $name: $(cat "$work/stderr")"
  else
    echo "FAIL $name: exit $rc, $lines stderr lines:"
    cat "$work/stderr"
    fail=1
  fi
}
small=(--set mesh.size=8 --set time.duration=0.2 --set output.every=100)

out="$work/run"
"$exe" --out "$out" "${small[@]}" --set material.model=viscoplastic \
  --set mesh.order=1 >/dev/null 2>&1
check "nonlinear run wrote dam_points.csv and strain_rates.png" \
  test -f "$out/dam_points.csv" -a -f "$out/strain_rates.png" \
  -a -f "$out/.damseis_outputs"
echo "my notes" >"$out/notes.txt"
echo "1,2" >"$out/mydata.csv"
"$exe" --out "$out" "${small[@]}" --set output.plots=false \
  >"$work/stdout" 2>&1
check "second run says it removed the earlier files" \
  grep -q "removed the [0-9]* files of the earlier run" "$work/stdout"
check "stale dam_points.csv and strain_rates.png are gone" \
  test ! -e "$out/dam_points.csv" -a ! -e "$out/strain_rates.png"
check "the user's files stay" test -f "$out/notes.txt" -a -f "$out/mydata.csv"
check "the run warns about mydata.csv" \
  grep -q "not written by this run (mydata.csv)" "$work/stdout"
check "the manifest lists the new run's files only" \
  bash -c "grep -qx summary.json '$out/.damseis_outputs' &&
           ! grep -q mydata '$out/.damseis_outputs'"

find "$out" -type f -printf '%P %s %T@\n' | sort >"$work/before"
one_line_exit2 refuse --out "$out" "${small[@]}" \
  --set output.overwrite=refuse
find "$out" -type f -printf '%P %s %T@\n' | sort >"$work/after"
check "refuse changes nothing" cmp -s "$work/before" "$work/after"

one_line_exit2 restart_without_checkpoint --out "$work/fresh" "${small[@]}" \
  --set run.restart=true
check "restart without checkpoint writes nothing" test ! -e "$work/fresh"

touch "$work/afile"
one_line_exit2 out_empty --out "" "${small[@]}"
one_line_exit2 out_is_file --out "$work/afile" "${small[@]}"
one_line_exit2 out_under_file --out "$work/afile/sub" "${small[@]}"
one_line_exit2 out_is_device --out /dev/null "${small[@]}"
one_line_exit2 out_not_writable --out /proc/damseis_out "${small[@]}"
check "the file is untouched" test ! -s "$work/afile"

[ "$fail" -eq 0 ] && echo "all output-folder checks passed"
exit "$fail"
