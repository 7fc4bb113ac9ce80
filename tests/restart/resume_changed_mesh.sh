#!/usr/bin/env bash
# resume_changed_mesh.sh EXE PRM MESH WORKDIR
# A run on the Gmsh file MESH (a copy in WORKDIR) stopped after 4 steps,
# then the mesh file edited (every node moved by 2%): the resume is refused
# with exit code 2 naming the file, and leaves the checkpoint and
# steps.csv as they were; with the file restored it resumes and ends
# bitwise equal to the uninterrupted run.
set -euo pipefail
exe=$1; prm=$2; mesh=$3; work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"; cd "$work"
cp "$mesh" mesh.msh; cp mesh.msh mesh-saved.msh
write_prm() { # NAME DIRECTORY STOP_AFTER
  { cat "$prm"
    printf 'subsection geometry\n  set mesh file = mesh.msh\n  set global refinements = 1\nend\n'
    printf 'subsection time\n  set end time = 0.1\nend\n'
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 2\n' "$2"
    printf '  set terminal = quiet\nend\n'
    printf 'subsection checkpoint\n  set interval = 2\n  set stop after = %s\nend\n' "$3"; } > "$1"
}
write_prm whole.prm whole 0
write_prm stop.prm parts 4
write_prm parts.prm parts 0
"$exe" whole.prm
status=0; "$exe" stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
before=$(cat parts/steps.csv parts/checkpoint/* | md5sum)

# MSH 4.1: the coordinate lines of the $Nodes section (three numbers)
awk '/^\$Nodes/ { nodes = 1 } /^\$EndNodes/ { nodes = 0 }
     nodes && NF == 3 { $1 *= 1.02; $2 *= 1.02 } { print }' mesh-saved.msh > mesh.msh
cmp -s mesh.msh mesh-saved.msh && { echo "FAIL: the mesh file was not changed"; exit 1; }
status=0; "$exe" --resume parts.prm 2> changed.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the resume on a changed mesh exited with $status, not 2"; cat changed.err; exit 1; }
grep -q "input error: checkpoint: the mesh file 'mesh.msh' is not the file the run that wrote 'parts/checkpoint/step-000004.state' read (size and CRC-32" changed.err ||
  { echo "FAIL: the message does not name the mesh file"; cat changed.err; exit 1; }
[ "$(cat parts/steps.csv parts/checkpoint/* | md5sum)" = "$before" ] ||
  { echo "FAIL: the refused resume changed the checkpoint or steps.csv"; exit 1; }
echo "refused: $(cat changed.err)"

cp mesh-saved.msh mesh.msh
"$exe" --resume parts.prm
bash "$here/compare_runs.sh" whole parts bitwise
