#!/usr/bin/env bash
# bench/build_time.sh [VARIANT...]: the from-scratch build time of the
# program (target hemicontact, what 'quickstart.sh example' builds) on a
# clean clone of HEAD, with -j2, for each variant:
#   pch     HEMICONTACT_PRECOMPILED_HEADERS=ON (the default)
#   nopch   HEMICONTACT_PRECOMPILED_HEADERS=OFF
# One CSV row per variant on standard output: variant, wall seconds, CPU
# seconds (user + system of the build and its children), objects built.
# Run on an idle machine; bench/results/build_time.csv holds a run.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
variants=${*:-pch nopch}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$repo" "$work/src"
echo "variant,wall_seconds,cpu_seconds,objects"
for v in $variants; do
  case $v in
    pch) flag=ON ;;
    nopch) flag=OFF ;;
    *) echo "unknown variant $v (pch, nopch)" >&2; exit 2 ;;
  esac
  rm -rf "$work/build"
  cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
    -DHEMICONTACT_PRECOMPILED_HEADERS=$flag > /dev/null
  /usr/bin/time -f "%e %U %S" -o "$work/time" \
    cmake --build "$work/build" -j2 --target hemicontact > "$work/log" 2>&1
  read -r wall user sys < "$work/time"
  objects=$(grep -c "Building CXX" "$work/log" || true)
  echo "$v,$wall,$(awk "BEGIN { print $user + $sys }"),$objects"
done
