#!/usr/bin/env bash
# unstable_memory_rule.sh EXE WORKDIR PRM: the stability limit of the
# explicit memory rule (doc/theory.md 11.13) on the cantilever of PRM
# (tests/memory/cantilever_2d.prm), for two kernels R(t) = r e^{-t/tau} B:
# (r, tau) = (100, 1) at k = 0.05 and (50, 0.1) at k = 0.0625. For a kernel
# that is a multiple of B the rule's recursion is h_{n+1} = q (1 - k r) h_n,
# q = e^{-k/tau}, stable iff k r <= 1 + e^{k/tau}. Each run must be refused
# (exit 2) with the limit that equation gives (0.1 % relative, the
# bisection's) and the growth |q (1 - k r)| (1e-3 relative), as a Prony
# series and as the same kernel written as an expression. At the limit's
# 90 % the run must go on, and its stored energy decay (alternating
# near the limit: each value below the one two steps before); with 'allow
# unstable time step' the refused run goes on with a warning and the
# summary line names the growth of the stored energy. The normal memory
# b(t) = b e^{-t} on the cantilever pressed into a foundation without a
# law (no wall, no slope) is refused at b = 1e4 and k = 0.05, with a limit
# that its own growth factor confirms (the static recursion's growth
# q |1 - k b/s| gives the contact mode's stiffness s, and k b/s = 1 +
# e^{k/tau} the limit), and runs at b = 1. A softening kernel R = -2 e^{-t} B
# (negative long-term modulus: the model grows as 2 e^t - 1) at k = 0.05
# runs with the warning that the model grows: the rule's growth
# e^{-k} (1 + 2 k) = 1.046 per step is below the model's e^k = 1.051.
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
# mu = E/(2(1 + nu)), lambda = E nu/((1 + nu)(1 - 2 nu)) of E = 100, nu = 0.3
mu=38.46153846153846; lambda=57.69230769230769
run() { # NAME K KERNEL-LINES [EXTRA-LINES]; writes NAME.log, NAME.rc
  { sed "s/set time step *=.*/set time step = $2/; s/set end time *=.*/set end time = $(/usr/bin/python3 -c "print(8 * $2)")/; s/set directory *=.*/set directory = $1/" "$prm" | sed '/^subsection relaxation/,/^end/d'
    printf 'subsection relaxation\n%b\nend\n%b\n' "$3" "${4:-}"; } > "$1.prm"
  set +e; "$exe" "$1.prm" > "$1.log" 2>&1; echo $? > "$1.rc"; set -e
}
prony() { printf '  set kernel = prony\n  set mu amplitudes = %s\n  set lambda amplitudes = %s\n  set relaxation times = %s' \
  "$(/usr/bin/python3 -c "print($1 * $mu)")" "$(/usr/bin/python3 -c "print($1 * $lambda)")" "$2"; }
expression() { printf '  set kernel = expression\n  set mu = %s*exp(-t/%s)\n  set lambda = %s*exp(-t/%s)' \
  "$(/usr/bin/python3 -c "print($1 * $mu)")" "$2" "$(/usr/bin/python3 -c "print($1 * $lambda)")" "$2"; }
