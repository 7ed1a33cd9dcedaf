// Reading a stranger's folder: a class folder, a submission handed in by someone else.
//
// The harness runs outside the sandbox, often as root, and a class folder comes from archives that
// restore symbolic links, FIFOs and hard links. So every read of a submission goes through here:
//   - every path is opened relative to a folder the lecturer named, one component at a time, with
//     O_NOFOLLOW: no symbolic link is followed, at any depth, not even to look at what it names;
//   - only regular files with one name (a hard link could be a second name of a root-only file)
//     and folders are read; a FIFO, socket or device is never opened (a FIFO would block the
//     harness, /dev/zero would read without end), and the entry is refused by its kind;
//   - every file is opened O_NONBLOCK and checked again after opening (the entry may have been
//     swapped between the look and the open), and read up to a cap; a submission is read within
//     limits of size, entries and depth.
// What is refused is said per student (the submission is NOT CHECKED, naming the file); nothing
// of a refused entry is read, copied or shown.
//
// Class mode takes a snapshot of each submission (SubmissionTree) into a folder of the harness (in
// the compilers' cache) and checks that: the fingerprint, the private copy, the compiler's inputs and the check all see the
// same bytes, and a C++ file in a flat class folder sees only itself (and the headers the lecturer
// shares on purpose, --shared), never a classmate's header.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gm::harness {

struct IntakeLimits {
  std::uint64_t file_bytes = 8u << 20;  // one file
  // A program built from a submission in the sandbox (a C++ file's protocol server): the suite's code
  // linked with theirs, about 9 MiB of it the suite's. Read as a stranger's file, within this.
  std::uint64_t program_bytes = 64u << 20;
  std::uint64_t total_bytes = 32u << 20;  // one submission, all files
  std::size_t entries = 512;              // files and folders in one submission
  int depth = 6;                          // folders within folders
};

// An entry of a submission that is not taken: where (relative to the folder read) and why.
class RefusedEntry : public std::runtime_error {
 public:
  RefusedEntry(std::string path, std::string why)
      : std::runtime_error(path + ": " + why), path_(std::move(path)), why_(std::move(why)) {}
  const std::string& path() const { return path_; }
  const std::string& why() const { return why_; }

 private:
  std::string path_, why_;
};

enum class EntryKind { File, Folder, Link, Fifo, Socket, Device, Other };

// "a symbolic link", "a FIFO (named pipe)", ...: what an entry that is not taken is, in words.
std::string describe(EntryKind k);

// A folder the lecturer named (trusted as a starting point: opened as given), whose entries are
// strangers' (never followed).
class StrangerFolder {
 public:
  // Throws std::runtime_error when the folder cannot be opened.
  explicit StrangerFolder(const std::string& path);
  ~StrangerFolder();
  StrangerFolder(const StrangerFolder&) = delete;
  StrangerFolder& operator=(const StrangerFolder&) = delete;

  struct Entry {
    std::string name;
    EntryKind kind = EntryKind::Other;
    std::uint64_t size = 0;
    std::uint64_t links = 1;  // hard links (names) of a file
  };
  // The entries of the sub-folder `rel` ("" for the folder itself), sorted by name, seen without
  // following anything (lstat). Throws RefusedEntry when a component of `rel` is not a folder.
  std::vector<Entry> list(const std::string& rel = "") const;
  // The kind of one entry, without following it.
  Entry look(const std::string& rel) const;
  // The bytes of the regular file `rel`, at most `cap` of them. Throws RefusedEntry for anything
  // else (a link, a FIFO, a device, a file with more than one name, a file larger than the cap).
  std::string read(const std::string& rel, std::uint64_t cap) const;

  const std::string& path() const { return path_; }

 private:
  int open_parent(const std::string& rel, std::string* leaf) const;  // the folder holding rel's last component
  std::string path_;
  int fd_ = -1;
};

// A submission's files, read safely: relative paths ("bob.py", "src/x.hpp") and their bytes,
// sorted by path. Folders are implied by the paths; an empty folder is not kept.
struct SubmissionTree {
  std::vector<std::pair<std::string, std::string>> files;
  std::uint64_t bytes() const;
};

// Reads the file or folder `rel` beneath `from`, within `limits`. Entries whose name starts with a
// dot and __pycache__ folders are left out (a .git folder, editor files: not part of what is
// checked, and never opened). Throws RefusedEntry for the first entry that is a link, a FIFO, a
// socket, a device, a file with several names, or beyond a limit.
SubmissionTree read_submission(const StrangerFolder& from, const std::string& rel, const IntakeLimits& limits = {});

// Writes `tree` into the folder `dest` (created; a folder of the harness): a file whose bytes are
// unchanged is not rewritten (its time stays, so a compiled submission is not compiled again), a
// file no longer in the tree is removed. Throws std::runtime_error.
void write_tree(const SubmissionTree& tree, const std::filesystem::path& dest);

// Reads one file that a stranger may control (`geomech check FILE --untrusted`, a header beside
// it): the folder holding it is opened as given, the file itself never followed, never blocked
// on, and read only when it is a regular file with one name, up to `cap` bytes. Throws RefusedEntry
// (path: the file as given).
std::string read_stranger_file(const std::string& path, std::uint64_t cap = IntakeLimits{}.file_bytes);

// Why `name` cannot name an implementation (a report folder, a gradebook row), or empty: it must
// not be empty, "." or "..", start with '-', nor hold a path separator, a control character or
// invalid UTF-8, and at most 100 bytes long.
std::string bad_implementation_name(const std::string& name);

}  // namespace gm::harness
