#include "harness/isolation/private_copy.hpp"

#include "harness/isolation/submission_intake.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

// Readable by anyone who knows the name (the sandbox's nobody), listable by no one else.
constexpr auto kFolder = fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec;
constexpr auto kFile = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read;
constexpr auto kSubFolder = kFolder | fs::perms::group_read | fs::perms::others_read;

void copy_into(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  const auto st = fs::symlink_status(from, ec);
  if (ec) throw std::runtime_error("cannot read " + from.string() + ": " + ec.message());
  if (fs::is_symlink(st)) return;
  if (fs::is_directory(st)) {
    fs::create_directory(to, ec);
    if (!ec) fs::permissions(to, kSubFolder, ec);
    if (ec) throw std::runtime_error("cannot copy " + from.string() + ": " + ec.message());
    std::vector<fs::path> entries;
    for (const auto& e : fs::directory_iterator(from, ec)) entries.push_back(e.path());
    if (ec) throw std::runtime_error("cannot read " + from.string() + ": " + ec.message());
    for (const auto& e : entries) copy_into(e, to / e.filename());
  } else if (fs::is_regular_file(st)) {
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    // A program (a C++ submission's server) stays executable.
    const bool program = (st.permissions() & fs::perms::owner_exec) != fs::perms::none;
    if (!ec)
      fs::permissions(
          to, program ? kFile | fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec : kFile, ec);
    if (ec) throw std::runtime_error("cannot copy " + from.string() + ": " + ec.message());
  }
}

}  // namespace

PrivateCopy::PrivateCopy() {
  std::error_code ec;
  std::string pattern = (fs::temp_directory_path(ec) / "geomech-sandbox-XXXXXX").string();
  if (ec || ::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a folder for the submission's private copy in " +
                             fs::temp_directory_path(ec).string());
  root_ = pattern;
  fs::permissions(root_, kFolder, ec);
}

PrivateCopy::~PrivateCopy() {
  std::error_code ec;
  fs::remove_all(root_, ec);
}

std::string PrivateCopy::add(const std::string& path, const std::string& area, std::uint64_t max_bytes) {
  const fs::path from = fs::path(path).lexically_normal();
  const fs::path name = from.has_filename() ? from.filename() : from.parent_path().filename();
  const fs::path folder = fs::path(root_) / area;
  std::error_code ec;
  if (std::find(areas_.begin(), areas_.end(), area) == areas_.end()) {
    fs::create_directory(folder, ec);
    if (!ec) fs::permissions(folder, kSubFolder, ec);
    if (ec) throw std::runtime_error("cannot create " + folder.string() + ": " + ec.message());
    areas_.push_back(area);
  }
  if (area == "submission") {
    // A stranger's file or folder: read without following a link at any depth, never a
    // FIFO or device opened, within limits (harness/isolation/submission_intake.hpp); a refusal names the entry.
    const std::string parent = from.has_parent_path() ? from.parent_path().string() : ".";
    const StrangerFolder folder(parent);
    const std::string leaf = name.string();
    const bool is_folder = folder.look(leaf).kind == EntryKind::Folder;
    const fs::path to = folder_path(area) / name;
    if (is_folder) {
      write_tree(read_submission(folder, leaf), to);
    } else {
      const std::string text = folder.read(leaf, max_bytes);
      std::ofstream out(to, std::ios::binary | std::ios::trunc);
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      if (!out) throw std::runtime_error("cannot write " + to.string());
    }
    // Readable by the sandbox's user, a program (a C++ submission's server) still executable.
    const bool program =
        !is_folder && (fs::symlink_status(from, ec).permissions() & fs::perms::owner_exec) != fs::perms::none;
    if (is_folder) {
      fs::permissions(to, kSubFolder, ec);
      for (auto it = fs::recursive_directory_iterator(to, ec); !ec && it != fs::recursive_directory_iterator();
           it.increment(ec))
        fs::permissions(it->path(), it->is_directory() ? kSubFolder : kFile, ec);
    } else {
      fs::permissions(
          to, program ? kFile | fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec : kFile, ec);
    }
    return "/" + area + "/" + name.string();
  }
  copy_into(fs::canonical(from, ec).empty() ? from : fs::canonical(from, ec), folder / name);
  return "/" + area + "/" + name.string();
}

fs::path PrivateCopy::folder_path(const std::string& area) const { return fs::path(root_) / area; }

std::vector<std::pair<std::string, std::string>> PrivateCopy::mounts() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& a : areas_) out.emplace_back((fs::path(root_) / a).string(), "/" + a);
  return out;
}

}  // namespace gm::harness
