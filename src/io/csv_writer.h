// Time-series output as CSV (forces.csv, probes.csv, bodies.csv, energy.csv), and the small
// reader the plotting and the tests use to read them back.
//
// Format: one header line, then one line per row; comma separated; numbers in shortest
// round-trip form (std::to_chars: at least as precise as %.17g, reads back exactly);
// non-finite values as "nan", "inf", "-inf". Every header carries its unit in brackets,
// e.g. "time [s]", "Fx [N/m]", "Z [-]"; a header without one is a programming error and
// throws std::invalid_argument. Headers containing ',' or '"' are quoted (RFC 4180).
// The file is flushed every `flush_rows` rows, at least every `flush_seconds` of wall
// time when rows arrive, on flush() and on destruction, so a stopped run keeps its data.
#pragma once
#include <chrono>
#include <cstddef>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace slamsph {

class CsvWriter {
 public:
  // Creates (truncates) `path`; its parent directory must exist. Throws
  // std::invalid_argument for a header without "[unit]" or duplicated headers,
  // std::system_error (path and OS reason) if the file cannot be opened or written.
  // Where a resumed run continues an existing file: its size and row count at a
  // checkpoint (taken right after flush()).
  struct Resume {
    std::uintmax_t bytes = 0;
    std::size_t rows = 0;
  };
  CsvWriter(std::string path, std::vector<std::string> headers, std::size_t flush_rows = 256,
            double flush_seconds = 2.0, std::optional<Resume> resume = std::nullopt);
  // Continues `path` (written by a CsvWriter with the same headers): truncates it to
  // at.bytes and appends.
  CsvWriter(std::string path, std::vector<std::string> headers, Resume at);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  // Appends one row; values.size() must equal the number of headers (else
  // std::invalid_argument).
  void row(const std::vector<double>& values);
  void flush();

  const std::string& path() const { return path_; }
  const std::vector<std::string>& headers() const { return headers_; }
  std::size_t rows_written() const { return rows_; }

 private:
  std::optional<Resume> resume_;
  std::string path_;
  std::vector<std::string> headers_;
  std::ofstream out_;
  std::size_t flush_rows_;
  double flush_seconds_;
  std::size_t rows_ = 0;
  std::size_t rows_since_flush_ = 0;
  std::chrono::steady_clock::time_point last_flush_;
};

// True when `header` ends with a non-empty "[unit]".
bool csv_header_has_unit(const std::string& header);

// A whole CSV file in memory (numbers only after the header line).
struct CsvTable {
  std::vector<std::string> headers;
  std::vector<std::vector<double>> columns;  // columns[c][row]

  // Index of the column whose header equals `name`, or -1.
  int find(const std::string& name) const;
  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
};

// Reads a CSV written by CsvWriter. Throws std::runtime_error naming file and line for a
// missing file, a row with the wrong number of fields or a field that is not a number.
CsvTable read_csv(const std::string& path);

}  // namespace slamsph
