/// \file
/// Reading a text file line by line with a bound on the line's length, so that a hostile input (a file
/// without newlines, /dev/zero) ends in a located error instead of filling the memory.
#pragma once
#include <doctest/doctest.h>

#include <istream>
#include <sstream>
#include <string>

namespace mpm::io {

/// The longest line the CSV readers accept (1 MiB).
inline constexpr std::size_t longest_line = 1 << 20;

/// Reads the next line of `in` into `line` (without its line end, LF or CR LF); false at the end of the input or when
/// the line exceeds `most` characters (`too_long` then set).
inline bool read_line(std::istream& in, std::string& line, bool& too_long, std::size_t most = longest_line) {
  line.clear();
  too_long = false;
  std::streambuf* buffer = in.rdbuf();
  for (int character = buffer->sbumpc(); ; character = buffer->sbumpc()) {
    if (character == std::char_traits<char>::eof()) {
      if (line.empty()) in.setstate(std::ios::eofbit);
      break;
    }
    if (character == '\n') break;
    if (line.size() == most) {
      too_long = true;
      return false;
    }
    line.push_back(static_cast<char>(character));
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return !(in.eof() && line.empty());
}

TEST_CASE("read_line: lines without their ends, the last without a newline, and a line too long") {
  std::istringstream text("a,b\r\nc\n\nlast");
  std::string line;
  bool too_long = false;
  CHECK(read_line(text, line, too_long));
  CHECK(line == "a,b");
  CHECK(read_line(text, line, too_long));
  CHECK(line == "c");
  CHECK(read_line(text, line, too_long));
  CHECK(line.empty());
  CHECK(read_line(text, line, too_long));
  CHECK(line == "last");
  CHECK(!read_line(text, line, too_long));
  CHECK(!too_long);
  std::istringstream endless(std::string(100, 'x'));
  CHECK(!read_line(endless, line, too_long, 10));
  CHECK(too_long);
}

}  // namespace mpm::io
