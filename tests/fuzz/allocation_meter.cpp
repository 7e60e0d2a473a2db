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

// Replacements of the global allocation functions (the array and nothrow forms call these).
// malloc underneath, so AddressSanitizer still sees every block.
void* operator new(std::size_t size) {
  if (touchline::fuzz::t_metering && size > touchline::fuzz::t_largest) touchline::fuzz::t_largest = size;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
