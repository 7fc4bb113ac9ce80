#!/usr/bin/env bash
# step_arguments.sh STEP_1 STEP_2 WORKDIR
# The tutorial programs check every command-line argument before they
# compute anything: each bad argument below (negative, non-numeric,
# trailing garbage, zero or too many levels, too many arguments, an unknown
# mode, an argument after block) ends the program within
# 20 s with exit code 2, nothing on standard output, nothing written, and a
# message on standard error that starts with "step-N: ", quotes the bad
# argument and is followed by the usage. Good arguments still run: --help
# (exit 0, the usage on standard output) and the smallest convergence study
# of each step (exit 0, its table).
set -uo pipefail
step1=$1; step2=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
failures=0

# bad PROGRAM QUOTED ARGS...: PROGRAM with ARGS must be refused; QUOTED is
# the argument the message has to name.
bad() {
  local program=$1 quoted=$2; shift 2
  local name; name=$(basename "$program")
  rm -rf run; mkdir run
  (cd run && timeout 20 "$program" "$@" > ../out.txt 2> ../err.txt)
  local rc=$?
  local shown; shown=$(printf "'%s' " "$@")
  if [ $rc -ne 2 ]; then
    echo "FAIL: $name $shown: exit code $rc, expected 2 (124: still running after 20 s)"
    failures=$((failures + 1)); return
  fi
  if [ -s out.txt ]; then
    echo "FAIL: $name $shown: printed on standard output:"; cat out.txt
    failures=$((failures + 1)); return
  fi
  if [ -n "$(ls -A run)" ]; then
    echo "FAIL: $name $shown: wrote $(ls -A run)"
    failures=$((failures + 1)); return
  fi
  if ! head -n 1 err.txt | grep -qF -- "$name: " ||
     ! head -n 1 err.txt | grep -qF -- "'$quoted'" ||
     ! grep -q "^usage: $name" err.txt; then
    echo "FAIL: $name $shown: the message does not name '$quoted' or lacks the usage:"
    cat err.txt
    failures=$((failures + 1)); return
  fi
  echo "refused: $name $shown-> $(head -n 1 err.txt)"
}

for step in "$step1" "$step2"; do
  bad "$step" -1 convergence -1
  bad "$step" abc convergence abc
  bad "$step" 3x convergence 3x
  bad "$step" 0 convergence 0
  bad "$step" "" convergence ""
  bad "$step" " 3" convergence " 3"
  bad "$step" +2 convergence +2
  bad "$step" 2.5 convergence 2.5
  bad "$step" 4294967295 convergence 4294967295
  bad "$step" 3 convergence 2 3
  bad "$step" foo foo
  bad "$step" "" ""
  bad "$step" --verbose --verbose
  bad "$step" x --help x
done
# the caps: step-1 at most 7 levels, step-2 at most 5
bad "$step1" 8 convergence 8
bad "$step2" 6 convergence 6
# neither block takes an argument
bad "$step1" dir block dir
bad "$step2" dir block dir
bad "$step2" -o block -o

# good arguments still run
for step in "$step1" "$step2"; do
  name=$(basename "$step")
  if ! "$step" --help > help.txt 2>&1 || ! grep -q "^usage: $name" help.txt; then
    echo "FAIL: $name --help"; cat help.txt; failures=$((failures + 1))
  fi
done
"$step1" convergence 2 > table1.txt 2>&1 && [ "$(grep -c '^ *[48] ' table1.txt)" = 2 ] ||
  { echo "FAIL: step-1 convergence 2"; cat table1.txt; failures=$((failures + 1)); }
"$step2" convergence 1 > table2.txt 2>&1 && [ "$(grep -c '^ *8 ' table2.txt)" = 1 ] ||
  { echo "FAIL: step-2 convergence 1"; cat table2.txt; failures=$((failures + 1)); }

[ $failures -eq 0 ] || { echo "FAIL: $failures cases"; exit 1; }
echo "every bad argument refused with exit code 2 and a message naming it; --help and good levels run"
