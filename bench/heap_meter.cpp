#include "heap_meter.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace vern {

namespace {

std::atomic<bool> metering{false};
std::atomic<std::int64_t> held{0};  // since the reset; negative if older blocks were released
std::atomic<std::int64_t> peak{0};

void note_allocation(void* p) {
  if (!metering.load(std::memory_order_relaxed)) return;
  const auto bytes = static_cast<std::int64_t>(malloc_usable_size(p));
  const std::int64_t now = held.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  std::int64_t seen = peak.load(std::memory_order_relaxed);
  while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
  }
}

void note_release(void* p) {
  if (p != nullptr && metering.load(std::memory_order_relaxed)) held.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
}

void* allocate(std::size_t n) {
  void* p = std::malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  note_allocation(p);
  return p;
}

void* allocate_aligned(std::size_t n, std::align_val_t align) {
  const auto a = static_cast<std::size_t>(align);
  void* p = std::aligned_alloc(a, (n + a - 1) / a * a);  // the size must be a multiple of the alignment
  if (p == nullptr) throw std::bad_alloc();
  note_allocation(p);
  return p;
}

void release(void* p) noexcept {
  note_release(p);
  std::free(p);
}

}  // namespace

void reset_peak_heap() {
  held.store(0, std::memory_order_relaxed);
  peak.store(0, std::memory_order_relaxed);
  metering.store(true, std::memory_order_relaxed);
}

std::int64_t peak_heap_since_reset() { return peak.load(std::memory_order_relaxed); }

void stop_heap_meter() { metering.store(false, std::memory_order_relaxed); }

}  // namespace vern

// The replaceable global allocation functions ([new.delete]): every form
// routes through the two counters above.
void* operator new(std::size_t n) { return vern::allocate(n); }
void* operator new[](std::size_t n) { return vern::allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return vern::allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return vern::allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t n, std::align_val_t a) { return vern::allocate_aligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return vern::allocate_aligned(n, a); }
void operator delete(void* p) noexcept { vern::release(p); }
void operator delete[](void* p) noexcept { vern::release(p); }
void operator delete(void* p, std::size_t) noexcept { vern::release(p); }
void operator delete[](void* p, std::size_t) noexcept { vern::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { vern::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { vern::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { vern::release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { vern::release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { vern::release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { vern::release(p); }
