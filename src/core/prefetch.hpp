// A cache hint: ask for the line holding p before it is read, so that a loop over items scattered
// in memory overlaps its misses instead of stalling on each. Never changes a result; nothing is
// read. p points into a live array (the x86-64 form names that byte as a memory operand).
// x86-64: the prefetcht0 instruction itself. GCC 12 silently dropped __builtin_prefetch of an
// address computed from two divisions into an index (world/terrain.hpp's posts; seen in the code
// it emitted, and in a six-line reduction); elsewhere the builtin.
#pragma once
#include <cstddef>

namespace npsnet::core {

inline void prefetch(const void* p) {
#if defined(__x86_64__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p);
#endif
}

// The same for a line about to be written: asks for it in the state a write needs, so that a
// line another core read last (its copy there to be invalidated) costs no stall at the store.
// x86-64: prefetchw (a no-op hint on processors without it).
inline void prefetch_write(const void* p) {
#if defined(__x86_64__)
  asm volatile("prefetchw %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p, 1);
#endif
}

// Every line an object spans: each 64-byte step from its first byte, and its last byte's (one
// of 24 bytes at an 8-byte boundary, say, may span two lines; a publisher of 200, four).
template <class T>
inline void prefetch_object(const T* p) {
  const char* b = reinterpret_cast<const char*>(p);
  for (size_t k = 0; k < sizeof(T); k += 64) prefetch(b + k);
  prefetch(b + sizeof(T) - 1);
}

}  // namespace npsnet::core
