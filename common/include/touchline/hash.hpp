#pragma once
// FNV-1a 64 over exact bytes: equal hashes mean bit-identical state, which is what the
// determinism tests compare.
#include <cstddef>
#include <cstdint>

namespace touchline {

class Fnv1a {
 public:
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value_ = (value_ ^ bytes[i]) * 1099511628211ull;
  }
  template <typename T>
  void add_value(const T& value) { add(&value, sizeof value); }
  uint64_t value() const { return value_; }

 private:
  uint64_t value_ = 14695981039346656037ull; // offset basis
};

} // namespace touchline
