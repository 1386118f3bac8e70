/// \file
/// The one checked writer: every file `mpm` writes goes through OutputFile, opened with O_NOFOLLOW (never written
/// through a symbolic link), every write, flush and close checked. An atomic OutputFile writes a hidden temporary
/// and renames it over the file at close(): a reader, or a run killed half-way, sees the old file or the new one.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/resource.h>
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

/// An output file: a std::ostream (its own buffer, writing to a descriptor) whose every failure raises
/// OutputFailure(path) at the latest at close().
class OutputFile : private std::streambuf, public std::ostream {
 public:
  enum class Mode { direct, atomic };

  /// Creates (or truncates) `path`. \throws OutputFailure if it cannot be opened, or is a symbolic link.
  explicit OutputFile(std::string path, Mode mode = Mode::direct)
      : std::ostream(static_cast<std::streambuf*>(this)), path_(std::move(path)),
        written_path_(mode == Mode::atomic ? temporary_path(path_) : path_) {
    if (mode == Mode::atomic) ::unlink(written_path_.c_str());  // a stale temporary of a killed run, or a link
    descriptor_ = ::open(written_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (descriptor_ < 0 && errno == ELOOP)
      throw OutputFailure(path_, "it is a symbolic link (mpm writes through no link)");
    if (descriptor_ < 0) throw OutputFailure(path_, std::strerror(errno));
    setp(buffer_, buffer_ + sizeof buffer_);
    precision(12);
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// An unfinished file (an exception on the way): a direct file keeps what it was given (a failed run keeps its
  /// history up to the failure), an atomic file's temporary is removed.
  ~OutputFile() override {
    if (!closed_ && written_path_ == path_) flush();
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!closed_ && written_path_ != path_) ::unlink(written_path_.c_str());
  }

  /// Raises the first write error so far. \throws OutputFailure.
  void check() {
    if (error_ != 0 || fail()) throw OutputFailure(path_, std::strerror(error_ != 0 ? error_ : EIO));
  }

  /// Flushes, closes and (atomic) renames into place. \throws OutputFailure if any of it failed.
  void close() {
    if (closed_) return;
    flush();
    check();
    closed_ = true;
    const int descriptor = descriptor_;
    descriptor_ = -1;
    if (::close(descriptor) == 0 && (written_path_ == path_ || std::rename(written_path_.c_str(), path_.c_str()) == 0))
      return;
    const int error = errno;
    if (written_path_ != path_) ::unlink(written_path_.c_str());
    throw OutputFailure(path_, std::strerror(error));
  }

  /// The hidden temporary of an atomic write: ".NAME.partial" beside NAME.
  static std::string temporary_path(const std::string& path) {
    const std::filesystem::path file(path);
    return (file.parent_path() / ("." + file.filename().string() + ".partial")).string();
  }

 private:
  using traits = std::streambuf::traits_type;
  std::streambuf::int_type overflow(std::streambuf::int_type character) override {
    if (!drain()) return traits::eof();
    if (!traits::eq_int_type(character, traits::eof())) sputc(traits::to_char_type(character));
    return traits::not_eof(character);
  }
  int sync() override { return drain() ? 0 : -1; }

  /// Writes the buffer out; false, and error_ the first errno, if the file took less than all of it.
  bool drain() {
    const char* next = pbase();
    while (next < pptr()) {
      const ssize_t written = ::write(descriptor_, next, static_cast<size_t>(pptr() - next));
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) {
        if (error_ == 0) error_ = written < 0 ? errno : EIO;
        break;
      }
      next += written;
    }
    const bool whole = next == pptr();
    setp(buffer_, buffer_ + sizeof buffer_);
    return whole;
  }

  char buffer_[1 << 16];
  std::string path_, written_path_;
  int descriptor_ = -1, error_ = 0;
  bool closed_ = false;
};

/// Writes `text` into `path` whole (atomically). \throws OutputFailure.
inline void write_file(const std::string& path, const std::string& text) {
  OutputFile out(path, OutputFile::Mode::atomic);
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
