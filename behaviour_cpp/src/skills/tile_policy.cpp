#include "touchline/behaviour/skills/tile_policy.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <utility>

#include "touchline/behaviour/registry.hpp"

namespace touchline::behaviour::skills {

namespace {

constexpr double kPiD = 3.14159265358979323846; // math.pi
constexpr const char* kNumberChars = "0123456789+-.eE";

std::vector<std::string> splitWords(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

/// The C++ reader accepts what Python's does: decimal numbers only (no nan, inf or hex).
bool parseReal(const char* begin, const char* end, double& value) {
  if (begin == end) return false;
  for (const char* c = begin; c != end; ++c)
    if (!std::strchr(kNumberChars, *c)) return false;
  char* parsed = nullptr;
  value = std::strtod(begin, &parsed);
  return parsed == end && std::isfinite(value);
}

double real(const std::string& name, const std::string& token, const std::string& what) {
  double value = 0;
  if (!parseReal(token.data(), token.data() + token.size(), value))
    throw BehaviourError(name + ": " + what + ": '" + token + "' is not a number");
  return value;
}

/// A whole number >= 1 of at most 9 digits.
int count(const std::string& name, const std::string& token, const std::string& what) {
  const bool digits = !token.empty() && token.size() <= 9 &&
                      std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || std::atoi(token.c_str()) < 1)
    throw BehaviourError(name + ": " + what + ": '" + token + "' is not a whole number >= 1");
  return std::atoi(token.c_str());
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

/// The weights after the 'weights' line: counted first (a wrong count is the likelier
/// mistake), then read one by one, naming a bad one.
std::vector<double> readWeights(const std::string& name, const std::string& text, size_t from, size_t expected) {
  std::vector<std::pair<size_t, size_t>> tokens; // [begin, end) in text
  tokens.reserve(expected);
  for (size_t i = from; i < text.size();) {
    while (i < text.size() && isSpace(text[i])) ++i;
    const size_t begin = i;
    while (i < text.size() && !isSpace(text[i])) ++i;
    if (i > begin) tokens.emplace_back(begin, i);
  }
  if (tokens.size() != expected)
    throw BehaviourError(name + ": " + std::to_string(tokens.size()) + " weights after 'weights', expected " +
                         std::to_string(expected));
  std::vector<double> weights(expected);
  for (size_t i = 0; i < expected; ++i) {
    const auto [begin, end] = tokens[i];
    if (!parseReal(text.data() + begin, text.data() + end, weights[i]))
      throw BehaviourError(name + ": weight " + std::to_string(i) + ": '" + text.substr(begin, end - begin) +
                           "' is not a number");
  }
  return weights;
}

const std::vector<std::string> kKeys = {"features", "tiles", "tilings", "actions", "distance_scale_mm",
                                        "max_distance_mm", "success_distance_mm", "success_heading_rad"};

bool contains(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

} // namespace

TilePolicy::TilePolicy(TilePolicyDef def)
    : def_(std::move(def)), uMax_(std::log(1.0 + def_.maxDistance / def_.distanceScale)) {}

std::vector<size_t> TilePolicy::cellIndices(double x, double y, double theta) const {
  const double d = std::sqrt(x * x + y * y);
  const double u = std::min(std::log(1.0 + d / def_.distanceScale), uMax_);
  const double b = (x == 0.0 && y == 0.0) ? 0.0 : std::atan2(y, x);
  const double h = wrapAngle(theta);
  const double su = (u / uMax_) * def_.tilesU;
  const double sb = ((b + kPiD) / (2.0 * kPiD)) * def_.tilesB;
  const double sh = ((h + kPiD) / (2.0 * kPiD)) * def_.tilesH;
  const auto positiveMod = [](long i, long n) { return ((i % n) + n) % n; };
  std::vector<size_t> indices(static_cast<size_t>(def_.tilings));
  for (int k = 0; k < def_.tilings; ++k) {
    const double K = def_.tilings;
    const long iu = std::clamp(static_cast<long>(std::floor(su + (k * U_TILING_OFFSET) / K)), 0L, long{def_.tilesU});
    const long ib = positiveMod(static_cast<long>(std::floor(sb + (k * B_TILING_OFFSET) / K)), def_.tilesB);
    const long ih = positiveMod(static_cast<long>(std::floor(sh + (k * H_TILING_OFFSET) / K)), def_.tilesH);
    const long cell = ((long{k} * (def_.tilesU + 1) + iu) * def_.tilesB + ib) * def_.tilesH + ih;
    indices[static_cast<size_t>(k)] = static_cast<size_t>(cell) * def_.actions.size();
  }
  return indices;
}

std::vector<double> TilePolicy::values(double x, double y, double theta) const {
  std::vector<double> q(def_.actions.size(), 0.0);
  for (const size_t base : cellIndices(x, y, theta))
    for (size_t a = 0; a < q.size(); ++a) q[a] += def_.weights[base + a];
  return q;
}

size_t TilePolicy::greedyAction(double x, double y, double theta) const {
  const std::vector<double> q = values(x, y, theta);
  size_t best = 0;
  for (size_t a = 1; a < q.size(); ++a)
    if (q[a] > q[best]) best = a;
  return best;
}

bool TilePolicy::arrived(double x, double y, double theta) const {
  return std::sqrt(x * x + y * y) < def_.successDistance && std::fabs(wrapAngle(theta)) < def_.successHeading;
}

TilePolicy parsePolicy(const std::string& text, const std::string& name) {
  std::vector<std::string> lines;
  for (size_t start = 0;;) { // split at '\n', as Python's text.split("\n")
    const size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  const std::vector<std::string> first = splitWords(lines[0]);
  const std::string expectedFirst = std::string(POLICY_MAGIC) + " " + std::to_string(POLICY_VERSION);
  if (first.size() != 2 || first[0] != POLICY_MAGIC)
    throw BehaviourError(name + ": not a policy file (the first line must be '" + expectedFirst + "')");
  if (first[1] != std::to_string(POLICY_VERSION))
    throw BehaviourError(name + ": policy format version '" + first[1] + "' is not supported (this reader knows " +
                         std::to_string(POLICY_VERSION) + ")");

  TilePolicyDef def;
  def.name = name;
  std::map<std::string, std::vector<std::string>> fields; // key -> its values, checked
  int weights = 0;
  size_t weightsFrom = std::string::npos; // offset in text just after the 'weights' line
  size_t offset = lines[0].size() + 1;
  for (size_t number = 2; number <= lines.size(); offset += lines[number - 1].size() + 1, ++number) {
    const std::vector<std::string> words = splitWords(lines[number - 1]);
    if (words.empty() || words[0][0] == '#') continue;
    const std::string& key = words[0];
    const std::vector<std::string> values(words.begin() + 1, words.end());
    const std::string where = "line " + std::to_string(number) + " (" + key + ")";
    if (key == "weights") {
      if (values.size() != 1) throw BehaviourError(name + ": " + where + ": expected one count");
      weights = count(name, values[0], where);
      weightsFrom = offset + lines[number - 1].size() + 1;
      break;
    }
    if (key == "action") {
      if (values.size() != 3) throw BehaviourError(name + ": " + where + ": expected forward, left, turn");
      def.actions.push_back({real(name, values[0], where), real(name, values[1], where), real(name, values[2], where)});
      continue;
    }
    if (!contains(kKeys, key)) throw BehaviourError(name + ": " + where + ": unknown key '" + key + "'");
    if (fields.count(key)) throw BehaviourError(name + ": " + where + ": '" + key + "' given twice");
    const size_t expected = key == "tiles" ? 3 : 1;
    if (values.size() != expected)
      throw BehaviourError(name + ": " + where + ": expected " + std::to_string(expected) + " value" +
                           (expected > 1 ? "s" : ""));
    if (key == "features") {
      if (values[0] != FEATURES_POLAR_LOG)
        throw BehaviourError(name + ": " + where + ": unknown feature kind '" + values[0] + "' (known: " +
                             FEATURES_POLAR_LOG + ")");
    } else if (key == "tiles") {
      def.tilesU = count(name, values[0], where);
      def.tilesB = count(name, values[1], where);
      def.tilesH = count(name, values[2], where);
    } else if (key == "tilings") {
      def.tilings = count(name, values[0], where);
    } else if (key == "actions") {
      count(name, values[0], where); // compared with the action lines below
    } else {
      real(name, values[0], where);
    }
    fields[key] = values;
  }
  for (const std::string& key : kKeys)
    if (!fields.count(key)) throw BehaviourError(name + ": missing '" + key + "'");
  if (weightsFrom == std::string::npos) throw BehaviourError(name + ": missing 'weights'");
  const auto realField = [&](const std::string& key) { return real(name, fields[key][0], key); };
  def.distanceScale = realField("distance_scale_mm");
  def.maxDistance = realField("max_distance_mm");
  def.successDistance = realField("success_distance_mm");
  def.successHeading = realField("success_heading_rad");
  using Field = std::pair<const char*, double>;
  for (const auto& [key, value] : {Field{"distance_scale_mm", def.distanceScale}, Field{"max_distance_mm", def.maxDistance}})
    if (!(value > 0.0)) throw BehaviourError(name + ": '" + key + "' must be > 0 (got " + format("%.9g", value) + ")");
  for (const auto& [key, value] :
       {Field{"success_distance_mm", def.successDistance}, Field{"success_heading_rad", def.successHeading}})
    if (!(value >= 0.0)) throw BehaviourError(name + ": '" + key + "' must be >= 0 (got " + format("%.9g", value) + ")");
  const int actions = std::atoi(fields["actions"][0].c_str());
  if (def.actions.size() != static_cast<size_t>(actions))
    throw BehaviourError(name + ": " + std::to_string(def.actions.size()) + " 'action' lines, but 'actions' says " +
                         std::to_string(actions));
  // In 64 bits: each factor has at most 9 digits, so only the product of all five could overflow.
  const long double product = static_cast<long double>(def.tilings) * (def.tilesU + 1.0L) * def.tilesB *
                              def.tilesH * actions;
  if (product > MAX_POLICY_WEIGHTS)
    throw BehaviourError(name + ": " + format("%.0f", static_cast<double>(product)) + " weights is more than " +
                         std::to_string(MAX_POLICY_WEIGHTS));
  const long expected = static_cast<long>(product);
  if (weights != expected)
    throw BehaviourError(name + ": 'weights' says " + std::to_string(weights) + ", but " +
                         std::to_string(def.tilings) + " tilings x " + std::to_string(def.tilesU + 1) + " x " +
                         std::to_string(def.tilesB) + " x " + std::to_string(def.tilesH) + " cells x " +
                         std::to_string(actions) + " actions need " + std::to_string(expected));
  def.weights = readWeights(name, text, std::min(weightsFrom, text.size()), static_cast<size_t>(expected));
  return TilePolicy(std::move(def));
}

TilePolicy loadPolicy(const std::string& path) {
  const auto cannotRead = [&](const std::string& why) {
    return BehaviourError(path + ": cannot read the policy (" + why + ")");
  };
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw cannotRead(std::strerror(EISDIR));
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw cannotRead(std::strerror(errno));
  std::string text(static_cast<size_t>(file.tellg()), '\0');
  file.seekg(0);
  if (!file.read(text.data(), static_cast<std::streamsize>(text.size()))) throw cannotRead(std::strerror(errno));
  return parsePolicy(text, path);
}

std::shared_ptr<const TilePolicy> cachedPolicy(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const TilePolicy>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& policy = cache[path];
  if (!policy) policy = std::make_shared<const TilePolicy>(loadPolicy(path));
  return policy;
}

} // namespace touchline::behaviour::skills
