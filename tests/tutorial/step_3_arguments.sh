#!/usr/bin/env bash
# step_3_arguments.sh STEP_3 WORKDIR
# tutorial/step-3 checks every command-line argument before it computes
# anything, as step-1 and step-2 do (tests/tutorial/step_arguments.sh):
# each bad argument below (negative, non-numeric, trailing garbage, zero or
# too many levels, too many arguments, an unknown mode) ends the program
# within 20 s with exit code 2, nothing on standard output, nothing
# written, and a message on standard error that starts with "step-3: ",
# quotes the bad argument and is followed by the usage. Good arguments
# still run: --help (exit 0, the usage on standard output) and the
# smallest convergence study (exit 0, its tables).
set -uo pipefail
step=$1; work=$2
rm -rf "$work"; mkdir -p "$work"; cd "$work"
failures=0

# bad QUOTED ARGS...: step-3 with ARGS must be refused; QUOTED is the
# argument the message has to name.
bad() {
  local quoted=$1; shift
  rm -rf run; mkdir run
  (cd run && timeout 20 "$step" "$@" > ../out.txt 2> ../err.txt)
  local rc=$?
  local shown; shown=$(printf "'%s' " "$@")
  if [ $rc -ne 2 ]; then
    echo "FAIL: step-3 $shown: exit code $rc, expected 2 (124: still running after 20 s)"
    failures=$((failures + 1)); return
  fi
  if [ -s out.txt ]; then
    echo "FAIL: step-3 $shown: printed on standard output:"; cat out.txt
    failures=$((failures + 1)); return
  fi
  if [ -n "$(ls -A run)" ]; then
    echo "FAIL: step-3 $shown: wrote $(ls -A run)"
    failures=$((failures + 1)); return
  fi
  if ! head -n 1 err.txt | grep -qF -- "step-3: " ||
     ! head -n 1 err.txt | grep -qF -- "'$quoted'" ||
     ! grep -q "^usage: step-3" err.txt; then
    echo "FAIL: step-3 $shown: the message does not name '$quoted' or lacks the usage:"
    cat err.txt
    failures=$((failures + 1)); return
  fi
  echo "refused: step-3 $shown-> $(head -n 1 err.txt)"
}

bad -1 convergence -1
bad abc convergence abc
bad 3x convergence 3x
bad 0 convergence 0
bad "" convergence ""
bad " 3" convergence " 3"
bad +2 convergence +2
bad 2.5 convergence 2.5
bad 4294967295 convergence 4294967295
bad 6 convergence 6
bad 3 convergence 2 3
bad dir block dir
bad foo foo
bad "" ""
bad --verbose --verbose
bad x --help x

if ! "$step" --help > help.txt 2>&1 || ! grep -q "^usage: step-3" help.txt; then
  echo "FAIL: step-3 --help"; cat help.txt; failures=$((failures + 1))
fi
"$step" convergence 1 > table.txt 2>&1 && grep -q '^  4   50     5 ' table.txt ||
  { echo "FAIL: step-3 convergence 1"; cat table.txt; failures=$((failures + 1)); }

[ $failures -eq 0 ] || { echo "FAIL: $failures cases"; exit 1; }
echo "every bad argument refused with exit code 2 and a message naming it; --help and good levels run"
