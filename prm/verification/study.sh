#!/usr/bin/env bash
# Run one convergence study of a shipped manufactured-solution case:
#   bash prm/verification/study.sh CASE TYPE LEVELS REFINEMENT TIME_STEP [NP]
# e.g. bash prm/verification/study.sh mms_2d_quad_exponential coupled 5 3 0.125
# CASE is a file prm/verification/CASE.prm; TYPE is h, k or coupled; level 0
# uses REFINEMENT global refinements and TIME_STEP. The table is printed and
# written to results/CASE-TYPE/convergence.csv (with the study's log).
# CLASS=quasistatic and/or SCHEME=implicit in the environment set
# 'problem/class' and 'problem/time scheme' (doc/theory.md, section 9) and
# write to results/CASE-TYPE-CLASS-SCHEME/ instead. The static cases
# (*_static.prm) set their class themselves and write to
# results/CASE-TYPE/. ESTIMATE=true sets 'output/error estimate' (the
# estimate and effectivity index per level, doc/theory.md section 11) and
# appends -estimate to the directory; ESTIMATE=equilibrated the
# equilibrated bound (section 12.5) and -equilibrated. REFERENCE=K (a 'k'
# study) takes the errors against the run with time step K on the same
# mesh instead of the manufactured solution ('convergence study/reference
# time step', doc/verification.md) and appends -reference to the
# directory.
# COUPLING=iterated sets 'temperature/coupling' (doc/theory.md 13.2) and
# appends -iterated to the directory.
# HEMICONTACT=PATH runs that program instead of build/hemicontact.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
case_name=$1; type=$2; levels=$3; refinement=$4; time_step=$5; np=${6:-1}
class=${CLASS:-}; scheme=${SCHEME:-}; estimate=${ESTIMATE:-false}
reference=${REFERENCE:-}; coupling=${COUPLING:-}
program=${HEMICONTACT:-$root/build/hemicontact}
out="$root/results/$case_name-$type"
if [ -n "$class$scheme" ]; then
  out="$out-${class:-dynamic}-${scheme:-left point}"
  out="${out// /-}"
fi
case "$estimate" in
  true) out="$out-estimate" ;;
  equilibrated) out="$out-equilibrated" ;;
esac
[ -z "$reference" ] || out="$out-reference"
[ -z "$coupling" ] || out="$out-$coupling"
mkdir -p "$out"
{
  cat "$root/prm/verification/$case_name.prm"
  printf 'subsection geometry\n  set global refinements = %s\nend\n' "$refinement"
  printf 'subsection time\n  set time step = %s\nend\n' "$time_step"
  printf 'subsection convergence study\n  set type = %s\n  set levels = %s\nend\n' "$type" "$levels"
  printf 'subsection output\n  set directory = %s\nend\n' "$out"
  [ -z "$class" ] || printf 'subsection problem\n  set class = %s\nend\n' "$class"
  [ -z "$scheme" ] || printf 'subsection problem\n  set time scheme = %s\nend\n' "$scheme"
  [ "$estimate" = false ] || printf 'subsection output\n  set error estimate = %s\nend\n' "$estimate"
  [ -z "$reference" ] || printf 'subsection convergence study\n  set reference time step = %s\nend\n' "$reference"
  [ -z "$coupling" ] || printf 'subsection temperature\n  set coupling = %s\nend\n' "$coupling"
} > "$out/study.prm"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
start=$(date +%s)
if [ "$np" -gt 1 ]; then
  mpirun -np "$np" "$program" "$out/study.prm" | tee "$out/study.log"
else
  "$program" "$out/study.prm" | tee "$out/study.log"
fi
echo "wall time: $(( $(date +%s) - start )) s" | tee -a "$out/study.log"
