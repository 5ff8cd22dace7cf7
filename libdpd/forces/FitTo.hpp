#pragma once
// Sizing of the pair loop's process-wide buffers (its inputs, its force sums): they are shared by
// every system of the process (the benchmark runs a million particles, then 32,000), and each should
// hold what it needs, not what the largest before it needed.
#include <cstddef>
#include <vector>

namespace dpd {

// n entries, and no more than twice that held. Entries added are value-initialised. A buffer that
// grows again takes an eighth more than it needs: a rank of a decomposed run holds a few per cent
// more or fewer particles from step to step, and a buffer sized exactly (or doubled, then released
// when the count fell back) was allocated again, its pages cleared by the kernel, at most steps.
template <class T, class Allocator>
void fitTo(std::vector<T, Allocator>& v, std::size_t n) {
    if (v.capacity() > 2 * n) std::vector<T, Allocator>().swap(v);
    if (n > v.capacity()) v.reserve(v.capacity() == 0 ? n : n + n / 8);
    v.resize(n);
}

}  // namespace dpd
