#!/usr/bin/env bash
# Bad input to the koyna demo: one clear line naming the file and the key,
# exit code 2, and nothing written to the output folder.
# Usage: bad_input.sh KOYNA_EXECUTABLE
set -u
exe=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect NAME PATTERN ARGS... (tests/demo/expect.sh)
source "$(dirname "$0")/expect.sh"

printf 'mesh = [\n' >"$work/malformed.toml"
printf '[material]\nEE = 3e10\n' >"$work/unknown.toml"
printf '[material]\nE = "thirty"\n' >"$work/wrongtype.toml"
printf '[material]\nE = -3e10\n' >"$work/negative.toml"
printf '[motion.horizontal]\nrecord = "missing.at2"\n' >"$work/missing.toml"
printf 'garbage here\n' >"$work/bad.at2"
printf '[motion.horizontal]\nrecord = "bad.at2"\n' >"$work/badrecord.toml"

expect malformed_toml 'malformed\.toml:[0-9]+' --case "$work/malformed.toml"
expect unknown_key 'unknown\.toml.*material\.EE.*material\.E' --case "$work/unknown.toml"
expect wrong_type 'wrongtype\.toml.*material\.E' --case "$work/wrongtype.toml"
expect negative_modulus 'negative\.toml.*material\.E.*1e\+08 <= E' --case "$work/negative.toml"
expect poisson_ratio 'koyna\.toml.*material\.nu.*0\.5' --set material.nu=0.6
expect zero_time_step 'koyna\.toml.*time\.dt' --set time.dt=0
expect negative_time_step 'koyna\.toml.*time\.dt' --set time.dt=-0.01
expect reservoir_above_crest 'koyna\.toml.*reservoir\.level.*crest' --set reservoir.level=120
expect missing_record 'missing\.toml.*motion\.horizontal\.record.*missing\.at2' --case "$work/missing.toml"
expect unreadable_record 'badrecord\.toml.*motion\.horizontal\.record.*bad\.at2' --case "$work/badrecord.toml"
expect missing_case_file 'nonexistent\.toml' --case "$work/nonexistent.toml"
expect bad_set_syntax 'mesh\.order' --set mesh.order
expect unknown_option 'bogus' --bogus
expect unknown_concrete_model 'koyna\.toml.*material\.model' --set material.model=damage
expect tensile_above_half_fc 'koyna\.toml.*concrete\.ft' --set material.model=plastic --set concrete.ft=20e6
expect negative_fracture_energy 'koyna\.toml.*concrete\.Gf' --set concrete.Gf=-1
# Hardening (issue 16): absurd values are refused by plausibility bounds
# before any work, never crash or hang.
printf '0.1\n1e300\n-1e300\n0.2\n' >"$work/huge.txt"
printf '0.1\n1e308\n-1e308\n0.2\n' >"$work/overflow.txt"
printf '[motion.horizontal]\nrecord = "overflow.txt"\ndt = 0.01\npeak_g = 0.3\n' >"$work/overflow.toml"
printf 'h1\nh2\nh3\nNPTS= 3, DT= 5.0 SEC\n0.1 0.2 0.3\n' >"$work/slow.at2"
printf '[motion.horizontal]\nrecord = "slow.at2"\n' >"$work/slow.toml"
printf 'h1\nh2\nh3\nNPTS= 3, DT= 1.0 SEC\n0.1 0.2 0.3\n' >"$work/long.at2"
printf '[motion.horizontal]\nrecord = "long.at2"\n[time]\nduration = 0.0\ndt = 1e-7\n' >"$work/long.toml"
printf '[motion.horizontal]\nrecord = "huge.txt"\ndt = 0.01\npeak_g = 0\n' >"$work/huge.toml"
"$(command -v python3)" -c "open('$work/deep.toml','w').write('['+'.'.join(['a']*50000)+']\\n')"
expect peak_far_too_high 'koyna\.toml.*peak_g.*<= 5' --set motion.horizontal.peak_g=1e308
expect dt_far_too_long 'koyna\.toml.*time\.dt' --set time.dt=1e300
expect duration_far_too_long 'koyna\.toml.*time\.duration' --set time.duration=1e308
expect modulus_implausible 'koyna\.toml.*material\.E' --set material.E=1e-300
expect density_implausible 'koyna\.toml.*material\.rho' --set material.rho=1e300
expect toe_far_away 'koyna\.toml.*geometry\.toe_x' --set geometry.toe_x=1e308
expect water_film 'koyna\.toml.*reservoir\.level' --set reservoir.level=1e-12
expect foundation_size_tiny 'koyna\.toml.*foundation\.mesh_size' --set foundation.enabled=true --set foundation.mesh_size=5e-324
expect record_not_an_acceleration 'huge\.toml.*motion\.horizontal\.record.*not a ground acceleration' --case "$work/huge.toml"
printf '0.1\n0.2\n0.3\n' >"$work/one.txt"
printf '[motion.horizontal]\nrecord = "one.txt"\ndt = 1e308\n[time]\nduration = 0.0\n' >"$work/onedt.toml"
head -c 2000 /dev/zero | tr '\0' '\1' >"$work/binary.at2"
printf 'x\0y\n' >>"$work/binary.at2"
printf '[motion.horizontal]\nrecord = "binary.at2"\n' >"$work/binary.toml"
expect record_dt_far_too_long 'onedt\.toml.*motion\.horizontal\.dt.*dt <= 1' --case "$work/onedt.toml"
expect record_binary 'binary\.toml.*motion\.horizontal\.record.*not a text file.*expected' --case "$work/binary.toml"
expect record_overflows 'overflow\.toml.*motion\.horizontal\.record.*value 2 overflows' --case "$work/overflow.toml"
expect record_step_implausible 'slow\.toml.*motion\.horizontal\.record.*sampling step 5 s' --case "$work/slow.toml"
expect record_too_many_steps 'long\.toml.*time\.dt.*2e\+07 steps' --case "$work/long.toml"
expect crest_point_outside 'koyna\.toml.*output\.crest_point.*outside the model' --set 'output.crest_point=[500.0, 103.0]'
expect base_point_outside 'koyna\.toml.*output\.base_point.*outside the model' --set 'output.base_point=[35.0, -20.0]'
expect key_nested_deep 'deep\.toml:1.*nested 50000 levels' --case "$work/deep.toml"
expect mesh_too_fine 'koyna\.toml.*mesh\.size.*estimated.*mesh\.max_cells' --set mesh.size=0.01
expect mesh_size_implausible 'koyna\.toml.*mesh\.size.*0\.001 <= size' --set mesh.size=5e-324
# The viscous-spring foundation (issue 20).
expect viscous_spring_without_block 'koyna\.toml.*foundation\.boundary.*foundation\.enabled = true' --set foundation.boundary=viscous_spring
expect mtf_with_hht 'koyna\.toml.*time\.hht_alpha.*must be 0.*multi-transmitting' --set foundation.enabled=true --set foundation.boundary=mtf --set mesh.order=1 --set time.dt=0.001 --set material.model=plastic --set time.hht_alpha=-0.1
expect unknown_boundary 'koyna\.toml.*foundation\.boundary' --set foundation.enabled=true --set foundation.boundary=bogus
expect split_without_block 'koyna\.toml.*foundation\.split.*foundation\.enabled = true' --set foundation.split=layers
expect split_below_the_block 'koyna\.toml.*foundation\.split_depth.*foundation\.depth' --set foundation.enabled=true --set foundation.split=layers --set foundation.split_depth=150
# The multi-transmitting boundary (issue 20): order 2 on P2 drifts, the
# formula's s = c_p dt / dx above 1, a time step above the explicit band's
# stable step (found after the modal stage, before anything is written), a
# split block, a band thicker than the block beside the dam.
mtf=(--set foundation.enabled=true --set foundation.boundary=mtf)
expect mtf_order_two_on_p2 'koyna\.toml.*foundation\.mtf_order.*mesh\.order = 1' "${mtf[@]}"
expect mtf_courant_above_one 'koyna\.toml.*time\.dt.*multi-transmitting.*at most' "${mtf[@]}" --set mesh.order=1
expect mtf_above_stable_step 'time\.dt = 0\.0028 s is above the stable step' "${mtf[@]}" --set mesh.order=1 --set mesh.size=4 --set foundation.band_size=10 --set time.dt=0.0028
expect mtf_split_block 'koyna\.toml.*foundation\.boundary.*split' "${mtf[@]}" --set mesh.order=1 --set foundation.split=layers
expect mtf_band_too_thick 'koyna\.toml.*foundation\.band_size' "${mtf[@]}" --set mesh.order=1 --set foundation.band_size=40 --set time.dt=0.001
# The stencil reads 2N = 4 node spacings inward: 3 layers of P1 are too few
# (checked before the mesh is built; the formula's own check came only after).
expect mtf_band_too_thin 'koyna\.toml.*foundation\.band_layers.*2N = 4.*at least 4 layers' "${mtf[@]}" --set mesh.order=1 --set foundation.band_layers=3 --set time.dt=0.001
expect mtf_band_damping_out_of_range 'koyna\.toml.*foundation\.band_damping' "${mtf[@]}" --set mesh.order=1 --set foundation.band_damping=0.8
expect rock_density_implausible 'koyna\.toml.*foundation\.rho' --set foundation.enabled=true --set foundation.boundary=viscous_spring --set foundation.rho=0

if [ "$failures" -ne 0 ]; then
  echo "$failures bad-input checks failed"; exit 1
fi
echo "all bad-input checks passed"
