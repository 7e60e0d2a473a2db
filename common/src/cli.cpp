#include "touchline/cli.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "touchline/ini.hpp"

namespace touchline {

void require_writable(const std::string& option, const std::string& path) {
  auto fail = [&](const std::string& why) {
    throw ConfigError(option + " " + path + ": cannot write there (" + why + ")");
  };
  if (path.empty()) fail("empty path");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) fail("it is a directory");
    // O_NONBLOCK: a FIFO without a reader fails at once instead of hanging the program.
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) fail(std::strerror(errno));
    ::close(fd);
    return;
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) fail(std::strerror(errno));
  ::close(fd);
  ::unlink(path.c_str());
}

} // namespace touchline
