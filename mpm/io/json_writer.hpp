/// \file
/// The one JSON writer of the command (run.json and the resolved scene in it): objects and arrays
/// written as they are opened and closed, strings escaped, and numbers that JSON cannot hold (inf,
/// NaN) written as null. Members of the outermost object go one per line, everything nested on one line.
#pragma once
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace mpm::io {

/// The length of the valid UTF-8 sequence at text[at] (1 to 4), or 0 if none starts there.
inline std::size_t utf8_length(const std::string& text, std::size_t at) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(at);
  const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 && lead >= 0xc2 ? 2 : (lead >> 4) == 0xe ? 3 : lead >= 0xf0 && lead <= 0xf4 ? 4 : 0;
  if (length == 0 || at + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(at + k) >> 6) != 0x2) return 0;
  return length;
}

/// `text` as a JSON string, quoted and escaped; a byte that is not UTF-8 (a path's 0xff) as U+FFFD, so the
/// document stays valid JSON.
inline std::string json_string(const std::string& text) {
  std::string json = "\"";
  for (std::size_t at = 0; at < text.size(); ++at) {
    const std::size_t length = utf8_length(text, at);
    if (length != 1) {
      json += length == 0 ? std::string("\\ufffd") : text.substr(at, length);
      at += length == 0 ? 0 : length - 1;
      continue;
    }
    const unsigned char character = static_cast<unsigned char>(text[at]);
    if (character == '"' || character == '\\') json += std::string("\\") + static_cast<char>(character);
    else if (character == '\n') json += "\\n";
    else if (character < 0x20 || character == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", character);
      json += escaped;
    } else json += static_cast<char>(character);
  }
  return json + "\"";
}

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& key(const std::string& name) {
    separate();
    out_ << json_string(name) << ": ";
    after_key_ = true;
    return *this;
  }
  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }
  JsonWriter& value(const std::string& text) { return raw(json_string(text)); }
  JsonWriter& value(const char* text) { return value(std::string(text)); }
  JsonWriter& value(bool flag) { return raw(flag ? "true" : "false"); }
  JsonWriter& value(long number) { return raw(std::to_string(number)); }
  JsonWriter& value(int number) { return value(static_cast<long>(number)); }
  /// A double to 12 significant digits (the precision of the run's CSV files); null if not finite.
  JsonWriter& value(double number) {
    if (!std::isfinite(number)) return raw("null");
    std::ostringstream text;
    text.precision(12);
    text << number;
    return raw(text.str());
  }
  template <class T>
  JsonWriter& array(const std::vector<T>& values) {
    begin_array();
    for (const T& entry : values) value(entry);
    return end_array();
  }
  /// A value already in JSON (a document another writer made, e.g. toml++'s).
  JsonWriter& raw(const std::string& json) {
    separate();
    out_ << json;
    return *this;
  }

 private:
  /// Writes what must come before a value or key: a comma after a sibling, a line break at the top level.
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_.empty()) {
      if (!first_.back()) out_ << ",";
      first_.back() = false;
      if (first_.size() == 1) out_ << "\n  ";
      else if (!opened_) out_ << " ";
    }
    opened_ = false;
  }
  JsonWriter& open(char bracket) {
    separate();
    out_ << bracket;
    first_.push_back(true);
    opened_ = true;
    return *this;
  }
  JsonWriter& close(char bracket) {
    const bool top = first_.size() == 1, empty = first_.back();
    first_.pop_back();
    if (top && !empty) out_ << "\n";
    out_ << bracket;
    if (first_.empty()) out_ << "\n";
    opened_ = false;
    return *this;
  }
  std::ostream& out_;
  std::vector<bool> first_;  ///< per open container: no member written yet
  bool after_key_ = false, opened_ = false;
};

TEST_CASE("JsonWriter: nesting, separators, escapes and numbers JSON cannot hold") {
  CHECK(json_string("failed: \"x\"\n\\") == "\"failed: \\\"x\\\"\\n\\\\\"");
  CHECK(json_string(std::string("a\tb")) == "\"a\\u0009b\"");
  CHECK(json_string("jl\xff") == "\"jl\\ufffd\"");                     // not UTF-8
  CHECK(json_string("\xc3\xa9t\xc3") == "\"\xc3\xa9t\\ufffd\"");  // kept, and a sequence cut short
  std::ostringstream out;
  JsonWriter json(out);
  json.begin_object().key("status").value("done").key("steps").value(12L).key("dt").value(1.0 / 0.0);
  json.key("x").array(std::vector<double>{0.5, 1e-300, std::nan("")}).key("o").begin_object().key("a").value(true);
  json.key("b").begin_array().end_array().end_object().key("empty").begin_object().end_object().end_object();
  CHECK(out.str() ==
        "{\n  \"status\": \"done\",\n  \"steps\": 12,\n  \"dt\": null,\n  \"x\": [0.5, 1e-300, null],\n"
        "  \"o\": {\"a\": true, \"b\": []},\n  \"empty\": {}\n}\n");
}

}  // namespace mpm::io
