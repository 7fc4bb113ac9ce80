#!/usr/bin/env bash
# json_input.sh EXE SOURCE_DIR WORKDIR
# A parameter file in JSON (read by its .json extension) gives the same run
# as the .prm file with the same settings; the JSON is what
# 'hemicontact --print-parameters json' prints, with a few values changed
# (so the printed form reads back).
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$exe" --print-parameters json > defaults.json
/usr/bin/python3 - <<'PY'
import json
p = json.load(open("defaults.json"))
settings = {("time", "end time"): "0.05", ("time", "time step"): "0.01",
            ("geometry", "global refinements"): "2",
            ("output", "directory"): "from_json", ("output", "vtu interval"): "0",
            ("output", "terminal"): "quiet", ("output", "probe points"): "4, 0; 2, 0"}
for (section, key), value in settings.items():
    assert key in p[section], f"no entry '{key}' in subsection '{section}' of the printed JSON"
    p[section][key]["value"] = value
json.dump(p, open("run.json", "w"), indent=1)
with open("run.prm", "w") as f:
    for (section, key), value in settings.items():
        value = "from_prm" if key == "directory" else value
        f.write(f"subsection {section}\n  set {key} = {value}\nend\n")
PY
"$exe" run.json 2> json.err || { echo "FAIL: the JSON file was not accepted"; cat json.err; exit 1; }
"$exe" run.prm 2> prm.err || { echo "FAIL: the .prm file was not accepted"; cat prm.err; exit 1; }
[ "$(tail -n +2 from_json/steps.csv | wc -l)" = 5 ] || { echo "FAIL: the JSON run did not take its 5 steps"; exit 1; }
bash "$src/tests/restart/compare_runs.sh" from_json from_prm
echo "JSON and .prm input give the same run"
