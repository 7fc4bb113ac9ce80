#!/usr/bin/env bash
# step_4_arguments.sh STEP_4 WORKDIR
# tutorial/step-4 checks its command line before it computes anything, as
# step-1 and step-2 do (tests/tutorial/step_arguments.sh): each bad
# argument below ends the program within 20 s with exit code 2, nothing on
# standard output, nothing written, and a message on standard error that
# starts with "step-4: ", quotes the bad argument and is followed by the
# usage. Good arguments still run: --help (exit 0, the usage) and one
# cycle of the adaptive loop (exit 0, its row and adaptive.csv).
set -uo pipefail
step=$1; work=$2
rm -rf "$work"; mkdir -p "$work"; cd "$work"
failures=0

# bad QUOTED ARGS...: step-4 with ARGS must be refused, naming QUOTED
bad() {
  local quoted=$1; shift
  rm -rf run; mkdir run
  (cd run && timeout 20 "$step" "$@" > ../out.txt 2> ../err.txt)
  local rc=$?
  local shown; shown=$(printf "'%s' " "$@")
  if [ $rc -ne 2 ] || [ -s out.txt ] || [ -n "$(ls -A run)" ] ||
     ! head -n 1 err.txt | grep -qF -- "step-4: " ||
     ! head -n 1 err.txt | grep -qF -- "'$quoted'" ||
     ! grep -q "^usage: step-4" err.txt; then
    echo "FAIL: step-4 $shown: exit code $rc (expected 2), output, files or message wrong:"
    cat out.txt err.txt; ls -A run
    failures=$((failures + 1)); return
  fi
  echo "refused: step-4 $shown-> $(head -n 1 err.txt)"
}

bad -1 adaptive -1
bad abc adaptive abc
bad 3x adaptive 3x
bad 0 adaptive 0
bad "" adaptive ""
bad " 3" adaptive " 3"
bad +2 adaptive +2
bad 2.5 adaptive 2.5
bad 17 adaptive 17
bad 4294967295 adaptive 4294967295
bad 3 adaptive 2 3
bad foo foo
bad "" ""
bad --verbose --verbose
bad x --help x

if ! "$step" --help > help.txt 2>&1 || ! grep -q "^usage: step-4" help.txt; then
  echo "FAIL: step-4 --help"; cat help.txt; failures=$((failures + 1))
fi
mkdir one && (cd one && "$step" adaptive 1 > ../one.txt 2>&1) &&
  grep -q '^    0    48   130 ' one.txt && [ "$(wc -l < one/adaptive.csv)" = 2 ] ||
  { echo "FAIL: step-4 adaptive 1"; cat one.txt; failures=$((failures + 1)); }

[ $failures -eq 0 ] || { echo "FAIL: $failures cases"; exit 1; }
echo "every bad argument refused with exit code 2 and a message naming it; --help and one cycle run"
