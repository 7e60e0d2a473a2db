#pragma once
// Seeded random mutation of valid encodings, for the bounded fuzz tests: bit flips, bytes
// and integer fields overwritten with edge values (-1, 0, the extremes: what a forged count
// looks like), truncation, extension, spans cut out or repeated, splices of two seeds, and
// random bytes behind a valid prefix (the right LCM fingerprint). Deterministic for a seed.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace touchline::fuzz {

using Bytes = std::vector<uint8_t>;

#ifndef TOUCHLINE_FUZZ_DEFAULT_ITERATIONS
#define TOUCHLINE_FUZZ_DEFAULT_ITERATIONS 20000
#endif

/// Random inputs per fuzz test: TOUCHLINE_FUZZ_ITERATIONS, or a default sized so that the
/// whole harness takes seconds (more in the sanitizer build, see tests/fuzz/CMakeLists.txt).
inline int iterations() {
  const char* text = std::getenv("TOUCHLINE_FUZZ_ITERATIONS");
  return text ? std::atoi(text) : TOUCHLINE_FUZZ_DEFAULT_ITERATIONS;
}

/// The run's seed: TOUCHLINE_FUZZ_SEED, or a fixed one (the same inputs every run).
inline uint64_t seed() {
  const char* text = std::getenv("TOUCHLINE_FUZZ_SEED");
  return text ? std::strtoull(text, nullptr, 10) : 13;
}

inline std::string hex(const Bytes& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (uint8_t b : bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

/// Big-endian (LCM's byte order) `width` bytes of `value` at `at`, clipped to the buffer.
inline void put_be(Bytes& bytes, size_t at, uint64_t value, size_t width) {
  for (size_t i = 0; i < width && at + i < bytes.size(); ++i)
    bytes[at + i] = static_cast<uint8_t>(value >> (8 * (width - 1 - i)));
}

/// Integer edge values for a field of `width` bytes: 0, 1, -1, the largest and the smallest.
inline std::vector<uint64_t> edge_values(size_t width) {
  const uint64_t all = width >= 8 ? ~uint64_t{0} : (uint64_t{1} << (8 * width)) - 1;
  const uint64_t top = uint64_t{1} << (8 * width - 1);
  return {0, 1, all, top - 1, top};
}

class Mutator {
 public:
  /// `keep` leading bytes survive the "random tail" mutation (the LCM fingerprint: 8).
  Mutator(uint64_t seed, std::vector<Bytes> seeds, size_t keep)
      : rng_(seed), seeds_(std::move(seeds)), keep_(keep) {}

  /// One mutant: a random seed with one to three random mutations.
  Bytes next() {
    Bytes bytes = pick();
    const int n = between(1, 3);
    for (int i = 0; i < n; ++i) mutate(bytes);
    return bytes;
  }

 private:
  int between(int lowest, int highest) { return std::uniform_int_distribution<int>(lowest, highest)(rng_); }
  size_t index(size_t size) { return std::uniform_int_distribution<size_t>(0, size - 1)(rng_); }
  uint8_t byte() { return static_cast<uint8_t>(between(0, 255)); }
  const Bytes& pick() { return seeds_[index(seeds_.size())]; }

  void mutate(Bytes& b) {
    switch (between(0, 8)) {
      case 0: // bit flips
        if (!b.empty())
          for (int i = between(1, 8); i > 0; --i) b[index(b.size())] ^= static_cast<uint8_t>(1u << between(0, 7));
        break;
      case 1: // random bytes
        if (!b.empty())
          for (int i = between(1, 4); i > 0; --i) b[index(b.size())] = byte();
        break;
      case 2: { // an integer field (count, length, id) set to an edge value
        if (b.empty()) break;
        const size_t width = size_t{1} << between(0, 3);
        const auto values = edge_values(width);
        put_be(b, index(b.size()), values[index(values.size())], width);
        break;
      }
      case 3: // truncation
        b.resize(b.empty() ? 0 : index(b.size()));
        break;
      case 4: // extension
        for (int i = between(1, 16); i > 0; --i) b.push_back(byte());
        break;
      case 5: { // a span cut out: later fields slide into earlier ones
        if (b.size() < 2) break;
        const size_t at = index(b.size());
        const size_t n = std::min(b.size() - at, static_cast<size_t>(between(1, 16)));
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(at), b.begin() + static_cast<std::ptrdiff_t>(at + n));
        break;
      }
      case 6: { // a span repeated
        if (b.empty()) break;
        const size_t at = index(b.size());
        const size_t n = std::min(b.size() - at, static_cast<size_t>(between(1, 16)));
        const Bytes span(b.begin() + static_cast<std::ptrdiff_t>(at), b.begin() + static_cast<std::ptrdiff_t>(at + n));
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), span.begin(), span.end());
        break;
      }
      case 7: { // splice: the head of this one, the tail of another seed
        const Bytes& other = pick();
        const size_t cut = b.empty() ? 0 : index(b.size());
        const size_t from = other.empty() ? 0 : index(other.size());
        b.resize(cut);
        b.insert(b.end(), other.begin() + static_cast<std::ptrdiff_t>(from), other.end());
        break;
      }
      default: { // random bytes behind the valid prefix, of a random length
        b.resize(std::min(b.size(), keep_) + static_cast<size_t>(between(0, 2 * static_cast<int>(b.size()) + 8)));
        for (size_t i = std::min(keep_, b.size()); i < b.size(); ++i) b[i] = byte();
        break;
      }
    }
  }

  std::mt19937_64 rng_;
  std::vector<Bytes> seeds_;
  size_t keep_;
};

/// Every input of the exhaustive sweep: each seed with each 1-, 2-, 4- and 8-byte window
/// set to each edge value. Whatever the layout, every count and length field meets -1, 0
/// and its extremes.
template <typename Visit>
void sweep_edge_values(const std::vector<Bytes>& seeds, Visit visit) {
  for (const Bytes& seed : seeds)
    for (size_t width : {1, 2, 4, 8})
      for (uint64_t value : edge_values(width))
        for (size_t at = 0; at + width <= seed.size(); ++at) {
          Bytes b = seed;
          put_be(b, at, value, width);
          visit(b);
        }
}

} // namespace touchline::fuzz
