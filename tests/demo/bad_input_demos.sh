#!/usr/bin/env bash
# Bad input to the other demos (issue 16: every demo gets the koyna
# treatment): one line naming the file and the key, exit code 2, nothing
# written. Usage: bad_input_demos.sh RCC_GRAVITY ARCH_DAM MATERIAL_POINT
set -u
rcc=$1 arch=$2 point=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

printf 'mesh = [\n' >"$work/malformed.toml"
printf '[dam]\nheight = 102.0\nheigth = 3\n' >"$work/typo.toml"

exe=$rcc
expect rcc_malformed 'malformed\.toml:[0-9]+' --case "$work/malformed.toml"
expect rcc_mesh_too_fine 'rcc_gravity\.toml.*mesh\.size.*mesh\.max_cells' --set mesh.size=0.01
expect rcc_silt_above_water 'rcc_gravity\.toml.*silt\.level' --set silt.level=186
expect rcc_crest_point_outside 'rcc_gravity\.toml.*output\.crest_point.*outside the model' --set 'output.crest_point=[0.0, 400.0]'
expect rcc_unscaled_peak 'rcc_gravity\.toml.*peak_g' --set motion.horizontal.peak_g=1e308

exe=$arch
expect arch_malformed 'malformed\.toml:[0-9]+' --case "$work/malformed.toml"
expect arch_unknown_key 'typo\.toml.*dam\.heigth.*dam\.height' --case "$work/typo.toml"
expect arch_height_implausible 'arch_dam\.toml.*dam\.height' --set dam.height=1e308
expect arch_canyon_implausible 'arch_dam\.toml.*canyon\.crest_width' --set canyon.crest_width=1e9
expect arch_foundation_implausible 'arch_dam\.toml.*foundation\.extent_below' --set foundation.extent_below=1e6
expect arch_thickness_implausible 'arch_dam\.toml.*dam\.crown_thickness' --set 'dam.crown_thickness=[24.6, 19.0, 13.6, 8.9, 1e300]'
expect arch_mesh_too_fine 'arch_dam\.toml.*mesh\.size.*mesh\.max_cells' --set mesh.size=0.05
expect arch_crest_point_outside 'arch_dam\.toml.*output\.crest_point.*outside the model' --set 'output.crest_point=[0.0, 0.0, 500.0]'
expect arch_concrete_ft_above_half_fc 'arch_dam\.toml.*concrete\.ft' --set material.model=plastic --set concrete.ft=20e6
expect arch_point_in_the_water 'arch_dam\.toml.*output\.base_point.*outside the model' --set 'output.base_point=[0.0, -60.0, 50.0]'
expect arch_reservoir_above_crest 'arch_dam\.toml.*reservoir\.level' --set reservoir.level=150
expect arch_modulus_implausible 'arch_dam\.toml.*material\.E' --set material.E=1e300
expect arch_study_unknown_joint 'arch_dam\.toml.*study\.joints.*"DGX".*not a candidate joint' --set 'study.joints=[none, DGX]'
expect arch_study_repeated_joint 'arch_dam\.toml.*study\.joints.*"DGD".*repeated' --set 'study.joints=[DGD]'
expect arch_foundation_study_with_joint_study 'arch_dam\.toml.*study\.foundation.*study\.joints' --set study.foundation=true --set 'study.joints=[none, DGJ]'
expect arch_foundation_ratios_empty 'arch_dam\.toml.*study\.foundation_ratios.*empty' --set study.foundation=true --set 'study.foundation_ratios=[]'
expect arch_rock_density_implausible 'arch_dam\.toml.*rock\.rho' --set rock.rho=1e9
expect arch_table1_level_at_crest 'arch_dam\.toml.*study\.reservoir_levels.*crest' --set study.table1=true --set 'study.reservoir_levels=[100, 101.5]'
expect arch_table1_with_joint_study 'arch_dam\.toml.*study\.table1.*one study at a time' --set study.table1=true --set 'study.joints=[none, DGJ]'
expect arch_table1_with_contact 'arch_dam\.toml.*study\.table1.*contact' --set study.table1=true --set joints.model=contact
expect arch_unknown_tension_softening 'arch_dam\.toml.*concrete\.tension_softening' --set concrete.tension_softening=linear
expect arch_study_with_active 'arch_dam\.toml.*study\.joints.*joints\.active' --set 'study.joints=[DGJ]' --set joints.active=DG

exe=$point
expect point_malformed 'malformed\.toml:[0-9]+' --case "$work/malformed.toml"
expect point_poisson 'material_point\.toml.*material\.nu' --set material.nu=0.49999999999999994
expect point_csv_name 'material_point\.toml.*output\.csv' --set 'output.csv=""'
expect point_strain_implausible 'material_point\.toml.*path\.max_strain' --set path.max_strain=1e308
expect point_too_many_steps 'material_point\.toml.*path\.strain_step.*steps' --set path.strain_step=1e-9 --set path.max_strain=0.05
expect point_rate_implausible 'material_point\.toml.*path\.strain_rate' --set path.strain_rate=1e300

if [ "$failures" -ne 0 ]; then
  echo "$failures bad-input checks failed"; exit 1
fi
echo "all bad-input checks passed"
