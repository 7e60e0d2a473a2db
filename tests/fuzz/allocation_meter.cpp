#include "allocation_meter.hpp"

#include <cstdlib>
#include <new>

namespace touchline::fuzz {
namespace {
thread_local bool t_metering = false;
thread_local std::size_t t_largest = 0;
} // namespace

AllocationMeter::AllocationMeter() {
  t_metering = true;
  t_largest = 0;
}
AllocationMeter::~AllocationMeter() { t_metering = false; }
std::size_t AllocationMeter::largest() const { return t_largest; }

} // namespace touchline::fuzz

// Replacements of every global allocation function but the aligned ones, all over malloc
// and free: AddressSanitizer still sees every block, and no pair can mismatch (a program
// that replaced only some would free one kind of block with another's function).
namespace {
void* allocate(std::size_t size) {
  if (touchline::fuzz::t_metering && size > touchline::fuzz::t_largest) touchline::fuzz::t_largest = size;
  return std::malloc(size == 0 ? 1 : size);
}
void* allocate_or_throw(std::size_t size) {
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
} // namespace

void* operator new(std::size_t size) { return allocate_or_throw(size); }
void* operator new[](std::size_t size) { return allocate_or_throw(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
