// A tiny ordered JSON object builder for run summaries and metrics (summary.json,
// validation results). Keys keep insertion order; set() on an existing key replaces the
// value in place. Numbers are written in shortest round-trip form; NaN and ±inf, which
// JSON cannot represent, are written as null. Strings are escaped per RFC 8259 (", \,
// control characters); UTF-8 bytes pass through unchanged.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace slamsph {

class JsonObject {
 public:
  JsonObject();
  ~JsonObject();
  JsonObject(const JsonObject&);
  JsonObject(JsonObject&&) noexcept;
  JsonObject& operator=(const JsonObject&);
  JsonObject& operator=(JsonObject&&) noexcept;

  JsonObject& set(const std::string& key, double v);
  JsonObject& set(const std::string& key, int v);
  JsonObject& set(const std::string& key, long v);
  JsonObject& set(const std::string& key, long long v);
  JsonObject& set(const std::string& key, unsigned long v);
  JsonObject& set(const std::string& key, bool v);
  JsonObject& set(const std::string& key, const char* v);  // not converted to bool
  JsonObject& set(const std::string& key, const std::string& v);
  JsonObject& set(const std::string& key, const JsonObject& v);
  JsonObject& set(const std::string& key, const std::vector<double>& v);
  JsonObject& set(const std::string& key, const std::vector<std::string>& v);
  JsonObject& set(const std::string& key, const std::vector<JsonObject>& v);
  JsonObject& set_null(const std::string& key);

  bool contains(const std::string& key) const;
  std::size_t size() const;

  // pretty: two-space indentation, one key per line, number arrays on one line.
  std::string to_string(bool pretty = true) const;
  // Writes to_string(pretty) + "\n" to `path` via a temporary file and a rename (never
  // half-written); throws std::system_error with the path and the OS reason on failure.
  void write_file(const std::string& path, bool pretty = true) const;

 private:
  struct Value;
  JsonObject& put(const std::string& key, Value v);
  void append_to(std::string& out, bool pretty, int indent) const;

  std::vector<std::pair<std::string, std::unique_ptr<Value>>> items_;
};

// JSON text for one string (with the quotes) and one number (null if not finite).
std::string json_quote(const std::string& s);
std::string json_number(double v);

}  // namespace slamsph
