# SUNDIALS 6 (Debian 12) or 7 (Debian 13), told apart by what their CMake package and headers
# offer, never by the version's number:
#
# * SUNDIALS 7 as Debian builds it links its core to MPI::MPI_C (and MPI::MPI_CXX), but its
#   package only calls find_dependency(MPI), which defines MPI_C only when C is an enabled
#   language of the project. When the core's link interface names MPI::MPI_C and no one has
#   found it, C is enabled and MPI's C component found here.
# * SUNDIALS 7 removed CVodeSetErrHandlerFn: errors go to the context's handler stack
#   (SUNContext_PushErrHandler). BOUNCE_SUNDIALS_PUSH_ERR_HANDLER says which one compiles.
# * SUNContext_Create takes a SUNComm (SUN_COMM_NULL) in 7 and a void* in 6:
#   BOUNCE_SUNDIALS_COMM_NULL.
# Used by src/dynamics/cvode_integrator.cpp through bounce_sundials_definitions.

find_package(SUNDIALS 6 REQUIRED)
set(BOUNCE_SUNDIALS_TARGETS SUNDIALS::cvode_shared SUNDIALS::nvecserial_shared
    SUNDIALS::sunmatrixdense_shared SUNDIALS::sunlinsoldense_shared)

# Every library the given targets link, with the SUNDIALS targets they name followed.
function(bounce_sundials_link_closure out)
  set(seen)
  set(todo ${ARGN})
  while(todo)
    list(POP_FRONT todo t)
    if(t IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${t})
    if(TARGET ${t})
      get_target_property(links ${t} INTERFACE_LINK_LIBRARIES)
      if(links)
        foreach(l IN LISTS links)
          if(l MATCHES "^SUNDIALS::")
            list(APPEND todo ${l})
          else()
            list(APPEND seen ${l})
          endif()
        endforeach()
      endif()
    endif()
  endwhile()
  set(${out} "${seen}" PARENT_SCOPE)
endfunction()

bounce_sundials_link_closure(_bounce_sundials_links ${BOUNCE_SUNDIALS_TARGETS})
string(FIND "${_bounce_sundials_links}" "MPI::MPI_C" _bounce_sundials_mpi)
if(NOT _bounce_sundials_mpi EQUAL -1 AND NOT TARGET MPI::MPI_C)
  message(STATUS "SUNDIALS links MPI::MPI_C: finding MPI's C component for it")
  enable_language(C)
  find_package(MPI REQUIRED COMPONENTS C CXX)
endif()

# The checks compile a call against the headers (no link: try_compile does not carry the
# imported targets' own MPI dependencies), with the include folders the targets declare
# and MPI's, which SUNDIALS' headers include when it was built with MPI.
set(_bounce_sundials_includes)
foreach(t IN LISTS BOUNCE_SUNDIALS_TARGETS ITEMS SUNDIALS::core_shared)
  if(TARGET ${t})
    get_target_property(dirs ${t} INTERFACE_INCLUDE_DIRECTORIES)
    if(dirs)
      list(APPEND _bounce_sundials_includes ${dirs})
    endif()
  endif()
endforeach()
if(NOT _bounce_sundials_mpi EQUAL -1)
  list(APPEND _bounce_sundials_includes ${MPI_C_INCLUDE_DIRS})
endif()

include(CheckCXXSourceCompiles)
include(CMakePushCheckState)
cmake_push_check_state(RESET)
set(CMAKE_REQUIRED_INCLUDES ${_bounce_sundials_includes})
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_REQUIRED_QUIET ON)
check_cxx_source_compiles([=[
#include <cvode/cvode.h>
static void handler(int, const char*, const char*, const char*, SUNErrCode, void*, SUNContext) {}
int main() {
  SUNContext context = nullptr;
  return SUNContext_PushErrHandler(context, handler, nullptr) == SUN_SUCCESS ? 0 : 1;
}
]=] BOUNCE_SUNDIALS_PUSH_ERR_HANDLER)
check_cxx_source_compiles([=[
#include <cvode/cvode.h>
static void handler(int, const char*, const char*, char*, void*) {}
int main() { return CVodeSetErrHandlerFn(nullptr, handler, nullptr); }
]=] BOUNCE_SUNDIALS_ERR_HANDLER_FN)
check_cxx_source_compiles([=[
#include <sundials/sundials_context.h>
int main() {
  SUNContext context = nullptr;
  return SUNContext_Create(SUN_COMM_NULL, &context);
}
]=] BOUNCE_SUNDIALS_COMM_NULL)
cmake_pop_check_state()

if(NOT BOUNCE_SUNDIALS_PUSH_ERR_HANDLER AND NOT BOUNCE_SUNDIALS_ERR_HANDLER_FN)
  message(FATAL_ERROR "SUNDIALS ${SUNDIALS_VERSION}: neither SUNContext_PushErrHandler (SUNDIALS 7) nor "
                      "CVodeSetErrHandlerFn (SUNDIALS 6) compiles; see CMakeFiles/CMakeConfigureLog.yaml")
endif()
if(BOUNCE_SUNDIALS_PUSH_ERR_HANDLER)
  message(STATUS "SUNDIALS ${SUNDIALS_VERSION}: CVODE's errors through SUNContext_PushErrHandler")
else()
  message(STATUS "SUNDIALS ${SUNDIALS_VERSION}: CVODE's errors through CVodeSetErrHandlerFn")
endif()
set(bounce_sundials_definitions
    BOUNCE_SUNDIALS_PUSH_ERR_HANDLER=$<BOOL:${BOUNCE_SUNDIALS_PUSH_ERR_HANDLER}>
    BOUNCE_SUNDIALS_COMM_NULL=$<BOOL:${BOUNCE_SUNDIALS_COMM_NULL}>)
