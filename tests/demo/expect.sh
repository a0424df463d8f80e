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

# `expect_no_equilibrium NAME PATTERN ARGS...`: runs "$exe" --out
# "$work/NAME" ARGS... and checks exit code 4 (a failure found once the run
# has begun, such as "no static equilibrium"), a stderr matching PATTERN
# and no summary.json; exits 1 otherwise. Needs $exe and $work.
expect_no_equilibrium() {
  local name=$1 pattern=$2
  shift 2
  local status=0
  "$exe" --out "$work/$name" "$@" >/dev/null 2>"$work/$name.err" || status=$?
  if [ "$status" -ne 4 ] || ! grep -q -- "$pattern" "$work/$name.err" ||
    [ -e "$work/$name/summary.json" ]; then
    echo "FAIL $name: exit $status, $(cat "$work/$name.err")"
    exit 1
  fi
  echo "ok   $name: $(cat "$work/$name.err")"
}