for case in "a 100 1 0.05" "b 50 0.1 0.0625"; do
  set -- $case
  run $1_prony $4 "$(prony $2 $3)"
  run $1_expression $4 "$(expression $2 $3)"
  limit=$(/usr/bin/python3 -c "
import math
r, tau = $2, $3
lo, hi = 0.0, $4
for _ in range(200):
    k = (lo + hi) / 2
    lo, hi = (k, hi) if k * r <= 1 + math.exp(k / tau) else (lo, k)
print(lo)")
  run $1_stable "$(/usr/bin/python3 -c "print(0.9 * $limit)")" "$(prony $2 $3)"
  run $1_allowed $4 "$(prony $2 $3)" 'subsection time\n  set allow unstable time step = true\nend'
  /usr/bin/python3 - "$1" "$2" "$3" "$4" "$limit" <<'PY'
import math, re, sys
import pandas as pd
name, r, tau, k, limit = sys.argv[1], *map(float, sys.argv[2:])
growth = abs(math.exp(-k / tau) * (1 - k * r))
for form in ("prony", "expression"):
    rc = int(open(f"{name}_{form}.rc").read())
    log = open(f"{name}_{form}.log").read()
    m = re.search(r"above the stability limit of the memory rule for (.*?), "
                  r"k <= ([0-9.e+-]+).*?grows by a factor ([0-9.e+-]+) per step",
                  log, re.S)
    if rc != 2 or m is None:
        sys.exit(f"FAIL ({name}, {form}): exit {rc}, expected 2 with the "
                 f"memory rule's limit:\n{log}")
    program_limit, program_growth = float(m.group(2)), float(m.group(3))
    print(f"{name} {form}: r = {r:g}, tau = {tau:g}, k = {k:g}: limit "
          f"{program_limit:.4g} (recursion {limit:.4g}), growth "
          f"{program_growth:.4g} (recursion |q(1 - k r)| = {growth:.4g})")
    if abs(program_limit - limit) > 2e-3 * limit:
        sys.exit(f"FAIL: the limit {program_limit} is not the recursion's {limit}")
    if abs(program_growth - growth) > 1e-3 * growth:
        sys.exit(f"FAIL: the growth {program_growth} is not the recursion's {growth}")
rc = int(open(f"{name}_stable.rc").read())
if rc != 0:
    sys.exit(f"FAIL ({name}): 90 % of the limit refused:\n" + open(f"{name}_stable.log").read())
elastic = pd.read_csv(f"{name}_stable/steps.csv")["elastic_energy"].to_numpy()
# near the limit the decay alternates (q (1 - k r) close to -1): each
# value below the one two steps before
if not all(elastic[2:] < elastic[:-2]):
    sys.exit(f"FAIL ({name}): below the limit the stored energy does not decay: {elastic}")
log = open(f"{name}_allowed.log").read()
rc = int(open(f"{name}_allowed.rc").read())
if rc != 0 or "warning: the time step" not in log:
    sys.exit(f"FAIL ({name}): the allowed run: exit {rc}\n{log}")
print(f"{name}: 90 % of the limit runs and its energy decays; allowed above it:",
      "the summary names the growth" if "an unstable run" in log else "no growth named")
if name == "a" and "an unstable run" not in log:
    sys.exit("FAIL (a): the allowed run's summary does not name the energy's growth")
PY
done
normal() { printf '  set kernel = none\nend\nsubsection normal memory\n  set kernel = prony\n  set amplitudes = %s\n  set relaxation times = 1' "$1"; }
run normal_refused 0.05 "$(normal 1e4)"
run normal_runs 0.05 "$(normal 1)"
/usr/bin/python3 - <<'PY'
import math, re, sys
log = open("normal_refused.log").read()
m = re.search(r"memory rule for 'normal memory', k <= ([0-9.e+-]+).*?grows by a factor "
              r"([0-9.e+-]+) per step", log, re.S)
if int(open("normal_refused.rc").read()) != 2 or m is None:
    sys.exit("FAIL: the normal memory's unstable step is not refused:\n" + log)
limit, growth = float(m.group(1)), float(m.group(2))
k, b, tau = 0.05, 1e4, 1.0
q = math.exp(-k / tau)
s = k * b / (1 + growth / q)            # from growth = q (k b/s - 1)
lo, hi = 0.0, k
for _ in range(200):
    mid = (lo + hi) / 2
    lo, hi = (mid, hi) if mid * b / s <= 1 + math.exp(mid / tau) else (lo, mid)
print(f"normal memory b = {b:g}, k = {k}: limit {limit:.4g}, growth {growth:.4g}; "
      f"the recursion with the stiffness s = {s:.4g} its growth gives: limit {lo:.4g}")
if abs(limit - lo) > 2e-3 * lo:
    sys.exit("FAIL: the normal memory's limit and growth disagree")
if int(open("normal_runs.rc").read()) != 0:
    sys.exit("FAIL: b = 1 refused:\n" + open("normal_runs.log").read())
PY
run softening 0.05 "$(prony -2 1)"
/usr/bin/python3 - <<'PY'
import sys
log = open("softening.log").read()
rc = int(open("softening.rc").read())
if rc != 0 or "the model itself grows" not in log or "above the stability limit" in log:
    sys.exit(f"FAIL: the softening kernel: exit {rc}, expected 0 with the growing "
             f"model's warning and no limit:\n{log}")
print("softening kernel r = -2, tau = 1, k = 0.05: runs, the model's growth warned about")
PY
