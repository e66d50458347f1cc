#include "hil/estimator/datasets/text_line_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

namespace hil::estimator::datasets {

TextLineReader::TextLineReader(const std::string& path) : path_(path) {
  f_ = std::fopen(path.c_str(), "r");
  if (!f_) throw DatasetError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::setvbuf(f_, nullptr, _IOFBF, 1 << 18);  // a dataset is read in large blocks
}

TextLineReader::~TextLineReader() {
  if (f_) std::fclose(f_);
}

void TextLineReader::Fail(const std::string& what) const { throw DatasetError(path_, line_, what); }

bool TextLineReader::Next(std::string_view& line) {
  while (std::fgets(buf_, kBufferSize, f_)) {
    ++line_;
    std::size_t n = std::strlen(buf_);
    if (n == kBufferSize - 1 && buf_[n - 1] != '\n' && !std::feof(f_))
      Fail("line longer than " + std::to_string(kBufferSize - 2) + " characters");
    while (n > 0 && (buf_[n - 1] == '\n' || buf_[n - 1] == '\r')) --n;
    std::size_t i = 0;
    while (i < n && (buf_[i] == ' ' || buf_[i] == '\t')) ++i;
    if (i == n || buf_[i] == '#' || buf_[i] == '%') continue;
    line = std::string_view(buf_ + i, n - i);
    return true;
  }
  return false;
}

int TextLineReader::ParseNumbers(std::string_view line, double* out, int max,
                                 const char* const* field_names) const {
  const auto separator = [](char c) { return c == ' ' || c == '\t' || c == ','; };
  const char* p = line.data();
  const char* const end = line.data() + line.size();
  int count = 0;
  while (count < max) {
    while (p < end && separator(*p)) ++p;
    if (p == end) break;
    const char* start = p;
    double v = 0;
    // from_chars does not take a leading '+'; it stops where the number ends, which must be a
    // separator or the line's end (one pass over the text: no separate scan for the field's end)
    const char* num = (*start == '+') ? start + 1 : start;
    const auto [ptr, ec] = std::from_chars(num, end, v);
    const bool whole = ec == std::errc() && (ptr == end || separator(*ptr));
    if (!whole || !std::isfinite(v)) {
      while (p < end && !separator(*p)) ++p;
      const std::string field =
          field_names ? std::string(field_names[count]) : "column " + std::to_string(count + 1);
      Fail(field + (whole ? ": not finite: '" : ": not a number: '") + std::string(start, p) + "'");
    }
    p = ptr;
    out[count++] = v;
  }
  return count;
}

}  // namespace hil::estimator::datasets
