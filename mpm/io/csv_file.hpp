/// \file
/// The one reader of text inputs (compare's CSV, the headers plot reads, particle files, times files), bounded:
/// regular files only, refused at once otherwise (`FILE: not a regular file`); lines of at most 1 MiB (LF or CR LF);
/// a UTF-8 byte-order mark skipped; blank and # lines skipped; errors as `FILE:LINE: ...`, never an exception.
/// One separator per file, told by the header line (csv_separator): a ';' or a ',' (not both), else a tab, else
/// runs of spaces; in a file not separated by commas a number with a decimal comma ('0,5') is refused, located.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace mpm::io {

/// The longest line the readers accept (1 MiB).
inline constexpr std::size_t longest_line = 1 << 20;

/// `text` without its leading and trailing spaces and tabs.
inline std::string trimmed(const std::string& text) {
  const auto start = text.find_first_not_of(" \t");
  return start == std::string::npos ? "" : text.substr(start, text.find_last_not_of(" \t") - start + 1);
}

/// The separator of a file whose header line is `header`: ';' or ',' when the line holds that one (both: '\0',
/// refused), else a tab when it holds one, else ' ' (runs of spaces and tabs; a header of one name reads alike).
inline char csv_separator(const std::string& header) {
  const bool semicolon = header.find(';') != std::string::npos, comma = header.find(',') != std::string::npos;
  if (semicolon && comma) return '\0';
  if (semicolon || comma) return semicolon ? ';' : ',';
  return header.find('\t') != std::string::npos ? '\t' : ' ';
}

/// Splits a line at `separator` (',', ';' or a tab; ' ' for runs of spaces and tabs); each field trimmed, and
/// of one pair of surrounding double quotes; a line ending in a ',', ';' or tab has an empty last field.
inline std::vector<std::string> csv_fields(const std::string& line, char separator = ',') {
  std::vector<std::string> fields;
  std::istringstream in(separator == ' ' ? line : line + separator);  // each field ends with a separator
  auto next = [&](std::string& field) {
    return static_cast<bool>(separator == ' ' ? in >> field : std::getline(in, field, separator));
  };
  for (std::string field; next(field);) {
    field = trimmed(field);
    if (field.size() >= 2 && field.front() == '"' && field.back() == '"') field = field.substr(1, field.size() - 2);
    fields.push_back(field);
  }
  return fields;
}

/// Reads the whole of `text` as a finite number into `value`. Returns "" or what is wrong, after the quoted text:
/// "is not a finite number" (a word, a unit after it, inf, nan), "is too large (beyond 1.8e308)" or "is too small
/// (below 2.2e-308 in magnitude, where doubles lose precision)" (strtod's ERANGE).
inline std::string read_finite_number(const std::string& text, double& value) {
  const std::string quoted = "'" + text + "' ";
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return quoted + "is not a finite number";
  char* end = nullptr;
  errno = 0;
  const double read = std::strtod(text.c_str(), &end);
  const bool out_of_range = errno == ERANGE;
  if (end != text.c_str() + text.size() || (!std::isfinite(read) && !out_of_range))
    return quoted + "is not a finite number";
  if (out_of_range && std::abs(read) > 1.0) return quoted + "is too large (beyond 1.8e308)";
  if (out_of_range) return quoted + "is too small (below 2.2e-308 in magnitude, where doubles lose precision)";
  value = read;
  return "";
}

/// True when `field` is a number written with a decimal comma ('0,5', '-1,25e3'): one comma, and a finite
/// number with a point in its place.
inline bool has_decimal_comma(std::string field) {
  const auto comma = field.find(',');
  if (comma == std::string::npos || field.find(',', comma + 1) != std::string::npos) return false;
  field[comma] = '.';
  double value = 0.0;
  return read_finite_number(field, value).empty();
}

/// Why the file of `status` (open as `descriptor`, or -1 when only the path was examined) is not a regular
/// file; "" if it is one.
inline std::string kind_refused(const struct stat& status, int descriptor) {
  struct statfs system {};
  if (S_ISDIR(status.st_mode)) return "is a folder, not a regular file; give a file";
  if (S_ISFIFO(status.st_mode)) return "not a regular file (a FIFO)";
  if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) return "not a regular file (a device)";
  if (!S_ISREG(status.st_mode)) return "not a regular file";
  if (descriptor < 0 || ::fstatfs(descriptor, &system) != 0) return "";
  const bool proc_or_sys = system.f_type == 0x9fa0 || system.f_type == 0x62656572;  // PROC_SUPER_MAGIC, SYSFS_MAGIC
  return proc_or_sys ? "not a regular file (a file of /proc or /sys)" : "";
}

/// Opens `path` for reading if it is a regular file, examined before it is opened (a FIFO is never waited on)
/// and again once open. Returns the descriptor, or -1 with `error` set to `PATH: why` and `missing` true when
/// the path names nothing.
inline int open_regular_file(const std::string& path, std::string& error, bool& missing) {
  const auto refuse = [&](const std::string& why) {
    error = path + ": " + why;
    return -1;
  };
  struct stat before {}, after {};
  if (::stat(path.c_str(), &before) != 0) {
    missing = errno == ENOENT;
    const bool absent = errno == ENOENT || errno == EACCES || errno == ENOTDIR;
    return refuse("cannot be read: " + std::string(absent ? "no such file, or no permission" : std::strerror(errno)));
  }
  if (const std::string why = kind_refused(before, -1); !why.empty()) return refuse(why);
  // O_NONBLOCK: should the path have become a FIFO since, opening it does not wait for a writer.
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (descriptor < 0) return refuse("cannot be read: " + std::string(std::strerror(errno)));
  const bool same = ::fstat(descriptor, &after) == 0 && after.st_ino == before.st_ino && after.st_dev == before.st_dev;
  const std::string why = same ? kind_refused(after, descriptor) : "changed while it was opened";
  if (why.empty()) return descriptor;
  ::close(descriptor);
  return refuse(why);
}

/// A text file read line by line, as the file's comment says. Every reading call returns false at the end of
/// the file or on a problem; error() then tells which ("" at the end), as `FILE: ...` or `FILE:LINE: ...`.
class CsvFile {
 public:
  explicit CsvFile(std::string path) : path_(std::move(path)) {
    descriptor_ = open_regular_file(path_, error_, missing_);
  }
  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;
  ~CsvFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }

  const std::string& error() const { return error_; }
  /// True when the path names nothing (so that an optional file can be told from an unreadable one).
  bool missing() const { return missing_; }
  /// The number of the line last read (1 = the first line of the file).
  int line() const { return number_; }
  /// "FILE:LINE: " of the line last read.
  std::string where() const { return path_ + ":" + std::to_string(number_) + ": "; }
  const std::vector<std::string>& header() const { return header_; }
  /// The separator read_header found (csv_separator): ',', ';', a tab, or ' ' for runs of spaces and tabs.
  char separator() const { return separator_; }

  /// The next line that is neither blank nor a # comment, trimmed of spaces and tabs.
  bool next_line(std::string& line) {
    while (raw_line(line)) {
      line = trimmed(line);
      if (!line.empty() && line[0] != '#') return true;
    }
    return false;
  }

  /// Reads the header (the fields of the first line that is neither blank nor a comment) and the file's
  /// separator from it (csv_separator); false on an empty file (error() empty) or a problem.
  bool read_header() {
    std::string line;
    if (!next_line(line)) return false;
    separator_ = csv_separator(line);
    if (separator_ == '\0') {
      error_ = where() + "the header holds both ',' and ';': separate the columns by one of them";
      return false;
    }
    header_ = csv_fields(line, separator_);
    return true;
  }

  /// The fields of the next data row, as many as the header's (`FILE:LINE: N fields; the header has M` else, with
  /// a hint at decimal commas when a comma-separated row has more); in a file not separated by commas, none a
  /// number with a decimal comma (`FILE:LINE: COLUMN: '0,5' has a decimal comma...`).
  bool next_row(std::vector<std::string>& fields) {
    std::string line;
    if (!next_line(line)) return false;
    fields = csv_fields(line, separator_);
    if (fields.size() != header_.size()) {
      error_ = where() + std::to_string(fields.size()) + " fields; the header has " + std::to_string(header_.size()) +
               (separator_ == ',' && fields.size() > header_.size() ? " (decimal commas? write 0.5, not 0,5)" : "");
      return false;
    }
    for (std::size_t k = 0; separator_ != ',' && k < fields.size(); ++k)
      if (has_decimal_comma(fields[k])) {
        error_ = where() + header_[k] + ": '" + fields[k] + "' has a decimal comma; write numbers with a decimal point";
        return false;
      }
    return true;
  }

 private:
  /// The next byte, or -1 at the end of the file or on a read error (error_ set).
  int next_byte() {
    if (position_ == buffer_.size()) {
      if (descriptor_ < 0 || !error_.empty()) return -1;
      buffer_.resize(1 << 16);
      ssize_t count = -1;
      do count = ::read(descriptor_, &buffer_[0], buffer_.size());
      while (count < 0 && errno == EINTR);
      if (count < 0) error_ = path_ + ": cannot be read: " + std::strerror(errno);
      buffer_.resize(count > 0 ? static_cast<std::size_t>(count) : 0);
      position_ = 0;
      if (count <= 0) return -1;
    }
    return static_cast<unsigned char>(buffer_[position_++]);
  }

  /// The next line of the file, without its end and (on line 1) without a byte-order mark.
  bool raw_line(std::string& line) {
    line.clear();
    if (!error_.empty()) return false;
    int byte = next_byte();
    if (byte < 0) return false;
    ++number_;
    for (; byte >= 0 && byte != '\n'; byte = next_byte()) {
      if (line.size() == longest_line) {
        error_ = where() + "a line longer than 1 MiB (is it a text file?)";
        return false;
      }
      line.push_back(static_cast<char>(byte));
    }
    if (!error_.empty()) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    return true;
  }

  std::string path_, error_;
  int descriptor_ = -1;
  bool missing_ = false;
  int number_ = 0;
  std::string buffer_;
  std::size_t position_ = 0;
  std::vector<std::string> header_;
  char separator_ = ',';
};

TEST_CASE("CsvFile: header and rows located, a BOM skipped, comments and blank lines skipped, a line too long refused") {
  namespace fs = std::filesystem;
  const std::string path =
      (fs::temp_directory_path() / ("mpm_csv_file_test_" + std::to_string(::getpid()) + ".csv")).string();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  REQUIRE(file);
  std::fputs("\xEF\xBB\xBFt, \"A v\" ,x,\r\n# a comment\n\n0,1,2,\n1,2\nlast", file);
  std::fclose(file);
  CsvFile csv(path);
  CHECK(csv.error().empty());
  REQUIRE(csv.read_header());
  CHECK(csv.header() == std::vector<std::string>{"t", "A v", "x", ""});  // the BOM gone, the CR gone
  std::vector<std::string> row;
  REQUIRE(csv.next_row(row));
  CHECK(csv.line() == 4);
  CHECK(row == std::vector<std::string>{"0", "1", "2", ""});
  CHECK(!csv.next_row(row));
  CHECK(csv.error() == path + ":5: 2 fields; the header has 4");
  CsvFile lines(path);
  std::string line;
  for (int k = 0; k < 4; ++k) REQUIRE(lines.next_line(line));
  CHECK(line == "last");  // the last line, without a newline
  CHECK(lines.line() == 6);
  CHECK(!lines.next_line(line));
  CHECK(lines.error().empty());  // the end, no problem
  file = std::fopen(path.c_str(), "wb");
  REQUIRE(file);
  std::fputs((std::string(longest_line, 'x') + "\nok\n").c_str(), file);  // 1 MiB exactly: taken
  std::fclose(file);
  CsvFile whole_line(path);
  CHECK(whole_line.next_line(line));
  CHECK(line.size() == longest_line);
  CHECK(whole_line.next_line(line));
  CHECK(line == "ok");
  file = std::fopen(path.c_str(), "wb");
  REQUIRE(file);
  std::fputs((std::string(longest_line + 1, 'x') + "\n").c_str(), file);  // a byte more: refused
  std::fclose(file);
  CsvFile long_line(path);
  CHECK(!long_line.next_line(line));
  CHECK(long_line.error() == path + ":1: a line longer than 1 MiB (is it a text file?)");
  fs::remove(path);
  CsvFile gone(path);
  CHECK(gone.missing());
  CHECK(gone.error() == path + ": cannot be read: no such file, or no permission");
  CHECK(!gone.next_line(line));
}

TEST_CASE("CsvFile: the separator told by the header (comma, semicolon, tab or spaces), decimal commas refused") {
  CHECK(csv_separator("t;v (m/s)") == ';');
  CHECK(csv_separator("t, v") == ',');
  CHECK(csv_separator("t\tA v") == '\t');
  CHECK(csv_separator("t  v") == ' ');
  CHECK(csv_separator("t") == ' ');
  CHECK(csv_separator("t;v,w") == '\0');
  CHECK(csv_separator("t;\tA v") == ';');  // a tab beside a ';' or ',' pads a field
  CHECK(csv_fields("0;\"1.5\" ; 2;", ';') == std::vector<std::string>{"0", "1.5", "2", ""});
  CHECK(csv_fields("0\t\t2", '\t') == std::vector<std::string>{"0", "", "2"});  // tabs: an empty field between
  CHECK(csv_fields("0 \t  1e-3   2", ' ') == std::vector<std::string>{"0", "1e-3", "2"});  // spaces: runs
  for (const char* number : {"0,5", "-1,25e3", ",5", "1,"}) CHECK_MESSAGE(has_decimal_comma(number), number);
  for (const char* text : {"0.5", "1,2,3", "a,b", "1,5 s", ""}) CHECK_MESSAGE(!has_decimal_comma(text), text);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("mpm_csv_separator_" + std::to_string(::getpid()) + ".csv")).string();
  const std::vector<std::pair<std::string, std::string>> files{
      {"t;v\n0;1.5\n1;2\n", ";"}, {"t\tv\n0\t1.5\n1\t2\n", "\t"}, {"  t   v\n0 1.5\n1\t 2\n", " "}};
  for (const auto& [text, separator] : files) {
    std::ofstream(path, std::ios::binary) << text;
    CsvFile csv(path);
    REQUIRE(csv.read_header());
    CHECK(csv.separator() == separator[0]);
    CHECK(csv.header() == std::vector<std::string>{"t", "v"});
    std::vector<std::string> row;
    REQUIRE(csv.next_row(row));
    CHECK(row == std::vector<std::string>{"0", "1.5"});
    REQUIRE(csv.next_row(row));
    CHECK(row == std::vector<std::string>{"1", "2"});
    CHECK((!csv.next_row(row) && csv.error().empty()));
  }
  const std::vector<std::pair<std::string, std::string>> refused{
      {"t;v\n0;1.5\n1;0,5\n", ":3: v: '0,5' has a decimal comma; write numbers with a decimal point"},
      {"t\tv\n0,5\t1\n", ":2: t: '0,5' has a decimal comma"},
      {"t,v\n0,1\n1,0,5\n", ":3: 3 fields; the header has 2 (decimal commas? write 0.5, not 0,5)"},
      {"t;v,w\n0;1\n", ":1: the header holds both ',' and ';'"}};
  for (const auto& [text, message] : refused) {
    std::ofstream(path, std::ios::binary) << text;
    CsvFile csv(path);
    std::vector<std::string> row;
    if (csv.read_header())
      while (csv.next_row(row)) {
      }
    CHECK_MESSAGE(csv.error().rfind(path + message, 0) == 0, csv.error());
  }
  std::filesystem::remove(path);
}

TEST_CASE("CsvFile: a folder, a FIFO, a device and a file of /proc are refused at once, never read") {
  namespace fs = std::filesystem;
  CHECK(CsvFile(fs::temp_directory_path().string()).error() == fs::temp_directory_path().string() + ": is a folder, not a regular file; give a file");
  const std::string fifo = (fs::temp_directory_path() / ("mpm_csv_file_fifo_" + std::to_string(::getpid()))).string();
  fs::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(CsvFile(fifo).error() == fifo + ": not a regular file (a FIFO)");  // and no wait for a writer
  fs::remove(fifo);
  CHECK(CsvFile("/dev/zero").error() == "/dev/zero: not a regular file (a device)");
  CHECK(CsvFile("/proc/self/mem").error() == "/proc/self/mem: not a regular file (a file of /proc or /sys)");
  CHECK(!CsvFile("/proc/self/mem").missing());
}

TEST_CASE("read_finite_number: the whole text, finite, and what is wrong said as it is") {
  double value = -1.0;
  CHECK(read_finite_number("1e-3", value).empty());
  CHECK(value == 1e-3);
  CHECK(read_finite_number("-2.5E+2", value).empty());
  CHECK(value == -250.0);
  CHECK(read_finite_number("0", value).empty());
  CHECK(value == 0.0);
  CHECK(read_finite_number("2.3e-308", value).empty());  // the smallest normal doubles are kept
  for (const char* word : {"", " 1", "1 ", "1e-3s", "heavy", "inf", "-inf", "nan", "1,5"})
    CHECK_MESSAGE(read_finite_number(word, value) == "'" + std::string(word) + "' is not a finite number", word);
  CHECK(read_finite_number("1e-320", value).rfind("'1e-320' is too small (below 2.2e-308", 0) == 0);  // subnormal, finite
  CHECK(read_finite_number("-1e-400", value).rfind("'-1e-400' is too small", 0) == 0);
  CHECK(read_finite_number("1e400", value) == "'1e400' is too large (beyond 1.8e308)");
  CHECK(read_finite_number("-1e400", value) == "'-1e400' is too large (beyond 1.8e308)");
  CHECK(value == 2.3e-308);  // never changed by a refused text
}

}  // namespace mpm::io
