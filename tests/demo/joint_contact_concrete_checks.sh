#!/usr/bin/env bash
# Contact joints on HTC concrete (issue 19: the contact as a constraint of
# the Newton iteration, joint::NonlinearContact), against the linear
# engine's condensed contact and against closed forms. The cube on a
# horizontal joint (friction 0.2) of tests/data/case/sliding_block.toml,
# HHT alpha = -0.1, dt = 1 ms, P1.
#  1. Elastic HTC concrete (material.model = "elastic") with contact is the
#     linear engine with contact (an independent code path: the contact
#     condensed on the linear effective matrix, the static stage by the
#     proximal-point iteration): the crest history within 1e-8 m (the static
#     stage's Newton tolerance 1e-6 of the load against the linear one's
#     1e-10: measured 1e-10 m, the digits written) and the largest
#     sliding within 1e-6 of the slip. And on the paper's arch dam (7
#     contact joints, 30 m mesh, P2 with the midside pairs following, low
#     reservoir 215 m, 1.5 s of the Section I record): every entry of the
#     joint table within 1e-3 cm (4 decimals written; measured 1e-4 cm, one
#     digit in the last place) and the crest history within 1e-6 m
#     (measured 4e-7 m: the static stage's Newton tolerance; run by hand
#     since, to keep CI short: the cube covers massless rock). On
#     rock with mass on the viscous-spring boundary (rho 2000 kg/m3: the
#     everything-on run's foundation): the same modes and Rayleigh
#     coefficients (the bonded system's springs in both engines; 1e-12),
#     the joint table within 1e-3 cm (measured equal) and the crest
#     history within 1e-6 m (measured 6e-8 m).
#  2. Yielding concrete (plastic, fc = 30 kPa, ft = 2 kPa, no softening:
#     the cube's own weight and inertia stress it to its strength) slides
#     as Newmark's rigid block (tests/demo/rigid_block.py), since the slip
#     of a compact block depends on its mass and the joint's friction
#     alone: within 0.5%, the elastic cube's tolerance in
#     joint_contact_checks.sh (measured +0.24%; the elastic cube +0.14%);
#     and the concrete did yield (kappa_t > 0).
#  3. The friction threshold in the static stage with yielding concrete: a
#     horizontal body force b = 0.98 mu rho g on the cube besides its
#     weight. Statics of the cube, held by the joint alone: the joint's
#     forces sum to (-b, 0, rho g) V whatever the concrete does (1e-6 of
#     rho g V, the static Newton tolerance; measured 9e-8), with inelastic
#     points; at b = 1.02 mu rho g there is no static equilibrium (exit 4).
#  4. 2 MPI ranks give the serial run of (2): crest history within 1e-8 m.
#  5. The run of (2) stopped at a checkpoint (step 300 of 600, the cube
#     sliding) and restarted gives the uninterrupted run: crest history
#     within 1e-9 m (the contact and material states are in the
#     checkpoint).
# Usage: joint_contact_concrete_checks.sh DAM_MODEL ARCH_DAM MPIEXEC PYTHON SOURCE_DIR
set -eu
dm=$1 arch=$2 mpiexec=$3 python=$4 src=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
exe=$dm
source "$(dirname "$0")/expect.sh"
case=$src/tests/data/case/sliding_block.toml
run() { # out args...
  local out=$1
  shift
  "$dm" --case "$case" --out "$work/$out" --set output.plots=false \
    --set output.every=100000 --set time.hht_alpha=-0.1 --set mesh.order=1 \
    --set joints.model=contact --set 'joints.friction=[0.2]' "$@" >/dev/null
}
weak=(--set material.model=plastic --set concrete.fc=3e4 --set concrete.ft=2e3
  --set concrete.tension_softening=none)
run linear
run elastic --set material.model=elastic
run plastic "${weak[@]}"
for stop in "--set run.stop_at_step=300" "--set run.restart=true"; do
  status=0
  run restarted "${weak[@]}" --set run.checkpoint_every=50 $stop \
    2>/dev/null || status=$?
  [ "$status" -eq 0 ] || [ "$status" -eq 3 ] || exit 1
done
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  OMPI_MCA_rmaps_base_oversubscribe=1 "$mpiexec" -n 2 "$dm" --case "$case" \
  --out "$work/plastic_2" --set output.plots=false --set output.every=100000 \
  --set time.hht_alpha=-0.1 --set mesh.order=1 --set joints.model=contact \
  --set 'joints.friction=[0.2]' "${weak[@]}" >/dev/null

# The friction threshold in the static stage (3).
bx() { "$python" -c "print($1 * 0.2 * 2400 * 9.81)"; }
run hold "${weak[@]}" --set time.duration=0.002 \
  --set 'loads.body_force_groups=[block]' --set "loads.body_force=[$(bx 0.98), 0, 0]"
expect_no_equilibrium "static_friction_threshold_plastic" \
  'no equilibrium' --case "$case" --set output.plots=false --set mesh.order=1 \
  --set joints.model=contact --set 'joints.friction=[0.2]' "${weak[@]}" \
  --set 'loads.body_force_groups=[block]' --set "loads.body_force=[$(bx 1.02), 0, 0]"

