#!/usr/bin/env bash
# The cores this machine gives the build and the tests (for -j): nproc's count, without
# OpenMP's variables, which GNU nproc also obeys. The tests set OMP_NUM_THREADS=1 each; a
# shell that has it set (to run a drape on one thread) must not make the build or ctest
# serial: the sanitizer job, started so, ran its build and its tests one at a time.
exec env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc
