# The Fortran 2008 example of the atlas's C API (examples/atlas_fortran): build a small atlas
# with the CLI, compile the example with gfortran against the build's libbounce, and compare
# what it prints with `bounce atlas query` at the same pair (the same C++ lookup: equal digits).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(atlas ${WORK_DIR}/ice.h5)
execute_process(COMMAND ${CLI} atlas build --model krijt --tvis 1e-11 --materials water-ice --radius 1e-6:1e-5:4
                        --velocity 0.3:20:5 --tol 1e-3 --threads 1 -o ${atlas}
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(rc)
  message(FATAL_ERROR "bounce atlas build failed: ${rc}")
endif()
execute_process(COMMAND ${FORTRAN} -std=f2008 -Wall -Werror ${SOURCE} -L${LIBDIR} -lbounce -Wl,-rpath,${LIBDIR}
                        -o ${WORK_DIR}/atlas_lookup
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "gfortran failed: ${rc}")
endif()
foreach(query "3e-6 4e-6 1.0" "3e-6 4e-6 12.5")
  separate_arguments(args UNIX_COMMAND "${query}")
  list(GET args 0 r1)
  list(GET args 1 r2)
  list(GET args 2 v)
  execute_process(COMMAND ${WORK_DIR}/atlas_lookup ${atlas} ${r1} ${r2} ${v} RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(rc)
    message(FATAL_ERROR "the Fortran example failed at ${query}: ${rc}")
  endif()
  execute_process(COMMAND ${CLI} atlas query ${atlas} --radius ${r1} --radius2 ${r2} --velocity ${v} --json
                  OUTPUT_VARIABLE json RESULT_VARIABLE rc)
  string(JSON cor GET "${json}" cor)
  string(JSON outcome GET "${json}" outcome)
  separate_arguments(fields UNIX_COMMAND "${out}")
  list(GET fields 0 f_cor)
  list(GET fields 1 f_sticks)
  math(EXPR expected_sticks "0")
  if(outcome STREQUAL "stick")
    set(expected_sticks 1)
  endif()
  # Both print the same double: Fortran with 17 significant digits, JSON in its shortest form.
  execute_process(COMMAND ${PYTHON} -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(a != b)"
                          ${f_cor} ${cor} RESULT_VARIABLE differ)
  if(differ OR NOT f_sticks EQUAL expected_sticks)
    message(FATAL_ERROR "at ${query}: Fortran says ${out}, the CLI cor ${cor} outcome ${outcome}")
  endif()
  message(STATUS "${query}: ${out}")
endforeach()
# Outside the atlas: exit 2 with a message, no number.
execute_process(COMMAND ${WORK_DIR}/atlas_lookup ${atlas} 3e-6 4e-6 50 RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT rc EQUAL 2 OR NOT out STREQUAL "")
  message(FATAL_ERROR "outside the atlas the example exited ${rc} and printed '${out}'")
endif()
