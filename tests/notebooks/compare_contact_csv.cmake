# The contact CSV files of two runs (DIR_A, DIR_B: the same input on 1 and 2
# MPI ranks) must list the same files with the same rows (the rows are
# sorted by coordinates); values may differ at the level of the solver
# tolerance (numdiff, absolute 1e-7 or relative 1e-6).
file(GLOB _files_a RELATIVE ${DIR_A} ${DIR_A}/contact_*.csv)
file(GLOB _files_b RELATIVE ${DIR_B} ${DIR_B}/contact_*.csv)
list(LENGTH _files_a _n)
if(_n LESS 2 OR NOT "${_files_a}" STREQUAL "${_files_b}")
  message(FATAL_ERROR "contact files differ or are missing:\n${DIR_A}: ${_files_a}\n${DIR_B}: ${_files_b}")
endif()
foreach(_f ${_files_a})
  file(STRINGS ${DIR_A}/${_f} _rows_a)
  file(STRINGS ${DIR_B}/${_f} _rows_b)
  list(LENGTH _rows_a _la)
  list(LENGTH _rows_b _lb)
  if(_la LESS 3 OR NOT _la EQUAL _lb)
    message(FATAL_ERROR "${_f}: ${_la} rows on one run, ${_lb} on the other")
  endif()
  execute_process(COMMAND ${NUMDIFF} -q -a 1e-7 -r 1e-6 -s " ,\n" ${DIR_A}/${_f} ${DIR_B}/${_f}
    RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    execute_process(COMMAND ${NUMDIFF} -a 1e-7 -r 1e-6 -s " ,\n" ${DIR_A}/${_f} ${DIR_B}/${_f})
    message(FATAL_ERROR "${_f} differs between ${DIR_A} and ${DIR_B}")
  endif()
endforeach()
message(STATUS "ok: ${_n} contact files agree")
