// libFuzzer target (TOUCHLINE_LIBFUZZER, clang): coverage-guided fuzzing of the decoders the
// CTest harness covers, against the same rules (checks.hpp). The first input byte picks the
// decoder: an LCM type, whose fingerprint is put in front of the rest (so the fuzzer explores
// the fields instead of guessing eight bytes; test_fuzz_lcm covers wrong fingerprints), or
// the GameController decoder without or with team numbers. A broken rule prints what broke
// and aborts, and libFuzzer keeps the input. With TOUCHLINE_FUZZ_WRITE_SEEDS=DIR it writes
// the samples there as inputs and exits (run_libfuzzer.sh starts from them).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "checks.hpp"
#include "samples.hpp"

using namespace touchline;
using fuzz::Bytes;

namespace {

using Check = fuzz::Verdict (*)(const uint8_t* body, size_t size);

template <typename Msg>
fuzz::Verdict check_lcm_body(const uint8_t* body, size_t size) {
  Bytes bytes(8 + size);
  fuzz::put_be(bytes, 0, static_cast<uint64_t>(Msg::getHash()), 8);
  std::copy(body, body + size, bytes.begin() + 8);
  return fuzz::check_lcm<Msg>(bytes);
}

fuzz::Verdict check_gamecontroller_default(const uint8_t* body, size_t size) {
  return fuzz::check_gamecontroller(Bytes(body, body + size), {});
}

fuzz::Verdict check_gamecontroller_by_number(const uint8_t* body, size_t size) {
  sim::GameControllerConfig config;
  config.team_numbers = {{12, 5}};
  return fuzz::check_gamecontroller(Bytes(body, body + size), config);
}

/// Every decoder, by the first input byte; and the seeds, each led by its decoder's byte.
template <typename... Msg>
std::vector<Check> checks() {
  return {&check_lcm_body<Msg>..., &check_gamecontroller_default, &check_gamecontroller_by_number};
}

template <typename... Msg>
std::vector<Bytes> seeds() {
  std::vector<Bytes> out;
  uint8_t selector = 0;
  const auto add = [&](const std::vector<Bytes>& encodings, size_t skip) {
    for (const Bytes& e : encodings) {
      Bytes input{selector};
      input.insert(input.end(), e.begin() + static_cast<std::ptrdiff_t>(skip), e.end());
      out.push_back(input);
    }
    ++selector;
  };
  (add(fuzz::sample_encodings<Msg>(), 8), ...);
  add(fuzz::gamecontroller_samples(), 0);
  add(fuzz::gamecontroller_samples(), 0);
  return out;
}

const std::vector<Check> kChecks = checks<TOUCHLINE_ALL_LCM_TYPES>();

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("TOUCHLINE_FUZZ_WRITE_SEEDS")) {
    int n = 0;
    for (const Bytes& seed : seeds<TOUCHLINE_ALL_LCM_TYPES>()) {
      std::ofstream out(std::string(dir) + "/sample_" + std::to_string(n++), std::ios::binary);
      out.write(reinterpret_cast<const char*>(seed.data()), static_cast<std::streamsize>(seed.size()));
    }
    std::exit(0);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const fuzz::Verdict verdict = kChecks[data[0] % kChecks.size()](data + 1, size - 1);
  if (!verdict.failure.empty()) {
    std::fprintf(stderr, "%s\n", verdict.failure.c_str());
    std::abort();
  }
  return 0;
}
