# Shared by the bad-input scripts: `expect NAME PATTERN ARGS...` runs
# "$exe" --out "$work/out_NAME" ARGS... and checks exit code 2, exactly one
# stderr line matching PATTERN, and no output folder. Needs $exe and $work;
# counts failures in $failures.
expect() {
  local name=$1 pattern=$2
  shift 2
  local out="$work/out_$name"
  "$exe" --out "$out" "$@" >"$work/stdout" 2>"$work/stderr"
  local rc=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ "$rc" -ne 2 ]; then
    echo "FAIL $name: exit code $rc, expected 2"; cat "$work/stderr"
    failures=$((failures + 1))
  elif [ "$lines" -ne 1 ]; then
    echo "FAIL $name: $lines stderr lines, expected 1:"; cat "$work/stderr"
    failures=$((failures + 1))
  elif ! grep -Eq -- "$pattern" "$work/stderr"; then
    echo "FAIL $name: message does not match '$pattern':"; cat "$work/stderr"
    failures=$((failures + 1))
  elif [ -e "$out" ]; then
    echo "FAIL $name: output folder was created"; failures=$((failures + 1))
  else
    echo "ok   $name: $(cat "$work/stderr")"
  fi
}
