# Run a shipped parameter file in a reduced form for the notebook tests:
# output to OUTDIR (removed first) with a contact CSV every VTU_INTERVAL
# steps, GLOBAL_REFINEMENTS and TIME_STEP overriding the shipped values (the
# overrides are appended as second subsections, which the parameter file
# reader applies last), a relative 'mesh file' taken from SOURCE_DIR, on
# MPI_RANKS ranks (1 unless given). Fails unless the run succeeds and writes
# steps.csv and at least two contact_*.csv files.
file(READ ${PRM} _text)
if(_text MATCHES "set mesh file *= *([^\n]+)")
  string(STRIP "${CMAKE_MATCH_1}" _mesh)
  if(NOT IS_ABSOLUTE "${_mesh}")
    string(REGEX REPLACE "set mesh file *= *[^\n]+" "set mesh file = ${SOURCE_DIR}/${_mesh}" _text "${_text}")
  endif()
endif()
string(REGEX REPLACE "set directory *= *[^\n]+" "set directory = ${OUTDIR}" _text "${_text}")
string(REGEX REPLACE "set vtu interval *= *[0-9]+" "set vtu interval = ${VTU_INTERVAL}" _text "${_text}")
string(APPEND _text "\nsubsection geometry\n  set global refinements = ${GLOBAL_REFINEMENTS}\nend\n")
string(APPEND _text "subsection time\n  set time step = ${TIME_STEP}\nend\n")
file(REMOVE_RECURSE ${OUTDIR})
get_filename_component(_parent ${OUTDIR} DIRECTORY)
file(MAKE_DIRECTORY ${_parent})
file(WRITE ${OUTDIR}.prm "${_text}")
if(MPI_RANKS AND MPI_RANKS GREATER 1)
  set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
  set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
  set(_command ${MPIEXEC} -np ${MPI_RANKS} ${EXE} ${OUTDIR}.prm)
else()
  set(_command ${EXE} ${OUTDIR}.prm)
endif()
execute_process(COMMAND ${_command} WORKING_DIRECTORY ${_parent}
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 300)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${PRM} (reduced) failed (exit ${_rc}):\n${_err}\n${_out}")
endif()
file(GLOB _contact ${OUTDIR}/contact_*.csv)
list(LENGTH _contact _n)
if(NOT EXISTS ${OUTDIR}/steps.csv OR _n LESS 2)
  message(FATAL_ERROR "${PRM} (reduced): no steps.csv or fewer than two contact_*.csv in ${OUTDIR}")
endif()
message(STATUS "ok: ${PRM} -> ${OUTDIR} (${_n} contact files)")
