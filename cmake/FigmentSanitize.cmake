# FIGMENT_SANITIZE: every FIGMENT target (libraries, tools, tests) built with AddressSanitizer and
# UndefinedBehaviorSanitizer. Included before the subdirectories, so the flags reach every target
# of this project and nothing else (Coin, assimp and OSMesa stay the system's uninstrumented
# builds). Undefined behaviour aborts (-fno-sanitize-recover) so a test that hits it fails
# instead of printing a warning no one reads. scripts/sanitize.sh builds and runs this in
# build-asan; tests/sanitize/*.supp hold the suppressions and say why each is there.
option(FIGMENT_SANITIZE "Build with -fsanitize=address,undefined" OFF)
if(FIGMENT_SANITIZE)
  set(figment_sanitize_flags -fsanitize=address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
  add_compile_options(${figment_sanitize_flags})
  add_link_options(-fsanitize=address,undefined)
endif()

# FIGMENT_SANITIZE_THREAD: the same with ThreadSanitizer (not with FIGMENT_SANITIZE: the two
# cannot share a program). scripts/sanitize.sh tsan builds test_serve so in build-tsan for the
# service's threaded units; OpenMP's own threads are not instrumented, so the tests keep one.
option(FIGMENT_SANITIZE_THREAD "Build with -fsanitize=thread" OFF)
if(FIGMENT_SANITIZE_THREAD)
  if(FIGMENT_SANITIZE)
    message(FATAL_ERROR "FIGMENT_SANITIZE_THREAD and FIGMENT_SANITIZE cannot be on together")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()

# FIGMENT_BUILD_FUZZERS: the libFuzzer targets in tests/fuzz (clang only). Everything they link is
# compiled with coverage instrumentation (-fsanitize=fuzzer-no-link) so the fuzzer sees which
# branches of our code an input reaches, except the numeric kernels tests/fuzz/coverage-ignorelist.txt
# names; scripts/fuzz.sh builds them in build-fuzz together with FIGMENT_SANITIZE.
option(FIGMENT_BUILD_FUZZERS "Build the libFuzzer targets in tests/fuzz (clang)" OFF)
if(FIGMENT_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "FIGMENT_BUILD_FUZZERS needs clang (libFuzzer): configure with CXX=clang++ CC=clang")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link
    -fsanitize-coverage-ignorelist=${CMAKE_CURRENT_SOURCE_DIR}/tests/fuzz/coverage-ignorelist.txt)
endif()
