#include "harness/isolation/submission_intake.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gm::harness {

namespace fs = std::filesystem;

namespace {

EntryKind kind_of(mode_t m) {
  if (S_ISREG(m)) return EntryKind::File;
  if (S_ISDIR(m)) return EntryKind::Folder;
  if (S_ISLNK(m)) return EntryKind::Link;
  if (S_ISFIFO(m)) return EntryKind::Fifo;
  if (S_ISSOCK(m)) return EntryKind::Socket;
  if (S_ISCHR(m) || S_ISBLK(m)) return EntryKind::Device;
  return EntryKind::Other;
}

// A file descriptor closed when it goes.
struct Fd {
  int fd = -1;
  explicit Fd(int f = -1) : fd(f) {}
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  Fd(Fd&& o) noexcept : fd(o.fd) { o.fd = -1; }
  Fd& operator=(Fd&& o) noexcept {
    if (this != &o) {
      if (fd >= 0) ::close(fd);
      fd = o.fd;
      o.fd = -1;
    }
    return *this;
  }
  int release() {
    const int f = fd;
    fd = -1;
    return f;
  }
};

std::vector<std::string> components(const std::string& rel) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : rel) {
    if (c == '/') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  for (const auto& c : out)
    if (c == "." || c == "..") throw RefusedEntry(rel, "a path that steps out of its folder ('" + c + "')");
  return out;
}

std::string joined(const std::vector<std::string>& parts, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n && i < parts.size(); ++i) out += (i ? "/" : "") + parts[i];
  return out;
}

