// Internal to the case-file parser (not a public contract): a typed, path-aware view of one
// TOML table that turns every problem into one InputError of the form
//   "<file>:<line>: <key path>: <what is wrong>; expected <what>[, got <value>]"
// and rejects unknown keys with the nearest valid key by edit distance.
#pragma once
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/vec.h"
#include "io/case_config.h"

namespace slamsph::case_detail {

// Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b);
// The candidate nearest to `word` if it is plausibly a typo of it, else "".
std::string nearest(std::string_view word, const std::vector<std::string>& candidates);
// Shortest round-trip decimal form of a double, always with a '.' or exponent.
std::string format_double(double v);
// Source line of a node (0 if unknown).
int line_of(const toml::node& n);
// Where a value came from: "--set KEY=VALUE" for a command-line override (case_overrides.cpp),
// else `file` (the case file's name).
std::string origin_of(const toml::source_region& r, const std::string& file);
// Applies `--set KEY=VALUE` overrides to the parsed table (before validation). Throws
// InputError naming the override for a malformed one or a path that does not exist.
void apply_overrides(toml::table& root, const std::vector<std::string>& sets);

// Throws the InputError "<source>:<line>: <path>: <what>; expected <expected>[, got <got>]";
// for a --set override the line is left out ("--set KEY=VALUE: <path>: ...").
[[noreturn]] void fail(const std::string& source, int line, const std::string& path,
                       const std::string& what, const std::string& expected,
                       const std::string& got = "");

// "got" text for a node: its value (strings quoted) or, for tables/arrays, its type.
std::string describe(const toml::node& n);

class Reader {
 public:
  Reader(const std::string& source, const toml::table& t, std::string path, int line);

  const std::string& path() const { return path_; }
  int line() const { return line_; }
  const std::string& source() const { return source_; }
  std::string key_path(std::string_view key) const;
  int line(std::string_view key) const;  // the key's value line, else the table's
  bool has(std::string_view key) const { return table_->contains(key); }
  const toml::node* node(std::string_view key) const { return table_->get(key); }
  const toml::table& raw() const { return *table_; }

  // Rejects any key not in `allowed` (the lowest-line offender first), suggesting the
  // nearest allowed key. `context` (e.g. "for shape type 'disc'") qualifies the message.
  void allow(std::initializer_list<std::string_view> allowed,
             const std::string& context = "") const;
  void allow(const std::vector<std::string>& allowed, const std::string& context = "") const;
  // Rejects `key` if present: "only allowed <when>".
  void forbid(std::string_view key, const std::string& when) const;

  // Typed optional getters: nullopt when absent, InputError on a wrong type. `expected`
  // describes a valid value ("a positive length in m").
  std::optional<double> number(std::string_view key, const std::string& expected) const;
  std::optional<long> integer(std::string_view key, const std::string& expected) const;
  std::optional<bool> boolean(std::string_view key) const;
  std::optional<std::string> string(std::string_view key, const std::string& expected) const;
  std::optional<Vec2> vec2(std::string_view key, const std::string& expected) const;
  // One of `choices` (unknown values get a "did you mean" suggestion).
  std::optional<std::string> choice(std::string_view key,
                                    const std::vector<std::string>& choices) const;
  std::optional<Reader> table(std::string_view key, const std::string& expected) const;
  // An array of tables ([[key]]); empty when absent.
  std::vector<Reader> table_array(std::string_view key, const std::string& expected) const;
  // Array of numbers-arrays of fixed width (motion rows, polygon vertices).
  std::optional<std::vector<std::vector<double>>> rows(std::string_view key, std::size_t width,
                                                       const std::string& expected) const;
  std::optional<std::vector<long>> int_list(std::string_view key,
                                            const std::string& expected) const;
  // Array of numbers (integers accepted); an element of another type names its index.
  std::optional<std::vector<double>> num_list(std::string_view key,
                                              const std::string& expected) const;

  [[noreturn]] void missing(std::string_view key, const std::string& expected) const;
  [[noreturn]] void bad(std::string_view key, const std::string& what, const std::string& expected,
                        const std::string& got = "") const;
  // Value checks on a number already read: fail unless ok, reporting the value.
  void check(bool ok, std::string_view key, const std::string& what, const std::string& expected,
             double value) const;

  template <class T>
  T required(const std::optional<T>& v, std::string_view key, const std::string& expected) const {
    if (!v) missing(key, expected);
    return *v;
  }

 private:
  double as_number(const toml::node& n, const std::string& path, const std::string& expected) const;

  std::string source_;
  const toml::table* table_;
  std::string path_;
  int line_;
};

}  // namespace slamsph::case_detail
