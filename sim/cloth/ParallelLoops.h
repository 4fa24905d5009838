#pragma once
// When the solver's per-node loops run in parallel. A conjugate-gradient iteration over
// a garment of a few hundred nodes takes a few microseconds, about what a barrier
// between the threads costs, so below this size the solve runs on one thread (the
// assembly, a hundred times more work per node, always runs in parallel).

namespace figment {

constexpr int kParallelSolveNodes = 256;

}  // namespace figment
