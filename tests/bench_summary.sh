#!/usr/bin/env bash
# benchmarks/summary.sh reads the speed targets from speed.csv by column name: a regression test
# for the ratio rows, which once read a column that no longer existed and printed "0.00 ... met".
# A synthetic speed.csv (and no scaling.csv) with values chosen by hand: linear + FE 3.5e7 (met),
# LME + NPC 9e6 (not met), LME/linear 1.5 in 1D FE (met), 2.5 in 1D NPC (not met), 2.9 and 3.1 in 2D.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
header="scene,shape,integrator,particles,steps,threads,seconds_per_particle_step,particle_steps_per_second,max_resident_kib,stencils,p2g,stress,forces,grid,g2p,checks,output,relative_to_linear"
{
  echo "$header"
  echo "dyka_bar,linear,fe,640,100,1,2.8e-08,3.5e+07,6000,0.2,0.1,0.1,0.1,0.1,0.2,0.2,0.0,1.000"
  echo "dyka_bar,lme,fe,640,100,1,4.2e-08,2.4e+07,6000,0.8,0.1,0.0,0.0,0.0,0.1,0.0,0.0,1.500"
  echo "soil_block,lme,fe,400,100,1,1e-07,1e+07,6000,0.7,0.1,0.1,0.0,0.0,0.1,0.0,0.0,2.900"
  echo "dyka_bar,lme,npc,640,100,1,1.1e-07,9e+06,6000,0.8,0.1,0.0,0.0,0.0,0.1,0.0,0.0,2.500"
  echo "soil_block,lme,npc,400,100,1,1e-07,1e+07,6000,0.7,0.1,0.1,0.0,0.0,0.1,0.0,0.0,3.100"
} >"$dir/speed.csv"
summary=$(bash "$root/benchmarks/summary.sh" "$dir" 2)
expect() {
  if ! grep -qF -- "$1" <<<"$summary"; then echo "bench_summary: expected a row with: $1"; echo "$summary"; exit 1; fi
}
expect "| Dyka bar 640 cells, linear + FE (particle-steps/s) | 3.5e+07 | >= 3e+07 | **met** |"
expect "| Dyka bar 640 cells, LME gamma 3 + NPC (particle-steps/s) | 9e+06 | >= 1e+07 | **not met** |"
expect "| 1D: LME cost / linear cost, fe | 1.50 | <= 2.00 | **met** |"
expect "| 1D: LME cost / linear cost, npc | 2.50 | <= 2.00 | **not met** |"
expect "| 2D soil block (400 particles): LME cost / linear cost, fe | 2.90 | <= 3.00 | **met** |"
expect "| 2D soil block (400 particles): LME cost / linear cost, npc | 3.10 | <= 3.00 | **not met** |"
# A value that is missing is "not measured", never met: the soil block's LME + FE row removed.
grep -v "^soil_block,lme,fe" "$dir/speed.csv" >"$dir/speed.tmp" && mv "$dir/speed.tmp" "$dir/speed.csv"
summary=$(bash "$root/benchmarks/summary.sh" "$dir" 2)
expect "| 2D soil block (400 particles): LME cost / linear cost, fe |  | <= 3 | **not measured** |"
echo "bench_summary: ok"
