#!/usr/bin/env bash
# check.sh SOURCE_DIR BUILD_DIR WORKDIR
# Install hemicontact from BUILD_DIR into WORKDIR/prefix, build the project
# in this directory against the installed package (find_package), and run
# it: its own friction law must be selectable, run, and give the friction
# force F_b (1 + c s) at every slipping node of the contact CSV files.
set -euo pipefail
source_dir=$1; build_dir=$2; work=$3
rm -rf "$work"; mkdir -p "$work"
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$source_dir/tests/installed_package" -B "$work/build" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
exe="$work/build/hemicontact_with_my_law"

# into a file first: grep -q stops reading at the first match, and under
# pipefail the writer's SIGPIPE would fail the pipeline
"$exe" --print-parameters > "$work/parameters.prm"
grep -q "velocity strengthening" "$work/parameters.prm" ||
  { echo "FAIL: the registered law is not among the parameters"; exit 1; }

{ cat "$source_dir/tests/block_2d_slip_rate.prm"
  printf 'subsection friction law\n  set law = velocity strengthening\n'
  printf '  subsection velocity strengthening\n    set coefficient = 2\n  end\nend\n'
  printf 'subsection output\n  set directory = %s/run\n  set vtu interval = 1\nend\n' "$work"; } > "$work/run.prm"
"$exe" "$work/run.prm" > "$work/run.log"
grep -q "friction law 'velocity strengthening'" "$work/run.log" ||
  { echo "FAIL: the run did not use the registered law"; cat "$work/run.log"; exit 1; }

# columns by name: friction_response = friction_bound (1 + 2 w_tau_norm)
awk -F, 'FNR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
  $c["tangential_branch"] == 1 {
    n++
    expected = $c["friction_bound"] * (1 + 2 * $c["w_tau_norm"])
    d = $c["friction_response"] - expected; if (d < 0) d = -d
    if (d > 1e-9 * (1 + expected)) { bad++; print FILENAME ": " $0 }
    s = $c["sigma_tau_norm"] - expected; if (s < 0) s = -s
    if (s > 1e-6 * (1 + expected)) { bad++; print FILENAME ": |sigma_tau| " $0 }
  }
  END {
    if (n == 0) { print "FAIL: no slipping node"; exit 1 }
    if (bad) { print "FAIL: " bad " slipping node-times off the law"; exit 1 }
    print "installed package: own law registered, " n " slipping node-times on F_b (1 + 2 s)"
  }' "$work"/run/contact_*.csv
