#!/usr/bin/env bash
# staggered_coupling_limit.sh EXE WORKDIR PRM: the stability limit of the
# staggered thermal coupling (doc/theory.md 13.2) on the block of PRM
# (tests/thermal/dilation_block_2d.prm), k <= 2 kappa_A / (c_e^2/c_theta -
# kappa_B) = 0.04082. At k = 0.1 the run is refused (exit 2) naming that
# limit, in the quasistatic and the dynamic class, before anything is
# written; at k = 0.04 it runs and the stored energy (elastic + thermal)
# falls from 0.5 at every step; at k = 0.05, allowed with 'time/allow
# unstable time step', the start-up warns, the stored energy grows and the
# energy growth check warns once: the coupling's work is an exchange
# between motion and heat, not energy put in.
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
run() { # NAME K EXTRA-LINES; writes NAME.log (both streams), NAME.rc
  { cat "$prm"
    printf 'subsection time\n  set time step = %s\nend\n' "$2"
    printf 'subsection output\n  set directory = %s\nend\n%b\n' "$1" "${3:-}"; } > "$1.prm"
  set +e; "$exe" "$1.prm" > "$1.log" 2>&1; echo $? > "$1.rc"; set -e
}
run refused 0.1
run refused_dynamic 0.1 'subsection problem\n  set class = dynamic\nend'
run stable 0.04
run allowed 0.05 'subsection time\n  set allow unstable time step = true\nend'
/usr/bin/python3 - <<'PY'
import os, re, sys
import pandas as pd
for name in ("refused", "refused_dynamic"):
    rc = int(open(f"{name}.rc").read())
    log = open(f"{name}.log").read()
    m = re.search(r"above the stability limit of the staggered thermal "
                  r"coupling, k <= ([0-9.e+-]+)", log)
    if rc != 2 or m is None:
        sys.exit(f"FAIL ({name}): exit {rc}, expected 2 with the coupling's limit:\n{log}")
    if abs(float(m.group(1)) - 4 / 98) > 1e-3 * 4 / 98:
        sys.exit(f"FAIL ({name}): the limit {m.group(1)} is not 2*2/(100 - 2)")
    if os.path.exists(f"{name}/steps.csv"):
        sys.exit(f"FAIL ({name}): the refused run wrote steps.csv")
print("k = 0.1: refused in both classes, limit", m.group(1))
rc = int(open("stable.rc").read())
if rc != 0:
    sys.exit("FAIL: k = 0.04 refused:\n" + open("stable.log").read())
s = pd.read_csv("stable/steps.csv")
stored = (s["elastic_energy"] + s["thermal_energy"]).to_numpy()
if not (stored[0] < 0.5 and all(stored[1:] < stored[:-1])):
    sys.exit(f"FAIL: at k = 0.04 the stored energy does not fall: {stored}")
print(f"k = 0.04: the stored energy falls from 0.5 to {stored[-1]:.4g}")
rc = int(open("allowed.rc").read())
log = open("allowed.log").read()
if rc != 0 or "warning: the time step k = 0.05 is above the stability limit of the staggered" not in log:
    sys.exit(f"FAIL: k = 0.05 allowed: exit {rc}, expected 0 with the start-up warning:\n{log}")
if log.count("warning: the stored energy") != 1:
    sys.exit("FAIL: k = 0.05: the energy growth check did not warn once:\n" + log)
s = pd.read_csv("allowed/steps.csv")
stored = (s["elastic_energy"] + s["thermal_energy"]).to_numpy()
if not stored[-1] > 100 * 0.5:
    sys.exit(f"FAIL: k = 0.05: the stored energy does not grow: {stored}")
print(f"k = 0.05: warned, the stored energy grows to {stored[-1]:.4g}, the growth check warns")
PY
