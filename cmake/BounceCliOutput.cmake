# cmake -DCLI=bounce -DARGS="a;b" -DOUT=file -P BounceCliOutput.cmake: runs the CLI and writes
# what it printed to OUT (a build step: the bash completion of cmake/BouncePackage.cmake).
get_filename_component(dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
execute_process(COMMAND ${CLI} ${ARGS} OUTPUT_FILE ${OUT}.tmp RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(REMOVE ${OUT}.tmp)
  message(FATAL_ERROR "${CLI} ${ARGS} failed (${rc})")
endif()
file(RENAME ${OUT}.tmp ${OUT})
