# Sanitizer and fuzzing builds (the `asan` preset in CMakePresets.json; docs/robustness.md).
#
#   LANCER_SANITIZE  every target with AddressSanitizer (LeakSanitizer included) and
#                    UndefinedBehaviorSanitizer; any report aborts the program, so it fails its test.
#   LANCER_FUZZ      the libFuzzer targets in tests/fuzz (clang only); the libraries they fuzz get
#                    libFuzzer's coverage instrumentation.
option(LANCER_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(LANCER_FUZZ "Build the libFuzzer targets in tests/fuzz (needs clang and LANCER_SANITIZE)" OFF)

if(LANCER_FUZZ AND NOT (CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND LANCER_SANITIZE))
  message(FATAL_ERROR "LANCER_FUZZ needs clang (CMAKE_CXX_COMPILER=clang++) and LANCER_SANITIZE=ON: use the asan preset")
endif()

if(LANCER_SANITIZE)
  # -fno-sanitize-recover: an undefined-behaviour report is an error that stops the program,
  # not a line in a log nobody reads. -fno-sanitize=vptr: the dynamic-type check needs the
  # typeinfo of every polymorphic class it sees, and Debian's glslang is built without RTTI.
  # float-cast-overflow: GCC's "undefined" leaves out the check that a float fits the integer it
  # is converted to.
  add_compile_options(-fsanitize=address,undefined,float-cast-overflow -fno-sanitize=vptr -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined,float-cast-overflow)
  add_compile_definitions(LANCER_SANITIZE)  # gpu/pin_loaded_libraries.cpp
  # The suppressions for leaks and reports inside the system's libraries (Mesa, SDL, X), each
  # explained in docs/robustness.md. Tests pass these to every process they start.
  set(LANCER_SANITIZER_DIR ${PROJECT_SOURCE_DIR}/tests/sanitizers)
  set(LANCER_SANITIZER_ENV
      "ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
      "LSAN_OPTIONS=suppressions=${LANCER_SANITIZER_DIR}/lsan.supp:print_suppressions=0"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
endif()

# The libraries the fuzz targets exercise, with coverage feedback for libFuzzer.
function(lancer_instrument_for_fuzzing)
  if(NOT LANCER_FUZZ)
    return()
  endif()
  foreach(library ${ARGN})
    target_compile_options(${library} PRIVATE -fsanitize=fuzzer-no-link)
  endforeach()
endfunction()
