// Ordered JSON object builder; conventions in json_writer.h.
#include "io/json_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <variant>

#include "io/atomic_file.h"

namespace slamsph {

struct JsonObject::Value {
  struct Null {};
  std::variant<Null, double, long long, bool, std::string, JsonObject, std::vector<double>,
               std::vector<std::string>, std::vector<JsonObject>>
      v;
};

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string json_quote(const std::string& s) {
  std::string r = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"':
        r += "\\\"";
        break;
      case '\\':
        r += "\\\\";
        break;
      case '\b':
        r += "\\b";
        break;
      case '\f':
        r += "\\f";
        break;
      case '\n':
        r += "\\n";
        break;
      case '\r':
        r += "\\r";
        break;
      case '\t':
        r += "\\t";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          r += buf;
        } else {
          r += static_cast<char>(c);
        }
    }
  }
  return r + "\"";
}

JsonObject::JsonObject() = default;
JsonObject::~JsonObject() = default;
JsonObject::JsonObject(JsonObject&&) noexcept = default;
JsonObject& JsonObject::operator=(JsonObject&&) noexcept = default;
JsonObject::JsonObject(const JsonObject& o) {
  items_.reserve(o.items_.size());
  for (const auto& [k, v] : o.items_) items_.emplace_back(k, std::make_unique<Value>(*v));
}
JsonObject& JsonObject::operator=(const JsonObject& o) {
  if (this != &o) {
    JsonObject copy(o);
    *this = std::move(copy);
  }
  return *this;
}

JsonObject& JsonObject::put(const std::string& key, Value v) {
  for (auto& [k, old] : items_) {
    if (k == key) {
      *old = std::move(v);
      return *this;
    }
  }
  items_.emplace_back(key, std::make_unique<Value>(std::move(v)));
  return *this;
}

JsonObject& JsonObject::set(const std::string& key, double v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, int v) {
  return put(key, Value{static_cast<long long>(v)});
}
JsonObject& JsonObject::set(const std::string& key, long v) {
  return put(key, Value{static_cast<long long>(v)});
}
JsonObject& JsonObject::set(const std::string& key, long long v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, unsigned long v) {
  return put(key, Value{static_cast<long long>(v)});
}
JsonObject& JsonObject::set(const std::string& key, bool v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, const char* v) {
  return put(key, Value{std::string(v)});
}
JsonObject& JsonObject::set(const std::string& key, const std::string& v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, const JsonObject& v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<double>& v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<std::string>& v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<JsonObject>& v) {
  return put(key, Value{v});
}
JsonObject& JsonObject::set_null(const std::string& key) {
  return put(key, Value{});
}

bool JsonObject::contains(const std::string& key) const {
  for (const auto& kv : items_)
    if (kv.first == key) return true;
  return false;
}
std::size_t JsonObject::size() const {
  return items_.size();
}

namespace {
void newline(std::string& out, bool pretty, int indent) {
  if (!pretty) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent) * 2, ' ');
}
}  // namespace

void JsonObject::append_to(std::string& out, bool pretty, int indent) const {
  if (items_.empty()) {
    out += "{}";
    return;
  }
  out += '{';
  bool first = true;
  for (const auto& [key, val] : items_) {
    if (!first) out += ',';
    first = false;
    newline(out, pretty, indent + 1);
    out += json_quote(key);
    out += pretty ? ": " : ":";
    std::visit(
        [&](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, Value::Null>) {
            out += "null";
          } else if constexpr (std::is_same_v<T, double>) {
            out += json_number(x);
          } else if constexpr (std::is_same_v<T, long long>) {
            out += std::to_string(x);
          } else if constexpr (std::is_same_v<T, bool>) {
            out += x ? "true" : "false";
          } else if constexpr (std::is_same_v<T, std::string>) {
            out += json_quote(x);
          } else if constexpr (std::is_same_v<T, JsonObject>) {
            x.append_to(out, pretty, indent + 1);
          } else if constexpr (std::is_same_v<T, std::vector<double>>) {
            out += '[';
            for (std::size_t i = 0; i < x.size(); ++i) {
              if (i) out += pretty ? ", " : ",";
              out += json_number(x[i]);
            }
            out += ']';
          } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
            out += '[';
            for (std::size_t i = 0; i < x.size(); ++i) {
              if (i) out += pretty ? ", " : ",";
              out += json_quote(x[i]);
            }
            out += ']';
          } else {  // std::vector<JsonObject>
            if (x.empty()) {
              out += "[]";
            } else {
              out += '[';
              for (std::size_t i = 0; i < x.size(); ++i) {
                if (i) out += ',';
                newline(out, pretty, indent + 2);
                x[i].append_to(out, pretty, indent + 2);
              }
              newline(out, pretty, indent + 1);
              out += ']';
            }
          }
        },
        val->v);
  }
  newline(out, pretty, indent);
  out += '}';
}

std::string JsonObject::to_string(bool pretty) const {
  std::string out;
  append_to(out, pretty, 0);
  return out;
}

void JsonObject::write_file(const std::string& path, bool pretty) const {
  write_file_atomically(path, to_string(pretty) + '\n');
}

}  // namespace slamsph
