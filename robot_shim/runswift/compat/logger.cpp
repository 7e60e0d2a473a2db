// Their Logger class's members, written by us against their declaration in
// utils/Logger.hpp. Their own Logger.cpp needs Logger::init first (a log directory made
// with mkdir, a symlink, a thread-local logger per thread); the walk files only write
// through llog(). Here errors and worse go to stderr, one line each as they write them,
// prefixed "rUNSWift: "; everything else (their INFO on construction and reset, ...) is
// dropped, so a match's output stays ours.
#include <iostream>
#include <string>

#include "utils/Logger.hpp"

namespace {
/// A stream that writes nothing: each thread its own, so robots on several threads never
/// share its state flags.
std::ostream& discard() {
  thread_local std::ostream stream(nullptr);
  stream.clear();
  return stream;
}
} // namespace

Logger::Logger(const char*) : logStream(nullptr) {}

Logger::~Logger() = default;

void Logger::init(std::string, std::string, bool, std::string) {}

void Logger::init(std::string, bool) {}

Logger* Logger::instance() {
  static Logger the_logger("touchline");
  return &the_logger;
}

std::ostream& Logger::realLlog(int level) {
  if (level > ERROR) return discard();
  std::cerr << "rUNSWift: ";
  return std::cerr;
}

std::ostream& Logger::realLlog(int level, int) { return realLlog(level); }

void Logger::readOptions(const boost::program_options::variables_map&) {}

std::string Logger::getLogDir() { return ""; }
