# What a build leaves out when an optional program or package is missing, said once.
#
# FIGMENT_REQUIRE_ALL_TESTS (scripts/setup.sh sets it when it builds everything, and so CI):
# a test or program that would be left out stops the configure instead, naming what is
# missing. Without it the line is a warning (on stderr, where scripts/setup.sh shows it),
# never a quiet status line: a suite that ran fewer tests than it has must be seen.
option(FIGMENT_REQUIRE_ALL_TESTS "Fail the configure when a test or program would be left out" OFF)

# figment_left_out(<what is left out and why; how to get it>)
function(figment_left_out line)
  if(FIGMENT_REQUIRE_ALL_TESTS)
    message(FATAL_ERROR "${line} (FIGMENT_REQUIRE_ALL_TESTS is on)")
  endif()
  message(WARNING "${line}")
endfunction()
