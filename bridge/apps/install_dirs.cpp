#include "touchline/apps/install_dirs.hpp"

#include <filesystem>
#include <system_error>

namespace touchline::apps {

std::string installed_share_dir(const std::string& program) {
  namespace fs = std::filesystem;
  std::error_code ec; // an unreadable folder is a program without an installed share/: never an exception
  const fs::path share = fs::path(program).parent_path().parent_path() / "share" / "touchline";
  if (fs::is_directory(share / "behaviour_py", ec) && fs::is_directory(share / "config", ec)) return share.string();
  return "";
}

std::string installed_share_dir() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : installed_share_dir(self.string());
}

} // namespace touchline::apps
