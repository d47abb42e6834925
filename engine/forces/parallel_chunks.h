#pragma once
/// \file parallel_chunks.h
/// \brief body(c) for every chunk c < count, on `threads` OpenMP threads, or in a plain loop at
/// one thread: no parallel region then (even a team of one goes through libgomp, measured at ~2 %
/// of an SP step). The chunks never depend on the thread count, so neither do the results.
namespace beverloo {

template <class Body>
inline void for_each_chunk(int threads, int count, Body&& body) {
  if (threads == 1) {
    for (int c = 0; c < count; ++c) body(c);
    return;
  }
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int c = 0; c < count; ++c) body(c);
}

}  // namespace beverloo
