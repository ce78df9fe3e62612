# Sanitizer and fuzzing builds (the `asan` and `fuzz` presets in CMakePresets.json; docs/robustness.md).
#
#   LANCER_SANITIZE  every target with AddressSanitizer (LeakSanitizer included) and
#                    UndefinedBehaviorSanitizer; any report aborts the program, so it fails its test.
#   LANCER_SANITIZERS which ones (-fsanitize=); the fuzz-ubsan preset leaves AddressSanitizer out,
#                    for the volume of executions its allocator costs (docs/robustness.md).
#   LANCER_FUZZ      the libFuzzer targets in tests/fuzz (clang only); the libraries they fuzz get
#                    libFuzzer's coverage instrumentation.
option(LANCER_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
set(LANCER_SANITIZERS "address,undefined,float-cast-overflow" CACHE STRING "The sanitizers of LANCER_SANITIZE (-fsanitize=)")
option(LANCER_FUZZ "Build the libFuzzer targets in tests/fuzz (needs clang and LANCER_SANITIZE)" OFF)

if(LANCER_FUZZ AND NOT (CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND LANCER_SANITIZE))
  message(FATAL_ERROR "LANCER_FUZZ needs clang (CMAKE_CXX_COMPILER=clang++) and LANCER_SANITIZE=ON: use the fuzz preset")
endif()

if(LANCER_SANITIZE)
  # -fno-sanitize-recover: an undefined-behaviour report is an error that stops the program,
  # not a line in a log nobody reads. -fno-sanitize=vptr: the dynamic-type check needs the
  # typeinfo of every polymorphic class it sees, and Debian's glslang is built without RTTI.
  # float-cast-overflow: GCC's "undefined" leaves out the check that a float fits the integer it
  # is converted to.
  add_compile_options(-fsanitize=${LANCER_SANITIZERS} -fno-sanitize=vptr -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${LANCER_SANITIZERS})
  add_compile_definitions(LANCER_SANITIZE)  # gpu/pin_loaded_libraries.cpp
  # Options and leak suppressions (tests/sanitizers/lsan.supp, each explained in
  # docs/robustness.md) compiled into every program, so nothing depends on the environment.
  set(LANCER_LSAN_SUPPRESSIONS_FILE ${PROJECT_SOURCE_DIR}/tests/sanitizers/lsan.supp)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${LANCER_LSAN_SUPPRESSIONS_FILE})
  file(READ ${LANCER_LSAN_SUPPRESSIONS_FILE} LANCER_LSAN_SUPPRESSIONS)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/sanitizer_defaults.cpp.in
                 ${PROJECT_BINARY_DIR}/generated/sanitizer_defaults.cpp @ONLY)
  add_library(lancer_sanitizer_defaults OBJECT ${PROJECT_BINARY_DIR}/generated/sanitizer_defaults.cpp)
  link_libraries(lancer_sanitizer_defaults)
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
