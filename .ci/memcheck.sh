#!/usr/bin/env bash
# Memory-safety checks (not part of .ci/run; see doc/development.md "Memory safety"
# and doc/robustness.md):
#
#   bash .ci/memcheck.sh asan       AddressSanitizer + UBSan + LeakSanitizer:
#                                   build-asan/ (Debug, against deal.II's debug
#                                   library, -DHEMICONTACT_WITH_SANITIZERS=ON),
#                                   then ctest the unit tests, the short runs
#                                   (1 and 2 MPI ranks; every problem class,
#                                   walls, laws with breakpoints, Coulomb
#                                   friction, HDF5 output) and the bad-input
#                                   corpus
#   bash .ci/memcheck.sh valgrind   valgrind memcheck: build-valgrind/ (Release
#                                   with -g), one short run
#                                   (tests/block_2d_short.prm), full leak check
#
# Each prints a summary and exits non-zero if anything is reported that is
# not on the committed suppression lists:
#   tests/sanitizers/lsan.supp      leaks inside OpenMPI's MPI_Init (LSan)
#   tests/sanitizers/valgrind.supp  the same for valgrind (together with
#                                   OpenMPI's own openmpi-valgrind.supp)
# Environment: JOBS (parallel build/test jobs, default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=${JOBS:-2}

# OpenMPI refuses to run as root unless told otherwise
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# the tests run under the sanitizers: unit tests, short runs, bad inputs;
# the static and quasistatic classes (static_block_2d, quasistatic_*_2d),
# walls (signorini_block_2d, finite_penetration_quasistatic_2d, one step of
# prm/wall_block_2d.prm), jumps and breakpoints (breakpoints_3d_simplex),
# Coulomb friction (one load value of prm/coulomb_block_2d.prm) and the
# HDF5 output (io/hdf5_output, nodal_hdf5_writer); the history: the
# stress's memory as a Prony series (memory_static_2d) and as expressions
# (memory/prony_vs_expression), the normal memory (memory_normal_2d), the
# accumulated slip (memory/slip_weakening), wear (memory/wear, one step of
# prm/wear_block_2d.prm), the memory rule's stability check
# (memory/unstable_memory_rule), adaptivity with memory
# (memory/normal_wall_adaptive_1), resumes with memory and wear
# (restart/memory_expression_1_to_1, restart/memory_wear_2_to_2); the error
# estimator (adaptive_static_estimator) and 'target error'
# (adaptive_static_target_error)
asan_tests='^tests/(normal_laws|node_contact|one_step_exact|one_step_rotated_gmsh|block_2d_short|block_3d_short|manufactured_data|projected_vs_direct|static_block_2d|quasistatic_left_point_2d|quasistatic_implicit_2d|signorini_block_2d|finite_penetration_quasistatic_2d|breakpoints_3d_simplex|nodal_hdf5_writer|memory_static_2d|memory_normal_2d|adaptive_static_estimator|adaptive_static_target_error)\.|^bad_input/|^shipped_prm/(coulomb_block_2d|wall_block_2d|wear_block_2d)\.prm$|^io/hdf5_output$|^memory/(prony_vs_expression|slip_weakening|wear|unstable_memory_rule|normal_wall_adaptive_1)$|^restart/(memory_expression_1_to_1|memory_wear_2_to_2)$'

run_asan() {
  local build=$root/build-asan log=$root/build-asan/memcheck-asan.log
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DHEMICONTACT_WITH_SANITIZERS=ON > /dev/null
  cmake --build "$build" -j"$jobs"
  # the run-time options (ASAN_OPTIONS, LSAN_OPTIONS with the suppression
  # list, UBSAN_OPTIONS) are test properties: tests/CMakeLists.txt
  # deal.II's test targets do not rerun a test whose output file is newer
  # than its executable: remove the outputs so that every test really runs
  find "$build/tests" -mindepth 2 -name output -type f -delete 2> /dev/null || true
  local rc=0
  (cd "$build" && ctest -j"$jobs" -R "$asan_tests" --output-on-failure < /dev/null) 2>&1 \
    | tee "$log" || rc=$?
  echo
  echo "=== memcheck asan summary (full log: $log) ==="
  grep -E "tests passed|tests failed out of" "$log" || true
  echo "sanitizer reports in the log:" \
       "ASan $(grep -c 'ERROR: AddressSanitizer' "$log" || true)," \
       "LSan $(grep -c 'ERROR: LeakSanitizer' "$log" || true)," \
       "UBSan $(grep -c 'runtime error:' "$log" || true)"
  if [ "$rc" -ne 0 ]; then
    echo "memcheck asan: FAILED"
    return 1
  fi
  echo "memcheck asan: OK"
}

run_valgrind() {
  local build=$root/build-valgrind
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-g > /dev/null
  cmake --build "$build" -j"$jobs" --target hemicontact
  local work=$build/memcheck-run log=$build/memcheck-valgrind.log
  rm -rf "$work"
  mkdir -p "$work"
  local supp=(--suppressions="$root/tests/sanitizers/valgrind.supp")
  if [ -f /usr/share/openmpi/openmpi-valgrind.supp ]; then
    supp+=(--suppressions=/usr/share/openmpi/openmpi-valgrind.supp)
  fi
  local rc=0
  (cd "$work" && valgrind --tool=memcheck --error-exitcode=1 \
      --leak-check=full --show-leak-kinds=definite,possible \
      --errors-for-leak-kinds=definite,possible --num-callers=50 \
      --track-origins=yes "${supp[@]}" -v --log-file="$log" \
      "$build/hemicontact" "$root/tests/block_2d_short.prm") || rc=$?
  echo
  echo "=== memcheck valgrind summary (full log: $log) ==="
  echo "exit code of the run: $rc"
  grep -E "ERROR SUMMARY|definitely lost:|indirectly lost:|possibly lost:|still reachable:" "$log" \
    | sed 's/^==[0-9]*== *//' | sort -u || true
  echo "suppressions used (count, name):"
  grep -E "used_suppression:" "$log" | sed -E 's/^--[0-9]+-- *used_suppression: *//' || true
  if [ "$rc" -ne 0 ]; then
    echo "memcheck valgrind: FAILED (errors in $log)"
    return 1
  fi
  echo "memcheck valgrind: OK"
}

case "${1:-}" in
  asan) run_asan ;;
  valgrind) run_valgrind ;;
  *)
    echo "usage: bash .ci/memcheck.sh asan|valgrind" >&2
    exit 1
    ;;
esac
