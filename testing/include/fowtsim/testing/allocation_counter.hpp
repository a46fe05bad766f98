#pragma once
// Counts heap allocations in a test executable: global operator new is replaced and counts while
// `counting` is set. The replacement operators are ordinary (non-inline) definitions, so include
// this header in exactly one source file of an executable.
#include <atomic>
#include <cstdlib>
#include <new>

namespace fowtsim::testing {
inline std::atomic<bool> counting{false};
inline std::atomic<long> allocations{0};
}  // namespace fowtsim::testing

void* operator new(std::size_t size) {
  if (fowtsim::testing::counting) ++fowtsim::testing::allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
