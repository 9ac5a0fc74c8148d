// Transparent huge pages for the FFT engines' large arrays (kernel spectra,
// the transform's buffer). The set-up writes each of them once, at first
// touch: with 4 KiB pages that was a page fault each, about 120 000 in a
// `balanced` 1080p set-up; a huge page takes one fault per 2 MiB.
#pragma once

#include <cstddef>

namespace eyestream::glare {

// Asks the system to back the whole 2 MiB pages inside [p, p + bytes) with
// huge pages (x86-64's size); call it right after allocating, before the
// array is written. Only advice: where the system gives none (THP off, not
// Linux) nothing changes, and the values stored never depend on it. Memory
// malloc reuses may have been touched already (then it keeps its pages),
// and the advice stays with the address range after the array is freed:
// it is meant for the FFT engines' large arrays, kept for the sequence, and
// the set-up's scratch arrays of the same size.
void prefer_huge_pages(void* p, size_t bytes);

}  // namespace eyestream::glare
