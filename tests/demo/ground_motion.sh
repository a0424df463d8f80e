#!/usr/bin/env bash
# The ground_motion demo: the default generation meets the acceptance in its
# own files (spectra.csv against target_spectrum.csv within +-10%, PGA, end
# at rest, correlations), the AT2 files it writes read back through the
# spectrum task give the same spectra (8 significant digits in g: asserted
# 1e-5 relative), and bad input is one line, exit 2, nothing written.
# Usage: ground_motion.sh GROUND_MOTION PYTHON
set -u
exe=$1 python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

"$exe" --out "$work/gen" --set output.plots=false >"$work/log" 2>&1 ||
  { echo "FAIL generate: exit $?"; cat "$work/log"; exit 1; }
"$exe" --out "$work/back" --set task=spectrum output.plots=false \
  records.h1="$work/gen/h1.at2" records.h2="$work/gen/h2.at2" \
  records.v="$work/gen/v.at2" spectra.period_min=0.04 spectra.period_max=4.0 \
  spectra.periods=100 >>"$work/log" 2>&1 ||
  { echo "FAIL spectrum task: exit $?"; cat "$work/log"; exit 1; }
"$python" - "$work/gen" "$work/back" <<'PY' || failures=$((failures + 1))
import csv, json, math, sys
gen, back = sys.argv[1:3]
def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}
s, t, b = (table(gen + "/spectra.csv"), table(gen + "/target_spectrum.csv"),
           table(back + "/spectra.csv"))
summary = json.load(open(gen + "/summary.json"))
assert summary["accepted"], summary
worst = 0.0
for name, target in [("h1", "horizontal_m_s2"), ("h2", "horizontal_m_s2"),
                     ("v", "vertical_m_s2")]:
    for sa, ta in zip(s[name + "_zeta_0.05"], t[target]):
        worst = max(worst, abs(sa / ta - 1))
    for x, y in zip(s[name + "_zeta_0.05"], b[name + "_zeta_0.05"]):
        assert abs(x - y) <= 1e-5 * abs(x), (name, x, y)
assert worst <= 0.10 + 1e-9, worst
g = 9.80665
for c in summary["components"]:
    pga = 0.321 * g * (2 / 3 if c["name"] == "v" else 1)
    assert abs(c["pga_m_s2"] - pga) < 1e-3 * pga, c
    assert abs(c["final_velocity_m_s"]) < 1e-6 and abs(c["final_displacement_m"]) < 1e-5, c
for r in summary["correlations"].values():
    assert abs(r) <= 0.16, summary["correlations"]
print("generated: worst spectral deviation %.3f, AT2 round trip ok" % worst)
PY

printf 'h1\nh2\nh3\nNPTS= 1, DT= 0.01 SEC\n0.1\n' >"$work/one.at2"
: >"$work/empty.txt"
expect unknown_code 'ground_motion\.toml.*target\.code.*NB35047-2015' --set target.code=GB50011
expect unknown_site_class 'ground_motion\.toml.*target\.site_class.*site class "V"' --set target.site_class=V
expect negative_period 'ground_motion\.toml.*generate\.period_min' --set generate.period_min=-1
expect damping_one 'ground_motion\.toml.*spectra\.damping' --set 'spectra.damping=[1.0]'
expect seed_not_integer 'ground_motion\.toml.*generate\.seed' --set generate.seed=1.5
expect empty_record 'ground_motion\.toml.*records\.h1.*empty\.txt' --set task=spectrum records.h1="$work/empty.txt"
expect one_point_record 'ground_motion\.toml.*records\.h1.*fewer than two samples' --set task=spectrum records.h1="$work/one.at2"
expect no_record 'ground_motion\.toml.*records\.h1.*at least one record' --set task=spectrum
expect strong_phase_too_long 'ground_motion\.toml.*generate\.strong_end' --set generate.strong_end=30
expect table_too_short 'ground_motion\.toml.*target\.table_period.*cover' --set target.code=table 'target.table_period=[0.0, 1.0]' 'target.table_sa_g=[0.3, 0.5]'

if [ "$failures" -ne 0 ]; then
  echo "$failures ground_motion checks failed"; exit 1
fi
echo "all ground_motion checks passed"
