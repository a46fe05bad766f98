#pragma once
// Large buffers filled once at set-up (a turbulence box and its spectra, 100–250 MB): backed by
// 2 MB pages where the kernel offers transparent huge pages (mode `madvise` or `always`), so that
// filling them takes one page fault per 2 MB instead of one per 4 kB. Those faults were a fifth of
// a turbine run's set-up (issue 28). Contents and results are the same either way.
#include <cstddef>
#include <vector>

namespace fowtsim {

// Asks the kernel for huge pages over [data, data + bytes) (the 2 MB-aligned part of it); does
// nothing where it is refused or unsupported.
void advise_huge_pages(void* data, std::size_t bytes);

// v = n copies of value, on memory advised for huge pages before it is first touched.
template <class T>
void assign_on_huge_pages(std::vector<T>& v, std::size_t n, const T& value) {
  std::vector<T>().swap(v);
  v.reserve(n);  // large blocks come from mmap, untouched until assign writes them
  advise_huge_pages(v.data(), n * sizeof(T));
  v.assign(n, value);
}

}  // namespace fowtsim
