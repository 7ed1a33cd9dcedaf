// Where the suite's own data files are: the catalogue, the Python and Octave protocol servers.
// An installed tool (<prefix>/bin/geomech) uses the copies installed beside it, in
// <prefix>/share/geomech-spec/ (cmake/GeomechInstall.cmake), so it never depends on a source tree
// that may have moved or changed; a tool run from a build tree uses the source tree it was built from.
#pragma once

#include <string>

namespace gm {

// `relative` (e.g. "spec/catalogue.json") under the installed data directory when that file
// exists there, else under the source directory.
std::string suite_data_path(const std::string& relative);

}  // namespace gm
