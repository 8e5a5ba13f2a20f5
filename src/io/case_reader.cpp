#include "io/case_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace slamsph::case_detail {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  // A plausible typo: at most 3 edits and fewer than half the word's length.
  const std::size_t limit = std::min<std::size_t>(3, std::max<std::size_t>(1, word.size() / 2));
  return best_d <= limit ? best : std::string();
}

std::string format_double(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // n: inf/nan
  return s;
}

int line_of(const toml::node& n) {
  return static_cast<int>(n.source().begin.line);
}

std::string origin_of(const toml::source_region& r, const std::string& file) {
  if (r.path && r.path->rfind("--set ", 0) == 0) return *r.path;
  return file;
}

void fail(const std::string& source, int line, const std::string& path, const std::string& what,
          const std::string& expected, const std::string& got) {
  const bool override = source.rfind("--set ", 0) == 0;
  std::string msg = source;
  if (!override) msg.append(":").append(std::to_string(line > 0 ? line : 1));
  msg.append(": ").append(path).append(": ").append(what).append("; expected ").append(expected);
  if (!got.empty()) msg += ", got " + got;
  throw InputError(msg);
}

namespace {
std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date/time";
  }
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + ("'" + v[i] + "'");
  return s;
}
}  // namespace

std::string describe(const toml::node& n) {
  if (auto s = n.as_string()) return "\"" + s->get() + "\"";
  if (auto i = n.as_integer()) return std::to_string(i->get());
  if (auto f = n.as_floating_point()) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, f->get());
    return std::string(buf, r.ptr);
  }
  if (auto b = n.as_boolean()) return b->get() ? "true" : "false";
  return type_name(n);
}

Reader::Reader(const std::string& source, const toml::table& t, std::string path, int line)
    : source_(origin_of(t.source(), source)), table_(&t), path_(std::move(path)), line_(line) {
  const int own = line_of(t);
  if (own > 0) line_ = own;
}

std::string Reader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

int Reader::line(std::string_view key) const {
  if (const toml::node* n = table_->get(key)) {
    const int l = line_of(*n);
    if (l > 0) return l;
  }
  return line_;
}

void Reader::allow(std::initializer_list<std::string_view> allowed,
                   const std::string& context) const {
  std::vector<std::string> v;
  for (auto a : allowed) v.emplace_back(a);
  allow(v, context);
}

void Reader::allow(const std::vector<std::string>& allowed, const std::string& context) const {
  const toml::key* worst = nullptr;
  for (auto&& [k, v] : *table_) {
    if (std::find(allowed.begin(), allowed.end(), k.str()) != allowed.end()) continue;
    if (!worst || k.source().begin.line < worst->source().begin.line) worst = &k;
  }
  if (!worst) return;
  const std::string key(worst->str());
  std::string what = "unknown key" + (context.empty() ? "" : " " + context);
  const std::string near = nearest(key, allowed);
  if (!near.empty()) what += " (did you mean '" + near + "'?)";
  const int l = static_cast<int>(worst->source().begin.line);
  fail(origin_of(worst->source(), source_), l > 0 ? l : line_, key_path(key), what,
       "one of " + join(allowed));
}

void Reader::forbid(std::string_view key, const std::string& when) const {
  if (has(key)) bad(key, "key not allowed here", "it only " + when);
}

double Reader::as_number(const toml::node& n, const std::string& path,
                         const std::string& expected) const {
  double v = 0.0;
  if (auto i = n.as_integer())
    v = static_cast<double>(i->get());
  else if (auto f = n.as_floating_point())
    v = f->get();
  else
    fail(origin_of(n.source(), source_), line_of(n) > 0 ? line_of(n) : line_, path, "wrong type",
         expected, type_name(n));
  if (!std::isfinite(v))
    fail(origin_of(n.source(), source_), line_of(n) > 0 ? line_of(n) : line_, path,
         "must be finite", expected, describe(n));
  return v;
}

std::optional<double> Reader::number(std::string_view key, const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return as_number(*n, key_path(key), expected);
}

std::optional<long> Reader::integer(std::string_view key, const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (auto i = n->as_integer()) return static_cast<long>(i->get());
  bad(key, "wrong type", expected, type_name(*n));
}

