// Copyright (c) 2026 CGAL_ext contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Writing a file so that it is never lost: the data goes to a temporary file
// beside the target, which is flushed to the disk and then renamed over the
// target. A failed or interrupted write leaves the old file as it was (and,
// for a killed process, a temporary file beside it, never a half target).

#ifndef CGAL_EXT_IO_INTERNAL_ATOMIC_OUTPUT_FILE_H
#define CGAL_EXT_IO_INTERNAL_ATOMIC_OUTPUT_FILE_H

#include <CGAL_ext/exceptions.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#define CGAL_EXT_POSIX_FILES 1
#endif

namespace CGAL_ext {
namespace IO {
namespace internal {

// ": <strerror(errno)>" if errno is set, else nothing.
inline std::string errno_reason()
{
  return errno != 0 ? std::string(": ") + std::strerror(errno) : std::string();
}

// The directory part of `filename` ("." if it has none).
inline std::string directory_of(const std::string& filename)
{
  const std::string::size_type slash = filename.find_last_of('/');
  if (slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : filename.substr(0, slash);
}

/// Refuses, before any work, an output path that cannot be written: a
/// directory, or a file in a directory that does not exist or that this
/// process cannot write in. Throws `IO_error` naming the file.
inline void check_output_path(const std::string& filename)
{
  if (filename.empty())
    throw IO_error(filename, 0, "the output file name is empty");
#ifdef CGAL_EXT_POSIX_FILES
  struct stat st;
  if (::stat(filename.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw IO_error(filename, 0, "the output path is a directory");
  const std::string dir = directory_of(filename);
  errno = 0;
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw IO_error(filename, 0, "the output directory " + dir + " does not exist" + errno_reason());
  errno = 0;
  if (::access(dir.c_str(), W_OK) != 0)
    throw IO_error(filename, 0, "the output directory " + dir + " is not writable" + errno_reason());
#endif
}

/// A file written in full or not at all. `stream()` writes to a temporary
/// file beside `target`; `commit()` flushes it to the disk (`fsync`) and
/// renames it over `target`, so that readers see the old file or the new one,
/// never a part. Without `commit()` (an exception, a failed write) the
/// destructor removes the temporary file and `target` is untouched.
class Atomic_output_file
{
public:
  /// Opens a temporary file beside `target`; throws `IO_error` if it cannot.
  Atomic_output_file(const std::string& target, std::ios::openmode mode) : target_(target)
  {
    check_output_path(target);
    open_temporary(mode);
  }
  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;
  ~Atomic_output_file()
  {
    if (!committed_) {
      out_.close();
      std::remove(temporary_.c_str());
    }
  }

  /// The stream to write to.
  std::ofstream& stream() { return out_; }
  /// The temporary file's name.
  const std::string& temporary_name() const { return temporary_; }

  /// Makes the written data the target's: throws `IO_error` (and leaves the
  /// target as it was) if a write failed, the data cannot be flushed to the
  /// disk, or the rename fails.
  void commit()
  {
    errno = 0;
    out_.flush();
    if (!out_)
      throw IO_error(target_, 0, "writing the file failed" + errno_reason() + "; the old file is unchanged");
    out_.close();
    if (out_.fail())
      throw IO_error(target_, 0, "closing the file failed" + errno_reason() + "; the old file is unchanged");
    sync(temporary_, false);
    errno = 0;
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
      throw IO_error(target_, 0, "renaming the written file over it failed" + errno_reason() +
                                   "; the old file is unchanged");
    committed_ = true;
    // The rename itself is durable once the directory is synced; a failure
    // here loses nothing that the rename did not already show.
    sync(directory_of(target_), true);
  }

private:
  void open_temporary(std::ios::openmode mode)
  {
    const std::string dir = directory_of(target_);
    const std::string base = target_.substr(target_.find_last_of('/') == std::string::npos
                                              ? 0
                                              : target_.find_last_of('/') + 1);
#ifdef CGAL_EXT_POSIX_FILES
    std::string pattern = (dir == "/" ? "" : dir) + "/." + base + ".tmp.XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    errno = 0;
    const int fd = ::mkstemp(name.data());
    if (fd < 0)
      throw IO_error(target_, 0, "cannot create a temporary file in " + dir + errno_reason());
    // mkstemp() makes the file private (0600): give it the mode the target
    // has, or the one a new file would get.
    struct stat st;
    mode_t file_mode;
    if (::stat(target_.c_str(), &st) == 0) {
      file_mode = st.st_mode & 07777;
    } else {
      const mode_t mask = ::umask(0);
      ::umask(mask);
      file_mode = 0666 & ~mask;
    }
    ::fchmod(fd, file_mode);
    ::close(fd);
    temporary_ = name.data();
#else
    temporary_ = target_ + ".tmp";
#endif
    errno = 0;
    out_.open(temporary_, mode | std::ios::out | std::ios::trunc);
    if (!out_) {
      const std::string reason = errno_reason();
      std::remove(temporary_.c_str());
      throw IO_error(target_, 0, "cannot open a temporary file for writing" + reason);
    }
  }

  // Flushes `path` (a file, or a directory) to the disk.
  void sync(const std::string& path, bool directory) const
  {
#ifdef CGAL_EXT_POSIX_FILES
    errno = 0;
    const int fd = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
    if (fd < 0) {
      if (!directory)
        throw IO_error(target_, 0, "cannot reopen the written file to flush it" + errno_reason());
      return;
    }
    const bool ok = ::fsync(fd) == 0 || directory; // some file systems refuse fsync on directories
    const std::string reason = errno_reason();
    ::close(fd);
    if (!ok)
      throw IO_error(target_, 0, "flushing the file to the disk failed" + reason + "; the old file is unchanged");
#else
    (void)path;
    (void)directory;
#endif
  }

  std::string target_;
  std::string temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

} // namespace internal
} // namespace IO
} // namespace CGAL_ext

#endif // CGAL_EXT_IO_INTERNAL_ATOMIC_OUTPUT_FILE_H