# The arch dam with 7 contact joints, linear and elastic HTC, on rock with
# mass (1; massless, the cube's runs above).
arch_run() { # out args...
  local out=$1
  shift
  "$arch" --case "$src/demos/arch_dam/section1_table1.toml" \
    --out "$work/$out" --set study.table1=false --set output.plots=false \
    --set output.every=100000 --set joints.count=7 --set joints.model=contact \
    --set mesh.size=30 --set time.duration=1.5 --set time.hht_alpha=-0.1 \
    --set reservoir.level=215 "$@" >/dev/null
}
vs=(--set foundation.boundary=viscous_spring --set rock.rho=2000)
for model in linear elastic; do
  arch_run "arch_vs_$model" --set material.model=$model "${vs[@]}"
done

"$python" - "$work" "$(dirname "$0")" <<'PY'
import csv, json, sys
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from rigid_block import rigid_slip

def summary(run):
    return json.load(open(f"{work}/{run}/summary.json"))

def rows(run, name):
    with open(f"{work}/{run}/{name}") as f:
        r = list(csv.reader(f))
    return [[float(v) for v in row[1:]] if name == "joint_table.csv"
            else [float(v) for v in row] for row in r[1:]]

def largest_difference(a, b):
    return max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))

failures = 0
def check(name, ok, detail):
    global failures
    print(("ok  " if ok else "FAIL") + f" {name}: {detail}")
    failures += not ok

# 1. Elastic HTC with contact = the linear engine with contact.
d = largest_difference(rows("linear", "crest.csv"), rows("elastic", "crest.csv"))
sl = summary("linear")["joints"]["max_sliding_cm"]
se = summary("elastic")["joints"]["max_sliding_cm"]
check("cube: elastic HTC = linear (crest)", d < 1e-8, f"crest histories differ by {d:.1e} m")
check("cube: elastic HTC = linear (sliding)", abs(se - sl) < 1e-6 * sl,
      f"largest sliding {se:.8f} cm against {sl:.8f} cm")
lin, el, where = "arch_vs_linear", "arch_vs_elastic", "rock with mass"
d = largest_difference(rows(lin, "joint_table.csv"), rows(el, "joint_table.csv"))
check(f"arch, 7 contact joints, {where}: elastic HTC = linear (joint table)",
      d <= 1e-3, f"entries differ by {d:.1e} cm")
d = largest_difference(rows(lin, "crest.csv"), rows(el, "crest.csv"))
check(f"arch, 7 contact joints, {where}: elastic HTC = linear (crest)",
      d < 1e-6, f"crest histories differ by {d:.1e} m")
a, b = summary(lin)["damping"], summary(el)["damping"]
same = all(abs(a[k] - b[k]) <= 1e-12 * abs(a[k])
           for k in ("a_mass", "b_stiffness"))
check(f"arch, 7 contact joints, {where}: the same Rayleigh damping", same,
      f"a_M {a['a_mass']:.6g} / {b['a_mass']:.6g}, "
      f"b_K {a['b_stiffness']:.6g} / {b['b_stiffness']:.6g}")

# 2. The yielding cube slides as the rigid block.
s = summary("plastic")
ref = rigid_slip(0.5)
slip = s["joints"]["max_sliding_cm"] / 100.0
check("yielding cube slides as the rigid block", abs(slip / ref - 1) < 5e-3,
      f"slip {slip:.6f} m, rigid block {ref:.6f} m ({slip / ref - 1:+.2%})")
check("the cube's concrete yielded", s["max_kappa_t"]["value"] > 0.0,
      f"largest kappa_t {s['max_kappa_t']['value']:.2e}")

# 3. Statics: the joint carries the cube's loads.
with open(f"{work}/hold/joint_static.csv") as f:
    r = list(csv.DictReader(f))
force = [sum(float(p[f"f_{c}_kN"]) * 1e3 for p in r) for c in "xyz"]
weight = 2400 * 9.81
expected = [-0.98 * 0.2 * weight, 0.0, weight]
err = max(abs(a - b) for a, b in zip(force, expected)) / weight
kappa = summary("hold")["max_kappa_t"]["value"]  # static and 2 steps
check("static friction threshold on yielding concrete, 0.98 mu rho g holds",
      err < 1e-6 and kappa > 0.0, f"largest kappa_t {kappa:.2e}; joint forces {force[0]:.3f}, {force[1]:.3f}, {force[2]:.3f} N "
      f"(statics: {expected[0]:.3f}, 0, {expected[2]:.3f}; {err:.1e} of rho g V)")

# 4-5. 2 ranks and a restart give the serial, uninterrupted run.
base = rows("plastic", "crest.csv")
d = largest_difference(base, rows("plastic_2", "crest.csv"))
check("2 ranks = serial", d < 1e-8, f"crest histories differ by {d:.1e} m")
d = largest_difference(base, rows("restarted", "crest.csv"))
check("restart = uninterrupted", d < 1e-9, f"crest histories differ by {d:.1e} m")
sys.exit(1 if failures else 0)
PY