std::optional<bool> Reader::boolean(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (auto b = n->as_boolean()) return b->get();
  bad(key, "wrong type", "true or false", type_name(*n));
}

std::optional<std::string> Reader::string(std::string_view key, const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (auto s = n->as_string()) return s->get();
  bad(key, "wrong type", expected, type_name(*n));
}

std::optional<Vec2> Reader::vec2(std::string_view key, const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2)
    bad(key, a ? "wrong length" : "wrong type", "a 2-element array [x, y] of " + expected,
        a ? "an array of " + std::to_string(a->size()) : type_name(*n));
  const std::string p = key_path(key);
  return Vec2{as_number(*a->get(0), p + "[0]", expected),
              as_number(*a->get(1), p + "[1]", expected)};
}

std::optional<std::string> Reader::choice(std::string_view key,
                                          const std::vector<std::string>& choices) const {
  auto s = string(key, "one of " + join(choices));
  if (!s) return s;
  if (std::find(choices.begin(), choices.end(), *s) != choices.end()) return s;
  std::string what = "unknown value";
  const std::string near = nearest(*s, choices);
  if (!near.empty()) what += " (did you mean '" + near + "'?)";
  bad(key, what, "one of " + join(choices), "\"" + *s + "\"");
}

std::optional<Reader> Reader::table(std::string_view key, const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::table* t = n->as_table();
  if (!t) bad(key, "wrong type", expected, type_name(*n));
  return Reader(source_, *t, key_path(key), line(key));
}

std::vector<Reader> Reader::table_array(std::string_view key, const std::string& expected) const {
  std::vector<Reader> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) bad(key, "wrong type", expected, type_name(*n));
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const std::string p = key_path(key) + "[" + std::to_string(i) + "]";
    const toml::table* t = e.as_table();
    if (!t)
      fail(origin_of(e.source(), source_), line_of(e) > 0 ? line_of(e) : line(key), p, "wrong type",
           expected, type_name(e));
    out.emplace_back(source_, *t, p, line(key));
  }
  return out;
}

std::optional<std::vector<std::vector<double>>> Reader::rows(std::string_view key,
                                                             std::size_t width,
                                                             const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a) bad(key, "wrong type", expected, type_name(*n));
  std::vector<std::vector<double>> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const std::string p = key_path(key) + "[" + std::to_string(i) + "]";
    const int l = line_of(e) > 0 ? line_of(e) : line(key);
    const toml::array* r = e.as_array();
    if (!r || r->size() != width)
      fail(origin_of(e.source(), source_), l, p, r ? "wrong length" : "wrong type", expected,
           r ? "an array of " + std::to_string(r->size()) : type_name(e));
    std::vector<double> row;
    for (std::size_t j = 0; j < width; ++j)
      row.push_back(as_number(*r->get(j), p + "[" + std::to_string(j) + "]", expected));
    out.push_back(std::move(row));
  }
  return out;
}

std::optional<std::vector<long>> Reader::int_list(std::string_view key,
                                                  const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a) bad(key, "wrong type", expected, type_name(*n));
  std::vector<long> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    auto v = e.as_integer();
    if (!v)
      fail(origin_of(e.source(), source_), line_of(e) > 0 ? line_of(e) : line(key),
           key_path(key) + "[" + std::to_string(i) + "]", "wrong type", expected, type_name(e));
    out.push_back(static_cast<long>(v->get()));
  }
  return out;
}

std::optional<std::vector<double>> Reader::num_list(std::string_view key,
                                                    const std::string& expected) const {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a) bad(key, "wrong type", expected, type_name(*n));
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i)
    out.push_back(as_number(*a->get(i), key_path(key) + "[" + std::to_string(i) + "]", expected));
  return out;
}

void Reader::missing(std::string_view key, const std::string& expected) const {
  fail(source_, line_, key_path(key), "missing required key", expected);
}

void Reader::bad(std::string_view key, const std::string& what, const std::string& expected,
                 const std::string& got) const {
  const toml::node* n = node(key);
  fail(n ? origin_of(n->source(), source_) : source_, line(key), key_path(key), what, expected,
       got);
}

void Reader::check(bool ok, std::string_view key, const std::string& what,
                   const std::string& expected, double value) const {
  if (!ok) bad(key, what, expected, format_double(value));
}

}  // namespace slamsph::case_detail
