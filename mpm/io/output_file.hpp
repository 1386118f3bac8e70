/// \file
/// The one checked writer of the command: every file `mpm` writes goes through OutputFile.
///
/// - It is opened with O_NOFOLLOW: a symbolic link where the file should be is refused, never written
///   through (a link planted in an output folder cannot redirect a write elsewhere).
/// - Every write() is checked, and so are the last flush and the close: a full disk, a quota or a file
///   size limit raises OutputFailure naming the file, never a silent short file.
/// - OutputFile::atomic writes into a hidden temporary beside the file and renames it over the file at
///   close(): a reader (or a run killed half-way) sees the old file or the whole new one, never a part.
///   run.json and snapshots.pvd are written so.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <streambuf>
#include <string>

#include "mpm/core/errors.hpp"

namespace mpm::io {

/// A stream buffer writing to a file descriptor, remembering the first failed write's errno.
class DescriptorBuffer : public std::streambuf {
 public:
  void attach(int descriptor) { descriptor_ = descriptor, setp(buffer_, buffer_ + sizeof buffer_); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type character) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(character, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(character);
      pbump(1);
    }
    return traits_type::not_eof(character);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  /// Writes the buffer out; false (and error_ set) if the descriptor took less than all of it.
  bool drain() {
    for (const char* next = pbase(); next < pptr();) {
      const ssize_t written = descriptor_ < 0 ? -1 : ::write(descriptor_, next, static_cast<size_t>(pptr() - next));
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) {
        if (error_ == 0) error_ = written < 0 ? errno : EIO;
        setp(buffer_, buffer_ + sizeof buffer_);
        return false;
      }
      next += written;
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return true;
  }
  char buffer_[1 << 16];
  int descriptor_ = -1;
  int error_ = 0;
};

/// An output file: a std::ostream whose every failure raises OutputFailure(path) at the latest at close().
class OutputFile : public std::ostream {
 public:
  enum class Mode { direct, atomic };

  /// Creates (or truncates) `path`. \throws OutputFailure if it cannot be opened, or is a symbolic link.
  explicit OutputFile(std::string path, Mode mode = Mode::direct) : std::ostream(&buffer_), path_(std::move(path)) {
    written_path_ = mode == Mode::atomic ? temporary_path(path_) : path_;
    if (mode == Mode::atomic) ::unlink(written_path_.c_str());  // a stale temporary of a killed run, or a link
    descriptor_ = ::open(written_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (descriptor_ < 0)
      throw OutputFailure(path_, errno == ELOOP ? "it is a symbolic link (mpm writes through no link)" : std::strerror(errno));
    buffer_.attach(descriptor_);
    precision(12);
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// An unfinished file (an exception on the way): what it holds is written out (a failed run keeps its
  /// history up to the failure), an atomic file's temporary removed.
  ~OutputFile() override {  // a failed close() leaves closed_ false: the temporary is removed here
    if (!closed_ && written_path_ == path_) flush();
    if (descriptor_ >= 0) ::close(descriptor_);
    if (written_path_ != path_ && !closed_) ::unlink(written_path_.c_str());
  }

  const std::string& path() const { return path_; }

  /// Raises the first write error so far. \throws OutputFailure.
  void check() {
    if (buffer_.error() != 0 || fail()) throw OutputFailure(path_, std::strerror(buffer_.error() != 0 ? buffer_.error() : EIO));
  }

  /// Flushes, closes and (atomic) renames into place. \throws OutputFailure if any of it failed.
  void close() {
    if (closed_) return;
    flush();
    check();
    closed_ = true;
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (::close(descriptor) != 0) {
      const int error = errno;
      if (written_path_ != path_) ::unlink(written_path_.c_str());
      throw OutputFailure(path_, std::strerror(error));
    }
    if (written_path_ != path_ && std::rename(written_path_.c_str(), path_.c_str()) != 0) {
      const int error = errno;
      ::unlink(written_path_.c_str());
      throw OutputFailure(path_, std::strerror(error));
    }
  }

  /// The hidden temporary of an atomic write: ".NAME.partial" beside NAME.
  static std::string temporary_path(const std::string& path) {
    const std::filesystem::path file(path);
    return (file.parent_path() / ("." + file.filename().string() + ".partial")).string();
  }

 private:
  DescriptorBuffer buffer_;
  std::string path_, written_path_;
  int descriptor_ = -1;
  bool closed_ = false;
};

/// Writes `text` into `path` whole (atomically). \throws OutputFailure.
inline void write_file(const std::string& path, const std::string& text, OutputFile::Mode mode = OutputFile::Mode::atomic) {
  OutputFile out(path, mode);
  out << text;
  out.close();
}

TEST_CASE("OutputFile: a write error, a link and an atomic replacement") {
  namespace fs = std::filesystem;
  const fs::path folder = fs::temp_directory_path() / ("mpm_output_file_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string file = (folder / "a.csv").string(), link = (folder / "link.csv").string();
  {
    OutputFile out(file);
    out << "t\n" << 0.5 << "\n";
    out.close();
  }
  std::FILE* in = std::fopen(file.c_str(), "r");
  char text[16] = {};
  CHECK(std::fread(text, 1, sizeof text - 1, in) == 6);
  std::fclose(in);
  CHECK(std::string(text) == "t\n0.5\n");
  fs::create_symlink(file, link);
  CHECK_THROWS_WITH_AS(OutputFile{link}, doctest::Contains("symbolic link"), OutputFailure);
  CHECK(fs::file_size(file) == 6);  // the link's target untouched
  write_file(link, "new\n");        // atomic: the link itself replaced by a file, its target untouched
  CHECK(!fs::is_symlink(link));
  CHECK(fs::file_size(link) == 4);
  CHECK(fs::file_size(file) == 6);
  CHECK(!fs::exists(OutputFile::temporary_path(link)));
  {
    OutputFile unfinished(file), unfinished_atomic(link, OutputFile::Mode::atomic);
    unfinished << "kept\n";
    unfinished_atomic << "dropped\n";
  }
  CHECK(fs::file_size(file) == 5);  // a direct file keeps what was written before it was left unclosed
  CHECK(fs::file_size(link) == 4);  // an atomic one is the old file until close()
  CHECK(!fs::exists(OutputFile::temporary_path(link)));
  if (::access("/dev/full", W_OK) == 0) {  // a full disk shows at the latest when the buffer is written
    OutputFile full("/dev/full");
    full << std::string(100, 'x');
    CHECK_THROWS_WITH_AS(full.close(), doctest::Contains("No space left"), OutputFailure);
  }
  struct rlimit limit {}, small {};  // a file size limit: the atomic file fails at close(), its temporary removed
  ::getrlimit(RLIMIT_FSIZE, &limit);
  small = limit;
  small.rlim_cur = 1000;
  void (*previous)(int) = std::signal(SIGXFSZ, SIG_IGN);
  if (::setrlimit(RLIMIT_FSIZE, &small) == 0) {
    {
      OutputFile big((folder / "big.json").string(), OutputFile::Mode::atomic);
      big << std::string(5000, 'x');
      CHECK_THROWS_WITH_AS(big.close(), doctest::Contains("too large"), OutputFailure);
    }
    ::setrlimit(RLIMIT_FSIZE, &limit);
    CHECK(!fs::exists(folder / "big.json"));
    CHECK(!fs::exists(OutputFile::temporary_path((folder / "big.json").string())));
  }
  std::signal(SIGXFSZ, previous);
  fs::remove_all(folder);
}

}  // namespace mpm::io
