#include "core/data_path.hpp"

#include <filesystem>

#ifndef GM_SOURCE_DIR
#define GM_SOURCE_DIR "."
#endif

namespace gm {

std::string suite_data_path(const std::string& relative) {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "geomech-spec" / relative;
    if (std::filesystem::exists(installed, ec)) return installed.string();
  }
  std::string in_source = GM_SOURCE_DIR;  // appended, not `+`: GCC 12 flags the temporary (a false -Warray-bounds)
  in_source += "/";
  in_source += relative;
  return in_source;
}

}  // namespace gm
