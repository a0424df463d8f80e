"""The asserted bounds of the demo test scripts: each check prints its
value and bound, ok or FAIL; the script ends with finish(), which exits 1
if any failed (so that every check is reported, not only the first)."""
import sys

failures = 0


def check(what, value, bound):
    """value < bound."""
    global failures
    ok = value < bound
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} {what}: {value:.3g} (bound {bound:.3g})")


def finish():
    sys.exit(1 if failures else 0)
