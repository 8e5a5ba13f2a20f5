// CSV time-series writer and reader; format in csv_writer.h.
#include "io/csv_writer.h"

#include <filesystem>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace slamsph {
namespace {

void put_number(std::string& out, double v) {
  if (std::isnan(v)) {
    out += "nan";
    return;
  }
  if (std::isinf(v)) {
    out += v > 0 ? "inf" : "-inf";
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// The environment refused (no such folder, permission, disk full): std::system_error with
// the OS reason, which the command line reports as exit 4. iostreams keep errno from the
// failing system call.
[[noreturn]] void throw_os_error(const std::string& what) {
  throw std::system_error(errno ? errno : EIO, std::generic_category(), what);
}

std::string quote_if_needed(const std::string& h) {
  if (h.find_first_of(",\"\n\r") == std::string::npos) return h;
  std::string r = "\"";
  for (char c : h) {
    if (c == '"') r += '"';
    r += c;
  }
  return r + "\"";
}

// Splits one CSV line into fields, honouring "..." quoting with "" escapes.
std::vector<std::string> split_line(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace

bool csv_header_has_unit(const std::string& header) {
  const std::string h = trim(header);
  if (h.size() < 3 || h.back() != ']') return false;
  const auto open = h.rfind('[');
  return open != std::string::npos && open + 2 < h.size();  // at least one char inside
}

CsvWriter::CsvWriter(std::string path, std::vector<std::string> headers, Resume at)
    : CsvWriter(std::move(path), std::move(headers), 256, 2.0, at) {}

CsvWriter::CsvWriter(std::string path, std::vector<std::string> headers, std::size_t flush_rows,
                     double flush_seconds, std::optional<Resume> resume)
    : resume_(resume),
      path_(std::move(path)),
      headers_(std::move(headers)),
      flush_rows_(flush_rows == 0 ? 1 : flush_rows),
      flush_seconds_(flush_seconds),
      last_flush_(std::chrono::steady_clock::now()) {
  if (headers_.empty()) throw std::invalid_argument("CsvWriter " + path_ + ": no columns");
  for (std::size_t i = 0; i < headers_.size(); ++i) {
    if (!csv_header_has_unit(headers_[i]))
      throw std::invalid_argument("CsvWriter " + path_ + ": header '" + headers_[i] +
                                  "' has no unit (write e.g. \"time [s]\" or \"Z [-]\")");
    for (std::size_t j = 0; j < i; ++j)
      if (headers_[j] == headers_[i])
        throw std::invalid_argument("CsvWriter " + path_ + ": duplicate header '" + headers_[i] +
                                    "'");
  }
  if (resume_) {
    // Continue a file this writer wrote before (resume from a checkpoint): drop what was
    // written after the checkpoint, then append.
    std::error_code ec;
    std::filesystem::resize_file(path_, resume_->bytes, ec);
    if (ec) throw std::system_error(ec, "cannot truncate " + path_);
    errno = 0;
    out_.open(path_, std::ios::out | std::ios::app | std::ios::binary);
    if (!out_) throw_os_error("cannot open " + path_ + " for writing");
    rows_ = resume_->rows;
    return;
  }
  errno = 0;
  out_.open(path_, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out_) throw_os_error("cannot open " + path_ + " for writing");
  std::string line;
  for (std::size_t i = 0; i < headers_.size(); ++i) {
    if (i) line += ',';
    line += quote_if_needed(headers_[i]);
  }
  line += '\n';
  out_ << line;
  flush();
}

CsvWriter::~CsvWriter() {
  if (out_.is_open()) out_.flush();  // errors were reported by flush() calls before
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != headers_.size())
    throw std::invalid_argument("CsvWriter " + path_ + ": row of " + std::to_string(values.size()) +
                                " values for " + std::to_string(headers_.size()) + " columns");
  std::string line;
  line.reserve(values.size() * 24);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) line += ',';
    put_number(line, values[i]);
  }
  line += '\n';
  out_ << line;
  ++rows_;
  ++rows_since_flush_;
  if (rows_since_flush_ >= flush_rows_) {
    flush();
  } else {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_flush_).count() >= flush_seconds_) flush();
  }
}

void CsvWriter::flush() {
  errno = 0;
  out_.flush();
  if (!out_) throw_os_error("cannot write " + path_);
  rows_since_flush_ = 0;
  last_flush_ = std::chrono::steady_clock::now();
}

int CsvTable::find(const std::string& name) const {
  for (std::size_t i = 0; i < headers.size(); ++i)
    if (headers[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  CsvTable t;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file (no header)");
  for (auto& h : split_line(line)) t.headers.push_back(trim(h));
  t.columns.assign(t.headers.size(), {});
  long lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (trim(line).empty()) continue;
    const auto fields = split_line(line);
    if (fields.size() != t.headers.size())
      throw std::runtime_error(path + ":" + std::to_string(lineno) + ": " +
                               std::to_string(fields.size()) + " fields, header has " +
                               std::to_string(t.headers.size()));
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const std::string f = trim(fields[c]);
      double v = 0.0;
      if (f == "nan" || f == "-nan") {
        v = std::numeric_limits<double>::quiet_NaN();
      } else if (f == "inf") {
        v = std::numeric_limits<double>::infinity();
      } else if (f == "-inf") {
        v = -std::numeric_limits<double>::infinity();
      } else {
        const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
        if (r.ec != std::errc() || r.ptr != f.data() + f.size())
          throw std::runtime_error(path + ":" + std::to_string(lineno) + ": column '" +
                                   t.headers[c] + "': '" + f + "' is not a number");
      }
      t.columns[c].push_back(v);
    }
  }
  return t;
}

}  // namespace slamsph
