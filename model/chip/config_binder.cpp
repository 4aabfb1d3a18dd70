#include "model/chip/config_binder.h"

#include <algorithm>

#include "json_input/strict_json.h"

#include <cmath>
#include <limits>

namespace strata::chip {
namespace {

template <class T>
bool read_unsigned(const nlohmann::json& j, T* out) {
  if (j.is_number_unsigned()) {
    const auto v = j.get<uint64_t>();
    if (v > std::numeric_limits<T>::max()) return false;
    *out = static_cast<T>(v);
    return true;
  }
  if (j.is_number_integer()) return false;  // negative
  if (j.is_number_float()) {
    const double d = j.get<double>();
    if (!(d >= 0.0) || d != std::floor(d) || d > double(std::numeric_limits<T>::max())) return false;
    *out = static_cast<T>(d);
    return true;
  }
  return false;
}

bool read_double(const nlohmann::json& j, double* out) {
  if (!j.is_number()) return false;
  const double d = j.get<double>();
  if (!std::isfinite(d)) return false;
  *out = d;
  return true;
}

}  // namespace

std::string ConfigBinder::join(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

void ConfigBinder::add(const std::string& path, Field f) {
  if (!fields_.emplace(path, std::move(f)).second) throw std::logic_error("config field bound twice: " + path);
}

void ConfigBinder::bind(const std::string& path, uint32_t* field) {
  add(path, {"a whole number in 0..4294967295", [field](const nlohmann::json& j) { return read_unsigned(j, field); },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind(const std::string& path, uint64_t* field) {
  add(path, {"a whole number >= 0", [field](const nlohmann::json& j) { return read_unsigned(j, field); },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind(const std::string& path, double* field) {
  add(path, {"a finite number", [field](const nlohmann::json& j) { return read_double(j, field); },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind(const std::string& path, bool* field) {
  add(path, {"true or false",
             [field](const nlohmann::json& j) {
               if (!j.is_boolean()) return false;
               *field = j.get<bool>();
               return true;
             },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind(const std::string& path, std::string* field) {
  add(path, {"a string",
             [field](const nlohmann::json& j) {
               if (!j.is_string()) return false;
               *field = j.get<std::string>();
               return true;
             },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind_choice(const std::string& path, std::string* field, std::vector<std::string> names,
                               std::function<void()> chosen) {
  add(path, {"one of " + join(names),
             [field, names, chosen](const nlohmann::json& j) {
               if (!j.is_string() || std::find(names.begin(), names.end(), j.get<std::string>()) == names.end())
                 return false;
               *field = j.get<std::string>();
               chosen();
               return true;
             },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind_text_or_index(const std::string& path, std::string* field) {
  add(path, {"a string or a whole number",
             [field](const nlohmann::json& j) {
               uint32_t index = 0;
               if (j.is_string()) {
                 *field = j.get<std::string>();
               } else if (read_unsigned(j, &index)) {
                 *field = std::to_string(index);
               } else {
                 return false;
               }
               return true;
             },
             [field] { return nlohmann::json(*field); }});
}
void ConfigBinder::bind(const std::string& path, std::optional<double>* field) {
  add(path, {"a finite number or null",
             [field](const nlohmann::json& j) {
               if (j.is_null()) {
                 field->reset();
                 return true;
               }
               double d = 0;
               if (!read_double(j, &d)) return false;
               *field = d;
               return true;
             },
             [field] { return *field ? nlohmann::json(**field) : nlohmann::json(nullptr); }});
}

void ConfigBinder::apply_value(const std::string& path, const nlohmann::json& value,
                               const std::string& source) {
  const auto it = fields_.find(path);
  if (it == fields_.end()) throw ConfigError(source + ": unknown key '" + path + "'");
  if (!it->second.read(value))
    throw ConfigError(source + ": " + path + ": expected " + it->second.type + ", got " +
                      value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

void ConfigBinder::apply_object(const nlohmann::json& obj, const std::string& prefix,
                                const std::string& source) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it.value().is_object() && fields_.find(path) == fields_.end())
      apply_object(it.value(), path, source);
    else
      apply_value(path, it.value(), source);
  }
}

void ConfigBinder::apply(const nlohmann::json& doc, const std::string& source) {
  if (!doc.is_object()) throw ConfigError(source + ": a config must be a JSON object");
  apply_object(doc, "", source);
}

void ConfigBinder::apply_override(const std::string& assignment) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ConfigError("--set " + assignment + ": expected key=value");
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  nlohmann::json value;
  bool is_json = true;
  try {  // as a config file: a value nested too deep or with a repeated key is refused
    value = json_input::parse_strict(text, "--set " + path);
  } catch (const json_input::JsonSyntaxError&) {
    is_json = false;
  } catch (const json_input::JsonInputError& e) {
    throw ConfigError(e.what());
  }
  if (!is_json) {
    // A bare word is a string. JSON holds only UTF-8, and the config is echoed as JSON (stats.json):
    // other bytes would make that echo throw (a fuzz-found crash: the error message's own dump).
    try {
      (void)nlohmann::json(text).dump();
    } catch (const nlohmann::json::type_error&) {
      throw ConfigError("--set " + path + ": the value is not valid UTF-8");
    }
    value = text;
  }
  apply_value(path, value, "--set " + assignment);
}

nlohmann::json ConfigBinder::dump() const {
  nlohmann::json doc = nlohmann::json::object();
  for (const auto& [path, field] : fields_) {
    std::string pointer = "/" + path;  // "memory.l2.size_bytes" -> "/memory/l2/size_bytes"
    for (char& c : pointer)
      if (c == '.') c = '/';
    doc[nlohmann::json::json_pointer(pointer)] = field.write();
  }
  return doc;
}

std::vector<std::string> ConfigBinder::paths() const {
  std::vector<std::string> out;
  for (const auto& kv : fields_) out.push_back(kv.first);
  return out;
}

}  // namespace strata::chip
