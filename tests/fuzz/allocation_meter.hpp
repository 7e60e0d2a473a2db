#pragma once
// The largest single allocation made while a meter is alive on this thread, so a fuzz test
// can show that a decoder never allocates more than its input can justify (a forged count
// must be rejected before the decoder allocates for it). allocation_meter.cpp replaces the
// global operator new of the test program to see every allocation.
#include <cstddef>

namespace touchline::fuzz {

class AllocationMeter {
 public:
  AllocationMeter();
  ~AllocationMeter();
  AllocationMeter(const AllocationMeter&) = delete;
  AllocationMeter& operator=(const AllocationMeter&) = delete;

  /// Bytes of the largest allocation since construction.
  std::size_t largest() const;
};

} // namespace touchline::fuzz
