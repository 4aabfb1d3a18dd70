// Binds typed config struct fields to dotted JSON paths ("memory.l2.size_bytes"), so a config
// file and command-line overrides fill the same structs with the same checks:
//   - every key in the file must name a bound field (a typo is an error, not a default);
//   - every value must have the field's type (unsigned integers must be whole, >= 0 and fit);
//   - errors name the file and the dotted field.
// The structs' own validate() then checks the values against each other.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::chip {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ConfigBinder {
 public:
  void bind(const std::string& path, uint32_t* field);
  void bind(const std::string& path, uint64_t* field);
  void bind(const std::string& path, double* field);
  void bind(const std::string& path, bool* field);
  void bind(const std::string& path, std::string* field);
  // A string that may also be written as a whole number (a list of indices with one entry:
  // `--set tm.pipeline_impl_tms=1` reads as the number 1), kept as its decimal text.
  void bind_text_or_index(const std::string& path, std::string* field);
  void bind(const std::string& path, std::optional<double>* field);
  // An enumeration stored as a string: `names` lists the accepted spellings in value order.
  template <class Enum>
  void bind_enum(const std::string& path, Enum* field, std::vector<std::string> names) {
    Field f;
    f.type = "one of " + join(names);
    f.read = [field, names](const nlohmann::json& j) {
      if (!j.is_string()) return false;
      for (size_t i = 0; i < names.size(); ++i)
        if (j.get<std::string>() == names[i]) {
          *field = static_cast<Enum>(i);
          return true;
        }
      return false;
    };
    f.write = [field, names] { return nlohmann::json(names.at(static_cast<size_t>(*field))); };
    add(path, std::move(f));
  }

  // A string from a fixed list of names; after a valid one is read, `chosen` runs (it may fill
  // in the fields the name implies: design.name sets the design's mechanism flags).
  void bind_choice(const std::string& path, std::string* field, std::vector<std::string> names,
                   std::function<void()> chosen);

  // Applies a JSON document (a config file); `source` names it in errors.
  void apply(const nlohmann::json& doc, const std::string& source);
  // Applies "dotted.path=value"; the value is read as JSON, or as a string if it is not JSON.
  void apply_override(const std::string& assignment);
  // The current values of every bound field, as a nested document.
  nlohmann::json dump() const;
  std::vector<std::string> paths() const;

 private:
  struct Field {
    std::string type;
    std::function<bool(const nlohmann::json&)> read;  // false: wrong type or range
    std::function<nlohmann::json()> write;
  };
  void add(const std::string& path, Field f);
  void apply_value(const std::string& path, const nlohmann::json& value, const std::string& source);
  void apply_object(const nlohmann::json& obj, const std::string& prefix, const std::string& source);
  static std::string join(const std::vector<std::string>& names);

  std::map<std::string, Field> fields_;
};

}  // namespace strata::chip
