# The regression cases: name, executable and arguments (sourced by
# regression.sh and by the script that wrote the references).
# Each line: NAME EXE ARGS...
regression_cases() {
  cat <<'CASES'
koyna_linear koyna --set mesh.size=4 --set time.duration=3
koyna_viscoplastic koyna --set material.model=viscoplastic --set mesh.order=1 --set mesh.size=4 --set time.duration=2 --set concrete.Gf=2000
koyna_table1 koyna --case @SRC@/demos/koyna/koyna_table1.toml --set mesh.size=3 --set time.duration=1
rcc_gravity rcc_gravity --set mesh.size=6 --set time.duration=1
arch_dam_joints arch_dam --set mesh.size=16 --set mesh.size_far=60 --set joints.count=3 --set time.duration=0.3 --set modal.count=4
CASES
}
