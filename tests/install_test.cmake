# Install the build into a scratch prefix and check it as a user meets it
# (scripts/check-package.sh --prefix: bounce --version, a collision, the bash completion, the
# man page when help2man made one, import bounce from another folder, the find_package
# consumer, and the LAMMPS plugin loaded into LMP when one is given).
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BOUNCE_BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
set(lmp)
if(LMP)
  set(lmp --lmp ${LMP})
endif()
execute_process(COMMAND ${SOURCE_DIR}/scripts/check-package.sh ${lmp} --prefix ${WORK_DIR}/prefix RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "scripts/check-package.sh failed: ${rc}")
endif()
