#pragma once
// Where an installed program finds its files: the prefix's share/touchline/ (config/ with the
// learned policies, behaviour_py/), beside the bin/ it runs from. cmake --install and
// `pip install .` both lay the prefix out so (cmake/install.cmake); a program run from a build
// tree's bin/ has none there and keeps the source tree's folders it was built with.
#include <string>

namespace touchline::apps {

/// `<program's folder>/../share/touchline` when it holds behaviour_py/ and config/, else "".
/// Reads /proc/self/exe.
std::string installed_share_dir();

/// installed_share_dir()'s rule for a program at `program` (a path to its executable).
std::string installed_share_dir(const std::string& program);

} // namespace touchline::apps