StrangerFolder::Entry look_at(int dirfd, const std::string& name, const std::string& shown) {
  struct stat st {};
  if (::fstatat(dirfd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
    throw RefusedEntry(shown, std::string("cannot be looked at (") + std::strerror(errno) + ")");
  StrangerFolder::Entry e;
  e.name = name;
  e.kind = kind_of(st.st_mode);
  e.size = static_cast<std::uint64_t>(st.st_size);
  e.links = static_cast<std::uint64_t>(st.st_nlink);
  return e;
}

// Opens the regular file `name` in `dirfd` for reading without following or blocking, and reads
// at most `cap` bytes; refuses anything else.
std::string read_at(int dirfd, const std::string& name, const std::string& shown, std::uint64_t cap) {
  // Looked at first: a FIFO or a device is never opened.
  const StrangerFolder::Entry e = look_at(dirfd, name, shown);
  if (e.kind != EntryKind::File) throw RefusedEntry(shown, describe(e.kind));
  Fd f(::openat(dirfd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (f.fd < 0) throw RefusedEntry(shown, std::string("cannot be opened (") + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw RefusedEntry(shown, "was replaced by something that is not a regular file while it was read");
  if (st.st_nlink > 1)
    throw RefusedEntry(shown, "a file with " + std::to_string(st.st_nlink) +
                                  " names (a hard link: it may be another name of a file that is not the student's); "
                                  "hand in a plain copy");
  if (static_cast<std::uint64_t>(st.st_size) > cap)
    throw RefusedEntry(shown, "larger than " + std::to_string(cap >> 20) + " MiB (" +
                                  std::to_string(static_cast<std::uint64_t>(st.st_size)) + " bytes)");
  std::string out;
  out.resize(static_cast<std::size_t>(st.st_size) + 1);
  std::size_t got = 0;
  for (;;) {
    if (got == out.size()) {
      if (got > cap) break;
      out.resize(std::min<std::uint64_t>(cap + 1, out.size() * 2 + 4096));
    }
    const ssize_t n = ::read(f.fd, out.data() + got, out.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw RefusedEntry(shown, std::string("cannot be read (") + std::strerror(errno) + ")");
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got > cap) throw RefusedEntry(shown, "grew beyond " + std::to_string(cap >> 20) + " MiB while it was read");
  out.resize(got);
  return out;
}

}  // namespace

std::string describe(EntryKind k) {
  switch (k) {
    case EntryKind::File:
      return "a file";
    case EntryKind::Folder:
      return "a folder";
    case EntryKind::Link:
      return "a symbolic link (submissions are never followed through a link: it may name another student's file or "
             "one that is not the student's; hand in the file itself)";
    case EntryKind::Fifo:
      return "a FIFO (named pipe), which is never opened: reading it would wait for a writer";
    case EntryKind::Socket:
      return "a socket, which is never opened";
    case EntryKind::Device:
      return "a device, which is never opened";
    case EntryKind::Other:
      break;
  }
  return "not a regular file or folder";
}

StrangerFolder::StrangerFolder(const std::string& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("cannot open the folder " + path + ": " + std::strerror(errno));
}

StrangerFolder::~StrangerFolder() {
  if (fd_ >= 0) ::close(fd_);
}

int StrangerFolder::open_parent(const std::string& rel, std::string* leaf) const {
  const auto parts = components(rel);
  if (parts.empty()) throw RefusedEntry(rel, "an empty path");
  Fd cur(::dup(fd_));
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    const std::string shown = joined(parts, i + 1);
    const Entry e = look_at(cur.fd, parts[i], shown);
    if (e.kind != EntryKind::Folder) throw RefusedEntry(shown, describe(e.kind));
    Fd next(::openat(cur.fd, parts[i].c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (next.fd < 0) throw RefusedEntry(shown, std::string("cannot be opened (") + std::strerror(errno) + ")");
    cur = std::move(next);  // closes the folder above
  }
  *leaf = parts.back();
  return cur.release();
}

std::vector<StrangerFolder::Entry> StrangerFolder::list(const std::string& rel) const {
  Fd dir(-1);
  if (components(rel).empty()) {
    dir = Fd(::dup(fd_));
  } else {
    std::string leaf;
    Fd parent(open_parent(rel, &leaf));
    const Entry e = look_at(parent.fd, leaf, rel);
    if (e.kind != EntryKind::Folder) throw RefusedEntry(rel, describe(e.kind));
    dir = Fd(::openat(parent.fd, leaf.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (dir.fd < 0) throw RefusedEntry(rel, std::string("cannot be opened (") + std::strerror(errno) + ")");
  }
  // fdopendir takes the descriptor; a duplicate stays ours for fstatat.
  DIR* d = ::fdopendir(::dup(dir.fd));
  if (d == nullptr)
    throw RefusedEntry(rel.empty() ? path_ : rel, std::string("cannot be listed (") + std::strerror(errno) + ")");
  std::vector<Entry> out;
  while (const dirent* de = ::readdir(d)) {
    const std::string name = de->d_name;
    if (name == "." || name == "..") continue;
    out.push_back(look_at(dir.fd, name, rel.empty() ? name : rel + "/" + name));
  }
  ::closedir(d);
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return out;
}

StrangerFolder::Entry StrangerFolder::look(const std::string& rel) const {
  std::string leaf;
  Fd parent(open_parent(rel, &leaf));
  return look_at(parent.fd, leaf, rel);
}

std::string StrangerFolder::read(const std::string& rel, std::uint64_t cap) const {
  std::string leaf;
  Fd parent(open_parent(rel, &leaf));
  return read_at(parent.fd, leaf, rel, cap);
}

std::uint64_t SubmissionTree::bytes() const {
  std::uint64_t n = 0;
  for (const auto& [path, text] : files) n += text.size();
  return n;
}

namespace {

bool left_out(const std::string& name) { return name.empty() || name[0] == '.' || name == "__pycache__"; }

void read_into(const StrangerFolder& from, const std::string& rel, const IntakeLimits& limits, int depth,
               std::size_t& entries, SubmissionTree& tree) {
  const StrangerFolder::Entry e = from.look(rel);
  if (++entries > limits.entries)
    throw RefusedEntry(
        rel, "one entry too many: a submission holds at most " + std::to_string(limits.entries) + " files and folders");
  if (e.kind == EntryKind::Folder) {
    if (depth > limits.depth)
      throw RefusedEntry(rel, "folders nested deeper than " + std::to_string(limits.depth) + " levels");
    for (const auto& sub : from.list(rel))
      if (!left_out(sub.name)) read_into(from, rel + "/" + sub.name, limits, depth + 1, entries, tree);
    return;
  }
  if (e.kind != EntryKind::File) throw RefusedEntry(rel, describe(e.kind));
  const std::uint64_t left = limits.total_bytes - std::min(limits.total_bytes, tree.bytes());
  if (e.size > left && e.size <= limits.file_bytes)
    throw RefusedEntry(rel,
                       "beyond the size of a submission: " + std::to_string(limits.total_bytes >> 20) + " MiB in all");
  tree.files.emplace_back(rel, from.read(rel, std::min(limits.file_bytes, left)));
}

}  // namespace

SubmissionTree read_submission(const StrangerFolder& from, const std::string& rel, const IntakeLimits& limits) {
  SubmissionTree tree;
  std::size_t entries = 0;
  read_into(from, rel, limits, 0, entries, tree);
  // Paths relative to the submission itself: "bob.py" for a file, "x.hpp" inside a folder "bob".
  const auto parts = components(rel);
  const std::string prefix = joined(parts, parts.size() - 1);
  const bool folder = from.look(rel).kind == EntryKind::Folder;
  const std::string strip = folder ? joined(parts, parts.size()) + "/" : (prefix.empty() ? "" : prefix + "/");
  for (auto& [path, text] : tree.files) path = path.substr(std::min(path.size(), strip.size()));
  std::sort(tree.files.begin(), tree.files.end());
  return tree;
}

void write_tree(const SubmissionTree& tree, const fs::path& dest) {
  std::error_code ec;
  fs::create_directories(dest, ec);
  if (ec) throw std::runtime_error("cannot create " + dest.string() + ": " + ec.message());
  std::set<fs::path> keep;
  for (const auto& [rel, text] : tree.files) {
    const fs::path to = dest / rel;
    keep.insert(to.lexically_normal());
    for (fs::path p = to.parent_path(); p != dest && p.has_relative_path(); p = p.parent_path())
      keep.insert(p.lexically_normal());
    fs::create_directories(to.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create " + to.parent_path().string() + ": " + ec.message());
    {
      std::ifstream in(to, std::ios::binary);
      if (in) {
        std::ostringstream os;
        os << in.rdbuf();
        if (os.str() == text) continue;  // unchanged: its time stays
      }
    }
    static std::atomic<unsigned> serial{0};
    const fs::path tmp = to.string() + ".intake-" + std::to_string(::getpid()) + "-" + std::to_string(serial++);
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      if (!out) throw std::runtime_error("cannot write " + tmp.string());
    }
    fs::rename(tmp, to, ec);
    if (ec) throw std::runtime_error("cannot write " + to.string() + ": " + ec.message());
  }
  // What the submission no longer holds goes (deepest first).
  std::vector<fs::path> gone;
  for (auto it = fs::recursive_directory_iterator(dest, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (!keep.count(it->path().lexically_normal())) gone.push_back(it->path());
  std::sort(gone.begin(), gone.end(), [](const fs::path& a, const fs::path& b) { return a.string() > b.string(); });
  for (const auto& p : gone) fs::remove_all(p, ec);
}

std::string read_stranger_file(const std::string& path, std::uint64_t cap) {
  const fs::path p(path);
  if (!p.has_filename()) throw RefusedEntry(path, "a folder, not a file");
  const std::string parent = p.has_parent_path() ? p.parent_path().string() : ".";
  Fd dir(::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.fd < 0) throw RefusedEntry(path, "its folder cannot be opened (" + std::string(std::strerror(errno)) + ")");
  return read_at(dir.fd, p.filename().string(), path, cap);
}

std::string bad_implementation_name(const std::string& name) {
  if (name.empty()) return "an empty name";
  if (name == "." || name == "..")
    return "the name '" + name + "' would name a folder above the report (rename the file)";
  if (name.size() > 100) return "a name longer than 100 bytes";
  if (name[0] == '-') return "a name starting with '-' (it would read as an option on a command line)";
  for (std::size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (c == '/' || c == '\\') return "a name holding a path separator";
    if (c < 0x20 || c == 0x7f) return "a name holding a control character (byte " + std::to_string(c) + ")";
  }
  // Valid UTF-8: a name is shown in every report.
  for (std::size_t i = 0; i < name.size();) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > name.size()) return "a name that is not valid UTF-8";
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(name[i + k]) >> 6) != 0x2) return "a name that is not valid UTF-8";
    i += n;
  }
  return {};
}

}  // namespace gm::harness
