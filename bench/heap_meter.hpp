// Peak heap use, for the memory columns of the benchmark table.
//
// vern_bench replaces the global operator new and delete (heap_meter.cpp).
// While the meter runs, they keep a count of the bytes allocated and not
// yet released since it started (as malloc_usable_size reports them, so
// the allocator's rounding counts) and its high-water mark. Relaxed
// atomics, so threads may allocate. The meter costs about 15 ns per
// allocation, 5% of an allocation-heavy benchmark, so the inverse rows time
// their iterations with it off and measure the peak in one run of their
// own (peak_heap_of in table_row.hpp). Memory that C libraries take with
// malloc directly is not seen (tinygltf's buffers are std::vectors, so
// they are).
#pragma once

#include <cstdint>

namespace vern {

// Starts the meter afresh: nothing held, no peak.
void reset_peak_heap();

// The most bytes held at once since the reset (above what was held then).
std::int64_t peak_heap_since_reset();

// Stops counting (until the next reset).
void stop_heap_meter();

}  // namespace vern
