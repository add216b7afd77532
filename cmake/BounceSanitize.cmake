# AddressSanitizer + UndefinedBehaviorSanitizer for every target, and the libFuzzer
# coverage the fuzz targets of fuzz/ need (docs/hardening.md). Included by the top-level
# CMakeLists.txt before any target, so that the library, the CLI, the tests and the
# build-time tools are all instrumented alike. `make test-sanitize` and `make fuzz`
# configure build-asan with both options on and clang.

if(BOUNCE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "BOUNCE_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  if(NOT BOUNCE_SANITIZE)
    message(FATAL_ERROR "BOUNCE_FUZZ runs the fuzz targets under the sanitizers: add -DBOUNCE_SANITIZE=ON")
  endif()
endif()

if(BOUNCE_SANITIZE)
  # -fno-sanitize-recover=all: the first undefined behaviour aborts (a report fails the test).
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
  if(BOUNCE_FUZZ)
    # Coverage counters and comparison tracing in every object (libFuzzer's guidance); only
    # the fuzz targets link the fuzzer itself (-fsanitize=fuzzer, fuzz/CMakeLists.txt).
    add_compile_options(-fsanitize=fuzzer-no-link)
  endif()
endif()
