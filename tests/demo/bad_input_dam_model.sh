#!/usr/bin/env bash
# Bad input to dam_model (issue 18): a missing physical group, a group of
# the wrong dimension, a cell group without a material, arrays of the wrong
# length, names listed twice, unmatched and non-conforming joint sides, a
# load on interior facets, a degenerate cell, a point outside the model,
# contact joints misconfigured (2D, no joints, friction count or sign,
# restitution outside [0, 1], a keyed joint that is not a joint, contact
# keys with bonded joints, with HTC concrete, an unknown dead-load option,
# joint history points not in threes; the multi-transmitting boundary's
# band empty, in the dam, unknown or too thin, its spacing, time step,
# order on P2, massless rock, HHT alpha with the band explicit):
# one line naming the file, the key and the fix,
# exit code 2, nothing written.
# Usage: bad_input_dam_model.sh DAM_MODEL SOURCE_DIR
set -u
exe=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"
block=$src/demos/dam_model/block_3d.toml
cases=$src/tests/data/case

expect dm_no_mesh 'section_2d\.toml: mesh\.file: .*nothere\.msh: no such mesh file' --set mesh.file=nothere.msh
expect dm_not_a_mesh 'section_2d\.toml: mesh\.file: .*gmsh' --set mesh.file=section_2d.toml
expect dm_missing_group 'supports\.fixed: names "nowhere", which is not a physical group.*"dam_base"' --set 'supports.fixed=[nowhere]'
expect dm_wrong_dimension 'supports\.fixed: names "dam", a group of dimension 2; expected a group of facets' --set 'supports.fixed=[dam]'
expect dm_no_support 'supports\.fixed: is empty' --set 'supports.fixed=[]'
expect dm_material_count 'regions\.E: has 2 values for 1 regions' --set 'regions.E=[1e9, 2e9]'
expect dm_cell_group_without_material 'regions\.groups: does not list the cell group "block_right"' --case "$block" --set 'regions.groups=[block_left]' --set 'regions.E=[24e9]' --set 'regions.nu=[0.2]' --set 'regions.rho=[2400]' --set 'regions.dam=[block_left]'
expect dm_two_roles 'reservoir\.wetted: names "dam_base", which supports\.fixed names too' --set 'reservoir.wetted=[dam_base]'
expect dm_unmatched_joint 'block_3d\.toml: joints\.side2: joint sides "joint_left" and "upstream" do not match' --case "$block" --set 'joints.side2=[upstream]'
expect dm_joint_count 'joints\.side2: has 0 groups for 1' --case "$block" --set 'joints.side2=[]'
expect dm_nonconforming_joint 'dam_model_nonconforming\.toml: joints\.side2: .* are not conforming' --case "$cases/dam_model_nonconforming.toml"
expect dm_degenerate_cell 'dam_model_degenerate\.toml: mesh\.file: has 1 degenerate cells' --case "$cases/dam_model_degenerate.toml"
expect dm_point_outside 'output\.history_points: puts a point .* from the nearest node' --set 'output.history_points=[0, 500, 5, 5]'
expect dm_z_motion_in_2d 'motion\.z\.record: is given for a 2D mesh' --set motion.z.record=../../data/records/elcentro_1940_ns.at2
expect dm_traction_components 'loads\.traction: has 3 values for 1 groups' --set 'loads.traction_groups=[crest]' --set 'loads.traction=[0, 1, 2]'
expect dm_history_file 'loads\.traction_history: .*nofile\.txt' --set 'loads.traction_groups=[crest]' --set 'loads.traction=[0, -1e5]' --set loads.traction_history=nofile.txt
expect dm_region_twice 'regions\.groups: lists "dam" twice' --set 'regions.groups=[dam, dam]' --set 'regions.E=[1e9, 1e9]' --set 'regions.nu=[0.2, 0.2]' --set 'regions.rho=[1, 1]'
expect dm_history_name_twice 'output\.history_names: lists "a" twice' --set 'output.history_names=[a, a]' --set 'output.history_points=[0, 100, 0, 100]'
# The viscous-spring boundary (issue 20).
expect dm_fixed_and_viscous_spring 'supports\.viscous_spring: is given with supports\.fixed' --set 'supports.viscous_spring=[upstream_face]'
expect dm_viscous_spring_without_rock 'supports\.viscous_spring: needs a rock region' --set 'supports.fixed=[]' --set 'supports.viscous_spring=[dam_base]'
expect dm_viscous_spring_massless_rock 'supports\.viscous_spring: needs rock with mass, and region "block_right" is massless' --case "$block" --set 'supports.fixed=[]' --set 'supports.viscous_spring=[base]' --set 'regions.dam=[block_left]' --set 'regions.rho=[2400, 0]'
expect dm_viscous_spring_rock_beside_the_dam 'supports\.viscous_spring: needs rock below the dam' --case "$block" --set 'supports.fixed=[]' --set 'supports.viscous_spring=[base]' --set 'regions.dam=[block_left]'
expect dm_interior_traction 'loads\.traction_groups: names "joint_left", which has .* facets inside the model' --case "$block" --set mesh.file=meshes/block_jointless.msh --set 'joints.side1=[]' --set 'joints.side2=[]' --set 'loads.traction_groups=[joint_left]' --set 'loads.traction=[0, 0, -1e5]'
expect dm_concrete_zones 'regions\.E: differs between the dam regions' --case "$block" --set material.model=plastic --set 'regions.E=[24e9, 20e9]'
# Contact joints (issue 19).
expect dm_contact_2d 'joints\.model: is "contact" for a 2D mesh' --set joints.model=contact --set 'joints.side1=[]' --set 'joints.side2=[]'
expect dm_contact_no_joints 'joints\.model: is "contact" but joints\.side1 is empty' --case "$block" --set joints.model=contact --set mesh.file=meshes/block_jointless.msh --set 'joints.side1=[]' --set 'joints.side2=[]'
expect dm_contact_friction_count 'joints\.friction: has 2 values for 1 joints' --case "$block" --set joints.model=contact --set 'joints.friction=[1, 1]'
expect dm_contact_friction_negative 'joints\.friction=\[-0\.5\] is out of range; expected 0 <= friction' --case "$block" --set joints.model=contact --set 'joints.friction=[-0.5]'
expect dm_contact_restitution 'joints\.restitution=1\.5 is out of range; expected 0 <= restitution <= 1' --case "$block" --set joints.model=contact --set joints.restitution=1.5
expect dm_contact_keyed_unknown 'joints\.keyed: names "joint_right", which is not a joint' --case "$block" --set joints.model=contact --set 'joints.keyed=[joint_right]'
expect dm_contact_keys_bonded 'joints\.friction: is given while joints\.model = "bonded"' --case "$block" --set 'joints.friction=[0.5]'
expect dm_contact_history_points 'joints\.history_points: has 4 values, not 3 coordinates per point' --case "$block" --set joints.model=contact --set 'joints.history_points=[0, 0, 1, 2]'
expect dm_contact_dead_load 'joints\.dead_load=glued is not an allowed value; expected one of "joints_active", "cantilever"' --case "$block" --set joints.model=contact --set joints.dead_load=glued
expect dm_bond_count 'joints\.tensile_strength: has 2 values for 1 joints' --case "$block" --set joints.model=contact --set 'joints.tensile_strength=[1e5, 1e5]'
expect dm_bond_negative 'joints\.cohesion=\[-1\] is out of range; expected 0 <= cohesion' --case "$block" --set joints.model=contact --set 'joints.cohesion=[-1]'
expect dm_bond_paper 'joints\.tensile_strength: is given with joints\.formulation = "paper"' --case "$block" --set joints.model=contact --set 'joints.tensile_strength=[1e5]' --set joints.formulation=paper
expect dm_bond_bonded 'joints\.cohesion: is given while joints\.model = "bonded"' --case "$block" --set 'joints.cohesion=[1e5]'
expect dm_gap_negative 'joints\.initial_gap=\[-0\.001\] is out of range; expected 0 <= initial_gap' --case "$block" --set joints.model=contact --set 'joints.initial_gap=[-0.001]'
expect dm_gap_bonded_joint 'joints\.initial_gap: opens joint 1 \(joints\.side1 order\), which has a bond' --case "$block" --set joints.model=contact --set 'joints.initial_gap=[0.001]' --set 'joints.tensile_strength=[1e5]'
# The multi-transmitting boundary (supports.transmitting) and its band.
rock=$src/demos/dam_model/dam_on_rock_2d.toml
expect dm_transmitting_and_fixed 'supports\.transmitting: is given with supports\.fixed' --case "$rock" --set 'supports.fixed=[boundary]'
expect dm_band_empty 'dam_on_rock_2d\.toml: foundation\.band: is empty; expected the cell groups of the band' --case "$rock" --set 'foundation.band=[]'
expect dm_band_dam 'foundation\.band: names "dam", a region of the dam' --case "$rock" --set 'foundation.band=[dam]'
expect dm_band_unknown 'foundation\.band: names "nowhere", which is not a region' --case "$rock" --set 'foundation.band=[nowhere]'
expect dm_band_too_thin 'foundation\.band: the foundation has no band for the multi-transmitting boundary at .*; expected band cells reaching 2N node spacings = 24 m' --case "$rock" --set foundation.mtf_spacing=6
expect dm_band_spacing_zero 'foundation\.mtf_spacing: must be positive' --case "$rock" --set foundation.mtf_spacing=0
expect dm_transmitting_dt 'time\.dt: is too large for the multi-transmitting boundary: s = c_p dt / dx = 1\.5.*or a larger foundation\.mtf_spacing' --case "$rock" --set time.dt=0.002
expect dm_transmitting_p2_order2 'foundation\.mtf_order: 2 drifts away on P2 elements' --case "$rock" --set mesh.order=2
expect dm_transmitting_massless_rock 'supports\.transmitting: needs rock with mass, and region "rock" is massless' --case "$rock" --set 'regions.rho=[2400, 0, 0]'
expect dm_transmitting_hht 'time\.hht_alpha: must be 0 with a multi-transmitting boundary.s explicit band' --case "$rock" --set time.hht_alpha=-0.1

if [ "$failures" -ne 0 ]; then
  echo "$failures bad-input checks failed"; exit 1
fi
echo "all bad-input checks passed"
